"""The one-degree-of-freedom references of scripts/rollerref (docs/validation.md section 10) against themselves: the
closed forms against the event-driven integrator and the integrator against Moreau's time-stepping; no roller run.

- growth rate and frequency of a small disturbance of steady sliding, measured from the integrated response
  (successive peaks), against the closed form -c_eff/(2I), both signs (Stender's oscillator at v_d = 0.8, unstable;
  the proposed roller set, stable), within 1 %; the sign changes across the closed-form onset sheet speed;
- the stick-slip cycle: its period by the single slip (stick_slip_cycle) against the long run's Poincare period,
  unchanged with the tolerance, and Moreau's first-order time-stepping converging to it as the step shrinks;
- the proposed roller set (Stender's numbers in roller variables) is bistable: steady sliding linearly stable, the
  start from rest in stick-slip with stick in every period, a small kick decays; the smallest kick is bracketed;
  Stender's onset is v_d = ln(10)/2 and the cycle ends between v_d = 1.8 and 1.85;
- the sheet picked from rest: the closed forms (constant mu and velocity weakening) against the integration, the
  sheet that is not picked above the settle slip speed, the coupled roller in steady sliding picks it the same way;
- the forced response to the ripple: 1-DOF (constant and linearized velocity-weakening friction) and hub + tyre
  2-DOF closed forms against integrations;
- the command line writes the JSON and the CSV that a C-side test reads.
"""
import json
import math
import os
import subprocess
import sys

import numpy as np
from scipy.integrate import solve_ivp

from rollertest import SOURCE, Checker

sys.path.insert(0, os.path.join(SOURCE, "scripts"))
from rollerref import basin, forced, sheet, stickslip as ss, timestep  # noqa: E402
from rollerref.drive import Motor  # noqa: E402
from rollerref.friction import Friction  # noqa: E402

c = Checker("rollerref_unit")


def measured_growth(p, kick, periods=8):
    """Growth rate and angular frequency of th' - omega from the peaks of an integrated small disturbance."""
    T = 2 * math.pi / p.w_n
    th, w = ss.initial_sliding(p, kick)
    res = ss.simulate(p, periods * T, th0=th, w0=w, dt_out=T / 400)
    x = res.u[:, 0] - p.omega
    t = res.t
    i = np.nonzero((x[1:-1] > x[:-2]) & (x[1:-1] >= x[2:]))[0] + 1
    tp, xp = [], []
    for k in i:
        cf = np.polyfit(t[k - 1:k + 2] - t[k], x[k - 1:k + 2], 2)
        tv = -cf[1] / (2 * cf[0])
        tp.append(t[k] + tv)
        xp.append(np.polyval(cf, tv))
    tp, xp = np.array(tp), np.array(xp)
    sigma = np.polyfit(tp, np.log(xp), 1)[0]
    return sigma, 2 * math.pi / np.mean(np.diff(tp)), len(res.events)


# 1. growth rates and the onset
for name, p in [("Stender v_d = 0.8 (unstable)", ss.stender(v_d=0.8)), ("roller set (stable)", ss.roller_set())]:
    lin = ss.linear_stability(p)
    v0 = abs(p.r * p.omega - p.V)
    sig, wd, nev = measured_growth(p, 1e-4 * p.friction.v_c / p.r)
    err = abs(sig / lin["growth_rate"] - 1)
    c.check(err < 0.01 and nev == 0, f"{name}: growth rate {sig:.6g} measured, {lin['growth_rate']:.6g} closed form "
            f"(error {err:.1e} < 1 %), no stick")
    werr = abs(wd / lin["eigenvalues"][0].imag - 1)
    c.check(werr < 1e-3, f"{name}: frequency {wd:.6g} measured, {lin['eigenvalues'][0].imag:.6g} closed form ({werr:.1e})")
p = ss.roller_set()
lin = ss.linear_stability(p)
Vs = lin["onset_sheet_speeds"]
c.check(abs(ss.linear_stability(ss.with_(p, V=Vs[0]))["c_eff"]) < 1e-12 * p.c_d and
        abs(ss.linear_stability(ss.with_(p, V=Vs[1]))["c_eff"]) < 1e-12 * p.c_d,
        f"roller set: c_eff = 0 at the onset sheet speeds {Vs[0]:.6g}, {Vs[1]:.6g}")
signs = []
for f in (0.98, 1.02):  # the sheet speed at which the slip speed is f v*
    q = ss.with_(p, V=p.r * p.omega - f * lin["onset_slip_speed"])
    signs.append(measured_growth(q, 1e-4 * p.friction.v_c / p.r, periods=6)[0])
c.check(signs[0] > 0 > signs[1], f"roller set: measured growth {signs[0]:.3g} at 0.98 v*, {signs[1]:.3g} at 1.02 v*: "
        "the onset is where the closed form puts it")

# 2. the stick-slip cycle
p = ss.stender(v_d=1.5)
ref = ss.stick_slip_cycle(p)
loose = ss.stick_slip_cycle(p, rtol=1e-7)
c.check(ref["exists"] and abs(loose["period"] / ref["period"] - 1) < 1e-6,
        f"Stender v_d = 1.5: cycle period {ref['period']:.9g} (rtol 1e-11), {loose['period']:.9g} (1e-7)")
T = 2 * math.pi
res = ss.simulate(p, 40 * T, th0=2.0, w0=2.0, dt_out=T / 400)  # bSTAB's limit-cycle template
lc = ss.limit_cycle(p, res, t_min=25 * T)
c.check(lc["periodic"] and lc["stick_every_period"] and abs(lc["period"] / ref["period"] - 1) < 1e-5 and
        abs(lc["rate_amplitude"] / ref["rate_amplitude"] - 1) < 1e-3 and abs(lc["stick_fraction"] / ref["stick_fraction"] - 1) < 1e-3,
        f"from (2, 2) the long run's cycle: period {lc['period']:.9g}, amplitude {lc['rate_amplitude']:.6g} "
        f"({ref['rate_amplitude']:.6g}), stick fraction {lc['stick_fraction']:.5f} ({ref['stick_fraction']:.5f}), stick every period")
errs, hs = [], []
for n in (400, 800, 1600):
    h = ref["period"] / n
    m = timestep.moreau(p, 24 * T, h, th0=2.0, w0=2.0)
    mc = ss.limit_cycle(p, m, t_min=14 * T)
    hs.append(h)
    errs.append(abs(mc["period"] / ref["period"] - 1) if mc.get("periodic") else math.inf)
order = np.polyfit(np.log(hs), np.log(errs), 1)[0] if all(map(math.isfinite, errs)) else 0.0
c.check(errs[0] > errs[1] > errs[2] and order > 0.6 and errs[2] < 1e-3,
        f"Moreau's time-stepping, period/{400}..{1600}: period errors {', '.join(f'{e:.2e}' for e in errs)}, order {order:.2f}")

# 3. bistability
p = ss.roller_set()
b = basin.bistability(p)
cyc = b["cycle"]
c.check(b["bistable"], f"roller set: linearly stable (growth {b['linear']['growth_rate']:.4g}), the start from rest "
        f"settles into stick-slip (period {cyc.get('period', 0):.6g}, stick fraction {cyc.get('stick_fraction', 0):.4f}, "
        f"stick every period {cyc.get('stick_every_period')}), a small kick {b['small_kick']}")
sc = ss.stick_slip_cycle(p)
c.check(abs(cyc["period"] / sc["period"] - 1) < 1e-5, f"roller set: start-from-rest period {cyc['period']:.8g} = "
        f"single-slip period {sc['period']:.8g}")
A = basin.kick_threshold(p, rel_tol=1e-2)
v0 = abs(p.r * p.omega - p.V) / p.r
lo = basin.classify(p, *ss.initial_sliding(p, -0.97 * A["threshold"]))[0]
hi = basin.classify(p, *ss.initial_sliding(p, -1.03 * A["threshold"]))[0]
c.check(0 < A["threshold"] < v0 and lo == "sliding" and hi == "cycle",
        f"roller set: smallest kick {A['threshold']:.5g} (|v0|/r = {v0:.5g}): 0.97 of it {lo}, 1.03 of it {hi}")
w = basin.bistable_window(ss.stender())
c.check(abs(w["onset_slip_speed"] - math.log(10) / 2) < 1e-12 and 1.8 < w["cycle_limit_slip_speed"] < 1.85,
        f"Stender: steady sliding stable above v_d = {w['onset_slip_speed']:.6f} (ln 10 / 2), the cycle ends at "
        f"v_d = {w['cycle_limit_slip_speed']:.4f}")

# 4. the sheet
S = sheet.Sheet(m_s=0.05, F_r=0.004)
for fr in (Friction(0.5, 0.5, 0.0), Friction(0.3, 1.0, 0.03)):
    cf = sheet.closed_form(S, fr, N=0.01, r=0.5, omega=0.06)
    res = sheet.pick(S, fr, 0.01, 0.5, Motor(omega=0.06), t_end=2 * cf["t_stick"])
    err = np.abs(res.u[:, 0] - cf["V_of_t"](res.t)).max() / cf["roller_speed"]
    ts = [e[0] for e in res.events if e[2] == "stick" and e[1] == 0]
    c.check(err < 1e-8 and len(ts) == 1 and abs(ts[0] / cf["t_stick"] - 1) < 1e-8 and res.mode[-1, 0] == 0,
            f"sheet {fr}: V(t) closed form vs integrated {err:.1e}, sticks to the roller at {ts[0]:.9g} ({cf['t_stick']:.9g})")
fr = Friction(0.3, 1.0, 0.01)
cf = sheet.closed_form(S, fr, N=0.01, r=0.5, omega=0.06)
res = sheet.pick(S, fr, 0.01, 0.5, Motor(omega=0.06), t_end=5.0)
c.check(not cf["moves"] and 0.5 * 0.06 > cf["settle_slip_speed"] and np.abs(res.u[:, 0]).max() == 0.0,
        f"sheet not picked: r omega = 0.03 above the (unstable) settle slip {cf['settle_slip_speed']:.5g}, it stays at rest")
fr = Friction(0.5, 0.5, 0.0)
q = ss.Torsion(I=0.192, k_d=0.192, c_d=0.0192, r=0.5, N=0.01, friction=fr, motor=Motor(omega=0.06))
cf = sheet.closed_form(S, fr, N=0.01, r=0.5, omega=0.06)
th0, w0 = ss.initial_sliding(ss.with_(q, V=0.0))
res = sheet.coupled(S, q, 300.0, th0=th0, w0=w0, dt_out=0.01)
before = res.t <= cf["t_stick"]
err = np.abs(res.u[before, 1] - cf["V_of_t"](res.t[before])).max() / cf["roller_speed"]
ts = [e[0] for e in res.events if e[2] == "stick" and e[1] == 0]
st = sheet.coupled_steady(S, q)["stuck"]
wind = q.motor.state(res.t[-1])[0] - res.q[-1, 0]
c.check(err < 1e-8 and abs(ts[0] / cf["t_stick"] - 1) < 1e-8 and abs(res.u[-1, 1] / st["V"] - 1) < 1e-3 and
        abs(wind / st["wind_up"] - 1) < 1e-3 and res.mode[-1, 0] == 0,
        f"coupled roller in steady sliding, constant mu: the sheet's V(t) as the kinematic closed form ({err:.1e}), "
        f"sticks at {ts[0]:.9g}, then rides with the roller: V {res.u[-1, 1]:.6g} ({st['V']:.6g}), wind-up {wind:.6g} "
        f"(r F_r / k_d = {st['wind_up']:.6g})")

# 5. the forced response to the ripple
q = ss.Torsion(I=0.192, k_d=0.192, c_d=0.0192, r=0.5, N=0.01, friction=Friction(0.5, 0.5, 0.0),
               motor=Motor(omega=0.5, ripple=1e-3, ripple_frequency=0.95 / (2 * math.pi)))


def fit(t, x, f):
    """Amplitude and phase (of sin) of x's line at frequency f, least squares with a mean and a trend."""
    W = 2 * math.pi * f
    A = np.stack([np.sin(W * t), np.cos(W * t), np.ones_like(t), t], 1)
    s_, c_ = np.linalg.lstsq(A, x, rcond=None)[0][:2]
    return math.hypot(s_, c_), math.atan2(c_, s_)


cases = [("constant mu", q, 0.0)]
pw = ss.with_(ss.roller_set(), motor_ripple=1e-4, motor_ripple_frequency=0.95 / (2 * math.pi))
cases.append(("velocity weakening, linearized", pw, ss.linear_stability(pw)["c_eff"] - pw.c_d))
for name, qq, c_f in cases:
    f = qq.motor.ripple_frequency
    th0, w0 = ss.initial_sliding(ss.with_(qq, motor_ripple=0.0))
    t_end = 400.0
    res = ss.simulate(qq, t_end, th0=th0, w0=w0, dt_out=0.05)
    keep = res.t > t_end - 100
    t = res.t[keep]
    amp, ph = fit(t, res.q[keep, 0] - qq.omega * t, f)
    ref = forced.one_dof(qq.I, qq.k_d, qq.c_d, f, a=qq.motor.ripple, c_f=c_f)
    tol = 1e-3 if c_f == 0 else 1e-2
    ea, ep = abs(amp / ref["amplitude"] - 1), abs(ph - ref["phase"])
    c.check(ea < tol and ep < tol and not res.stick_intervals(0),
            f"ripple, {name}: hub amplitude {amp:.6g} vs {ref['amplitude']:.6g} ({ea:.1e}), phase {ph:.5f} vs "
            f"{ref['phase']:.5f} ({ep:.1e}), within {tol:g}")
I_h, I_t, k_d, c_d, k_r, c_r, c_f, a = 0.125, 0.067, 0.192, 0.0192, 0.5, 0.002, 0.003, 1e-3
for f in (0.12, 0.5):
    W = 2 * math.pi * f

    def rhs(t, y):
        th, tt, wh, wt = y
        m, mv = a * math.sin(W * t), a * W * math.cos(W * t)
        Th = k_d * (m - th) + c_d * (mv - wh) - k_r * (th - tt) - c_r * (wh - wt)
        Tt = k_r * (th - tt) + c_r * (wh - wt) - c_f * wt
        return [wh, wt, Th / I_h, Tt / I_t]

    sol = solve_ivp(rhs, (0, 1500), [0, 0, 0, 0], method="DOP853", rtol=1e-10, atol=1e-14, dense_output=True)
    t = np.linspace(1300, 1500, 4001)
    y = sol.sol(t)
    ref = forced.two_dof(I_h, I_t, k_d, c_d, k_r, f, a=a, c_r=c_r, c_f=c_f)
    eh = abs(fit(t, y[0], f)[0] / ref["hub"]["amplitude"] - 1)
    et = abs(fit(t, y[1], f)[0] / ref["tyre"]["amplitude"] - 1)
    ph = abs(fit(t, y[0], f)[1] - ref["hub"]["phase"])
    c.check(eh < 1e-3 and et < 1e-3 and ph < 1e-3, f"hub + tyre 2-DOF at f = {f}: hub amplitude error {eh:.1e}, "
            f"tyre {et:.1e}, hub phase {ph:.1e}")
nf = forced.natural_frequencies(I_h, I_t, k_d, 1e6)
c.check(abs(nf["free_low"] / nf["one_dof"] - 1) < 1e-5, f"2-DOF with a stiff rubber: lowest frequency {nf['free_low']:.7g} "
        f"-> 1-DOF {nf['one_dof']:.7g}")

# 5b. the motor's cubic ramp is Roller's -drive_ramp (src/model/forcing.c): speed omega x^2 (3 - 2 x), its angle and
# acceleration consistent with it (central differences), at rest before t0 and omega (t - t0 - T/2) after the ramp
m = Motor(omega=0.3, t0=1.0, t_ramp=2.0, ramp="cubic")
h, worst = 1e-5, 0.0
for tt in np.linspace(1.05, 2.95, 20):
    a, v, acc = m.state(tt)
    x = (tt - 1.0) / 2.0
    worst = max(worst, abs(v - 0.3 * x * x * (3 - 2 * x)), abs((m.state(tt + h)[0] - m.state(tt - h)[0]) / (2 * h) - v),
                abs((m.state(tt + h)[1] - m.state(tt - h)[1]) / (2 * h) - acc))
c.check(worst < 1e-8 and m.state(0.5) == (0.0, 0.0, 0.0) and abs(m.state(4.0)[0] - 0.3 * (4.0 - 1.0 - 1.0)) < 1e-15,
        f"the cubic ramp: speed x^2 (3 - 2x), angle and acceleration consistent ({worst:.1e}), at rest before t0, omega (t - t0 - T/2) after")

# 6. the command line
env = dict(os.environ, PYTHONPATH=os.path.join(SOURCE, "scripts"))
out = subprocess.run([sys.executable, "-m", "rollerref", "cycle", "--json", "cycle.json", "--csv", "cycle.csv",
                      "--t_end", "60", "--th0", "2", "--w0", "2"], env=env, capture_output=True, text=True)
ok = out.returncode == 0 and os.path.exists("cycle.json") and os.path.exists("cycle.csv")
if ok:
    js = json.load(open("cycle.json"))
    rows = np.loadtxt("cycle.csv", delimiter=",", skiprows=1)
    ok = abs(js["cycle"]["period"] / ss.stick_slip_cycle(ss.stender())["period"] - 1) < 1e-9
    ok = ok and rows.shape[1] == 9 and rows[0, 0] == 0.0 and rows[-1, 0] <= 60 + 1e-9
c.check(ok, "python3 -m rollerref cycle --json --csv: the cycle's period in the JSON, the run in the CSV"
        + ("" if out.returncode == 0 else f" (exit {out.returncode}: {out.stderr[-300:]})"))
c.close()
