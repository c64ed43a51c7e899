"""Divergence: a run that blows up (rotation far beyond the centrifugal-softening limit, with the check
switched off) stops with a message naming the step and the time, exits non-zero, and leaves the last good
state in the checkpoint, from which a restart can continue.

Discretization: Roller's default degree and Coriolis velocity (P2 curved, extrapolated): the divergence
handling must work for what users run; h and dt are given (coarse, so that the blow-up comes quickly)."""
import re

import h5py

from rollertest import Checker, run

c = Checker("hard_divergence")
code, out, err = run(["-mesh_h", 0.05, "-omega", 5, "-stability_check", 0, "-ts_dt", 0.1, "-ts_max_time", 1000, "-quiet",
                      "-checkpoint", "last_good.h5", "-monitor_csv", "div.csv"], check=False)
m = re.search(r"not finite at step (\d+), t = (\S+); the last good state \(step (\d+)\) is in the checkpoint last_good.h5", out + err)
c.check(code != 0 and m is not None, f"exit {code}, message names step and time: {m.group(0) if m else (out + err)[-300:]}")
if m:
    with h5py.File("last_good.h5") as f:
        step = int(f.attrs["step"])
    c.check(step == int(m.group(1)) - 1 == int(m.group(3)), f"the checkpoint holds step {step}, the one before the failure")
    c.check(not __import__("os").path.exists("div.csv"), "no complete-looking CSV left (only div.csv.part)")
c.close()
