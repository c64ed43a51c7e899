"""-modes with the generalized Maxwell rubber (-rubber maxwell, issue 35; docs/squeal.md section 1.2): the augmented
state (xi, z_1, ..., z_n) of src/modes/branches.c.

The free roller at rest (-omega 0, P2, -mesh_h 0.05), the rubber fitted to the loss factor 0.1 over 0.1-10 cycles per
unit time (the branches read back from the shapes' file, /parameters maxwell_tau_i, maxwell_weight_i):
1. every oscillating mode's modal loss factor 2|sigma|/omega (the CSV's loss_factor, recomputed here from re, im) is
   within 5 % of the model's loss factor at the mode's frequency: the rubber's eta(omega) = G''/G' times the share of
   the shape's strain energy that is deviatoric (the CSV's rubber_loss_factor: Im(x^H K*(i omega) x)/Re(...), the
   bulk elastic); and that, for the torsional mode (order 0, div xi = 0: all of its energy deviatoric), is eta(omega)
   of the branches themselves to 1e-3.
   The two differ by about eta/pi: a causal flat loss has a storage modulus rising like omega^(2 eta/pi), and the
   eigenvalue feels G* at lambda = -sigma + i omega, not at i omega (G*(lambda) ~ G*(i omega) - sigma dG*/ds adds
   sigma dG'/domega = eta^2 G'/pi to G''): 3.2 % at 0.1.
2. the torsional eigenvalue is the closed form's: lambda^2 + w0^2 G*(lambda)/mu = 0, w0 the elastic roller's
   torsional frequency on the same mesh (-modes without -rubber maxwell), to 1e-4: the augmented problem is exact
   for the Prony series, not a first-order estimate, and the discrete torsional shape is isochoric to about 3e-4 of
   its energy (its loss factor is that much below G''/G'), which moves lambda by 2.6e-5 at -mesh_h 0.05.
3. the co-rotating frame and the lab frame agree at rest to round-off (1e-9): the lab's transport B_L of the
   branches is multiplied by omega.
4. no eigenvalue grows.
The seeded transient against the CEA's decay is tests/modes_maxwell_transient.py; the rotating roller's lab frame
against the co-rotating one tests/modes_maxwell_lab.py."""
import numpy as np

from rollertest import Checker, read_csv, run, maxwell_branches, maxwell_modulus, maxwell_oscillator_roots

c = Checker("modes_maxwell")
BASE = ["-omega", 0, "-mesh_h", 0.05, "-degree", 2, "-quiet"]
RUBBER = ["-rubber", "maxwell", "-rubber_loss_factor", 0.1, "-rubber_band", "0.1,10"]

run(["-modes", *BASE, "-modes_nev", 4, "-modes_csv", "elastic.csv"])
run(["-modes", *BASE, *RUBBER, "-modes_nev", 16, "-modes_csv", "rot.csv", "-modes_output", "rot.h5"])
run(["-modes", *BASE, *RUBBER, "-modes_nev", 16, "-modes_frame", "lab", "-modes_csv", "lab.csv"])
el, rot, lab = read_csv("elastic.csv"), read_csv("rot.csv"), read_csv("lab.csv")
tau, g = maxwell_branches("rot.h5")
nb = len(tau)


def modulus(s):
    return maxwell_modulus(s, tau, g)


# 1. modal loss factors against the model's
osc = rot["im"] > 0
c.check(osc.sum() >= 7, f"{osc.sum()} oscillating modes (orders {sorted(set(rot['order'][osc].astype(int)))}), {nb} branches")
for j in np.where(osc)[0]:
    modal = 2 * abs(rot["re"][j]) / rot["im"][j]
    model = rot["rubber_loss_factor"][j]
    eta = modulus(1j * rot["im"][j])
    eta = eta.imag / eta.real
    e = modal / model - 1
    c.check(abs(e) < 0.05 and abs(rot["loss_factor"][j] / modal - 1) < 1e-12,
            f"mode {j} (order {rot['order'][j]:.0f}, omega {rot['im'][j]:.5f}): 2|sigma|/omega = {modal:.5f} against the model's {model:.5f} "
            f"({100 * e:+.2f} %; the rubber's G''/G' there {eta:.5f})")
tors = np.where(osc & (rot["order"] == 0))[0]
c.check(len(tors) > 0, "the torsional mode (order 0) is among them")
j = tors[0]
eta = modulus(1j * rot["im"][j])
eta = eta.imag / eta.real
c.check(abs(rot["rubber_loss_factor"][j] / eta - 1) < 1e-3,
        f"the torsional shape's model loss factor {rot['rubber_loss_factor'][j]:.6f} is the rubber's G''/G' = {eta:.6f} at its frequency (all its energy deviatoric)")

# 2. the torsional eigenvalue against the closed form
w0 = el["im"][0]
c.check(el["order"][0] == 0, f"the elastic roller's lowest mode is the torsional one, w0 = {w0:.6f}")
lam, _ = maxwell_oscillator_roots(w0, tau, g)
got = rot["re"][j] + 1j * rot["im"][j]
c.check(abs(got - lam) / abs(lam) < 1e-4, f"torsional lambda = {got.real:.8f} + {got.imag:.8f} i, closed form {lam.real:.8f} + {lam.imag:.8f} i: {abs(got - lam) / abs(lam):.1e} < 1e-4")

# 3. the frames at rest
n = min(len(rot["re"]), len(lab["re"]))
d = max(abs(rot["re"][:n] - lab["re"][:n]).max(), abs(rot["im"][:n] - lab["im"][:n]).max()) / abs(rot["im"]).max()
c.check(n >= 7 and d < 1e-9, f"lab frame = co-rotating frame at rest: {n} eigenvalues, largest difference {d:.1e} < 1e-9 of the highest frequency")

# 4. nothing grows
c.check(rot["re"].max() < 0 and lab["re"].max() < 0, f"no eigenvalue grows: largest re {max(rot['re'].max(), lab['re'].max()):.3e}")
c.close()
