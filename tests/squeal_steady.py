"""The steady rolling/sliding state of -modes (docs/squeal.md section 3) against the long-time transient of the
co-rotating solver (the roller pressed to the same depth and turned until the press transients have faded):

- frictionless rolling (jobs/rolling.yaml, Kelvin-Voigt damping), t in [20, 30]: the transient's mean contact force
  equals the steady state's normal force within 1.5 % (measured 0.1 %), its contact node count within 3 nodes, and
  its oscillation about the mean is below 5 % (settled);
- sliding with friction 0.3 on the held sheet (jobs/slip.yaml -friction 0.3): the same for the normal force (measured
  0.4 %), the friction force = -mu times the normal force in both (the steady state's from its per-node CSV), no
  stick node in the transient (full sliding in both);
- rolling with stick and slip zones (Carter's scene of tests/carter.py: mu = 0.8, omega = 0.025, mass damping
  eta = 1 as tests/friction_carter.py long: h_c = 0.002, dt = 0.04, t = 70, the last 5 time units averaged) at the
  creeps 0.0043, 0.0128, 0.025: normal force within 0.5 % (measured 0.02-0.11 %), Q/(mu P) within 0.02 (measured
  0.0006, 0.0002, 0.0165: the steady state's Q/(mu P) scatters by +-0.011 from mesh to mesh, the law being
  collocated at fixed nodes the patch's edges fall between, docs/squeal.md section 3; the transient's drift 0.0005
  and its dt error 0.002), and both have a stick zone.
The steady states carry the same damping as the transients (the lab frame's objective rate, docs/squeal.md 1.1)."""
import csv
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from carter import DEPTH, MU, R, sector_mesh  # noqa: E402
from rollertest import SOURCE, Checker, read_csv, run  # noqa: E402

c = Checker("squeal_steady")
cases = [("rolling", [os.path.join(SOURCE, "jobs", "rolling.yaml")], 0.0), ("sliding", [os.path.join(SOURCE, "jobs", "slip.yaml"), "-friction", "0.3"], 0.3)]
for name, (job, *extra), mu in cases:
    run(["-options_file", job] + extra + ["-modes", "-modes_nev", "0", "-modes_steady_csv", f"steady_{name}.csv", "-quiet"])
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

# rolling with stick zones: Carter's scene
OMEGA, HC = 0.025, 0.002
damping = ["-damping", 1, "-viscosity", 0]
sector_mesh("carter_sector.msh", -0.12, OMEGA * 70 + 0.12, HC)  # the arc the patch visits in the rotating frame
sector_mesh("carter_bottom.msh", -0.12, 0.12, HC)  # the patch stands at the bottom in the lab
for xi in (0.0043, 0.0128, 0.025):
    V = repr(OMEGA * R * (1 - xi))
    scene = ["-degree", 2, "-obstacle", "-obstacle_depth", DEPTH, "-omega", OMEGA, "-sheet_speed", V, "-friction", MU] + damping
    run(["-dm_plex_filename", "carter_bottom.msh"] + scene + ["-modes", "-modes_nev", 0, "-modes_steady_csv", f"steady_carter_{xi}.csv", "-quiet"])
    st = read_csv(f"steady_carter_{xi}.csv")
    on = st["state"] > 0
    P, Q = st["normal_force"][on].sum(), st["tangential_force"][on].sum()
    run(["-dm_plex_filename", "carter_sector.msh"] + scene + ["-obstacle_speed", 0.01, "-ts_dt", 0.04, "-ts_max_time", 70, "-monitor_csv", f"transient_carter_{xi}.csv", "-quiet"])
    d = read_csv(f"transient_carter_{xi}.csv")
    w = d["t"] > d["t"][-1] - 5
    Pt, Qt = d["contact_force"][w].mean(), d["friction_force"][w].mean()
    q, qt = Q / (MU * P), Qt / (MU * Pt)
    c.check(abs(P - Pt) < 0.005 * Pt and abs(q - qt) < 0.02, f"rolling xi = {xi}: steady P = {P:.6e}, Q/(mu P) = {q:+.4f} vs transient {Pt:.6e} ({abs(P - Pt) / Pt:.2%} < 0.5 %), {qt:+.4f} (diff {q - qt:+.4f}, < 0.02)")
    c.check((st["state"] == 1).sum() > 0 and d["stick_nodes"][w].min() > 0, f"rolling xi = {xi}: stick zones in both ({(st['state'] == 1).sum()} steady stick nodes of {on.sum()}; transient {d['stick_nodes'][w].mean():.1f} of {d['contact_nodes'][w].mean():.1f})")
c.close()
