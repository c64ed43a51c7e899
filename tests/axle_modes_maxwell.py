"""-modes with -axle and -rubber maxwell (docs/squeal.md section 3.1, issue 36): the hub's rows bordered first, then the
Maxwell branches over the bordered body (each branch's field with its hub part, as the time step carries it).

The scene: the hub (mass 1) pressed by its spring (-nip_force 0.05) onto the sheet, the rubber a generalized Maxwell
solid of loss factor 0.2 over 0.05-5 cycles per unit time; its bounce on the rubber's contact (3.5 rad/s) decays by the
rubber alone. The transient starts from rest, the nip ramped in over 0.5 (a third of the bounce's period, which starts
it), trapezoidal at dt 0.01 (180 steps a period); the fit: axle_y from t = 2 to 12, a damped sine plus the branches'
creep exponentials e^{-t/tau_i} and a constant (rollertest.fit_maxwell_decay).
1. At rest (omega 0, frictionless): the CEA's bounce (the mode with the largest axle_y) against the transient: growth
   rate within 5 %, frequency within 1 % (measured -0.6 %, -0.07 %); its modal loss factor 2|sigma|/omega within 5 % of
   the rubber's loss factor of its strain (the shape relative to the hub: the modes_maxwell test's measure); 1 and 2
   ranks agree to 1e-8 (the hub's rows and their branch parts on the last rank).
2. Rolling at omega 0.05 (friction 0.5, creep 1 %; the branches frozen in the lab, -modes_branch_transport false: the
   transported creep spectrum crowds the bounce): the same two comparisons with the transient (measured +1.8 %, -0.8 %;
   the frozen branches' error grows with omega: +9 % at 0.1, +15 % at 0.2 on this scene, docs/squeal.md 3.1).
3. -modes_branch_transport true with the axle turning is refused by name.
quick: two eigenproblems of 6000 unknowns (seconds), one on 2 ranks, one rolling (half a minute), two transients of
1200 steps."""
import math

import numpy as np

from rollertest import Checker, fit_maxwell_decay, maxwell_branches, read_csv, run

SCENE = ["-obstacle", "-axle", "-young", 10, "-rubber", "maxwell", "-rubber_loss_factor", 0.2, "-rubber_band", "0.05,5", "-nip_force", 0.05, "-axle_mass", 1, "-axle_stiffness", 0.01,
         "-axle_inertia", 0.3, "-drive_stiffness", 0.04, "-drive_damping", 0.01, "-mesh_h", 0.1, "-mesh_h_contact", 0.02, "-quiet"]
CEA = ["-modes", "-modes_nev", 4]
STEP = ["-nip_ramp", 0.5, "-ts_max_time", 12, "-ts_scheme", "trapezoidal", "-ts_dt", 0.01]
ROLL = ["-omega", 0.05, "-sheet_speed", 0.05 * 0.5 * 0.99, "-friction", 0.5]

c = Checker("axle_modes_maxwell")


def bounce(name):
    d = read_csv(name)
    i = int(d["axle_y"].argmax())
    return {k: float(d[k][i]) for k in ("re", "im", "axle_y", "loss_factor", "rubber_loss_factor")}, d


def transient(name, tau):
    d = read_csv(name)
    m = d["t"] > 2.0
    a = d["axle_y"][m] - d["axle_y"][m][-100:].mean()
    s, w, res = fit_maxwell_decay(d["t"][m] - d["t"][m][0], a, [0.0] + [-1 / t for t in tau])
    return s, w, res, d


def compare(label, b, s, w, res):
    c.check(abs(b["re"] / s - 1) < 0.05 and b["re"] < 0, f"{label}: the bounce's growth rate {b['re']:.6f} against the transient's {s:.6f} ({100 * (b['re'] / s - 1):+.2f} %; fit residual {res:.1e})")
    c.check(abs(b["im"] / w - 1) < 0.01, f"{label}: the bounce's frequency {b['im']:.6f} against the transient's {w:.6f} ({100 * (b['im'] / w - 1):+.3f} %)")


# 1. at rest
run(SCENE + CEA + ["-omega", 0, "-modes_csv", "rest.csv", "-modes_output", "rest.h5"])
run(SCENE + CEA + ["-omega", 0, "-modes_csv", "rest2.csv"], nproc=2)
run(SCENE + STEP + ["-omega", 0, "-monitor_csv", "rest_step.csv"])
tau, g = maxwell_branches("rest.h5")
b, d1 = bounce("rest.csv")
s, w, res, st = transient("rest_step.csv", tau)
c.check(b["axle_y"] > 0.9, f"at rest: the bounce is the hub's (axle_y {b['axle_y']:.3f}), {len(tau)} branches")
compare("at rest", b, s, w, res)
c.check(abs(b["loss_factor"] / b["rubber_loss_factor"] - 1) < 0.05,
        f"at rest: the bounce's modal loss factor {b['loss_factor']:.4f} against the rubber's of its strain {b['rubber_loss_factor']:.4f} ({100 * (b['loss_factor'] / b['rubber_loss_factor'] - 1):+.2f} %)")
d2 = read_csv("rest2.csv")
dev = max(float(np.abs(d1[k] - d2[k]).max() / max(np.abs(d1[k]).max(), 1e-300)) for k in ("re", "im", "axle_y", "hub_phi")) if len(d1["re"]) == len(d2["re"]) else math.inf
c.check(dev < 1e-8, f"at rest: 1 and 2 ranks agree to {dev:.1e} over {len(d1['re'])} eigenvalues (re, im, axle_y, hub_phi)")

# 2. rolling, the branches frozen in the lab
run(SCENE + CEA + ROLL + ["-modes_branch_transport", "false", "-modes_csv", "roll.csv"])
run(SCENE + STEP + ROLL + ["-monitor_csv", "roll_step.csv"])
b, _ = bounce("roll.csv")
s, w, res, st = transient("roll_step.csv", tau)
c.check(st["stick_nodes"][-1] > 0 and st["slip_nodes"][-1] > 0, f"rolling: {int(st['stick_nodes'][-1])} nodes stuck, {int(st['slip_nodes'][-1])} slipping at the end")
compare("rolling at omega 0.05", b, s, w, res)

# 3. the transported branches refused with the hub
rc, out, err = run(SCENE + CEA + ROLL, check=False)
said = [line for line in (out + err).splitlines() if "-modes_branch_transport" in line]
c.check(rc != 0 and said, f"-modes_branch_transport true on the turning axle: exit {rc}, {said[0].strip()[:160] if said else 'no message naming it'}")
c.close()
