"""The axle and the drive (-axle, docs/model.md section 10; issue 36): the hub a rigid body on a vertical spring
preloaded to -nip_force and driven through a torsional spring and damper by the motor.

1. Stiff-rubber limit (E = 1000 x the paper's, the body nearly rigid), no obstacle: the drive's torsional frequency
   sqrt(k_d/(I_h + I_r)) and the axle's bounce sqrt(k_a/(m_h + m_r)) within 1 % (I_r, m_r: the annulus's polar
   inertia rho pi (r_o^4 - r_i^4)/2 and mass rho pi (r_o^2 - r_i^2)), read from zero crossings of hub_rate and axle_y.
2. The motor's ripple a sin(2 pi f t) near the torsional resonance, with the drive's damper: the hub rate's steady
   amplitude against the closed form a W |H(W)|, H = (k_d + i W c_d)/(k_d - I W^2 + i W c_d), within 5 %.
2b. -drive_kick J on the hub at rest (no damping): the drive's mode swings with the hub rate's amplitude J/(I_h + I_r)
   within 1 % (the impulse's momentum, the nearly rigid roller's inertia: a least-squares cosine from the kick at the
   best frequency within 2 % of sqrt(k_d/(I_h + I_r)); the rubber's own torsion rings on top, undamped), the hub at rest before the kick's level and
   moving from it; the energy's rise is the kick's work (shaft_work) to 1e-10 of the energy at every step. Its fields
   (-output every 100 steps with -output_start 30): the 16 from t = 30 on, and the inner circle's vertices turned with the hub, their
   rotation phi = -drive_torque/k_d (no damper) to 1e-9 at every stored step.
3. -nip_force F on the sheet at rest (damped): the mean contact force F within 0.5 %, and the hub's indentation that
   of -static at it: the static contact force at that depth within 0.5 % of F.
4. Rolling with friction on the axle (press, start from rest, drive ripple): the energy balance E^k - E^0 = shaft_work +
   sheet_work - friction_work - the dissipations within 1e-10 of max E at every step, every dissipation >= 0, 1 and 2
   ranks agree (1e-8), and a checkpoint of 1 rank after the spring's anchoring restarted on 2 ranks gives the
   uninterrupted rows (1e-8): the hub's levels and anchor are in the checkpoint.
5. With the Maxwell rubber (-rubber maxwell): the branches see the hub's rigid motion as none (the stiff roller's torsion
   unchanged within 0.05 %), the balance closes on rolling on the axle with dmf and trapezoidal, and a restart from 1
   rank on 2 repeats the rows (the branches' hub parts are in the checkpoint).
quick: coarse meshes, a few thousand steps (about 40 s)."""
import math
import shutil

import h5py
import numpy as np

from rollertest import Checker, read_csv, run

RHO, RI, RO = 1.0, 0.25, 0.5
I_R = RHO * math.pi * (RO**4 - RI**4) / 2
M_R = RHO * math.pi * (RO**2 - RI**2)
STIFF = ["-young", 100, "-mesh_h", 0.1, "-ts_scheme", "trapezoidal", "-ts_dt", 0.02, "-quiet", "-stability_check", 0]


def period(t, y):
    """Mean period from the zero crossings of y - mean(y) (linear interpolation)."""
    y = y - y.mean()
    i = np.where(np.sign(y[:-1]) * np.sign(y[1:]) < 0)[0]
    tz = t[i] - y[i] * (t[i + 1] - t[i]) / (y[i + 1] - y[i])
    return 2.0 * float(np.mean(np.diff(tz)))


c = Checker("axle")

# 1. free torsion and bounce of the (nearly) rigid roller on its axle
kd, I_h = 0.1, 0.05
run(["-axle", "-drive_stiffness", kd, "-axle_inertia", I_h, "-omega", 0.01, "-drive_ramp", 1, "-ts_max_time", 60, "-monitor_csv", "torsion.csv"] + STIFF)
d = read_csv("torsion.csv")
m = d["t"] > 2
w = 2 * math.pi / period(d["t"][m], d["hub_rate"][m])
w0 = math.sqrt(kd / (I_h + I_R))
c.check(abs(w / w0 - 1) < 0.01, f"torsion: omega {w:.6f} against sqrt(k_d/(I_h + I_r)) = {w0:.6f} ({100 * (w / w0 - 1):+.3f} %)")

ka, m_h = 0.5, 0.3
run(["-axle", "-drive_stiffness", kd, "-axle_mass", m_h, "-axle_stiffness", ka, "-nip_force", 0.01, "-nip_ramp", 1, "-omega", 0, "-ts_max_time", 60, "-monitor_csv", "bounce.csv"] + STIFF)
d = read_csv("bounce.csv")
m = d["t"] > 2
w = 2 * math.pi / period(d["t"][m], d["axle_y"][m])
w0 = math.sqrt(ka / (m_h + M_R))
c.check(abs(w / w0 - 1) < 0.01, f"bounce: omega {w:.6f} against sqrt(k_a/(m_h + m_r)) = {w0:.6f} ({100 * (w / w0 - 1):+.3f} %)")

# 2. the motor's ripple near the torsional resonance: the hub's steady response
I = I_h + I_R
wt = math.sqrt(kd / I)
cd = 2 * 0.05 * math.sqrt(kd * I)  # 5 % of critical damping
a, W = 1e-3, 0.95 * wt
run(["-axle", "-drive_stiffness", kd, "-drive_damping", cd, "-axle_inertia", I_h, "-omega", 0, "-drive_ripple", a, "-drive_ripple_frequency", W / (2 * math.pi), "-ts_max_time", 260, "-monitor_csv", "ripple.csv"] + STIFF)
d = read_csv("ripple.csv")
m = d["t"] > 260 - 4 * 2 * math.pi / W  # the last four periods: the free response has decayed by exp(-0.05 wt 200)
amp = 0.5 * (d["hub_rate"][m].max() - d["hub_rate"][m].min())
H = (kd + 1j * W * cd) / (kd - I * W**2 + 1j * W * cd)
ref = a * W * abs(H)
c.check(abs(amp / ref - 1) < 0.05, f"ripple at 0.95 of the torsional resonance: hub rate amplitude {amp:.6e} against a W |H| = {ref:.6e} ({100 * (amp / ref - 1):+.2f} %)")

# 2b. a kick on the hub: its momentum J
J, tk = 2e-3, 1.0
run(["-axle", "-drive_stiffness", kd, "-axle_inertia", I_h, "-omega", 0, "-drive_kick", J, "-drive_kick_time", tk, "-ts_max_time", 60, "-monitor_csv", "kick.csv",
     "-output", "kick.h5", "-output_every", 100, "-output_start", 30] + STIFF)
d = read_csv("kick.csv")
before, after = d["t"] < tk - 0.5 * 0.02, d["t"] > tk + 5
ref, fits = J / I, []
for w in wt * np.linspace(0.98, 1.02, 81):
    A = np.c_[np.cos(w * (d["t"][after] - tk)), np.sin(w * (d["t"][after] - tk))]
    co, res = np.linalg.lstsq(A, d["hub_rate"][after], rcond=None)[:2]
    fits.append((float(res[0]), co))
co = min(fits, key=lambda f: f[0])[1]
amp = float(co[0])  # the cosine's: a jump of the hub's rate at the kick
c.check(not np.any(d["hub_rate"][before]) and d["hub_rate"][np.argmax(d["t"] > tk + 0.5 * 0.02)] > 0.5 * ref,
        f"-drive_kick at t = {tk}: the hub at rest before the kick's level, moving after it")
c.check(abs(amp / ref - 1) < 0.01, f"-drive_kick {J}: hub rate amplitude {amp:.6e} against J/(I_h + I_r) = {ref:.6e} ({100 * (amp / ref - 1):+.3f} %)")
bal = np.abs(d["energy"] - d["energy"][0] - d["shaft_work"]).max() / d["energy"].max()
c.check(bal < 1e-10, f"-drive_kick: energy - shaft_work constant to {bal:.2e} of max energy")
with h5py.File("kick.h5", "r") as f:
    times, xv = f["time"][:].ravel(), f["geometry/vertices"][:][:, :2]
    uv = f["vertex_fields/displacement_displacement"][:][:, :, :2]
inner = np.abs(np.hypot(xv[:, 0], xv[:, 1]) - RI) < 1e-9
phi = [np.mean(xv[inner, 0] * u[inner, 1] - xv[inner, 1] * u[inner, 0]) / RI**2 for u in uv]
want = [-d["drive_torque"][np.argmin(np.abs(d["t"] - tt))] / kd for tt in times]
err = max(abs(a - b) for a, b in zip(phi, want)) / max(abs(b) for b in want)
c.check(times.min() >= 30 - 0.01 and len(times) == 16 and inner.sum() > 8 and err < 1e-9,
        f"-output -output_start 30: {len(times)} frames from t = {times.min():.4g}; the inner circle's {inner.sum()} vertices turned with the hub (phi within {err:.1e})")

# 3. the nip force on the sheet at rest, and the indentation of -static at that force
F = 0.005
common = ["-obstacle", "-omega", 0, "-mesh_h", 0.05, "-quiet"]
run(common + ["-axle", "-drive_stiffness", kd, "-nip_force", F, "-nip_ramp", 10, "-axle_stiffness", 0.001, "-damping", 0.5, "-viscosity", 0.5, "-ts_scheme", "trapezoidal", "-ts_dt", 0.05, "-ts_max_time", 60, "-monitor_csv", "nip.csv"])
d = read_csv("nip.csv")
m = d["t"] > 40
P, depth = d["contact_force"][m].mean(), -d["axle_y"][m].mean()
c.check(abs(P / F - 1) < 0.005, f"-nip_force {F}: mean contact force {P:.7f} ({100 * (P / F - 1):+.3f} %), hub down by {depth:.6f}")
run(common + ["-static", "-obstacle_depth", repr(depth), "-obstacle_speed", 1, "-ts_max_time", 1, "-monitor_csv", "static.csv"])
Ps = read_csv("static.csv")["contact_force"][-1]
c.check(abs(Ps / F - 1) < 0.005, f"-static at that depth: contact force {Ps:.7f} ({100 * (Ps / F - 1):+.3f} % of -nip_force)")

# 4. rolling with friction on the axle: the energy balance, the dissipations, 1 and 2 ranks
roll = ["-obstacle", "-axle", "-drive_stiffness", kd, "-drive_damping", 0.01, "-nip_force", F, "-nip_ramp", 5, "-axle_stiffness", 0.001, "-theta_start", 5, "-drive_ramp", 5,
        "-drive_ripple", 1e-3, "-drive_ripple_frequency", 0.1, "-friction", 0.5, "-friction_static", 0.6, "-friction_decay", 0.05, "-sheet_speed", 0.15, "-viscosity", 0.5, "-ts_scheme", "trapezoidal", "-mesh_h", 0.05,
        "-ts_dt", 0.02, "-ts_max_time", 30, "-quiet"]
for np_, name in ((1, "roll1.csv"), (2, "roll2.csv")):
    run(roll + ["-monitor_csv", name], nproc=np_)
d = read_csv("roll1.csv")
E = d["energy"]
diss = np.cumsum(d["damping_dissipation"] + d["viscous_dissipation"] + d["contact_dissipation"])
bal = E - E[0] - (d["shaft_work"] + d["sheet_work"] - d["friction_work"] - diss)
c.check(np.abs(np.diff(bal)).max() < 1e-10 * np.abs(E).max(), f"rolling on the axle: energy balance per step {np.abs(np.diff(bal)).max() / np.abs(E).max():.2e} of max E (< 1e-10)")
c.check(min(d["damping_dissipation"].min(), d["viscous_dissipation"].min(), np.diff(d["friction_work"]).min()) >= -1e-15 * np.abs(E).max(), "every dissipation >= 0 at every step")
c.check(d["slip_nodes"].max() > 0 and np.abs(d["hub_rate"] - math.pi / 10).max() > 1e-3, f"the hub turns on its drive (hub rate {d['hub_rate'][-1]:.4f}, omega {math.pi / 10:.4f}) and the sheet slips")
d2 = read_csv("roll2.csv")
worst = max(float(np.abs(d[q] - d2[q]).max() / np.abs(d[q]).max()) for q in ("contact_force", "friction_force", "hub_rate", "axle_y", "drive_torque", "energy"))
c.check(worst < 1e-8, f"1 and 2 ranks agree: {worst:.2e} (< 1e-8)")
run(roll + ["-monitor_csv", "part.csv", "-ts_max_steps", 900, "-checkpoint", "roll.h5", "-checkpoint_every", 900])
shutil.copyfile("part.csv", "restart.csv")
run(roll + ["-monitor_csv", "restart.csv", "-restart", "roll.h5"], nproc=2)
d3 = read_csv("restart.csv")
worst = max(float(np.abs(d[q] - d3[q]).max() / np.abs(d[q]).max()) for q in ("contact_force", "friction_force", "hub_rate", "axle_y", "drive_torque", "energy"))
c.check(len(d3["t"]) == len(d["t"]) and worst < 1e-8, f"restart at step 900 (t = 18, the spring anchored at 5) from 1 rank on 2: {worst:.2e} (< 1e-8)")

# 5. the Maxwell rubber's branches on the axle
maxwell = ["-rubber", "maxwell", "-rubber_loss_factor", 0.2, "-rubber_band", "0.01,10"]
run(["-axle", "-drive_stiffness", kd, "-axle_inertia", I_h, "-omega", 0.01, "-drive_ramp", 1, "-ts_max_time", 60, "-monitor_csv", "torsion_mx.csv"] + STIFF + maxwell)
d = read_csv("torsion_mx.csv")
m = d["t"] > 2
w_mx = 2 * math.pi / period(d["t"][m], d["hub_rate"][m])
w_el = 2 * math.pi / period(*(lambda e: (e["t"][e["t"] > 2], e["hub_rate"][e["t"] > 2]))(read_csv("torsion.csv")))
c.check(abs(w_mx / w_el - 1) < 5e-4, f"maxwell: the stiff roller's torsion {w_mx:.6f} against the elastic {w_el:.6f}: a rigid motion stretches no branch")
roll_mx = [a for a in roll] + ["-rubber", "maxwell", "-rubber_loss_factor", 0.1, "-rubber_band", "0.01,1"]
i = roll_mx.index("-viscosity")
del roll_mx[i:i + 2]
for scheme in ("trapezoidal", "dmf"):
    i = roll_mx.index("-ts_scheme")
    roll_mx[i + 1] = scheme
    run(roll_mx + ["-monitor_csv", f"mx_{scheme}.csv"])
    d = read_csv(f"mx_{scheme}.csv")
    E = d["energy"]
    diss = np.cumsum(d["damping_dissipation"] + d["viscous_dissipation"] + d["contact_dissipation"])
    bal = E - E[0] - (d["shaft_work"] + d["sheet_work"] - d["friction_work"] - diss)
    c.check(np.abs(np.diff(bal)).max() < 1e-10 * np.abs(E).max() and d["viscous_dissipation"].min() >= -1e-15 * np.abs(E).max(),
            f"maxwell on the axle, {scheme}: energy balance per step {np.abs(np.diff(bal)).max() / np.abs(E).max():.2e} of max E, branch dissipation >= 0")
run(roll_mx + ["-monitor_csv", "mx_part.csv", "-ts_max_steps", 900, "-checkpoint", "mx.h5", "-checkpoint_every", 900])
shutil.copyfile("mx_part.csv", "mx_restart.csv")
run(roll_mx + ["-monitor_csv", "mx_restart.csv", "-restart", "mx.h5"], nproc=2)
d, d3 = read_csv("mx_dmf.csv"), read_csv("mx_restart.csv")
worst = max(float(np.abs(d[q] - d3[q]).max() / np.abs(d[q]).max()) for q in ("contact_force", "friction_force", "hub_rate", "axle_y", "energy", "viscous_dissipation"))
c.check(len(d3["t"]) == len(d["t"]) and worst < 1e-8, f"maxwell on the axle: restart at step 900 from 1 rank on 2: {worst:.2e} (< 1e-8)")
c.close()
