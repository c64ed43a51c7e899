"""The steady rolling/sliding state of -modes (docs/squeal.md section 3) against the long-time transient of the
co-rotating solver (the roller pressed to the same depth and turned until the press transients have faded):

- frictionless rolling (jobs/rolling.yaml, Kelvin-Voigt damping), t in [20, 30]: the transient's mean contact force
  equals the steady state's normal force within 1.5 % (measured 0.1 %), its contact node count within 3 nodes, and
  its oscillation about the mean is below 5 % (settled);
- sliding with friction 0.3 on the held sheet (jobs/slip.yaml -friction 0.3): the same for the normal force (measured
  0.4 %), the friction force = -mu times the normal force in both (the steady state's from its per-node CSV), no
  stick node in the transient (the steady state's full-sliding assumption holds).
The steady state has no damping (the lab frame's): the damping of the transients is small (tau = 0.0115) and its
effect on the mean state is within the tolerance."""
import csv
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from rollertest import SOURCE, Checker, read_csv, run  # noqa: E402

c = Checker("squeal_steady")
cases = [("rolling", [os.path.join(SOURCE, "jobs", "rolling.yaml")], 0.0), ("sliding", [os.path.join(SOURCE, "jobs", "slip.yaml"), "-friction", "0.3"], 0.3)]
for name, (job, *extra), mu in cases:
    run(["-options_file", job] + extra + ["-modes", "-viscosity", "0", "-modes_steady_csv", f"steady_{name}.csv", "-quiet"])
    with open(f"steady_{name}.csv") as f:
        rows = list(csv.DictReader(f))
    N = sum(float(r["normal_force"]) for r in rows)
    T = sum(float(r["tangential_force"]) for r in rows)
    nodes = sum(1 for r in rows if float(r["normal_force"]) > 0)
    c.check(abs(T + mu * N) <= 1e-12 * N, f"{name}: steady friction force {T:.6e} = -mu N = {-mu * N:.6e}")
    run(["-options_file", job] + extra + ["-ts_max_time", "30", "-monitor_csv", f"transient_{name}.csv", "-quiet"])
    d = read_csv(f"transient_{name}.csv")
    w = (d["t"] >= 20) & (d["t"] <= 30)
    F, Ft = d["contact_force"][w].mean(), d["friction_force"][w].mean()
    c.check(abs(F - N) < 0.015 * N, f"{name}: transient mean contact force {F:.6e} vs steady {N:.6e}: {abs(F - N) / N:.2%} < 1.5 %")
    c.check(d["contact_force"][w].std() < 0.05 * F, f"{name}: transient settled, oscillation {d['contact_force'][w].std() / F:.2%} < 5 % of the mean")
    c.check(abs(d["contact_nodes"][w].mean() - nodes) <= 3, f"{name}: contact nodes {d['contact_nodes'][w].mean():.1f} vs steady {nodes}")
    if mu > 0:
        c.check(np.abs(d["friction_force"][w] + mu * d["contact_force"][w]).max() < 1e-9 * F and d["stick_nodes"][w].max() == 0, f"{name}: transient friction force = -mu contact force (mean {Ft:.6e}), no stick node: full sliding as the steady state assumes")
c.close()
