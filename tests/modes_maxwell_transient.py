"""A seeded transient decays at the CEA's rate with the generalized Maxwell rubber (issue 35; docs/squeal.md section 1.2).

The free roller at rest (-omega 0, P2, -mesh_h 0.05), the rubber fitted to the loss factor 0.1 over 0.1-10 cycles per
unit time. -modes (the augmented eigenproblem of src/modes/branches.c) gives the torsional eigenvalue
lambda = sigma + i omega and its shape; the time step (src/integrate/scheme_maxwell.c, the default trapezoidal rule,
-ts_dt 0.05: 160 steps a period) is started on that shape (-initial_condition mode, the branches unstretched, as the
step starts them) and its rotation angle alpha(t) over 0 <= t <= 60 (7 periods, the amplitude down to 10 %) is fitted
by exp(s t)(a cos w t + b sin w t) + sum_j c_j exp(r_j t): s and w free, the r_j the creep roots of the torsional
closed form lambda^2 + w0^2 G*(lambda)/mu = 0 (the unstretched branches start them), w0 backed out of the CEA's own
lambda (w0^2 = -lambda^2 mu/G*(lambda)), the branches read from the shapes' file. The transient's s within 5 % of the
CEA's sigma and w within 0.5 % of its omega; the modal loss factor 2|s|/w of the transient within 5 % of the
rubber's G''/G' at w (the torsional mode is deviatoric)."""
import numpy as np

from rollertest import Checker, read_csv, run, maxwell_branches, maxwell_modulus, maxwell_oscillator_roots, fit_maxwell_decay

c = Checker("modes_maxwell_transient")
BASE = ["-omega", 0, "-mesh_h", 0.05, "-degree", 2, "-quiet"]
RUBBER = ["-rubber", "maxwell", "-rubber_loss_factor", 0.1, "-rubber_band", "0.1,10"]
DT, T = 0.05, 60.0

run(["-modes", *BASE, *RUBBER, "-modes_nev", 4, "-modes_csv", "modes.csv", "-modes_output", "modes.h5"])
m = read_csv("modes.csv")
j = int(np.where((m["order"] == 0) & (m["im"] > 0))[0][0])
lam = m["re"][j] + 1j * m["im"][j]
tau, g = maxwell_branches("modes.h5")
nb = len(tau)


def modulus(s):
    return maxwell_modulus(s, tau, g)


w0 = np.sqrt((-lam * lam / modulus(lam)).real)
_, creep = maxwell_oscillator_roots(w0, tau, g)
c.check(m["order"][j] == 0 and len(creep) == nb,
        f"the CEA's torsional mode {j}: lambda = {lam.real:.6f} + {lam.imag:.6f} i ({nb} branches; w0 = {w0:.6f}, creep roots {', '.join(f'{r:.4f}' for r in creep)})")

run([*BASE, *RUBBER, "-initial_condition", "mode", "-initial_mode_file", "modes.h5", "-initial_mode", j, "-ic_amplitude", 1e-3,
     "-ts_dt", DT, "-ts_max_time", T, "-monitor_csv", "decay.csv"])
d = read_csv("decay.csv")
t, a = d["t"], d["alpha"]


s, w, r = fit_maxwell_decay(t, a, creep)
es, ew = s / lam.real - 1, w / lam.imag - 1
c.check(abs(es) < 0.05 and abs(ew) < 0.005 and s < 0,
        f"the transient decays at s = {s:.6f} against the CEA's {lam.real:.6f} ({100 * es:+.2f} %, < 5 %), w = {w:.6f} against {lam.imag:.6f} ({100 * ew:+.3f} %, < 0.5 %); "
        f"the fit's largest residual {r:.1e} of max |alpha|")
eta = modulus(1j * w)
eta = eta.imag / eta.real
c.check(abs(2 * abs(s) / w / eta - 1) < 0.05, f"the transient's modal loss factor 2|s|/w = {2 * abs(s) / w:.5f} against the rubber's G''/G' = {eta:.5f} at w (< 5 %)")
c.close()
