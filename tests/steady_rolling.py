"""The steady rolling state with stick and slip zones of -modes (docs/squeal.md section 3.2) against Carter.

Carter's scene of tests/friction_carter.py (tests/carter.py: the paper's annulus pressed to depth 0.002, mu = 0.8,
omega = 0.025, the mesh graded to h_c = 0.003 at the bottom of Gamma_C where the patch stands in the lab frame),
solved as ONE static problem in the Eulerian description (-modes -modes_nev 0: the steady state only) at the
creeps xi = (omega R - V)/(omega R) of the transient test and two braking ones. Read from -modes_steady_csv
(one row per contact candidate: x, normal and tangential force, gap, slip speed, mu, state):
  (1) Coulomb's law at every node: N >= 0, gap >= 0, N gap = 0; |T| <= mu N; a stick node's slip speed
      |v| < 1e-9 omega R; a slip node's force T = -mu N sign(v) (1e-12);
  (2) |Q|/(mu P) against Carter's q(xi - xi_0) (tests/carter.py) within TOL = 0.02 (measured -0.012 to +0.000;
      the transient test measured +0.001 to +0.010 with the same budget: finite wall, mesh, Dundurs' beta), the
      free-rolling creep xi_0 interpolated between the two runs around Q = 0;
  (3) the stick zone: one block from the leading edge (the material enters the patch at -x: the stick nodes are
      contiguous, the first within h_c of the first node in contact, every slip node behind them), its width
      2c = 2a sqrt(1 - |q|) within 2 h_c, at driving and braking creeps alike (the braking force Q > 0). The first
      node in contact (N -> 0 there) may slip, backwards: the upwind difference there reaches the free surface
      ahead of the patch (measured: it does at xi = 0.025 and -0.015);
  (4) the same state on 2 ranks (P, Q to 1e-9 relative, the same stick count);
  (5) the linearization about it (section 3: the stick nodes' multipliers, a saddle point factored with pivoting):
      the lowest eigenvalues (-modes_nev 12: 7 kept) on 1 and 2 ranks agree to 1e-8 of |lambda| (SuperLU against MUMPS, the
      multipliers on the last rank), every residual error below 1e-8.
About 25 s."""
import math

import numpy as np

from carter import DEPTH, E_STAR, MU, R, carter_q, sector_mesh
from rollertest import Checker, read_csv, run

OMEGA, HC, TOL = 0.025, 0.003, 0.02
CREEPS = [-0.0015, 0.0043, 0.0128, 0.025, -0.006, -0.015]
c = Checker("steady_rolling")
mesh = "steady_rolling.msh"
sector_mesh(mesh, -0.12, 0.12, HC)


def steady(xi, nproc=1):
    tag = f"steady_rolling_{xi}_{nproc}.csv"
    run(["-dm_plex_filename", mesh, "-degree", 2, "-obstacle", "-obstacle_depth", DEPTH, "-omega", OMEGA, "-sheet_speed", repr(OMEGA * R * (1 - xi)),
         "-friction", MU, "-viscosity", 0, "-modes", "-modes_nev", 0, "-modes_steady_csv", tag, "-quiet"], nproc=nproc)
    d = read_csv(tag)
    on = d["state"] > 0
    P, Q = d["normal_force"][on].sum(), d["tangential_force"][on].sum()
    return dict(xi=xi, d=d, on=on, P=P, Q=Q, q=Q / (MU * P), a=math.sqrt(4 * P * R / (math.pi * E_STAR)))


runs = [steady(xi) for xi in CREEPS]
for r in runs:
    d, on, xi = r["d"], r["on"], r["xi"]
    N, T, v, gap, mu, st = d["normal_force"], d["tangential_force"], d["slip_velocity"], d["gap"], d["mu"], d["state"]
    stick, slip = st == 1, st == 2
    law = max(np.abs(N * gap).max() / (r["P"] * DEPTH), -N.min() / r["P"], -gap.min() / DEPTH, ((np.abs(T) - mu * N) / (mu * r["P"])).max())
    c.check(law < 1e-10, f"xi = {xi:+.4f}: N >= 0, gap >= 0, N gap = 0, |T| <= mu N (worst {law:.1e})")
    vs = np.abs(v[stick]).max() / (OMEGA * R) if stick.any() else 0.0
    c.check(stick.any() and vs < 1e-9, f"xi = {xi:+.4f}: {stick.sum()} stick nodes, slip speed there {vs:.1e} omega R")
    if slip.any():
        e = np.abs(T[slip] + mu[slip] * N[slip] * np.sign(v[slip])).max() / (MU * r["P"])
        c.check(e < 1e-12, f"xi = {xi:+.4f}: {slip.sum()} slip nodes, T = -mu N sign(v) to {e:.1e}")
    print(f"xi = {xi:+.4f}: P = {r['P']:.6e}, Q = {r['Q']:+.6e}, q = {r['q']:+.5f}, a = {r['a']:.5f}, contact nodes {on.sum()}, stick {stick.sum()}")

xs = np.array([r["xi"] for r in runs])
qs = np.array([r["q"] for r in runs])
order = np.argsort(np.abs(qs))
i0, i1 = order[0], order[1]
xi0 = float(xs[i0] - qs[i0] * (xs[i1] - xs[i0]) / (qs[i1] - qs[i0]))
print(f"free-rolling creep xi_0 = {xi0:+.6f} (the transient of tests/friction_carter.py, with mass damping: -0.00141)")
c.check(-0.003 < xi0 < 0, f"free-rolling creep xi_0 = {xi0:+.6f}: a compressed rim rolls slower than its radius (between -0.003 and 0)")
for r in runs:
    if abs(r["q"]) < 0.05:
        continue
    d, xi = r["d"], r["xi"]
    qc = carter_q(xi - xi0, r["a"])
    c.check(abs(abs(r["q"]) - qc) < TOL and np.sign(r["Q"]) == -np.sign(xi - xi0), f"xi = {xi:+.4f}: |Q|/(mu P) = {abs(r['q']):.4f} vs Carter {qc:.4f} (diff {abs(r['q']) - qc:+.4f}, TOL {TOL}), Q against the creep")
    x, st = d["x"][r["on"]], d["state"][r["on"]]
    ix = np.argsort(x)
    x, st = x[ix], st[ix]
    ks, kp = np.where(st == 1)[0], np.where(st == 2)[0]
    trail = kp[kp > ks.max()]
    block = ks.max() - ks.min() + 1 == len(ks) and x[ks.min()] - x[0] <= HC and len(trail) == len(x) - 1 - ks.max()
    c2 = 2 * r["a"] * math.sqrt(max(0.0, 1 - abs(r["q"])))
    width = x[ks.max()] - x[0] + 0.5 * (x[min(ks.max() + 1, len(x) - 1)] - x[ks.max()])  # to the middle of the stick-slip step
    c.check(block and abs(width - c2) < 2 * HC, f"xi = {xi:+.4f}: stick zone one block from the leading edge x = {x[0]:+.5f} (states {''.join(str(int(k)) for k in st)}), width {width:.5f} vs Carter 2c = {c2:.5f} (within 2 h_c = {2 * HC})")

r2 = steady(0.0128, nproc=2)
r1 = runs[CREEPS.index(0.0128)]
dp, dq = abs(r2["P"] - r1["P"]) / r1["P"], abs(r2["Q"] - r1["Q"]) / abs(r1["Q"])
c.check(dp < 1e-9 and dq < 1e-9 and (r2["d"]["state"] == 1).sum() == (r1["d"]["state"] == 1).sum(), f"2 ranks: P to {dp:.1e}, Q to {dq:.1e}, the same stick nodes")

def cea(nproc):
    tag = f"steady_rolling_cea_{nproc}.csv"
    run(["-dm_plex_filename", mesh, "-degree", 2, "-obstacle", "-obstacle_depth", DEPTH, "-omega", OMEGA, "-sheet_speed", repr(OMEGA * R * (1 - 0.0128)),
         "-friction", MU, "-viscosity", 0, "-modes", "-modes_nev", 12, "-modes_csv", tag, "-quiet"], nproc=nproc)
    return read_csv(tag)


e1, e2 = cea(1), cea(2)
n = min(len(e1["re"]), len(e2["re"]))
lam1, lam2 = e1["re"][:n] + 1j * e1["im"][:n], e2["re"][:n] + 1j * e2["im"][:n]
dl = float(np.max(np.abs(lam1 - lam2) / np.abs(lam1).clip(1e-3)))
c.check(n >= 6 and dl < 1e-8 and max(e1["error"].max(), e2["error"].max()) < 1e-8,
        f"the CEA about the rolling state (stick multipliers): {n} eigenvalues on 1 and 2 ranks agree to {dl:.1e} (growth rates {', '.join(f'{x:+.2e}' for x in e1['re'][:6])})")
c.close()
