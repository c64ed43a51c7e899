"""An exact reference for the real problem: the rotating annulus without obstacle, started at rest, stays
axisymmetric, and reduces to a 1D radial problem in (u, v)(r, t) that scripts/rollerref/axisym.py
solves to ~1e-9 (spectral in r, exact in t). The 2D R(t) and alpha(t) must approach it as h and dt
shrink together (P1, dt = h/4, 0 <= t <= 5): the max error falls by at least 1.5x per halving, and the
finest run is within 2 % (R) and 5 % (alpha) of the reference's amplitude.

Discretization: this is the convergence path of the paper's scheme, so it is pinned: P1 (-degree 1), the
paper's backward Coriolis velocity (first order in time), dt = h/4 given with every h. (The defaults are P2
curved and the extrapolated velocity; tests/accurate_defaults.py checks those against this reference.)"""
import os
import subprocess
import sys

from rollertest import SOURCE, Checker, read_csv, rel_max_error, run

c = Checker("dmf_axisym")
T = 5.0
subprocess.run([sys.executable, "-m", "rollerref.axisym", "--scheme", "exact",
                "--t-end", str(T), "--dt-out", "0.003125", "--out", "reference.csv"], check=True)
ref = read_csv("reference.csv")
errors = []
for h in (0.05, 0.025, 0.0125):
    run(["-ts_scheme", "dmf", "-mesh_h", h, "-ts_dt", h / 4, "-degree", 1, "-coriolis_velocity", "backward", "-ts_max_time", T, "-quiet", "-monitor_csv", f"h{h}.csv"])
    d = read_csv(f"h{h}.csv")
    eR, ea = rel_max_error(d, ref, "R"), rel_max_error(d, ref, "alpha")
    print(f"h = {h}, dt = {h / 4}: max error R {eR:.3e}, alpha {ea:.3e} (relative to the reference's max)")
    errors.append((eR, ea))
for (r0, a0), (r1, a1), h in zip(errors, errors[1:], (0.025, 0.0125)):
    c.check(r0 / r1 >= 1.5 and a0 / a1 >= 1.5, f"h -> {h}: errors fall by R x{r0 / r1:.2f}, alpha x{a0 / a1:.2f} (>= 1.5)")
c.check(errors[-1][0] < 0.02 and errors[-1][1] < 0.05, f"h = 0.0125: R error {errors[-1][0]:.3%} < 2 %, alpha {errors[-1][1]:.3%} < 5 %")
c.close()
