"""Damping in the lab (Eulerian) frame of roller -modes (docs/squeal.md section 1.1): the damping acts on the objective
rate u_t + omega L u, L u = d_phi u - J u, so the lab pencil gets C += tau K0 + eta M0, K += omega (tau A_L + eta B_L).

The free annulus at omega = pi/10, -mesh_h 0.02 (P2, curved), damped by Kelvin-Voigt (-viscosity 0.02) and, separately,
by mass damping (-damping 0.05): for every circumferential order n = 0..4, forward and backward, the lab eigenvalue
is the co-rotating one shifted by the Doppler term, lambda_lab = lambda_rot + i s n omega (s = +1 forward, -1
backward, matched by the CSV's order and wave columns): imaginary part to 1e-3, real part (the decay rate) to 1e-2
relative. Without the omega tau A_L term the lab decay rates are off by the Doppler factor (30-70 %). Also: no lab
eigenvalue grows (the rotational part of the rate dissipates nothing), and the broken A_L with its edge terms is skew
to 1e-6 (the defect the shapes' file holds, /parameters skew_defect_A_L). On 2 ranks (the edges between the ranks' cells assembled with the other
rank's side) the damped lab eigenvalues equal the serial ones to 1e-9 (-mesh_h 0.04)."""
import csv
import math
import os
import sys

import h5py
import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from rollertest import Checker, run  # noqa: E402

W = math.pi / 10
MESH = ["-mesh_h", "0.02"]
c = Checker("modes_damped")


def roller_modes(frame, damping, nev, name):
    """The eigenvalue rows and the /parameters attributes of the shapes' file"""
    h5 = name.replace(".csv", ".h5")
    run(["-modes", "-modes_frame", frame, "-omega", repr(W), "-modes_nev", nev, "-modes_csv", name, "-modes_output", h5, "-quiet"] + damping + MESH)
    with open(name) as f, h5py.File(h5, "r") as g:
        return [dict(r) for r in csv.DictReader(f)], dict(g["parameters"].attrs)


for label, damping in (("Kelvin-Voigt tau 0.02", ["-viscosity", "0.02"]), ("mass damping eta 0.05", ["-damping", "0.05"])):
    tag = damping[0][1:]
    rot, _ = roller_modes("rotating", damping, 24, f"rot_{tag}.csv")
    lab, par = roller_modes("lab", damping, 130, f"lab_{tag}.csv")  # the lab: high orders swept down near 0 (n omega)
    if tag == "viscosity":
        defect = float(np.ravel(par.get("skew_defect_A_L", [math.nan]))[0])
        c.check(defect < 1e-6, f"{label}: the broken A_L with its edge terms is skew: ||A + A^T||/||A|| = {defect:.2e} < 1e-6")
    for n in range(5):
        for wave in ("standing",) if n == 0 else ("forward", "backward"):
            rr = [r for r in rot if int(r["order"]) == n and r["wave"] == wave]
            if not rr:
                c.check(False, f"{label}: n {n} {wave}: no co-rotating mode")
                continue
            r = min(rr, key=lambda r: float(r["im"]))
            shift = 0 if n == 0 else (n * W if wave == "forward" else -n * W)
            want_im, want_re = float(r["im"]) + shift, float(r["re"])
            ll = [x for x in lab if int(x["order"]) == n and x["wave"] == wave]
            if not ll:
                c.check(False, f"{label}: n {n} {wave}: no lab mode near {want_im:.6f}")
                continue
            l = min(ll, key=lambda x: abs(float(x["im"]) - want_im))
            e_im = abs(float(l["im"]) - want_im) / want_im
            e_re = abs(float(l["re"]) - want_re) / abs(want_re)
            c.check(e_im < 1e-3 and e_re < 1e-2 and want_re < 0,
                    f"{label}: n {n} {wave}: lab {float(l['re']):.6e} + {float(l['im']):.6f} i vs co-rotating {want_re:.6e} + {float(r['im']):.6f} i {'+' if shift >= 0 else '-'} {abs(shift):.6f} i: im {e_im:.1e} < 1e-3, re {e_re:.1e} < 1e-2")
    grow = max(float(x["re"]) for x in lab)
    c.check(grow < 0, f"{label}: no lab mode grows (largest real part {grow:.3e} of {len(lab)})")

one, two = [], []
for nproc, rows in ((1, one), (2, two)):
    run(["-modes", "-modes_frame", "lab", "-omega", repr(W), "-modes_nev", 40, "-viscosity", "0.01", "-mesh_h", "0.04", "-modes_csv", f"lab_np{nproc}.csv", "-quiet"], nproc=nproc)
    with open(f"lab_np{nproc}.csv") as f:
        rows += [complex(float(r["re"]), float(r["im"])) for r in csv.DictReader(f)]
k = min(len(one), len(two))
d = max(abs(a - b) / abs(a) for a, b in zip(one[:k], two[:k])) if k else math.inf
c.check(k >= 15 and d < 1e-9, f"Kelvin-Voigt in the lab frame on 2 ranks: {k} eigenvalues equal the serial ones to {d:.1e} < 1e-9")
c.close()
