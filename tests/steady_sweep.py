"""The steady rolling state of -modes (docs/squeal.md section 3) over Carter's whole creep curve: 24 creeps from free
rolling (Q = 0) to full slip (|Q| = mu P), each a separate `roller -modes -modes_nev 0` run on the scene of
tests/steady_rolling.py (tests/carter.py: the paper's annulus pressed to depth 0.002, mu = 0.8, omega = 0.025, the
bottom of Gamma_C graded to h_c). Usage: steady_sweep.py [quick|long]; quick: h_c = 0.003 (36 nodes in contact);
long: h_c = 0.0007 (about 150 nodes in contact), where the solver before the fix of docs/squeal.md section 3 failed
at 18 of these 24 creeps (its normal/tangential alternation stalled at round-off above its 1e-13 stopping test) and
its stick/slip active set took up to 99 of its 100 iterations (a spurious slip node travelling up the stick zone).

The creeps xi = (omega R - V)/(omega R) run from -0.0015 (just below the free-rolling creep xi_0, about -0.0012) to
0.0445 (beyond Carter's full-slip creep xi_0 + mu a/R, about 0.041) in steps of 0.002. Read from each run's
-modes_steady_csv (one row per contact candidate: x, forces, gap, slip speed, mu, state):
  (1) every run converges: it exits 0 and writes its CSV (the solver's errors: the stick/slip states or the
      alternations not settling, Lemke's secondary ray);
  (2) Coulomb's law at every node: N >= 0, gap >= 0, N gap = 0, |T| <= mu N (1e-10 of mu P); a stick node's slip
      speed below 1e-9 omega R; a slip node's force -mu N sign(v) (1e-12 of mu P);
  (3) free rolling to full slip: the first creep within 0.03 of Q = 0 with every contact node sticking but at
      most one (xi_0 interpolated between the two creeps around Q = 0, as tests/steady_rolling.py), the last two
      fully sliding (no stick node, |Q| = mu P to 1e-9), |Q|/(mu P) rising with the creep;
  (4) each creep against Carter's curve q(xi - xi_0) (tests/carter.py, a from P by Hertz) within TOL = 0.02, the
      tolerance of tests/steady_rolling.py and docs/squeal.md section 3 (finite wall, mesh, Dundurs' beta; the
      mesh alone scatters the steady state's q by +-0.011), Q against the creep;
  (5) the stick zone at the leading edge wherever nodes stick and slip, as tests/steady_rolling.py: the stick nodes
      one block within h_c of the first node in contact (the leading edge, -x; the nodes ahead of the block, where
      N -> 0, may slip), every node behind them slipping, its width within 2 h_c of Carter's
      2c = 2a sqrt(1 - |q|).
Measured: Carter within 0.0119 (quick) and 0.0075 (long), the stick zone's width within 0.71 and 0.98 h_c.
quick: about 50 s of CPU; long: about 150 s of CPU."""
import math
import sys
from concurrent.futures import ThreadPoolExecutor

import numpy as np

from carter import DEPTH, E_STAR, MU, R, carter_q, sector_mesh
from rollertest import Checker, read_csv, run

MODE = sys.argv[1] if len(sys.argv) > 1 else "quick"
OMEGA, TOL = 0.025, 0.02
HC = 0.003 if MODE == "quick" else 0.0007
CREEPS = [-0.0015 + 0.002 * k for k in range(24)]
c = Checker(f"steady_sweep {MODE}")
mesh = f"steady_sweep_{HC}.msh"
sector_mesh(mesh, -0.12, 0.12, HC)

def steady(xi):
    """One creep's steady state: its CSV read, or None if the run failed or wrote none."""
    tag = f"steady_sweep_{xi:+.4f}.csv"
    rc, _, _ = run(["-dm_plex_filename", mesh, "-degree", 2, "-obstacle", "-obstacle_depth", DEPTH, "-omega", OMEGA, "-sheet_speed", repr(OMEGA * R * (1 - xi)),
                    "-friction", MU, "-viscosity", 0, "-modes", "-modes_nev", 0, "-modes_steady_csv", tag, "-quiet"], check=False)
    try:
        d = read_csv(tag)
    except OSError:
        return None
    return d if rc == 0 else None


with ThreadPoolExecutor(2) as pool:  # two runs at a time (registered with PROCESSORS 2)
    states = list(pool.map(steady, CREEPS))
runs, failed = [], []
for xi, d in zip(CREEPS, states):
    if d is None:
        failed.append(xi)
        continue
    on = d["state"] > 0
    P, Q = d["normal_force"][on].sum(), d["tangential_force"][on].sum()
    runs.append(dict(xi=xi, d=d, on=on, P=P, Q=Q, q=Q / (MU * P), a=math.sqrt(4 * P * R / (math.pi * E_STAR))))
c.check(not failed, f"(1) all {len(CREEPS)} creeps from {CREEPS[0]:+.4f} to {CREEPS[-1]:+.4f} converge and write their CSV (failed: {failed or 'none'})")
if failed:
    c.close()

worst_law = worst_stick = worst_slip = 0.0
for r in runs:
    d = r["d"]
    N, T, v, gap, mu, st = d["normal_force"], d["tangential_force"], d["slip_velocity"], d["gap"], d["mu"], d["state"]
    worst_law = max(worst_law, np.abs(N * gap).max() / (r["P"] * DEPTH), -N.min() / r["P"], -gap.min() / DEPTH, ((np.abs(T) - mu * N) / (mu * r["P"])).max())
    if (st == 1).any():
        worst_stick = max(worst_stick, np.abs(v[st == 1]).max() / (OMEGA * R))
    if (st == 2).any():
        worst_slip = max(worst_slip, np.abs(T[st == 2] + mu[st == 2] * N[st == 2] * np.sign(v[st == 2])).max() / (MU * r["P"]))
c.check(worst_law < 1e-10 and worst_stick < 1e-9 and worst_slip < 1e-12,
        f"(2) Coulomb's law at every node of every creep: N >= 0, gap >= 0, N gap = 0, |T| <= mu N to {worst_law:.1e}; stick slip speeds {worst_stick:.1e} omega R; slip forces -mu N sign(v) to {worst_slip:.1e}")

xs = np.array([r["xi"] for r in runs])
qs = np.array([r["q"] for r in runs])
i0, i1 = np.argsort(np.abs(qs))[:2]
xi0 = float(xs[i0] - qs[i0] * (xs[i1] - xs[i0]) / (qs[i1] - qs[i0]))
first, last = runs[0], runs[-2:]
stick0 = (first["d"]["state"] == 1).sum()
c.check(abs(first["q"]) < 0.03 and stick0 >= first["on"].sum() - 1 and -0.003 < xi0 < 0,
        f"(3) free rolling: xi = {first['xi']:+.4f} has |Q|/(mu P) = {abs(first['q']):.4f} < 0.03, {stick0} of {first['on'].sum()} contact nodes stick; xi_0 = {xi0:+.6f}")
slide = max(abs(abs(r["q"]) - 1) for r in last)
c.check(all((r["d"]["state"] == 1).sum() == 0 for r in last) and slide < 1e-9,
        f"(3) full slip: xi = {last[0]['xi']:+.4f}, {last[1]['xi']:+.4f} without a stick node, |Q| = mu P to {slide:.1e}")
aq = np.abs(qs[xs > xi0])
c.check(bool(np.all(np.diff(aq) >= -1e-9)), "(3) |Q|/(mu P) rises with the creep beyond xi_0: " + " ".join(f"{q:.3f}" for q in aq))

print(" xi       xi-xi_0   P           |Q|/(mu P)  Carter   diff     stick/contact  width   2c")
worst, worst_width, bad_zone = 0.0, 0.0, []
for r in runs:
    d, xi = r["d"], r["xi"]
    qc = carter_q(xi - xi0, r["a"])
    diff = abs(r["q"]) - qc
    worst = max(worst, abs(diff))
    sign_ok = abs(r["q"]) < 0.01 or np.sign(r["Q"]) == -np.sign(xi - xi0)
    if not sign_ok:
        bad_zone.append(f"{xi:+.4f} (sign)")
    x, st = d["x"][r["on"]], d["state"][r["on"]]
    ix = np.argsort(x)
    x, st = x[ix], st[ix]
    ks, kp = np.where(st == 1)[0], np.where(st == 2)[0]
    width = c2 = float("nan")
    if len(ks) and len(kp):  # stick and slip: the zone at the leading edge, Carter's width
        block = ks.max() - ks.min() + 1 == len(ks) and x[ks.min()] - x[0] <= HC and np.all(st[ks.max() + 1:] == 2)
        c2 = 2 * r["a"] * math.sqrt(max(0.0, 1 - abs(r["q"])))
        width = x[ks.max()] - x[0] + 0.5 * (x[min(ks.max() + 1, len(x) - 1)] - x[ks.max()])  # to the middle of the stick-slip step
        worst_width = max(worst_width, abs(width - c2) / HC)
        if not block or abs(width - c2) >= 2 * HC:
            bad_zone.append(f"{xi:+.4f} (states {''.join(str(int(k)) for k in st)}, width {width:.5f} vs 2c {c2:.5f})")
    print(f"{xi:+.4f}  {xi - xi0:+.5f}  {r['P']:.5e}  {abs(r['q']):.4f}      {qc:.4f}   {diff:+.4f}  {len(ks):3d}/{len(x):3d}        {width:.4f}  {c2:.4f}")
c.check(worst < TOL, f"(4) |Q|/(mu P) against Carter's curve at all {len(runs)} creeps within {worst:.4f} (TOL {TOL})")
c.check(not bad_zone, f"(4, 5) Q against the creep; the stick zone one block at the leading edge with Carter's width within {worst_width:.2f} h_c (<= 2) wherever nodes stick and slip (failed: {bad_zone or 'none'})")
c.close()
