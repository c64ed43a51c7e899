"""scripts/rollerref/annulus_modes.py alone (no roller run): the 1D per-order reference for the modes of the
rotating annulus (docs/squeal.md section 2) that the 2D -modes output is to be compared with.

1. n = 0, Omega = 0: the lowest two torsional and the lowest breathing frequencies against the roots of their
   Bessel cross-products (relative 1e-8); the lowest torsional period is the paper's ~8.69.
2. Convergence in the degree: the lowest 2 eigenvalues of every signed m = -4..4 at Omega = pi/10 agree
   between degree 16 and 32 to 1e-9 relative, and degree 8 is visibly worse (the check sees the refinement).
3. The frame shift at tau = 0: every low rotating-frame eigenvalue lambda of order m is a lab eigenvalue
   lambda - i m Omega to 1e-9 relative; with tau > 0 the same holds for --lab-viscosity objective.
4. Bryan: at Omega = 1e-4 the rotating-frame splitting w(m = n) - w(m = -n) = w_b - w_f equals 2 gamma_n Omega
   to 1e-3 relative for n = 1..4 (gamma_n from the Omega = 0 shape), gamma_n > 0; a thin free-free ring gives
   gamma_n -> 2n/(n^2+1) (1e-3).
5. The CLI: CSV columns re,im,frequency,growth_rate,order,wave,m; sorted by frequency; wave labels from the
   sign of m Omega; count rows per signed m; the lab CSV is the rotating one shifted by -m Omega."""
import csv
import io
import os
import subprocess
import sys

import numpy as np

from rollertest import SOURCE, Checker

sys.path.insert(0, os.path.join(SOURCE, "scripts"))
from rollerref import annulus_modes as amr  # noqa: E402

c = Checker("modes_reference_unit")
p = amr.params()
W = p["omega"]

# 1. Bessel roots, n = 0, Omega = 0
p0 = amr.params(omega=0.0)
num = np.sort(amr.eigenvalues(p0, 0).imag)
tors, breath = amr.torsion_exact(p0, 2), amr.breathing_exact(p0, 1)
for name, exact in (("torsional", tors), ("breathing", breath)):
    for k, w in enumerate(exact):
        e = np.min(np.abs(num - w)) / w
        c.check(e < 1e-8, f"n = 0 {name} mode {k + 1}: w = {w:.12f} (Bessel), discrete within {e:.1e} (< 1e-8)")
c.check(abs(2 * np.pi / tors[0] - 8.69) < 0.01, f"lowest torsional period {2 * np.pi / tors[0]:.6f} ~ 8.69")
c.check(abs(num[0] - tors[0]) / tors[0] < 1e-8, "the lowest n = 0 mode is the torsional one")

# 2. convergence in the degree
def low(deg):
    return {m: amr.eigenvalues(amr.params(n=deg), m)[:2] for m in range(-4, 5)}
l8, l16, l32 = low(8), low(16), low(32)
d16 = max(np.max(np.abs(l16[m] - l32[m]) / np.abs(l32[m])) for m in l32)
d8 = max(np.max(np.abs(l8[m] - l32[m]) / np.abs(l32[m])) for m in l32)
c.check(d16 < 1e-9 and d8 > 100 * d16, f"degree 16 vs 32: {d16:.1e} (< 1e-9); degree 8 vs 32: {d8:.1e} (coarser)")

# 3. frame shift
worst = 0.0
for m in range(-4, 5):
    ll = amr.solve_quadratic(*amr.quadratic(p, m, "lab")[:3])
    worst = max(worst, max(np.min(np.abs(ll - (z - 1j * m * W))) / abs(z) for z in amr.eigenvalues(p, m)[:4]))
c.check(worst < 1e-9, f"tau = 0: lab = rotating - i m Omega within {worst:.1e} (< 1e-9), m = -4..4, lowest 4")
pv = amr.params(viscosity=0.0115)
worst = 0.0
for m in range(-4, 5):
    ll = amr.solve_quadratic(*amr.quadratic(pv, m, "lab", "objective")[:3])
    worst = max(worst, max(np.min(np.abs(ll - (z - 1j * m * W))) / abs(z) for z in amr.eigenvalues(pv, m)[:2]))
c.check(worst < 1e-9, f"tau = 0.0115, objective lab rate: shift within {worst:.1e} (< 1e-9)")

# 4. Bryan splitting
ps = amr.params(omega=1e-4)
for n in range(1, 5):
    g = amr.bryan_gamma(n)
    split = amr.eigenvalues(ps, n)[0].imag - amr.eigenvalues(ps, -n)[0].imag
    rel = abs(split - 2 * g * 1e-4) / (2 * g * 1e-4)
    c.check(g > 0 and rel < 1e-3, f"n = {n}: w_b - w_f = {split:.9e} vs 2 gamma_n Omega = {2 * g * 1e-4:.9e} "
            f"(gamma_n = {g:.9f}), relative {rel:.1e} (< 1e-3)")
pt = amr.params(r_inner=0.99 * p["r_outer"], n=16)
for n in (2, 3, 4):
    g = amr.bryan_gamma(n, pt, inner="free")
    c.check(abs(g - 2 * n / (n * n + 1)) < 1e-3, f"thin free-free ring, n = {n}: gamma_n = {g:.6f} vs 2n/(n^2+1) = "
            f"{2 * n / (n * n + 1):.6f}")

# 5. the CLI
def cli(*args):
    out = subprocess.run([sys.executable, "-m", "rollerref.annulus_modes", *args],
                         capture_output=True, text=True, check=True).stdout
    return list(csv.DictReader(io.StringIO(out))), out.splitlines()[0]
rot, head = cli("--frame", "rotating", "--orders", "0-4", "--count", "2")
lab, _ = cli("--frame", "lab", "--orders", "0-4", "--count", "2")
c.check(head == "re,im,frequency,growth_rate,order,wave,m", f"CSV header: {head}")
fr = [float(r["frequency"]) for r in rot]
c.check(len(rot) == 18 and fr == sorted(fr) and all(f > 0 for f in fr), f"{len(rot)} rows (2 per signed m, m = -4..4), sorted, frequency > 0")
c.check(all(r["wave"] == ("standing" if int(r["m"]) == 0 else "backward" if int(r["m"]) > 0 else "forward")
            and int(r["order"]) == abs(int(r["m"])) and r["im"] == r["frequency"] and r["re"] == r["growth_rate"]
            for r in rot), "Omega > 0: m > 0 backward, m < 0 forward, m = 0 standing; order = |m|")
rs = sorted((int(r["m"]), float(r["frequency"]) - int(r["m"]) * W) for r in rot)
ls = sorted((int(r["m"]), float(r["frequency"])) for r in lab)
dev = max(abs(a[1] - b[1]) / abs(b[1]) for a, b in zip(rs, ls)) if [a[0] for a in rs] == [b[0] for b in ls] else 1.0
c.check(dev < 1e-9, f"lab CSV = rotating CSV with frequency - m Omega (within {dev:.1e})")
st, _ = cli("--omega", "0", "--orders", "2", "--count", "1")
c.check(len(st) == 2 and all(r["wave"] == "standing" for r in st)
        and abs(float(st[0]["frequency"]) - float(st[1]["frequency"])) < 1e-12 * float(st[0]["frequency"]),
        "Omega = 0: m = +-2 degenerate and standing")
c.close()
