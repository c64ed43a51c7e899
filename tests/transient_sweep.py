"""-sweep without -modes (src/sweep/sweep_run.c, sweep_transient.c, sweep_journal.c; docs/squeal.md section 6.5): a
transient map of the feeder (jobs/feed.yaml), creep x friction: sheet_speed 0.05 (the roller's surface, omega r_C =
0.157, slides over a slow sheet) and 0.1555 (1 % creep) times mu 0.3, 0.5, 0.8, on the coarse mesh -mesh_h 0.05, the
sheet pressed in by t = 0.5 (-obstacle_speed 0.05) and run to t = 4; the rows are over the last half. Asserted:
  - every case present, in order, with its swept values and status ok; the columns of docs/squeal.md section 6.5;
  - `mpiexec -n 2` (two sub-communicators, cases round-robin) and one rank: the same CSV but for wall_time, byte
    for byte (each case runs on one rank either way);
  - each row is its single run's: the means of contact_force, friction_force and stick/(stick + slip) over the
    window of `roller -monitor_csv` with the case's options (to 1e-12);
  - a map killed (SIGKILL) after two cases and run again (on 2 ranks) skips the journaled cases (their wall_time is
    the killed run's) and ends with the uninterrupted map's CSV; a run with another scene refuses the journals and
    leaves them; no journal remains after a complete map;
  - the job array's way: slices 0,2 and 1,2 merged by scripts/rollertools/merge_sweep.py are the map;
  - one case on 2 ranks (a sub-communicator without a case) exits 0 with its row (it stopped with an error before);
  - a case whose run fails (the VI contact solver held to one Newton step, an error at the first step) is a row with
    status failed and NaN results, and the map goes on;
  - the physics of Coulomb friction: where the whole contact slips (stick fraction < 0.05) the mean friction force
    is -mu times the mean contact force (to 2 %), where it sticks in part (1 % creep) |Q| < mu P."""
import csv
import glob
import os
import signal
import subprocess
import sys
import time

import numpy as np

from rollertest import EXE, SOURCE, Checker, read_csv, run

SHEET, MU = [0.05, 0.1555], [0.3, 0.5, 0.8]
SCENE = ["-options_file", os.path.join(SOURCE, "jobs", "feed.yaml"), "-mesh_h", 0.05, "-ts_max_time", 4, "-obstacle_speed", 0.05, "-quiet"]
MAP = SCENE + ["-sweep_sheet_speed", "0.05,0.1555", "-sweep_friction", "0.3,0.5,0.8"]
COLUMNS = ["case", "friction", "sheet_speed", "window_start", "window_end", "contact_force", "friction_force", "stick_fraction", "amplitude", "growth_rate", "frequency", "wall_time", "status"]


def rows(path):
    with open(path) as f:
        return list(csv.DictReader(f))


def without_wall(path):
    """The CSV's lines with the wall_time field removed"""
    with open(path) as f:
        lines = [line.rstrip("\n").split(",") for line in f]
    k = lines[0].index("wall_time")
    return [",".join(fields[:k] + fields[k + 1:]) for fields in lines]


def journals(name):
    return sorted(glob.glob(name + ".journal.*"))


c = Checker("transient_sweep")
for f in glob.glob("*.csv*"):
    os.remove(f)
run(MAP + ["-sweep", "np2.csv"], nproc=2)
run(MAP + ["-sweep", "np1.csv"])
np1, np2 = rows("np1.csv"), rows("np2.csv")
expect = [(mu, v) for mu in MU for v in SHEET]  # the table's order: friction before sheet_speed, the last fastest
c.check(list(np1[0].keys()) == COLUMNS, f"columns {','.join(np1[0].keys())}")
c.check([int(r["case"]) for r in np1] == list(range(len(expect))) and all(float(r["friction"]) == mu and float(r["sheet_speed"]) == v for r, (mu, v) in zip(np1, expect)), f"cases 0..{len(expect) - 1} in order with their friction, sheet_speed")
c.check(all(r["status"] == "ok" for r in np1 + np2), "every case's status ok")
c.check(without_wall("np1.csv") == without_wall("np2.csv"), "1 rank and 2 ranks: the same CSV but for wall_time, byte for byte")
c.check(not journals("np1.csv") and not journals("np2.csv") and not glob.glob("*.part"), "no journal or .part left by a complete map")

# each row is its single run: the window means of the monitor CSV
k = 3
mu, v = expect[k]
run(SCENE + ["-friction", mu, "-sheet_speed", v, "-monitor_csv", "single.csv"])
d = read_csv("single.csv")
w = d["t"] >= float(np1[k]["window_start"]) - 1e-12
nodes = d["stick_nodes"][w] + d["slip_nodes"][w]
single = {"contact_force": d["contact_force"][w].mean(), "friction_force": d["friction_force"][w].mean(), "stick_fraction": (d["stick_nodes"][w][nodes > 0] / nodes[nodes > 0]).mean()}
err = max(abs(float(np1[k][q]) - x) / abs(x) for q, x in single.items())
c.check(err < 1e-12 and float(np1[k]["window_end"]) == d["t"][-1] and w.sum() > 100, f"case {k} (mu {mu}, sheet_speed {v}): the means over t >= {float(np1[k]['window_start']):.4f} ({w.sum()} states) = the single run's -monitor_csv, to {err:.1e} (< 1e-12)")

# the cases as a table (-sweep_cases: a Latin hypercube's way), in another order and with each case's own series
# (-sweep_monitor_csv): every row = the product map's row of the same values, the series = the single run's CSV
table = [expect[5], expect[3], expect[0]]
with open("cases.csv", "w") as f:
    f.write("case,friction,sheet_speed\n" + "".join(f"{i},{mu!r},{v!r}\n" for i, (mu, v) in enumerate(table)))
run(SCENE + ["-sweep", "table.csv", "-sweep_cases", "cases.csv", "-sweep_monitor_csv", "series.csv"], nproc=2)
tab = rows("table.csv")
same = all(without_wall("table.csv")[1 + i].split(",", 1)[1] == without_wall("np1.csv")[1 + expect.index(mv)].split(",", 1)[1] for i, mv in enumerate(table))
c.check(len(tab) == 3 and list(tab[0].keys()) == COLUMNS and same, "-sweep_cases: the table's 3 cases, each row = the product map's row of its values (but for case and wall_time)")
with open("single.csv", "rb") as f1, open("series.case1.csv", "rb") as f2:
    c.check(f1.read() == f2.read(), f"-sweep_monitor_csv: case 1's series.case1.csv = the single run's -monitor_csv (mu {table[1][0]}, sheet_speed {table[1][1]}), byte for byte")
# fewer cases than sub-communicators: the rank without a case takes rank 0's use of the options (a rank that solved
# nothing used none of them, and the options check would stop it alone after the map was written)
with open("one.csv", "w") as f:
    f.write("case,friction,sheet_speed\n" + f"0,{table[1][0]!r},{table[1][1]!r}\n")
one = run(SCENE + ["-sweep", "one_case.csv", "-sweep_cases", "one.csv"], nproc=2, check=False)
c.check(one[0] == 0 and os.path.exists("one_case.csv") and without_wall("one_case.csv")[1].split(",", 1)[1] == without_wall("table.csv")[2].split(",", 1)[1],
        f"one case on 2 ranks: exit {one[0]} ({(one[1] + one[2]).strip()[-200:]}), its row = the table's of the same values")
with open("misspelt.csv", "w") as f:
    f.write("friction,sheet_sped\n0.3,0.05\n")
bad = run(SCENE + ["-sweep", "misspelt.csv.out", "-sweep_cases", "misspelt.csv"], check=False)
c.check(bad[0] != 0 and not os.path.exists("misspelt.csv.out"), f"a misspelt column (sheet_sped) is refused (exit {bad[0]}), no map written")

# killed after two cases, resumed on two ranks
proc = subprocess.Popen([EXE, "-sweep", "killed.csv"] + [str(a) for a in MAP], stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
done, t0 = 0, time.time()
while done < 2 and proc.poll() is None and time.time() - t0 < 120:
    time.sleep(0.02)
    done = sum(open(j).read().count("\n# end ") for j in journals("killed.csv"))
proc.send_signal(signal.SIGKILL)
proc.wait()
kept = sum(open(j).read().count("\n# end ") for j in journals("killed.csv"))
c.check(2 <= kept < len(expect) and not os.path.exists("killed.csv"), f"SIGKILL after {kept} of {len(expect)} cases: they are in the journal {journals('killed.csv')}, no killed.csv")
journal_before = {j: open(j).read() for j in journals("killed.csv")}
refused = run(MAP + ["-sweep", "killed.csv", "-ts_max_time", 3], check=False)[0]
c.check(refused != 0 and {j: open(j).read() for j in journals("killed.csv")} == journal_before and not os.path.exists("killed.csv"), f"a run with another scene (-ts_max_time 3) refuses the journals (exit {refused}) and leaves them")
journaled = {int(line.split(",", 1)[0]): line.rstrip("\n").split(",")[COLUMNS.index("wall_time")] for text in journal_before.values() for line in text.splitlines()[2:] if not line.startswith("#")}
run(MAP + ["-sweep", "killed.csv"], nproc=2)
resumed = rows("killed.csv")
c.check(without_wall("killed.csv") == without_wall("np1.csv"), "the killed and resumed map = the uninterrupted map (but for wall_time)")
c.check(all(resumed[case]["wall_time"] == wall for case, wall in journaled.items()), f"the journaled cases {sorted(journaled)} were not run again (their wall_time is the killed run's)")
c.check(not journals("killed.csv"), "no journal left after the resumed map completes")

# the job array's way
run(MAP + ["-sweep", "part_0.csv", "-sweep_slice", "0,2"])
run(MAP + ["-sweep", "part_1.csv", "-sweep_slice", "1,2"], nproc=2)
merge = subprocess.run([sys.executable, "-m", "rollertools.merge_sweep", "part_0.csv", "part_1.csv", "-o", "merged.csv", "--cases", str(len(expect))], capture_output=True, text=True)
c.check(merge.returncode == 0 and without_wall("merged.csv") == without_wall("np1.csv"), f"slices 0,2 and 1,2 merged = the map ({merge.stdout.strip() or merge.stderr.strip()[-200:]})")

# a run that fails is its case's status: the frictionless VI solver refused after one iteration
run(SCENE + ["-friction", 0, "-ts_max_time", 0.1, "-sweep", "failing.csv", "-sweep_obstacle_depth", "0.02,0.025", "-contact_solver", "vi", "-contact_vi_snes_max_it", 1, "-contact_vi_snes_error_if_not_converged"])
failing = rows("failing.csv")
c.check(len(failing) == 2 and all(r["status"] == "failed" and r["contact_force"] == "nan" and r["growth_rate"] == "nan" for r in failing), f"two failing runs: both rows status failed with NaN results, the map complete ({[r['status'] for r in failing]})")

# Coulomb friction: full slip gives Q = -mu P, partial stick |Q| < mu P
for r in np1:
    mu, v = float(r["friction"]), float(r["sheet_speed"])
    P, Q, stick = float(r["contact_force"]), float(r["friction_force"]), float(r["stick_fraction"])
    if v == 0.05:
        c.check(stick < 0.05 and abs(Q / P + mu) < 0.02 * mu, f"mu {mu}, sheet_speed {v} (the roller slides): stick fraction {stick:.3f} (< 0.05), mean Q/P = {Q / P:.4f} = -mu to {abs(Q / P + mu) / mu:.1e} (< 2 %)")
    else:
        c.check(stick > 0.3 and 0 < -Q < 0.9 * mu * P, f"mu {mu}, sheet_speed {v} (1 % creep): stick fraction {stick:.3f} (> 0.3), |Q|/(mu P) = {-Q / (mu * P):.3f} (< 0.9)")
c.check(all(np.isfinite([float(r["growth_rate"]), float(r["frequency"]), float(r["amplitude"])]).all() and float(r["amplitude"]) > 0 for r in np1), "every case has a fitted growth rate and frequency (the window's contact force oscillates)")
c.close()
