"""Energy against a stationary obstacle (issue 4): omega = 0, no damping, the obstacle rises to its depth and
stops. Multiplying the step equation A xi^k = b^k + E N lambda^k by xi^k - xi^{k-2} gives the discrete energy
identity  E^k - E^{k-1} = 1/2 sum_n lambda_n^k (q_n^k - q_n^{k-2}),  q_n the normal displacement; where
lambda_n^k > 0 the node sits on the obstacle, q_n^k = its bound <= q_n^{k-2} once xi^{k-2} is admissible for the
final obstacle (from the second step after it stops). So the scheme may dissipate at impacts but must not
create energy: checked to a relative round-off of 1e-9 per step; the dissipated fraction is printed
(docs/contact.md)."""
from rollertest import Checker, read_csv, run

c = Checker("contact_energy")
speed, depth, h = 0.05, 0.01, 0.05
run(["-mesh_h", h, "-obstacle", "-obstacle_speed", speed, "-obstacle_depth", depth, "-omega", 0, "-damping", 0,
     "-ts_max_time", 4, "-quiet", "-monitor_csv", "energy.csv"])
d = read_csv("energy.csv")
e, t = d["energy"], d["t"]
k0 = int(next(i for i, ti in enumerate(t) if ti >= depth / speed - 1e-12)) + 2
rel = (e[k0 + 1:] - e[k0:-1]) / e[k0:-1]
touching = d["contact_nodes"][k0:] > 0
c.check(touching.sum() > 10, f"the roller touches the stopped obstacle in {int(touching.sum())} of {len(touching)} steps")
c.check(max(rel) < 1e-9, f"energy never increases after the obstacle stops (largest relative increase {max(rel):.2e} < 1e-9)")
drops = -rel[rel < -1e-9]
print(f"dissipation: E = {e[k0]:.6e} at t = {t[k0]:.4g} -> {e[-1]:.6e} at t = {t[-1]:.4g}: "
      f"{100 * (e[k0] - e[-1]) / e[k0]:.2f}% lost in {len(drops)} steps (impacts), largest single drop {100 * max(drops, default=0):.3f}%")
c.check(e[-1] <= e[k0] and e[-1] > 0.5 * e[k0], f"dissipated fraction {(e[k0] - e[-1]) / e[k0]:.3f} lies in [0, 0.5)")
c.close()
