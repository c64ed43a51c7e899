"""-modes with -axle (docs/squeal.md section 3.1, docs/model.md section 10; issue 36): the hub's lab-frame (Y, phi) in
the quadratic eigenproblem, no obstacle.

1. Stiff-rubber limit (E = 100, the scene of tests/axle.py part 1), the motor at rest: the drive's torsion
   sqrt(k_d/(I_h + I_r)) and the axle's bounce sqrt(k_a/(m_h + m_r)) within 1 % (I_r, m_r: the annulus's polar inertia
   and mass), read from the modes CSV: the torsion the mode with the largest hub_phi, the bounce the one with the
   largest axle_y, each of them the hub's (the other column below 1e-6).
2. Turning at omega = 0.3 (the lab frame: the convective D and P, and the Kelvin-Voigt A_L, border the hub's rows):
   the bounce unchanged within 1 %, and the torsion sqrt((k_d - rho omega^2 I_r)/(I_h + I_r)) within 1 %: the
   linearized rotation phi J x inflates the rim, and the centrifugal term's -rho omega^2 P on it is a torsional
   softening rho omega^2 I_r (the linearized model's: docs/model.md section 10, Limits), and within 0.5 % of the time
   step's on the same roller (hub_rate's zero crossings, tests/axle.py's measurement); 1 and 2 ranks agree to 1e-8.
3. Rolling on the sheet on the axle (stick and slip zones, velocity weakening, Kelvin-Voigt, the hub turning with the
   motor at omega = 0.1, creep 2 %): the steady state's contact force -nip_force within 1e-8, a stick zone and a slip
   zone, and 1 and 2 ranks give the same eigenvalues and hub amplitudes (1e-8: the hub's rows on the last rank, the
   stick multipliers after them).
4. Bad input: -modes -axle -obstacle with -nip_force 0, -modes_frame rotating with omega != 0, -damping with
   omega != 0: non-zero exit and a message naming the option.
quick: coarse meshes (610 and 6460 unknowns), seven eigenproblems of seconds."""
import math

import numpy as np

from rollertest import Checker, read_csv, run

RHO, RI, RO = 1.0, 0.25, 0.5
I_R = RHO * math.pi * (RO**4 - RI**4) / 2
M_R = RHO * math.pi * (RO**2 - RI**2)
KD, I_H, KA, M_H = 0.1, 0.05, 0.5, 0.3
SCENE = ["-modes", "-axle", "-young", 100, "-mesh_h", 0.1, "-drive_stiffness", KD, "-axle_inertia", I_H, "-axle_mass", M_H, "-axle_stiffness", KA, "-modes_nev", 6, "-quiet"]

c = Checker("axle_modes")


def hub_modes(name):
    d = read_csv(name)
    it, ib = int(d["hub_phi"].argmax()), int(d["axle_y"].argmax())
    return d, it, ib


def frequencies(omega, name, nproc=1, extra=()):
    run(SCENE + ["-omega", omega, "-modes_csv", name] + list(extra), nproc=nproc)
    d, it, ib = hub_modes(name)
    c.check(it != ib and d["axle_y"][it] < 1e-6 and d["hub_phi"][ib] < 1e-6 and d["hub_phi"][it] > 0.5 and d["axle_y"][ib] > 0.5,
            f"omega {omega} ({nproc} rank{'s' if nproc > 1 else ''}): the torsion (hub_phi {d['hub_phi'][it]:.4f}, axle_y {d['axle_y'][it]:.1e}) and the bounce (axle_y {d['axle_y'][ib]:.4f}, hub_phi {d['hub_phi'][ib]:.1e}) are the hub's two modes")
    return float(d["im"][it]), float(d["im"][ib]), float(d["re"][it])


# 1. the motor at rest
wt, wb, _ = frequencies(0, "rest.csv")
ref_t, ref_b = math.sqrt(KD / (I_H + I_R)), math.sqrt(KA / (M_H + M_R))
c.check(abs(wt / ref_t - 1) < 0.01, f"torsion {wt:.6f} against sqrt(k_d/(I_h + I_r)) = {ref_t:.6f} ({100 * (wt / ref_t - 1):+.3f} %)")
c.check(abs(wb / ref_b - 1) < 0.01, f"bounce {wb:.6f} against sqrt(k_a/(m_h + m_r)) = {ref_b:.6f} ({100 * (wb / ref_b - 1):+.3f} %)")

# 2. turning at omega = 0.3, with the Kelvin-Voigt damping (the lab frame's A_L)
W = 0.3
wt, wb, rt = frequencies(W, "turning.csv", extra=["-viscosity", 1e-3])
ref_w = math.sqrt((KD - RHO * W**2 * I_R) / (I_H + I_R))
run(["-axle", "-drive_stiffness", KD, "-axle_inertia", I_H, "-omega", W, "-drive_ramp", 1, "-ts_max_time", 60, "-monitor_csv", "step.csv", "-young", 100, "-mesh_h", 0.1, "-ts_scheme", "trapezoidal", "-ts_dt", 0.02, "-quiet",
     "-stability_check", 0])
st = read_csv("step.csv")
m = st["t"] > 2
y = st["hub_rate"][m] - st["hub_rate"][m].mean()
tt = st["t"][m]
iz = np.nonzero(np.sign(y[:-1]) * np.sign(y[1:]) < 0)[0]
tz = tt[iz] - y[iz] * (tt[iz + 1] - tt[iz]) / (y[iz + 1] - y[iz])
w_step = math.pi / float(np.mean(np.diff(tz)))
c.check(abs(wb / ref_b - 1) < 0.01, f"omega {W}: bounce {wb:.6f} against {ref_b:.6f} ({100 * (wb / ref_b - 1):+.3f} %)")
c.check(abs(wt / ref_w - 1) < 0.01, f"omega {W}: torsion {wt:.6f} against sqrt((k_d - rho omega^2 I_r)/(I_h + I_r)) = {ref_w:.6f} ({100 * (wt / ref_w - 1):+.3f} %; growth rate {rt:+.2e})")
c.check(abs(wt / w_step - 1) < 0.005, f"omega {W}: torsion {wt:.6f} against the time step's {w_step:.6f} ({100 * (wt / w_step - 1):+.3f} %; {len(tz)} zero crossings of hub_rate)")
wt2, wb2, _ = frequencies(W, "turning2.csv", nproc=2, extra=["-viscosity", 1e-3])
c.check(abs(wt2 / wt - 1) < 1e-8 and abs(wb2 / wb - 1) < 1e-8, f"2 ranks: torsion {wt2:.12f}, bounce {wb2:.12f} (1 rank {wt:.12f}, {wb:.12f})")

# 3. rolling on the sheet, 1 and 2 ranks
NIP = 0.005
ROLL = ["-modes", "-axle", "-obstacle", "-nip_force", NIP, "-drive_stiffness", 0.1, "-friction", 0.5, "-friction_static", 0.7, "-friction_decay", 0.05, "-viscosity", 0.01, "-omega", 0.1, "-sheet_speed", 0.049,
        "-mesh_h", 0.1, "-mesh_h_contact", 0.02, "-modes_nev", 6, "-quiet"]
run(ROLL + ["-modes_csv", "roll1.csv", "-modes_steady_csv", "steady1.csv"])
run(ROLL + ["-modes_csv", "roll2.csv"], nproc=2)
st = read_csv("steady1.csv")
c.check(abs(st["normal_force"].sum() / NIP - 1) < 1e-8 and (st["state"] == 1).sum() > 0 and (st["state"] == 2).sum() > 0,
        f"rolling: the contact force {st['normal_force'].sum():.10g} (-nip_force {NIP}), {int((st['state'] == 1).sum())} nodes stuck, {int((st['state'] == 2).sum())} slipping")
a1, a2 = read_csv("roll1.csv"), read_csv("roll2.csv")
dev = max(float(abs(a1[k] - a2[k]).max() / max(abs(a1[k]).max(), 1e-300)) for k in ("re", "im", "axle_y", "hub_phi")) if len(a1["re"]) == len(a2["re"]) else math.inf
c.check(dev < 1e-8, f"rolling: 1 and 2 ranks agree to {dev:.1e} over {len(a1['re'])} eigenvalues (re, im, axle_y, hub_phi)")

# 4. bad input
for extra, option in ((["-obstacle", "-nip_force", 0, "-omega", 0], "-nip_force"), (["-omega", W, "-modes_frame", "rotating"], "-modes_frame"), (["-omega", W, "-damping", 0.01], "-damping")):
    rc, out, err = run(SCENE + extra, check=False)
    said = [line for line in (out + err).splitlines() if option in line]
    c.check(rc != 0 and said, f"{' '.join(map(str, extra))}: exit {rc}, the message names {option}: {said[0].strip()[:200] if said else ''}")
c.close()
