"""Restart anywhere (issue 37). A checkpoint written on one number of ranks restarts on another: its vectors are
read in the restart's own numbering by matching the positions of their nodes (src/integrate/checkpoint_order.c).
Before, a 1-rank checkpoint restarted on 2 ranks ran to the end in silence with its first contact force 90 times
the uninterrupted run's.

Scene: frictional rolling on the coarse mesh, -mesh_h 0.05 -ts_dt 0.01 -obstacle -friction 0.5 -sheet_speed 0.15,
400 steps (t = 4), checkpoints at step 150 (7 contact nodes, 2 sticking, 5 slipping). The uninterrupted runs on 1
and 2 ranks differ by round-off only (the partition changes the order of the sums: 1e-10 of the column at most over
these 400 steps, 1.3e-10 over 2000), so every restart (1 -> 2, 2 -> 1, 2 -> 3 ranks) is compared with the 1-rank
uninterrupted run: every column within 1e-8 of its largest value, the counts (contact, stick and slip nodes,
flips, iterations) equal, and the columns that are round-off by construction (gap_min, kkt_residual,
friction_residual: 1e-16 to 1e-13) within 1e-12. A checkpoint of another mesh, degree, dt or scheme is refused in
one line that names what differs with both values; so is a mesh of the same counts whose nodes are elsewhere
(the mesh file turned by 90 degrees) and a checkpoint of the earlier format.

-ts_max_wall: with a limit already past at the first step (0.001 s) a run stops after one step with the checkpoint
(exit 0), the restart with the same limit after one more, the last link runs to the end: the CSV is the
uninterrupted run's, byte for byte. A chain on 2 ranks (1000 steps) whose limit falls inside the stepping (a fraction
of the uninterrupted run's wall time, lowered until a run stops before its end, so that the machine's load changes
the limit and the number of links, not what is checked) stops, resumes with the same limit until done, and ends
with the uninterrupted run's CSV, byte for byte (what jobs/slurm/chain.sbatch does)."""
import os
import shutil
import time

import h5py
import numpy as np

from rollertest import SOURCE, Checker, read_csv, run

c = Checker("restart_ranks")
BASE = ["-mesh_h", "0.05", "-ts_dt", "0.01", "-obstacle", "-friction", "0.5", "-sheet_speed", "0.15", "-quiet"]
SCENE = BASE + ["-ts_max_time", "4"]
CUT = 150
ROUNDOFF = ("gap_min", "kkt_residual", "friction_residual")
COUNTS = ("step", "contact_nodes", "qp_iterations", "contact_flips", "contact_reversals", "stick_nodes", "slip_nodes", "coulomb_iterations", "coulomb_fallback")


def agreement(path, ref):
    """(ok, worst relative difference and its column, worst round-off column's absolute difference)."""
    d, r = read_csv(path), read_csv(ref)
    if len(d["step"]) != len(r["step"]):
        return False, f"{len(d['step'])} rows against {len(r['step'])}"
    ok, worst, worst_abs = True, (0.0, ""), (0.0, "")
    for name in r:
        diff = np.abs(d[name] - r[name]).max()
        if name in COUNTS:
            ok &= bool(diff == 0)
        elif name in ROUNDOFF:
            ok &= bool(diff <= 1e-12)
            worst_abs = max(worst_abs, (float(diff), name))
        else:
            rel = float(diff / max(np.abs(r[name]).max(), 1e-300))
            ok &= rel <= 1e-8
            worst = max(worst, (rel, name))
    return ok, f"worst {worst[0]:.1e} ({worst[1]}), round-off columns within {worst_abs[0]:.1e} ({worst_abs[1]}), counts equal"


run(SCENE + ["-monitor_csv", "full1.csv"])
run(SCENE + ["-monitor_csv", "full2.csv"], nproc=2)
ok, how = agreement("full2.csv", "full1.csv")
c.check(ok, f"uninterrupted runs on 1 and 2 ranks agree to round-off: {how}")

# the checkpoints at step 150, each beside the CSV its restarts continue
run(SCENE + ["-ts_max_steps", CUT, "-checkpoint_every", CUT, "-checkpoint", "ck1.h5", "-monitor_csv", "r12.csv"])
run(SCENE + ["-ts_max_steps", CUT, "-checkpoint_every", CUT, "-checkpoint", "ck2.h5", "-monitor_csv", "r21.csv"], nproc=2)
shutil.copy("r21.csv", "r23.csv")
for path, ranks in (("ck1.h5", 1), ("ck2.h5", 2)):
    with h5py.File(path, "r") as f:
        c.check(int(f.attrs["ranks"]) == ranks and int(f.attrs["step"]) == CUT and int(f.attrs["reduced"]) == 0, f"{path}: written on {int(f.attrs['ranks'])} rank(s) at step {int(f.attrs['step'])}, reduced {int(f.attrs['reduced'])}")
for ck, csv, nproc in (("ck1.h5", "r12.csv", 2), ("ck2.h5", "r21.csv", 1), ("ck2.h5", "r23.csv", 3)):
    run(SCENE + ["-restart", ck, "-monitor_csv", csv], nproc=nproc)
    ok, how = agreement(csv, "full1.csv")
    c.check(ok, f"{ck} restarted on {nproc} rank(s) ({csv}): the uninterrupted run's 401 rows to 1e-8: {how}")

# refusals, each in one line naming what differs with both values
for extra, name, expect in ((["-mesh_h", "0.04"], "mesh", "-mesh_h 0.05 (checkpoint) vs 0.04 (this run)"),
                            (["-degree", "1"], "degree", "-degree 2 (checkpoint) vs 1 (this run)"),
                            (["-ts_dt", "0.005"], "dt", "-ts_dt 0.01 (checkpoint) vs 0.005 (this run)"),
                            (["-ts_scheme", "dmf"], "scheme", "-ts_scheme trapezoidal (checkpoint) vs dmf (this run)")):
    code, out, err = run(SCENE + extra + ["-restart", "ck1.h5", "-monitor_csv", "refused.csv"], check=False)
    line = next((ln for ln in (out + err).splitlines() if "-restart ck1.h5: refused" in ln), "")
    c.check(code != 0 and expect in line and not os.path.exists("refused.csv"), f"another {name}: exit {code}, {line.strip()[:200]}")
code, out, err = run(SCENE + ["-mesh_h", "0.04", "-restart", "ck1.h5"], check=False)
line = next((ln for ln in (out + err).splitlines() if "refused" in ln), "")
c.check("mesh vertices 354 (checkpoint) vs 522 (this run)" in line and "mesh checksum" in line, f"another mesh: its counts and checksum named too: {line.strip()[:160]}")

# the same counts, radii and checksum (a rotation by 90 degrees keeps every |x|), the nodes elsewhere
mesh = os.path.join(SOURCE, "meshes", "annulus-h0.05-v41.msh")
lines, inside = [], False
for ln in open(mesh).read().splitlines():
    inside = (inside or ln == "$Nodes") and ln != "$EndNodes"
    p = ln.split()
    if inside and len(p) == 3:
        ln = f"{-float(p[1])!r} {float(p[0])!r} {p[2]}"
    lines.append(ln)
with open("turned.msh", "w") as f:
    f.write("\n".join(lines) + "\n")
FILE = ["-ts_dt", "0.01", "-obstacle", "-friction", "0.5", "-sheet_speed", "0.15", "-quiet", "-ts_max_time", "4"]
run(FILE + ["-dm_plex_filename", mesh, "-ts_max_steps", "5", "-checkpoint_every", "5", "-checkpoint", "file.h5"])
code, out, err = run(FILE + ["-dm_plex_filename", "turned.msh", "-restart", "file.h5"], check=False)
line = next((ln for ln in (out + err).splitlines() if "-restart file.h5" in ln), "")
c.check(code != 0 and "refused, another mesh: this run's node at" in line, f"the mesh turned by 90 degrees (same counts and checksum): exit {code}, {line.strip()[:200]}")
code, out, err = run(FILE + ["-dm_plex_filename", mesh, "-restart", "file.h5", "-ts_max_steps", "10"], nproc=2, check=False)
c.check(code == 0, f"the same mesh file restarted on 2 ranks: exit {code}")

# a checkpoint of the earlier format (no node positions: read in the writer's numbering) is refused
shutil.copy("ck1.h5", "old.h5")
with h5py.File("old.h5", "a") as f:
    del f.attrs["format"]
code, out, err = run(SCENE + ["-restart", "old.h5"], check=False)
line = next((ln for ln in (out + err).splitlines() if "-restart old.h5" in ln), "")
c.check(code != 0 and "checkpoint format 1" in line, f"format 1: exit {code}, {line.strip()[:160]}")

# -ts_max_wall past at once: one step per link, the last link without the limit
for f in ("wall.h5", "wall.csv"):
    if os.path.exists(f):
        os.remove(f)
codes = []
for link in range(3):
    limit = ["-ts_max_wall", "0.001"] if link < 2 else []
    resume = ["-restart", "wall.h5"] if link else []
    code, out, err = run(SCENE + limit + resume + ["-checkpoint", "wall.h5", "-monitor_csv", "wall.csv"], check=False)
    codes.append(code)
    if link < 2:
        with h5py.File("wall.h5", "r") as f:
            c.check(code == 0 and int(f.attrs["step"]) == link + 1, f"-ts_max_wall 0.001, link {link + 1}: exit {code}, checkpoint at step {int(f.attrs['step'])}")
c.check(codes[2] == 0 and open("wall.csv").read() == open("full1.csv").read(), "stopped after steps 1 and 2 by -ts_max_wall, resumed: CSV identical to the uninterrupted run")

# a limit that falls inside the stepping (2 ranks, 1000 steps): from 0.7 of the uninterrupted run's wall time down by
# factors 0.7 until a run stops before its end (the machine's load changes the limit and the step it stops at, not
# what is checked), then the resume with the same limit, until done
LONG = BASE + ["-ts_max_time", "10"]
start = time.time()
run(LONG + ["-monitor_csv", "long.csv"], nproc=2)
whole = time.time() - start
for f in ("chain.h5", "chain.csv"):
    if os.path.exists(f):
        os.remove(f)
limit, first = whole, 1000
for attempt in range(8):
    limit *= 0.7
    code, out, err = run(LONG + ["-ts_max_wall", f"{limit:.3f}", "-checkpoint", "chain.h5", "-monitor_csv", "chain.csv"], nproc=2, check=False)
    first = int(read_csv("chain.csv")["step"][-1]) if code == 0 else -1
    if first != 1000:
        break
# a loaded machine can spend most of the limit starting the process: after the 10th link the limit grows by 1.2 per
# link (a user may resume with another limit), so the chain ends in 40 links whatever the load
links, codes, link_limit = 1, [code], limit
while 0 <= first < 1000 and links < 40 and read_csv("chain.csv")["step"][-1] < 1000:
    if links >= 10:
        link_limit *= 1.2
    code, out, err = run(LONG + ["-ts_max_wall", f"{link_limit:.3f}", "-checkpoint", "chain.h5", "-restart", "chain.h5", "-monitor_csv", "chain.csv"], nproc=2, check=False)
    codes.append(code)
    links += 1
    if code != 0:
        break
same = os.path.exists("chain.csv") and open("chain.csv").read() == open("long.csv").read()
c.check(0 <= first < 1000 and all(k == 0 for k in codes) and same, f"-ts_max_wall {limit:.2f} s (the whole run {whole:.2f} s; the last link {link_limit:.2f} s): the first run stopped after step {first} of 1000, {links} links, exits {codes}, CSV identical to the uninterrupted run: {same}")
c.close()
