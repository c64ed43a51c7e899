"""Compression (issue 4; docs/model.md section 5 scene jobs/compression.yaml on a coarse mesh with a faster, shallower
obstacle): at every step no node penetrates (gap_min >= -1e-10), the obstacle only pushes (contact force
>= 0, and every multiplier >= 0 through the KKT residual), the obstacle is in contact at every step once it
has started pressing, the contact force grows while the obstacle advances, and the KKT residual is at
round-off. Both the slow quasi-static press and a fast one (with bouncing) are run.

Discretization: the scene file states physics only. These properties must hold for whatever discretization
runs it, so every run is made twice on -mesh_h 0.05: with Roller's default (P2 curved, dt from
-ts_phase_error: 0.0077 for t <= 1, 0.0054 for t <= 2; the scene's own discretization) and with the one the
checks were written for, P1 (-degree 1) with -ts_dt 0.0125 (what the scene set before the accurate
defaults). The Coriolis velocity plays no part at omega = 0."""
import os

from rollertest import SOURCE, Checker, read_csv, run

c = Checker("contact_compression")
scene = os.path.join(SOURCE, "jobs", "compression.yaml")
for disc, pin in (("default", []), ("P1", ["-degree", 1, "-ts_dt", 0.0125])):
    for press, speed, depth, t_end in (("slow", 0.005, 0.005, 1.0), ("fast", 0.05, 0.01, 2.0)):
        name = f"{disc} {press}"
        csv = f"compression_{disc}_{press}.csv"
        run(["-options_file", scene] + pin + ["-mesh_h", 0.05, "-obstacle_speed", speed, "-obstacle_depth", depth,
             "-ts_max_time", t_end, "-quiet", "-monitor_csv", csv])
        d = read_csv(csv)
        k = d["step"] > 0
        c.check(min(d["gap_min"][k]) >= -1e-10, f"{name}: least gap over all steps {min(d['gap_min'][k]):.2e} >= -1e-10")
        c.check(min(d["contact_force"]) >= 0, f"{name}: contact force >= 0 at every step (least {min(d['contact_force']):.2e})")
        c.check(max(d["kkt_residual"]) < 1e-10, f"{name}: KKT residual {max(d['kkt_residual']):.2e} < 1e-10 at every step")
        c.check(max(d["contact_nodes"]) > 0, f"{name}: contact happens (up to {int(max(d['contact_nodes']))} nodes, force up to {max(d['contact_force']):.3e})")
        if press == "slow":
            c.check(min(d["contact_nodes"][k]) > 0, f"{name}: in contact at every step of the quasi-static press")
            pressing = d["t"] <= depth / speed
            f = d["contact_force"][pressing & k]
            c.check(f[-1] > 2 * f[len(f) // 4], f"{name}: the force grows as the obstacle advances ({f[len(f) // 4]:.3e} -> {f[-1]:.3e})")
c.close()
