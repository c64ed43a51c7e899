"""The time schemes' discrete energy (docs/model.md section 2.1). Usage: scheme_energy.py [quick|long].

Theorem 1's setting (theta = 0, xi = 0 on the whole boundary, no damping, a bump at rest; P2, -mesh_h 0.1,
dt = 0.0125): every scheme conserves its energy exactly in exact arithmetic; what remains is round-off. The
trapezoidal family solves for an increment without a scalar of dt in front of M (docs/model.md section 2.1): a scalar
rounded once for the run, the same every step, had drifted the energy linearly (2.8e-17 E a step, trapezoidal; 5.5e-16,
composed). quick: 2000 steps, the drift below 1e-13 for every scheme, and each step's change below 2e-14 E. long:
1e5 steps, below 1e-12 (the issue's bound) for every scheme.

With rotation (omega, a perturbation theta_a, theta_b: Euler, centrifugal and Coriolis loads) and both dampings, the
balance E^k - E^{k-1} = load_work - damping_dissipation - viscous_dissipation closes to 1e-12 of max E at every step
for every scheme, the dissipations >= 0 (the composition damps in its positive stages only)."""
import sys

import numpy as np

from rollertest import Checker, read_csv, run

mode = sys.argv[1] if len(sys.argv) > 1 else "quick"
c = Checker(f"scheme_energy {mode}")
SCHEMES = ("dmf", "trapezoidal", "composed")
steps = 2000 if mode == "quick" else 100000
bound = {"quick": 1e-13, "long": 1e-12}[mode]
for s in SCHEMES:
    csv = f"theorem1_{s}.csv"
    run(["-ts_scheme", s, "-mesh_h", 0.1, "-ts_dt", 0.0125, "-clamp_outer", "-initial_condition", "bump", "-omega", 0,
         "-ts_max_steps", steps, "-ts_max_time", steps * 0.0125, "-quiet", "-monitor_csv", csv])
    e = read_csv(csv)["energy"]
    drift, jump = np.abs(e - e[0]).max() / e[0], np.abs(np.diff(e)).max() / e[0]
    c.check(len(e) == steps + 1 and drift < bound and jump < 2e-14,
            f"{s}: energy drift over {steps} steps {drift:.2e} < {bound:.0e}, largest step change {jump:.1e} < 2e-14 (E = {e[0]:.6e})")

if mode == "quick":
    for s in SCHEMES:
        csv = f"rotation_{s}.csv"
        run(["-ts_scheme", s, "-mesh_h", 0.05, "-ts_dt", 0.0125, "-theta_a", 0.1, "-theta_b", 2, "-damping", 0.3,
             "-viscosity", 0.005, "-ts_max_steps", 300, "-quiet", "-monitor_csv", csv])
        d = read_csv(csv)
        e = d["energy"]
        terms = d["load_work"] - d["damping_dissipation"] - d["viscous_dissipation"]
        closure = np.abs(e[1:] - e[:-1] - terms[1:]).max() / e.max()
        c.check(closure < 1e-12 and d["damping_dissipation"].min() >= 0 and d["viscous_dissipation"].min() >= 0,
                f"{s}, rotation and dampings: balance closes to {closure:.1e} < 1e-12 of max E, dissipations >= 0")
c.close()
