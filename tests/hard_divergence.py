"""Divergence and failed steps: a run that blows up (rotation far beyond the centrifugal-softening limit, with
the check switched off) stops with a message naming the step and the time, exits non-zero, and leaves the
last good state in the checkpoint. So does a step whose solver fails (here the contact QP's projected CG
capped at 5 iterations): the checkpoint holds the state before the failed step, and a restart from it with a
working solver gives the same series as a run that never failed.

Discretization: Roller's default degree and Coriolis velocity (P2 curved, extrapolated): the divergence
handling must work for what users run; h and dt are given (coarse, so that the blow-up comes quickly)."""
import os
import re

import h5py
import numpy as np

from rollertest import Checker, read_csv, run

c = Checker("hard_divergence")
code, out, err = run(["-mesh_h", 0.05, "-omega", 5, "-stability_check", 0, "-ts_dt", 0.1, "-ts_max_time", 1000, "-quiet",
                      "-checkpoint", "last_good.h5", "-monitor_csv", "div.csv"], check=False)
m = re.search(r"not finite at step (\d+), t = (\S+); the last good state \(step (\d+)\) is in the checkpoint last_good.h5", out + err)
c.check(code != 0 and m is not None, f"exit {code}, message names step and time: {m.group(0) if m else (out + err)[-300:]}")
if m:
    with h5py.File("last_good.h5") as f:
        step = int(f.attrs["step"])
    c.check(step == int(m.group(1)) - 1 == int(m.group(3)), f"the checkpoint holds step {step}, the one before the failure")
    c.check(not os.path.exists("div.csv"), "no complete-looking CSV left (only div.csv.part)")

scene = ["-obstacle", "-omega", 0, "-obstacle_speed", 0.05, "-degree", 1, "-mesh_h", 0.05, "-ts_dt", 0.01, "-ts_max_time", 0.5, "-quiet"]
run(scene + ["-monitor_csv", "clean.csv"])
code, out, err = run(scene + ["-contact_solver", "pcg", "-contact_pcg_max_it", 5, "-checkpoint", "failed.h5", "-monitor_csv", "failed.csv"], check=False)
c.check(code != 0 and os.path.exists("failed.h5") and not os.path.exists("failed.csv"),
        f"a failed contact solve: exit {code}, checkpoint written: {os.path.exists('failed.h5')}, no complete-looking CSV")
if os.path.exists("failed.h5"):
    with h5py.File("failed.h5") as f:
        step = int(f.attrs["step"])
    run(scene + ["-restart", "failed.h5", "-monitor_csv", "failed.csv"])
    a, b = read_csv("clean.csv"), read_csv("failed.csv")
    diff = max(float(np.nanmax(np.abs(a[q] - b[q]))) for q in ("R", "alpha", "energy", "contact_force"))
    c.check(len(a["t"]) == len(b["t"]) and diff < 1e-12,
            f"restarted from the checkpoint of step {step} with the default solver: {len(b['t'])} rows, the clean run's series to {diff:.1e}")
c.close()
