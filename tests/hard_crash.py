"""Nothing lost on a crash (issue 26): at least 50 SIGKILLs at random times while the run writes its monitor CSV,
the HDF5 fields with their XDMF index and a checkpoint every step. After each kill:
- a reader of the CSV's .part meets no half row (every line ends with its newline and has the header's columns:
  the writer formats a row whole and writes it with one fwrite, src/io/output_csv.c);
- the checkpoint on disk opens (h5py) and is a Roller checkpoint (its step attribute): it is written to a
  temporary name and renamed;
- the run restarted from it with the same outputs ends with a CSV byte-identical to the uninterrupted run's, and
  with complete HDF5 fields and XDMF index (no .part left).

The scene is the contact scene of restart.py on the coarse mesh, P1, -ts_dt 0.0125 (480 steps to t = 6): each
life is a second or two. ROLLER_CRASH_KILLS overrides the number of kills (default 50)."""
import os
import random
import signal
import subprocess
import time

import h5py

from rollertest import EXE, Checker, run, scratch

KILLS = int(os.environ.get("ROLLER_CRASH_KILLS", "50"))
# a run killed while it meshes leaves gmsh's temporary folder behind (nothing can remove it on a SIGKILL): PETSc's
# temporary directory (PetscGetTmp, the generated mesh's) in a folder removed when the test exits
os.environ["PETSC_TMP"] = scratch("hard_crash-tmp-")
BASE = ["-mesh_h", "0.05", "-degree", "1", "-ts_dt", "0.0125", "-coriolis_velocity", "backward", "-ts_max_time", "6", "-quiet",
        "-obstacle", "-obstacle_speed", "0.05", "-obstacle_depth", "0.01", "-damping", "1"]
OUT = ["-monitor_csv", "crash.csv", "-output", "crash.h5", "-output_every", "5", "-checkpoint", "crash_ck.h5", "-checkpoint_every", "1"]


def clean():
    for f in os.listdir("."):
        if f.startswith("crash"):
            os.remove(f)


def whole_rows(path):
    """True if every line of path ends with a newline and has as many fields as the header."""
    if not os.path.exists(path):
        return True
    data = open(path, "rb").read()
    if not data:
        return True
    if not data.endswith(b"\n"):
        return False
    lines = data.decode().splitlines()
    n = lines[0].count(",")
    return all(line.count(",") == n for line in lines[1:])


def opens(path):
    try:
        with h5py.File(path, "r") as f:
            return "step" in f.attrs
    except OSError:
        return False


c = Checker("hard_crash")
clean()
start = time.time()
run(BASE + ["-monitor_csv", "full.csv"])
life = time.time() - start
reference = open("full.csv", "rb").read()
rng = random.Random(26)
bad_rows = bad_ck = bad_restart = kills = 0
for k in range(KILLS):
    clean()
    proc = subprocess.Popen([EXE] + BASE + OUT, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    time.sleep(rng.uniform(0.1, 0.9) * life)
    if proc.poll() is not None:  # ended before the kill: not a kill
        continue
    proc.send_signal(signal.SIGKILL)
    proc.wait()
    kills += 1
    # a reader of the .part at any moment: checked at the kill (the worst moment)
    bad_rows += not whole_rows("crash.csv.part")
    if not os.path.exists("crash_ck.h5"):  # killed before the first checkpoint: a new run starts over
        continue
    bad_ck += not opens("crash_ck.h5")
    code, _, _ = run(BASE + OUT + ["-restart", "crash_ck.h5"], check=False)
    same = code == 0 and os.path.exists("crash.csv") and open("crash.csv", "rb").read() == reference
    complete = os.path.exists("crash.h5") and os.path.exists("crash.xmf") and not os.path.exists("crash.h5.part")
    if not (same and complete):
        bad_restart += 1
        print(f"kill {k}: restart exit {code}, CSV identical {same}, fields complete {complete}", flush=True)
c.check(kills >= 50 or KILLS < 50, f"{kills} SIGKILLs during the run (of {KILLS} tries)")
c.check(bad_rows == 0, f"the CSV .part at each kill: {bad_rows} with a half row")
c.check(bad_ck == 0, f"the checkpoint on disk at each kill: {bad_ck} that do not open")
c.check(bad_restart == 0, f"restarts with the same outputs: {bad_restart} whose CSV differs from the uninterrupted run's or whose fields are incomplete")
c.close()
