"""Fast rotation. The centrifugal term softens the roller: the rotating-frame model (and the DMF step,
whatever dt) loses stability when theta' reaches omega_1, the lowest natural frequency of the annulus
clamped on Gamma_D. Roller computes omega_1 and refuses faster rotations with a message; below the limit
(centred Coriolis) the solution stays bounded, above it (check disabled) it grows exponentially: the
limit is the physical one.

Discretization: Roller's default degree (P2 curved; omega_1 is then that of the P2 model, 0.723 for E = 0.1);
the Coriolis velocity is the centred one (given: the explicit variants have their own dt limits), h and dt
are given (coarse: omega_1 is computed for the discrete model on this mesh, and the limit does not depend
on dt)."""
import re

import numpy as np

from rollertest import Checker, read_csv, run

c = Checker("hard_fast_rotation")
base = ["-mesh_h", 0.05, "-ts_dt", 0.05, "-quiet", "-coriolis_velocity", "centered"]
_, out, _ = run(base + ["-stability_view", "-ts_max_steps", 0])
omega1 = float(re.search(r"omega_1 = (\S+),", out).group(1))
c.check(0.5 < omega1 < 1.0, f"omega_1 = {omega1:.4f} for E = 0.1 (the paper's omega = pi/10 is {np.pi / 10 / omega1:.0%} of it)")

code, out, err = run(base + ["-omega", 1.05 * omega1, "-ts_max_steps", 1], check=False)
c.check(code != 0 and "-omega" in out + err and "omega_1" in out + err, "omega = 1.05 omega_1 refused with a message naming -omega and omega_1")

for factor, bounded in ((0.9, True), (1.05, False)):
    run(base + ["-omega", factor * omega1, "-stability_check", 0, "-ts_max_time", 400, "-monitor_csv", f"w{factor}.csv"])
    R = read_csv(f"w{factor}.csv")["R"]
    q = len(R) // 4
    growth = np.abs(R[-q:]).max() / np.abs(R[:q]).max()
    if bounded:
        c.check(growth < 1.5, f"omega = {factor} omega_1: bounded over t <= 400 (growth {growth:.2f})")
    else:
        c.check(growth > 100 or not np.isfinite(growth), f"omega = {factor} omega_1 without the check: grows (x{growth:.3g})")
c.close()
