"""Compression (issue 4; SPEC section 5 scene jobs/compression.yaml on a coarse mesh with a faster, shallower
obstacle): at every step no node penetrates (gap_min >= -1e-10), the obstacle only pushes (contact force
>= 0, and every multiplier >= 0 through the KKT residual), the obstacle is in contact at every step once it
has started pressing, the contact force grows while the obstacle advances, and the KKT residual is at
round-off. Both the slow quasi-static press and a fast one (with bouncing) are run."""
import os

from rollertest import SOURCE, Checker, read_csv, run

c = Checker("contact_compression")
scene = os.path.join(SOURCE, "jobs", "compression.yaml")
for name, speed, depth, t_end in (("slow", 0.005, 0.005, 1.0), ("fast", 0.05, 0.01, 2.0)):
    csv = f"compression_{name}.csv"
    run(["-options_file", scene, "-mesh_h", 0.05, "-obstacle_speed", speed, "-obstacle_depth", depth,
         "-ts_max_time", t_end, "-quiet", "-monitor_csv", csv])
    d = read_csv(csv)
    k = d["step"] > 0
    c.check(min(d["gap_min"][k]) >= -1e-10, f"{name}: least gap over all steps {min(d['gap_min'][k]):.2e} >= -1e-10")
    c.check(min(d["contact_force"]) >= 0, f"{name}: contact force >= 0 at every step (least {min(d['contact_force']):.2e})")
    c.check(max(d["kkt_residual"]) < 1e-10, f"{name}: KKT residual {max(d['kkt_residual']):.2e} < 1e-10 at every step")
    c.check(max(d["contact_nodes"]) > 0, f"{name}: contact happens (up to {int(max(d['contact_nodes']))} nodes, force up to {max(d['contact_force']):.3e})")
    if name == "slow":
        c.check(min(d["contact_nodes"][k]) > 0, f"{name}: in contact at every step of the quasi-static press")
        pressing = d["t"] <= depth / speed
        f = d["contact_force"][pressing & k]
        c.check(f[-1] > 2 * f[len(f) // 4], f"{name}: the force grows as the obstacle advances ({f[len(f) // 4]:.3e} -> {f[-1]:.3e})")
c.close()
