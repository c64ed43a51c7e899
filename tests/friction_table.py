"""A measured friction curve, -friction_table v1:mu1,v2:mu2,... (issue 36; docs/friction.md section 1): the monotone
cubic interpolant acts wherever the exponential law mu + (mu_s - mu) exp(-|v|/v_c) does.

The tolerances follow from the interpolation error, computed here with scipy's PchipInterpolator (the same
Fritsch-Butland slopes and end conditions, an independent implementation): eps_mu = max |table - law| over the
table's speeds, eps_s the same for the slope at the steady slip speeds.

1. Transient (jobs/feed.yaml, rolling with 1 % creep, made velocity-weakening: mu 0.5, mu_s 1.0, v_c 0.002, coarse
   mesh, to t = 3): the law sampled every v_c/20 up to 15 v_c gives the CSV of the exponential law: contact_force,
   friction_force, R, alpha, shaft_torque within 10 eps_mu / mu_min of their largest values (a step's friction force is
   mu(v) lambda_N at a slipping node, so the law's relative error eps_mu/mu_min is the size of a step's change; 10 for
   its accumulation over the run), the same stick and slip nodes. The weakening matters here: the friction force
   differs by ~15 % from v_c = 0.01's.
2. Complex eigenvalues (-modes -obstacle, the paper's roller on the held sheet: full sliding at v ~ 0.16, mu 0.5,
   mu_s 1.0, v_c 0.1, squeal_quick's coarse graded mesh): the sampled table's steady state has the law's mu at every
   node to 2 eps_mu, and its growth rates are the law's to 10 (dsigma/dmu eps_mu + dsigma/dmu' eps_s), the
   sensitivities of this scene measured in 3 (growth ~ mu: sigma/mu; the slope's: the rise/fall difference over the
   slopes' difference).
3. The slope's sign (same scene): a constant mu 0.655, then two rise-then-fall tables through mu(v_bar) = 0.655 at the
   steady state's force-weighted slip speed v_bar, exactly linear (collinear points) with slope -1 (falling branch)
   and +1 (rising branch) over every node's slip speed. The steady states take mu_j = the interpolant at their slip
   speeds (scipy's, to 1e-12); the order-1 backward and order-0 pairs grow faster on the falling branch and slower
   on the rising one than at constant mu (the slope's damping, docs/squeal.md), by more than 10 % of the constant-mu
   growth between the two (26 % and 87 %; the levels of mu alone, the slope dropped from the linearization in a
   mutated build, move the order-1 growth by 1 % and the order-0 growth the other way), antisymmetrically to first
   order: |sigma_F + sigma_R - 2 sigma_C| <= 0.2 |sigma_F - sigma_R|."""
import csv
import math

import numpy as np
from scipy.interpolate import PchipInterpolator

from rollertest import SOURCE, Checker, read_csv, run

c = Checker("friction_table")
MU, MU_S = 0.5, 1.0


def law(v, v_c):
    return MU + (MU_S - MU) * np.exp(-np.abs(v) / v_c)


def sampled(v_c, per=20, span=15):
    """The exponential law at v = 0, v_c/per, ..., span v_c: the option's text and scipy's interpolant of it."""
    v = np.arange(span * per + 1) * v_c / per
    mu = law(v, v_c)
    return ",".join(f"{a:.17g}:{b:.17g}" for a, b in zip(v, mu)), PchipInterpolator(v, mu)


def table_text(points):
    return ",".join(f"{v:.17g}:{m:.17g}" for v, m in points)


# 1. the transient
V_C = 0.002
MESH = ["-mesh_h", 0.05, "-mesh_h_contact", 0.0112, "-mesh_contact_layer", 0.0224]
text, pchip = sampled(V_C)
fine = np.linspace(0, 15 * V_C, 200001)
eps_mu = np.abs(pchip(fine) - law(fine, V_C)).max()
base = ["-options_file", f"{SOURCE}/jobs/feed.yaml", *MESH, "-ts_max_time", 3, "-quiet"]
run(base + ["-friction", MU, "-friction_static", MU_S, "-friction_decay", V_C, "-monitor_csv", "feed_law.csv"])
run(base + ["-friction_table", text, "-monitor_csv", "feed_table.csv"])  # replaces the YAML's friction: 0.8, warned
a, b = read_csv("feed_law.csv"), read_csv("feed_table.csv")
tol = 10 * eps_mu / MU
worst = {q: np.abs(a[q] - b[q]).max() / np.abs(a[q]).max() for q in ("contact_force", "friction_force", "R", "alpha", "shaft_torque")}
c.check(max(worst.values()) <= tol and (a["stick_nodes"] == b["stick_nodes"]).all() and (a["slip_nodes"] == b["slip_nodes"]).all(),
        f"transient: the table sampled every v_c/20 (eps_mu = {eps_mu:.2e}) gives the law's CSV: " + ", ".join(f"{q} {w:.1e}" for q, w in worst.items()) + f" <= 10 eps_mu/mu = {tol:.1e}; the same stick and slip nodes")
c.check(b["friction_residual"].max() <= 1e-8 and b["slip_nodes"].max() > 0, f"transient: Coulomb's law with the table at every node and step (friction_residual {b['friction_residual'].max():.1e}), {b['slip_nodes'].max():.0f} nodes slip")
run(base + ["-friction", MU, "-friction_static", MU_S, "-friction_decay", 0.01, "-monitor_csv", "feed_law_slow.csv"])
slow = read_csv("feed_law_slow.csv")
effect = np.abs(slow["friction_force"] - a["friction_force"]).max() / np.abs(a["friction_force"]).max()
c.check(effect > 100 * tol, f"transient: the weakening matters in this scene: v_c 0.01 instead of 0.002 changes the friction force by {effect:.1%}")

# 2. and 3. complex eigenvalues on the held sheet
CEA_MESH = ["-mesh_h", "0.07", "-mesh_h_contact", "0.0175", "-mesh_contact_layer", "0.035"]


def cea(name, *law_options):
    run(["-modes", "-obstacle", *law_options, "-modes_nev", 16, "-modes_csv", f"{name}.csv", "-modes_steady_csv", f"{name}_steady.csv", "-quiet"] + CEA_MESH)
    with open(f"{name}.csv") as f:
        rows = list(csv.DictReader(f))
    st = read_csv(f"{name}_steady.csv")
    on = st["state"] > 0
    return rows, {k: v[on] for k, v in st.items()}


def pair(rows, order, wave):
    r = [x for x in rows if int(x["order"]) == order and x["wave"] == wave]
    return float(min(r, key=lambda x: float(x["frequency"]))["growth_rate"])


PAIRS = ((1, "backward"), (0, "standing"))
# 3 first: the sensitivities of the scene
MU_C, SLOPE = 0.655, 1.0
rows_c, st_c = cea("constant", "-friction", MU_C)
v_bar = float((st_c["normal_force"] * st_c["slip_velocity"]).sum() / st_c["normal_force"].sum())
line = [(v_bar + 0.03 * k, MU_C + SLOPE * 0.03 * k) for k in range(-3, 4)]  # exactly linear between the inner five
falling = [(0, 0.55), (0.035, 0.8)] + [(v, 2 * MU_C - m) for v, m in line] + [(0.45, 0.5), (1, 0.5)]
rising = [(0, 0.5)] + line + [(0.32, 0.8), (0.7, 0.6), (1.5, 0.55)]
c.check(min(st_c["slip_velocity"]) > line[1][0] and max(st_c["slip_velocity"]) < line[-2][0], f"slope: every node slides within the tables' linear stretch [{line[1][0]:.3f}, {line[-2][0]:.3f}] (v from {min(st_c['slip_velocity']):.3f} to {max(st_c['slip_velocity']):.3f}, v_bar {v_bar:.4f})")
sig = {"C": {p: pair(rows_c, *p) for p in PAIRS}}
for tag, pts in (("F", falling), ("R", rising)):
    rows, st = cea(f"table_{tag}", "-friction_table", table_text(pts))
    ref = PchipInterpolator(*zip(*pts))(st["slip_velocity"])
    c.check(np.abs(st["mu"] - ref).max() <= 1e-12 and (st["state"] == 2).all(),
            f"slope {tag}: the steady state slides at every node with mu = the interpolant (scipy's) at its slip speed: {np.abs(st['mu'] - ref).max():.1e} <= 1e-12")
    sig[tag] = {p: pair(rows, *p) for p in PAIRS}
for p in PAIRS:
    f_, c_, r_ = sig["F"][p], sig["C"][p], sig["R"][p]
    c.check(f_ > c_ > r_ and f_ - r_ > 0.1 * c_ and abs(f_ + r_ - 2 * c_) <= 0.2 * abs(f_ - r_),
            f"slope: order {p[0]} {p[1]}: growth {f_:.5f} falling > {c_:.5f} constant > {r_:.5f} rising, F - R = {(f_ - r_) / c_:.0%} of C (> 10 %); first order in the slope: |F + R - 2C| = {abs(f_ + r_ - 2 * c_):.1e} <= 0.2 |F - R| = {0.2 * abs(f_ - r_):.1e}")

# 2. the exponential law against its sampled table
V_C2 = 0.1
rows_law, st_law = cea("law", "-friction", MU, "-friction_static", MU_S, "-friction_decay", V_C2)
text2, pchip2 = sampled(V_C2)
rows_tab, st_tab = cea("law_table", "-friction_table", text2)
fine2 = np.linspace(0, 15 * V_C2, 200001)
eps_mu2 = np.abs(pchip2(fine2) - law(fine2, V_C2)).max()
v = np.linspace(st_law["slip_velocity"].min(), st_law["slip_velocity"].max(), 10001)
eps_s = np.abs(pchip2.derivative()(v) + (MU_S - MU) / V_C2 * np.exp(-v / V_C2)).max()
c.check(np.abs(st_tab["mu"] - st_law["mu"]).max() <= 2 * eps_mu2 and len(st_tab["mu"]) == len(st_law["mu"]),
        f"law: the sampled table's steady state has the law's mu at every node: {np.abs(st_tab['mu'] - st_law['mu']).max():.1e} <= 2 eps_mu = {2 * eps_mu2:.1e}")
for p in PAIRS:
    d_mu = abs(sig["C"][p]) / MU_C
    d_slope = abs(sig["F"][p] - sig["R"][p]) / (2 * SLOPE)
    tol2 = 10 * (d_mu * eps_mu2 + d_slope * eps_s)
    g_law, g_tab = pair(rows_law, *p), pair(rows_tab, *p)
    c.check(abs(g_tab - g_law) <= tol2, f"law: order {p[0]} {p[1]}: growth {g_tab:.9f} with the table, {g_law:.9f} with the law: {abs(g_tab - g_law):.1e} <= 10 (dsigma/dmu {d_mu:.3f} eps_mu {eps_mu2:.1e} + dsigma/dmu' {d_slope:.4f} eps_s {eps_s:.1e}) = {tol2:.1e}")
same = [(x["order"], x["wave"]) for x in rows_law] == [(x["order"], x["wave"]) for x in rows_tab]
c.check(same, f"law: the same {len(rows_law)} modes (orders and waves, in order of frequency)")
c.close()
