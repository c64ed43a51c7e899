"""Nearly incompressible rubber, nu = 0.49, 0.499, 0.4999, against the exact axisymmetric reference
(scripts/rollerref/axisym.py) over 0 <= t <= 5, h = 0.025, dt = 0.003125, centred Coriolis velocity.
P1 locks: its error in the shear-driven tangential motion alpha grows as nu -> 1/2. P2 stays accurate
(docs/stability.md). R is compared through its time mean (the centrifugal equilibrium it oscillates
about), because its fast radial mode (period 0.067 at nu = 0.4999) is a time-resolution question."""
import os
import subprocess
import sys

from rollertest import SOURCE, Checker, read_csv, rel_max_error, run

c = Checker("hard_incompressible")
T, dt = 5.0, 0.003125
err = {}
for nu in (0.49, 0.499, 0.4999):
    subprocess.run([sys.executable, "-m", "rollerref.axisym", "--scheme", "exact", "--poisson", str(nu),
                    "--t-end", str(T), "--dt-out", str(dt), "--out", f"ref{nu}.csv"], check=True, capture_output=True)
    ref = read_csv(f"ref{nu}.csv")
    for degree in (1, 2):
        run(["-mesh_h", 0.025, "-degree", degree, "-poisson", nu, "-ts_dt", dt, "-ts_max_time", T, "-coriolis_velocity", "centered",
             "-quiet", "-monitor_csv", f"p{degree}_{nu}.csv"])
        d = read_csv(f"p{degree}_{nu}.csv")
        ea = rel_max_error(d, ref, "alpha")
        eR = abs(d["R"].mean() - ref["R"].mean()) / abs(ref["R"].mean())
        err[degree, nu] = (ea, eR)
        print(f"nu = {nu}, P{degree}: alpha max error {ea:.3e}, mean R error {eR:.3e}")
c.check(err[1, 0.4999][0] > 5 * err[1, 0.49][0], f"P1 locks: alpha error {err[1, 0.49][0]:.2e} (nu 0.49) -> {err[1, 0.4999][0]:.2e} (nu 0.4999), > 5x")
for nu in (0.49, 0.499, 0.4999):
    ea, eR = err[2, nu]
    c.check(ea < 0.03 and eR < 0.02, f"P2, nu = {nu}: alpha error {ea:.2e} < 3 %, mean R error {eR:.2e} < 2 %")
c.close()
