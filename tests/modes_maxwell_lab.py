"""The lab (Eulerian) frame of -modes with the generalized Maxwell rubber (issue 35; docs/squeal.md section 1.2): the
branch fields z_i are transported with the material, tau_i (z_i' + omega L z_i) = xi - z_i in the lab, in the
Galerkin form weighted by M (B_L = (L u, v), section 1.1).

The free roller at omega = pi/10 (P2, -mesh_h 0.05), the rubber fitted to 0.1 over 0.1-10: every oscillating
co-rotating mode of order n = 0..5 whose Doppler-shifted frequency im + s n omega (s = +1 forward, -1 backward) lies
below the highest lab frequency computed is found in the lab with the same order and wave, at that frequency to 1e-3
and with the same decay rate to 1e-2 (without the transport term the branches would relax at the lab frequency:
the decay rates would be off by the Doppler factor, as Kelvin-Voigt's without A_L, tests/modes_damped.py). The lab's
other eigenvalues are the branches' transported creep, re near -1/tau_i, im near multiples of omega: none grows.
At least 6 matches are asserted (with -modes_nev 130: n = 0, 1 forward and backward, 2, 4, 5 backward)."""
import math

import numpy as np

from rollertest import Checker, read_csv, run

W = math.pi / 10
c = Checker("modes_maxwell_lab")
BASE = ["-omega", repr(W), "-mesh_h", 0.05, "-rubber", "maxwell", "-rubber_loss_factor", 0.1, "-rubber_band", "0.1,10", "-quiet"]
run(["-modes", *BASE, "-modes_nev", 24, "-modes_csv", "rot.csv"])
run(["-modes", *BASE, "-modes_nev", 130, "-modes_frame", "lab", "-modes_csv", "lab.csv"])
rot, lab = read_csv("rot.csv"), read_csv("lab.csv")
top = lab["im"].max()
matched = 0
for n in range(6):
    for wave in ("standing",) if n == 0 else ("forward", "backward"):
        rr = np.where((rot["order"] == n) & (rot["wave"] == wave) & (rot["im"] > 0))[0]
        if not len(rr):
            continue
        r = rr[np.argmin(rot["im"][rr])]
        want = rot["im"][r] + (0 if n == 0 else (n * W if wave == "forward" else -n * W))
        if want > top + 1e-3:
            continue
        ll = np.where((lab["order"] == n) & (lab["wave"] == wave))[0]
        if not len(ll):
            c.check(False, f"n {n} {wave}: no lab mode near {want:.6f}")
            continue
        k = ll[np.argmin(abs(lab["im"][ll] - want))]
        e_im, e_re = abs(lab["im"][k] - want) / want, abs(lab["re"][k] / rot["re"][r] - 1)
        c.check(e_im < 1e-3 and e_re < 1e-2,
                f"n {n} {wave}: lab {lab['re'][k]:.6e} + {lab['im'][k]:.6f} i, co-rotating {rot['re'][r]:.6e} + {rot['im'][r]:.6f} i shifted to {want:.6f}: im {e_im:.1e} < 1e-3, re {e_re:.1e} < 1e-2")
        matched += 1
# -modes_branch_transport false: the branches frozen in the lab (the approximation the printer's CEA takes, docs/squeal.md
# 1.2): the torsional mode (order 0: no Doppler shift) as transported to 1e-3; the others move with the loss factor's
# change over n omega (on this scene, n omega up to half the frequency: a few %)
run(["-modes", *BASE, "-modes_nev", 24, "-modes_frame", "lab", "-modes_branch_transport", "false", "-modes_csv", "frozen.csv"])
fz = read_csv("frozen.csv")
k0, f0 = np.where(lab["order"] == 0)[0], np.where(fz["order"] == 0)[0]
if len(k0) and len(f0):
    a, b = lab["re"][k0[0]] + 1j * lab["im"][k0[0]], fz["re"][f0[0]] + 1j * fz["im"][f0[0]]
    c.check(abs(a - b) / abs(a) < 1e-3 and fz["re"].max() < 0,
            f"frozen branches: the torsional eigenvalue {b.real:.6e} + {b.imag:.6f} i against the transported {a.real:.6e} + {a.imag:.6f} i ({abs(a - b) / abs(a):.1e} < 1e-3); nothing grows")
else:
    c.check(False, "frozen branches: a torsional mode in both lab runs")
c.check(matched >= 6, f"{matched} co-rotating modes matched in the lab (highest lab frequency {top:.4f})")
c.check(lab["re"].max() < 0 and rot["re"].max() < 0, f"no eigenvalue grows: largest re {max(lab['re'].max(), rot['re'].max()):.3e}")
c.close()
