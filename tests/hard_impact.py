"""Hard impact: the obstacle rises 100x faster than in the paper (0.5 instead of 0.005, depth 0.025
reached at t = 0.05), omega = 0, damping 1, dt = 0.0025, 0 <= t <= 2, h = 0.05, 0.025, 0.0125. At every
step: no penetration beyond 1e-10, the QP solved (KKT residual below 1e-10). The contact-force history
converges with h: the impulse int F dt and the L1 distance to the finest history shrink.

Discretization: an h-refinement path of P1 at a fixed dt, so -degree 1 is given (the default is P2 curved,
which on the finest mesh would also cost several times as much); dt and h are given; the Coriolis velocity
plays no part at omega = 0."""
import numpy as np

from rollertest import Checker, read_csv, run

c = Checker("hard_impact")
hs = (0.05, 0.025, 0.0125)
runs = {}
for h in hs:
    run(["-mesh_h", h, "-degree", 1, "-obstacle", "-obstacle_speed", 0.5, "-omega", 0, "-damping", 1, "-ts_dt", 0.0025, "-ts_max_time", 2,
         "-quiet", "-monitor_csv", f"impact{h}.csv"])
    d = runs[h] = read_csv(f"impact{h}.csv")
    c.check(d["gap_min"][1:].min() >= -1e-10, f"h = {h}: min gap {d['gap_min'][1:].min():.2e} >= -1e-10")
    c.check(d["kkt_residual"].max() < 1e-10 and d["contact_force"].min() >= 0,
            f"h = {h}: max KKT residual {d['kkt_residual'].max():.1e} < 1e-10, force >= 0, max {d['contact_force'].max():.3f}")
impulse = {h: np.trapz(runs[h]["contact_force"], runs[h]["t"]) for h in hs}
d1, d2 = abs(impulse[0.05] - impulse[0.025]), abs(impulse[0.025] - impulse[0.0125])
c.check(d2 < 0.5 * d1, f"impulse {impulse[0.05]:.6f}, {impulse[0.025]:.6f}, {impulse[0.0125]:.6f}: differences {d1:.2e} -> {d2:.2e} shrink")
fine = runs[0.0125]
dist = {h: np.trapz(np.abs(runs[h]["contact_force"] - fine["contact_force"]), fine["t"]) / impulse[0.0125] for h in (0.05, 0.025)}
c.check(dist[0.025] < dist[0.05], f"L1 distance of the force history to h = 0.0125: {dist[0.05]:.3f} (h = 0.05) -> {dist[0.025]:.3f} (h = 0.025)")
c.close()
