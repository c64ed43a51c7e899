"""The sheet's own motion (-sheet_mass, -sheet_resistance; docs/model.md section 10.1, issue 36): the sheet picked from
rest by the turning roller, held back by a Coulomb resistance F_r.

1. Held: with mu N < F_r the sheet does not move (its speed 0 at every step) and the roller slides over it (the
   friction force mu N, every contact node slipping).
2. Picked: with mu N > F_r the sheet's momentum balance holds at every step to round-off, m (V^k - V^{k-1}) = dt (F_k -
   F_r s) (F_k the friction on the sheet, -friction_force; s its direction), it accelerates at (mu N - F_r)/m while the
   roller slides over it (full sliding: the closed form with the run's own N), its speed comes to the roller's surface
   less a creep, where the friction force's mean is F_r within 2 %; the energy balance (the sheet's kinetic energy in
   E, the resistance's dissipation in friction_work) within 1e-10 of max E every step; a restart from 1 rank on 2
   repeats the rows.
3. long (the argument `long`): the settled creep against the steady rolling state's (-modes) at the tangential force
   F_r, on a finer contact mesh: within 10 % (the steady state's force-creep curve interpolated)."""
import math
import shutil
import sys

import numpy as np

from rollertest import Checker, read_csv, run

LONG = len(sys.argv) > 1 and sys.argv[1] == "long"
c = Checker("sheet" + ("_long" if LONG else ""))
omega, r, mu = math.pi / 40, 0.5, 0.5
mesh = ["-mesh_h", 0.05] + (["-mesh_h_contact", 0.01] if LONG else [])
press = ["-obstacle", "-obstacle_speed", 0.05, "-obstacle_depth", 0.02, "-omega", omega, "-friction", mu, "-viscosity", 0.5, "-quiet"] + mesh
common = press + ["-theta_start", 2, "-ts_scheme", "trapezoidal", "-ts_dt", 0.02]
m_s = 0.1

if not LONG:
    # 1. held: mu N (about 0.0015) below F_r
    run(common + ["-sheet_mass", m_s, "-sheet_resistance", 0.002, "-ts_max_time", 10, "-monitor_csv", "held.csv"])
    d = read_csv("held.csv")
    on = d["t"] > 3
    c.check(np.abs(d["sheet_speed"]).max() == 0.0, f"held (mu N {mu * d['contact_force'][on].mean():.5f} < F_r 0.002): the sheet never moves")
    c.check(np.abs(-d["friction_force"][on] - mu * d["contact_force"][on]).max() < 1e-9 * d["contact_force"].max() and (d["stick_nodes"][on] == 0).all(), "held: the roller slides over it (friction mu N, no node sticks)")

# 2. picked
F_r = 0.001
run(common + ["-sheet_mass", m_s, "-sheet_resistance", F_r, "-ts_max_time", 60, "-monitor_csv", "pick.csv"])
d = read_csv("pick.csv")
dt, V, F = 0.02, d["sheet_speed"], -d["friction_force"]
moving = np.where(V[1:] > 0)[0] + 1
k = moving[moving > moving[0] + 1]
lhs, rhs = m_s * (V[k] - V[k - 1]), dt * (F[k] - F_r)
# round-off: V is a difference of positions X ~ 1 over dt, its change dt (F - F_r)/m ~ 1e-4: eps X/dt^2 m/(F - F_r) ~ 1e-10
c.check(np.abs(lhs - rhs).max() < 1e-8 * np.abs(rhs).max(), f"picked: the sheet's momentum m dV = dt (F - F_r) at every step while it moves ({np.abs(lhs - rhs).max() / np.abs(rhs).max():.1e} of its largest: the round-off of V = dX/dt)")
slide = (d["t"] > 3) & (d["stick_nodes"] == 0) & (d["slip_nodes"] > 0) & (V > 0)
a = np.polyfit(d["t"][slide], V[slide], 1)[0]
a0 = (mu * d["contact_force"][slide].mean() - F_r) / m_s
c.check(abs(a / a0 - 1) < 0.02, f"picked, full sliding: acceleration {a:.5f} against (mu N - F_r)/m = {a0:.5f} with the run's N ({100 * (a / a0 - 1):+.2f} %)")
late = d["t"] > 40
V_end = V[late].mean()
c.check(abs(F[late].mean() / F_r - 1) < 0.02 and 0 < r * omega - V_end < 0.1 * r * omega,
        f"settled: friction {F[late].mean():.6f} against F_r {F_r} ({100 * (F[late].mean() / F_r - 1):+.2f} %), creep (r omega - V)/(r omega) {100 * (r * omega - V_end) / (r * omega):.2f} %")
E = d["energy"]
diss = np.cumsum(d["damping_dissipation"] + d["viscous_dissipation"] + d["contact_dissipation"])
bal = E - E[0] - (d["shaft_work"] + d["sheet_work"] - d["friction_work"] - diss)
c.check(np.abs(np.diff(bal)).max() < 1e-10 * np.abs(E).max() and np.diff(d["friction_work"]).min() >= -1e-15 * np.abs(E).max(), f"energy balance with the sheet's kinetic energy and resistance: {np.abs(np.diff(bal)).max() / np.abs(E).max():.1e} of max E a step; dissipation >= 0")

if LONG:
    # 3. the settled creep against the steady rolling state's at the tangential force F_r
    speeds = np.linspace(V_end - 0.0006, V_end + 0.0004, 3)
    Q = []
    for Vs in speeds:
        run(press + ["-sheet_speed", repr(float(Vs)), "-modes", "-modes_nev", 0, "-modes_steady_csv", "steady.csv"])
        Q.append(-read_csv("steady.csv")["tangential_force"].sum())
    V_steady = float(np.interp(F_r, Q[::-1], speeds[::-1]))  # Q falls as the sheet's speed approaches the roller's
    creep_t, creep_s = r * omega - V_end, r * omega - V_steady
    c.check(abs(creep_t / creep_s - 1) < 0.10, f"settled creep {creep_t:.6f} against the steady state's {creep_s:.6f} at F_r ({100 * (creep_t / creep_s - 1):+.1f} %)")
else:
    run(common + ["-sheet_mass", m_s, "-sheet_resistance", F_r, "-ts_max_time", 60, "-ts_max_steps", 700, "-monitor_csv", "pick_part.csv", "-checkpoint", "pick.h5", "-checkpoint_every", 700])
    shutil.copyfile("pick_part.csv", "pick_restart.csv")
    run(common + ["-sheet_mass", m_s, "-sheet_resistance", F_r, "-ts_max_time", 60, "-monitor_csv", "pick_restart.csv", "-restart", "pick.h5"], nproc=2)
    d3 = read_csv("pick_restart.csv")
    worst = max(float(np.abs(d[q] - d3[q]).max() / np.abs(d[q]).max()) for q in ("sheet_speed", "friction_force", "contact_force", "energy"))
    c.check(len(d3["t"]) == len(d["t"]) and worst < 1e-8, f"restart at step 700 (the sheet moving) from 1 rank on 2: {worst:.1e} (< 1e-8)")
c.close()
