"""Coulomb friction: the law, the energy identity, the solvers and -friction 0 (issue 14; docs/friction.md).

1. The feeder (jobs/feed.yaml: the rolling scene with mu = 0.8 and the sheet at 0.99 of the surface speed) to
   t = 6 on a coarse mesh (-mesh_h 0.05 -mesh_h_contact 0.0112: the law and the identity hold on any mesh):
   - the law holds at every contact node and step: friction_residual <= 1e-8 (it bounds |lambda_T| <= mu
     lambda_N (1 + 1e-8), the slip of sticking nodes relative to the nodes' tangential motion, and the force of
     slipping ones against their slip; docs/friction.md section 4);
   - the energy identity of every step, E^k - E^{k-1} = dW_shaft + dW_sheet - D_f - D_contact - D_eta - D_tau
     (the cumulative columns differenced), closes to 1e-12 of the largest energy, and D_f >= -1e-15 E_max;
   - with friction the frictionless contact dissipation stays as small as without friction (the same scene at
     mu = 0): its sum is below 2x the frictionless one plus 1e-12 E_max;
   - the KKT residual of the step (equilibrium with the normal and tangential forces) <= 1e-10, no penetration;
   - both sticking and slipping nodes occur (the feeder rolls with a stick zone and a slip zone).
2. Sliding (jobs/slip.yaml, same mesh, t = 6): every contact node slips, and the friction force is -mu times the
   normal force (against the roller's surface motion) to 1e-10.
3. The solvers agree: the default (semismooth Newton on Coulomb), the fixed point of Tresca steps with each box-QP
   solver (-contact_friction_newton false -contact_friction_qp activeset, tao, vi) and Coulomb as one LCP (lemke)
   give the same contact_force, friction_force, R and alpha to 1e-8 (relative to their largest values) over the
   feeder to t = 3.
4. -friction 0 builds no friction machinery and gives the frictionless results bit for bit: the rolling scene
   to t = 2 with and without -friction 0 writes byte-identical CSVs (coulomb_iterations 0, friction_force 0)."""
import filecmp

import numpy as np

from rollertest import SOURCE, Checker, read_csv, run

c = Checker("friction_law")
MESH = ["-mesh_h", 0.05, "-mesh_h_contact", 0.0112, "-mesh_contact_layer", 0.0224]


def scene(name, csv, t_end, *extra):
    run(["-options_file", f"{SOURCE}/jobs/{name}.yaml", *MESH, "-ts_max_time", t_end, "-quiet", "-monitor_csv", csv, *extra])
    return read_csv(csv)


def identity(d):
    """max over steps of |E^k - E^{k-1} - (works - dissipations)| / E_max, and the least D_f / E_max."""
    emax = np.abs(d["energy"]).max()
    works = np.diff(d["shaft_work"] + d["sheet_work"] - d["friction_work"])
    losses = (d["contact_dissipation"] + d["damping_dissipation"] + d["viscous_dissipation"])[1:]
    return np.abs(np.diff(d["energy"]) - works + losses).max() / emax, np.diff(d["friction_work"]).min() / emax, emax


# 1. the feeder
feed = scene("feed", "feed.csv", 6.0)
bal, dmin, emax = identity(feed)
c.check(feed["friction_residual"].max() <= 1e-8, f"feed: Coulomb's law at every node and step: max friction_residual = {feed['friction_residual'].max():.1e} <= 1e-8")
c.check(bal < 1e-12, f"feed: energy identity with the shaft, sheet and friction works closes at every step: {bal:.1e} of E_max < 1e-12")
c.check(dmin > -1e-15, f"feed: friction dissipation >= 0 at every step: min D_f / E_max = {dmin:.1e} (total {feed['friction_work'][-1] / emax:.2e} E_max)")
c.check(feed["kkt_residual"].max() <= 1e-10 and feed["gap_min"].min() >= -1e-10, f"feed: KKT residual {feed['kkt_residual'].max():.1e} <= 1e-10, gap_min {feed['gap_min'].min():.1e} >= -1e-10")
contact = feed["contact_nodes"] > 0
c.check((feed["stick_nodes"][contact] > 0).any() and (feed["slip_nodes"][contact] > 0).any() and (feed["stick_nodes"] + feed["slip_nodes"] == feed["contact_nodes"]).all(),
        f"feed: stick ({feed['stick_nodes'][-1]:.0f}) and slip ({feed['slip_nodes'][-1]:.0f}) nodes at the end, and they add up to the contact nodes at every step")
free = scene("feed", "feed_mu0.csv", 6.0, "-friction", 0)
dc, dc0 = feed["contact_dissipation"].sum(), free["contact_dissipation"].sum()
c.check(dc <= 2 * dc0 + 1e-12 * emax, f"feed: the contact dissipation stays small with friction: {dc / emax:.2e} E_max (without friction {dc0 / emax:.2e})")
print(f"feed: Coulomb solve: {feed['coulomb_iterations'].mean():.1f} Newton iterations per step on average, at most {feed['coulomb_iterations'].max():.0f}")

# 2. sliding
slip = scene("slip", "slip.csv", 6.0)
on = slip["contact_nodes"] > 0
ratio = np.abs(slip["friction_force"][on] + 0.8 * slip["contact_force"][on]).max() / slip["contact_force"].max()
c.check((slip["stick_nodes"][on] == 0).all() and (slip["slip_nodes"][on] == slip["contact_nodes"][on]).all(), "slip: every contact node slips at every step")
c.check(ratio < 1e-10, f"slip: friction_force = -mu contact_force to {ratio:.1e} < 1e-10")
bal, dmin, _ = identity(slip)
c.check(bal < 1e-12 and dmin > -1e-15, f"slip: energy identity {bal:.1e} < 1e-12, min D_f / E_max {dmin:.1e}")

# 3. the solvers agree
ref = scene("feed", "feed_newton.csv", 3.0)
for qp in ("activeset", "tao", "vi", "lemke"):
    d = scene("feed", f"feed_{qp}.csv", 3.0, "-contact_friction_newton", "false", "-contact_friction_qp", qp)
    diff = max(np.abs(d[q] - ref[q]).max() / np.abs(ref[q]).max() for q in ("contact_force", "friction_force", "R", "alpha"))
    c.check(diff < 1e-8 and d["friction_residual"].max() <= 1e-8, f"-contact_friction_qp {qp} agrees with the Newton default: {diff:.1e} < 1e-8 (law residual {d['friction_residual'].max():.1e})")

# 4. -friction 0
for tag, extra in (("none", []), ("zero", ["-friction", 0])):
    run(["-options_file", f"{SOURCE}/jobs/rolling.yaml", *MESH, "-ts_max_time", 2.0, "-quiet", "-monitor_csv", f"rolling_{tag}.csv", *extra])
z = read_csv("rolling_zero.csv")
c.check(filecmp.cmp("rolling_none.csv", "rolling_zero.csv", shallow=False) and not z["coulomb_iterations"].any() and not z["friction_force"].any(),
        "-friction 0: the CSV is byte-identical to the run without the option (no friction machinery)")
c.close()
