"""Energy against a stationary obstacle (issue 4): omega = 0, no damping, the obstacle rises to its depth and
stops. Multiplying the step equation A xi^k = b^k + E N lambda^k by xi^k - xi^{k-2} gives the discrete energy
identity  E^k - E^{k-1} = 1/2 sum_n lambda_n^k (q_n^k - q_n^{k-2}),  q_n the normal displacement; where
lambda_n^k > 0 the node sits on the obstacle, q_n^k = its bound <= q_n^{k-2} once xi^{k-2} is admissible for the
final obstacle (from the second step after it stops). So the scheme may dissipate at impacts but must not
create energy: checked to a relative round-off of 1e-9 per step; the dissipated fraction is printed
(docs/contact.md).

Discretization: the identity holds for any degree, dt and h, so the check runs twice on -mesh_h 0.05: with
Roller's default discretization (P2 curved, dt from -ts_phase_error: 0.00384 for t <= 4) and with the one the
test was written for (P1, -ts_dt 0.0125). The Coriolis velocity plays no part at omega = 0."""
from rollertest import Checker, read_csv, run

c = Checker("contact_energy")
speed, depth, h = 0.05, 0.01, 0.05
for name, tag, extra in (("default P2", "default", []), ("P1 dt 0.0125", "p1", ["-degree", 1, "-ts_dt", 0.0125])):
    csv = f"energy_{tag}.csv"
    run(["-mesh_h", h, "-obstacle", "-obstacle_speed", speed, "-obstacle_depth", depth, "-omega", 0, "-damping", 0,
         "-ts_max_time", 4, "-quiet", "-monitor_csv", csv] + extra)
    d = read_csv(csv)
    e, t = d["energy"], d["t"]
    k0 = int(next(i for i, ti in enumerate(t) if ti >= depth / speed - 1e-12)) + 2
    rel = (e[k0 + 1:] - e[k0:-1]) / e[k0:-1]
    touching = d["contact_nodes"][k0:] > 0
    c.check(touching.sum() > 10, f"{name}: the roller touches the stopped obstacle in {int(touching.sum())} of {len(touching)} steps")
    c.check(max(rel) < 1e-9, f"{name}: energy never increases after the obstacle stops (largest relative increase {max(rel):.2e} < 1e-9)")
    drops = -rel[rel < -1e-9]
    print(f"{name}: dissipation: E = {e[k0]:.6e} at t = {t[k0]:.4g} -> {e[-1]:.6e} at t = {t[-1]:.4g}: "
          f"{100 * (e[k0] - e[-1]) / e[k0]:.2f}% lost in {len(drops)} steps (impacts), largest single drop {100 * max(drops, default=0):.3f}%")
    c.check(e[-1] <= e[k0] and e[-1] > 0.5 * e[k0], f"{name}: dissipated fraction {(e[k0] - e[-1]) / e[k0]:.3f} lies in [0, 0.5)")
c.close()
