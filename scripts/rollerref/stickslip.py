"""The torsional one-degree-of-freedom model of a driven roller on a sheet (issue 36, docs/validation.md section 9.1).

    I th'' = k_d (th_m - th) + c_d (th_m' - th') - r F,   v = r th' - V,

th the hub's angle, th_m(t) the motor's (drive.py), V the sheet's speed (constant, or ramped from rest: V_ramp), F the friction force on the
roller's surface (positive when it opposes a positive slip v): in slip F = mu(|v|) N sgn(v), in stick (v = 0) the
force that keeps v = 0 while |F| <= mu_s N. Integrated by engine.py (exact stick/slip switching).

Steady sliding (motor at constant omega): th' = omega, v0 = r omega - V, the drive's wind-up
th_m - th = r mu(|v0|) N sgn(v0) / k_d. Linearized about it (d[mu(|v|) sgn v]/dv = mu'(|v|) for either sign):

    I s^2 + c_eff s + k_d = 0,   c_eff = c_d + r^2 N mu'(|v0|),   mu'(s) = -(mu_s - mu_k)/v_c exp(-s/v_c),

growth rate -c_eff / (2 I) (underdamped). c_eff = 0 at |v0| = v* = v_c ln(r^2 N (mu_s - mu_k) / (c_d v_c)): steady
sliding is unstable for 0 < |v0| < v*, the onset sheet speeds are V = r omega -+ v*, the onset motor speeds
omega = (V +- v*) / r. In units of tau = sqrt(k_d/I) t, x = k_d (th - th_m)/(r N) the model is Stender, Hoffmann and
Papangelo's oscillator x'' + 2 xi x' + x = -mu(x' - v_d) sgn(x' - v_d) (see `stender`), with
2 xi = c_d / sqrt(k_d I), velocities in units of U = r^2 N / sqrt(k_d I) and v_d = (V - r omega) / U.
"""
import math
from dataclasses import dataclass, field, replace

import numpy as np

from .drive import Motor
from .engine import Contact, Integrator, System
from .friction import Friction


@dataclass(frozen=True)
class Torsion:
    I: float  # total polar inertia (hub + rubber), per unit width
    k_d: float  # drive's torsional stiffness
    c_d: float  # drive's torsional damping
    r: float  # radius of the contact
    N: float  # normal force per unit width
    friction: Friction
    V: float = 0.0  # sheet speed
    motor: Motor = field(default_factory=Motor)
    V_ramp: float = 0.0  # the sheet's speed ramps linearly from 0 at t = 0 to V at t = V_ramp (0: V from the start)

    def sheet(self, t):
        """The sheet's (speed, acceleration) at time t."""
        if self.V_ramp > 0.0 and t < self.V_ramp:
            return (self.V * max(t, 0.0) / self.V_ramp, self.V / self.V_ramp if t >= 0.0 else 0.0)
        return self.V, 0.0

    @property
    def omega(self):
        return self.motor.omega

    @property
    def w_n(self):
        """Undamped torsional frequency sqrt(k_d / I) (rad per unit time)."""
        return math.sqrt(self.k_d / self.I)

    def system(self):
        m = self.motor

        def force(t, q, u):
            a, v, _ = m.state(t)
            return np.array([self.k_d * (a - q[0]) + self.c_d * (v - u[0])])

        return System(M=np.array([[self.I]]), force=force,
                      contacts=[Contact(w=[self.r], friction=self.friction, N=self.N, belt=self.sheet,
                                        name="roller-sheet")])


def steady_sliding(p: Torsion):
    """The steady sliding state at the motor's final speed: slip speed, friction force, wind-up, drive torque."""
    v0 = p.r * p.omega - p.V
    if v0 == 0.0:
        return {"slip_speed": 0.0, "sliding": False}
    mu = p.friction.mu(abs(v0))
    F = mu * p.N * math.copysign(1.0, v0)
    return {"slip_speed": v0, "sliding": True, "mu": mu, "friction_force": F, "drive_torque": p.r * F,
            "wind_up": p.r * F / p.k_d, "hub_rate": p.omega}


def linear_stability(p: Torsion):
    """Closed-form linear stability of steady sliding: effective damping, eigenvalues, growth rate, the onset."""
    v0 = p.r * p.omega - p.V
    s = abs(v0)
    dmu = p.friction.dmu(s) if s > 0 else p.friction.dmu(0.0)
    c_eff = p.c_d + p.r ** 2 * p.N * dmu
    disc = c_eff ** 2 - 4.0 * p.I * p.k_d
    if disc < 0:
        re, im = -c_eff / (2 * p.I), math.sqrt(-disc) / (2 * p.I)
        eig = [complex(re, im), complex(re, -im)]
    else:
        eig = [complex((-c_eff + math.sqrt(disc)) / (2 * p.I)), complex((-c_eff - math.sqrt(disc)) / (2 * p.I))]
    v_star = p.friction.weakening_speed(p.c_d / (p.r ** 2 * p.N)) if p.c_d > 0 else (math.inf if p.friction.v_c > 0 else None)
    out = {"slip_speed": v0, "dmu": dmu, "c_eff": c_eff, "eigenvalues": eig, "growth_rate": max(e.real for e in eig),
           "frequency": abs(eig[0].imag) / (2 * math.pi), "w_n": p.w_n, "stable": c_eff > 0,
           "onset_slip_speed": v_star}
    if v_star is not None and math.isfinite(v_star):
        out["onset_sheet_speeds"] = [p.r * p.omega - v_star, p.r * p.omega + v_star]
        out["onset_motor_speeds"] = [(p.V - v_star) / p.r, (p.V + v_star) / p.r]
    return out


def steady_copy(p: Torsion):
    """p with the motor at constant speed from t = 0 and the sheet at V from t = 0 (no ramps; the ripple kept)."""
    return with_(p, V_ramp=0.0, motor_t0=0.0, motor_t_ramp=0.0)


def initial_sliding(p: Torsion, kick=0.0, t0=0.0):
    """(th, th') on steady sliding at time t0 (the motor at constant speed) with th' kicked by `kick`."""
    ss = steady_sliding(p)
    a, v, _ = p.motor.state(t0)
    return a - ss.get("wind_up", 0.0), v + kick


def simulate(p: Torsion, t_end, th0=0.0, w0=0.0, t0=0.0, dt_out=None, rtol=1e-10, stop=None, chunk=None):
    """Integrate from th(t0) = th0, th'(t0) = w0 (stuck if r w0 = V exactly). Returns engine.Result."""
    integ = Integrator(p.system(), rtol=rtol, atol=1e-14 * max(1.0, abs(p.omega), abs(p.V) / p.r))
    V0 = p.sheet(t0)[0]
    g0 = [p.r * w0 - V0]
    if abs(g0[0]) <= 1e-15 * max(abs(V0), abs(p.r * w0), 1e-300):
        g0 = [0.0]
    return integ.run([th0], [w0], t_end, t0=t0, dt_out=dt_out or (2 * math.pi / p.w_n) / 200, g0=g0, stop=stop,
                     chunk=chunk)


def _crossings(t, x):
    """Times of upward zero crossings of x(t), linearly interpolated."""
    i = np.nonzero((x[:-1] < 0) & (x[1:] >= 0))[0]
    return t[i] - x[i] * (t[i + 1] - t[i]) / (x[i + 1] - x[i])


def limit_cycle(p: Torsion, res, t_min=None, periods=4):
    """The limit cycle at the end of a run: period, amplitudes, stick fraction, stick in every period.

    The Poincare section is th' - omega rising through 0 (once per oscillation); the period is the smallest
    repeat (1 to 4 crossings) of the last crossing intervals. Amplitudes are half the peak-to-peak over the last
    period of th' - omega (rate), of F (friction) and of the wind-up th_m - th."""
    t, w = res.t, res.u[:, 0]
    keep = t >= (t_min if t_min is not None else t[0])
    tc = _crossings(t[keep], w[keep] - p.omega)
    if len(tc) < 4:
        return {"periodic": False, "state": "sliding" if len(tc) == 0 and not res.stick_intervals(0) else "unknown",
                "crossings": len(tc)}
    d = np.diff(tc)
    best = None
    for k in range(1, 5):
        if len(d) < 2 * k + 1:
            break
        P = np.array([tc[i + k] - tc[i] for i in range(len(tc) - k)])
        spread = abs(P[-1] - P[-1 - k]) / P[-1]
        if spread < 1e-3:
            best = (k, P[-1], spread)
            break
    if best is None:
        return {"periodic": False, "state": "unknown", "crossings": len(tc), "last_interval": float(d[-1])}
    k, T, spread = best
    ta, tb = tc[-1] - T, tc[-1]
    win = (t >= ta) & (t <= tb)
    th_m = np.array([p.motor.state(x)[0] for x in t[win]])
    wind = th_m - res.q[win, 0]
    stick = sum(max(0.0, min(b, tb) - max(a, ta)) for a, b in res.stick_intervals(0))
    n_check = min(periods, int((len(tc) - 1) // k))
    every = True
    for i in range(n_check):
        a, b = tc[-1] - (i + 1) * T, tc[-1] - i * T
        if not any(min(bb, b) - max(aa, a) > 0 for aa, bb in res.stick_intervals(0)):
            every = False
    F = res.F[win, 0]
    rate = w[win] - p.omega
    stuck = res.mode[win, 0] == 0
    lo, hi = _extrema(t[win][~stuck], rate[~stuck]) if np.any(~stuck) else (rate.min(), rate.max())
    rate = np.concatenate([rate, [lo, hi]])
    prev = (t >= ta - T) & (t <= ta)
    amp_prev = (w[prev].max() - w[prev].min()) / 2 if np.any(prev) else math.nan
    amp = (rate.max() - rate.min()) / 2
    change = abs(amp - amp_prev) / amp if amp > 0 else math.inf
    if not change < 1e-3:  # a decaying (or growing) oscillation about steady sliding, not a limit cycle
        decaying = amp < amp_prev and not any(b > ta for a, b in res.stick_intervals(0))
        return {"periodic": False, "state": "sliding" if decaying else "unknown", "crossings": len(tc),
                "rate_amplitude": float(amp), "amplitude_change": float(change), "last_interval": float(T)}
    return {"periodic": True, "state": "cycle" if stick > 0 else "slip cycle", "period": float(T), "crossings_per_period": k, "period_spread": float(spread),
            "amplitude_change": float(change), "rate_amplitude": float(amp), "rate_max": float(rate.max()),
            "rate_min": float(rate.min()), "friction_amplitude": float((F.max() - F.min()) / 2),
            "friction_max": float(F.max()), "friction_min": float(F.min()), "friction_mean": float(np.mean(F)),
            "wind_up_amplitude": float((wind.max() - wind.min()) / 2), "stick_fraction": float(stick / T),
            "stick_every_period": bool(every and stick > 0), "periods_checked": n_check, "t_start": float(ta)}


def _extrema(t, x):
    """(min, max) of sampled x(t), each refined by the parabola through the extreme sample and its neighbours."""
    if len(x) == 0:
        return math.inf, -math.inf
    out = []
    for i in (int(np.argmin(x)), int(np.argmax(x))):
        v = float(x[i])
        if 0 < i < len(x) - 1:
            c = np.polyfit(t[i - 1:i + 2] - t[i], x[i - 1:i + 2], 2)
            if c[0] != 0.0:
                tv = -c[1] / (2 * c[0])
                if abs(tv) <= max(t[i + 1] - t[i], t[i] - t[i - 1]):
                    v = float(np.polyval(c, tv))
        out.append(v)
    return out[0], out[1]


def _energy(p: Torsion, t, th, w):
    """Quadratic energy of the disturbance about steady sliding: I (th' - omega)^2/2 + k_d (dev of wind-up)^2/2."""
    a, v, _ = p.motor.state(t)
    dev = (a - th) - steady_sliding(p).get("wind_up", 0.0)
    return 0.5 * p.I * (w - v) ** 2 + 0.5 * p.k_d * dev ** 2


def classify(p: Torsion, th0, w0, t0=0.0, t_max=None, decay=1e-4, n_stick=6):
    """Where a disturbance settles: 'cycle' (n_stick stick phases at equal intervals, 1 %, or still sticking at
    t_max), 'sliding' (the disturbance's energy about steady sliding below 1 % of its initial value and below
    `decay` times that of a kick to stick, I (v0/r)^2 / 2, none sticking for two periods) or 'undecided' at t_max
    (default 400 torsional periods). For a motor at constant speed (no ripple)."""
    T_n = 2 * math.pi / p.w_n
    t_max = t_max or t0 + 400 * T_n
    v0 = p.r * p.omega - p.V
    e_ref = 0.5 * p.I * (v0 / p.r) ** 2
    e_init = _energy(p, t0, th0, w0)

    def stop(res, t, y):
        sticks = [e[0] for e in res.events if e[2] == "stick"]
        if len(sticks) >= n_stick:
            gaps = np.diff(sticks[-n_stick:])
            if gaps.max() - gaps.min() < 1e-2 * gaps.max():
                return "cycle"
        if res.events and res.events[-1][3][0] == 0:
            return ""
        e = _energy(p, t, y[0], y[1])
        if e < min(decay * e_ref, 1e-2 * e_init) and (not sticks or sticks[-1] < t - 2 * T_n):
            return "sliding"
        return ""

    res = simulate(p, t_max, th0=th0, w0=w0, t0=t0, stop=stop, chunk=T_n / 2, dt_out=T_n / 50, rtol=1e-9)
    if not res.stopped:
        sticks = [e[0] for e in res.events if e[2] == "stick"]
        res.stopped = "cycle" if sticks and sticks[-1] > t_max - 5 * T_n else "undecided"
    return res.stopped, res


def kick_threshold(p: Torsion, sign=None, rel_tol=1e-3, a_max=None):
    """The smallest kick A of th' (from steady sliding, th' = omega + sign A) that reaches the stick-slip cycle,
    by bisection; sign (default) is toward stick: -sgn(r omega - V). Returns the threshold, the largest kick seen
    to settle to sliding and the smallest seen to reach the cycle; None if a_max (default 4 |v0| / r) does not.
    Ramps of p are ignored (steady_copy)."""
    p = steady_copy(p)
    v0 = p.r * p.omega - p.V
    sign = sign if sign is not None else -math.copysign(1.0, v0)
    a_max = a_max or 4 * abs(v0) / p.r
    runs = 0

    def goes(A):
        nonlocal runs
        runs += 1
        th, w = initial_sliding(p, sign * A)
        return classify(p, th, w)[0]

    hi = abs(v0) / p.r
    while goes(hi) != "cycle":
        hi *= 1.5
        if hi > a_max:
            return None
    lo = 0.0
    while hi - lo > rel_tol * hi:
        mid = 0.5 * (lo + hi)
        if goes(mid) == "cycle":
            hi = mid
        else:
            lo = mid
    return {"threshold": 0.5 * (lo + hi), "sliding_at": lo, "cycle_at": hi, "runs": runs, "sign": sign}


def bistability(p: Torsion, start_from_rest=True, kick=None):
    """Is steady sliding linearly stable while a large disturbance settles into stick-slip (stick every period)?
    The large disturbance is the start from rest (hub and motor at rest at t = 0, the motor's ramp as given) or a
    kick of size `kick` in th'. A small kick (1e-3 |v0|/r) must decay."""
    lin = linear_stability(p)
    T_n = 2 * math.pi / p.w_n
    if start_from_rest:
        th0, w0 = 0.0, 0.0
    else:
        p = steady_copy(p)
        th0, w0 = initial_sliding(p, -kick)
    res = simulate(p, 300 * T_n + p.motor.t0 + p.motor.t_ramp + p.V_ramp, th0=th0, w0=w0, dt_out=T_n / 400)
    cyc = limit_cycle(p, res, t_min=res.t[-1] - 60 * T_n)
    q = steady_copy(p)
    small = classify(q, *initial_sliding(q, -1e-3 * abs(p.r * p.omega - p.V) / p.r))[0]
    big = cyc.get("periodic") and cyc.get("stick_every_period")
    return {"linear": lin, "cycle": cyc, "small_kick": small, "bistable": bool(lin["stable"] and big and small == "sliding")}


def stender(xi=0.05, v_d=1.5, mu_d=0.5, mu_sd=2.0, v0=0.5):
    """Stender, Hoffmann, Papangelo's oscillator (Lubricants 8:105, 2020; the parameters of their bSTAB friction case)
    as a Torsion: I = k_d = r = N = 1, c_d = 2 xi, the motor at rest and the sheet (belt) at V = v_d."""
    return Torsion(I=1.0, k_d=1.0, c_d=2 * xi, r=1.0, N=1.0, friction=Friction(mu_d, mu_d * mu_sd, v0), V=v_d)


def to_nondimensional(p: Torsion):
    """Stender's parameters (xi, v_d, mu_d, mu_sd, v0) of a Torsion with a motor at constant speed."""
    U = p.r ** 2 * p.N / math.sqrt(p.k_d * p.I)
    return {"xi": p.c_d / (2 * math.sqrt(p.k_d * p.I)), "v_d": (p.V - p.r * p.omega) / U, "mu_d": p.friction.mu_k,
            "mu_sd": p.friction.mu_s / p.friction.mu_k, "v0": p.friction.v_c / U, "velocity_scale": U,
            "time_scale": 1 / p.w_n, "angle_scale": p.r * p.N / p.k_d}


def roller_set(I_rubber=0.092, I_hub=0.1, r=0.5, N=0.01, w_n=1.0, xi=0.05, v_d=1.5, mu_k=0.5, mu_s=1.0, v0=0.5,
               V=0.0, t_ramp=0.0):
    """A parameter set in roller variables with Stender's nondimensional numbers (xi, v_d, mu_k, mu_s/mu_k, v0):
    I = I_hub + I_rubber, k_d = I w_n^2, c_d = 2 xi sqrt(k_d I), U = r^2 N / sqrt(k_d I), v_c = v0 U, the sheet at V
    and the motor at omega = (V + v_d U) / r (the roller's surface faster than the sheet by v_d U: it drives)."""
    I = I_hub + I_rubber
    k_d = I * w_n ** 2
    U = r ** 2 * N / math.sqrt(k_d * I)
    omega = (V + v_d * U) / r
    return Torsion(I=I, k_d=k_d, c_d=2 * xi * math.sqrt(k_d * I), r=r, N=N, friction=Friction(mu_k, mu_s, v0 * U),
                   V=V, motor=Motor(omega=omega, t_ramp=t_ramp))


def with_(p: Torsion, **kw):
    """A copy of p with fields replaced (motor fields prefixed 'motor_')."""
    mk = {k[6:]: v for k, v in kw.items() if k.startswith("motor_")}
    rest = {k: v for k, v in kw.items() if not k.startswith("motor_")}
    if mk:
        rest["motor"] = replace(p.motor, **mk)
    return replace(p, **rest)


def stick_slip_cycle(p: Torsion, t_max=None, rtol=1e-11, dt_out=None):
    """The stick-slip limit cycle by its single slip (motor at constant speed, no ripple): start at break-away
    (v = 0, the stuck force at mu_s N sgn(v0)) and integrate the slip until v returns to 0. If the contact then
    sticks, the stick lasts until the wind-up is back at break-away, (Delta_b - Delta_e) / (omega - V/r), and the
    orbit repeats exactly: the cycle exists and its period is t_slip + t_stick. If the slip never returns to v = 0
    (within t_max, default 20 torsional periods, the disturbance decaying) there is no stick-slip cycle.
    Ramps of p are ignored (steady_copy)."""
    p = steady_copy(p)
    v0 = p.r * p.omega - p.V
    s = math.copysign(1.0, v0)
    rel = p.omega - p.V / p.r  # th_m' - th' while stuck
    delta_b = (p.r * p.friction.mu_s * p.N * s - p.c_d * rel) / p.k_d  # wind-up th_m - th at break-away
    T_n = 2 * math.pi / p.w_n
    t_max = t_max or 20 * T_n

    def stop(res, t, y):
        return "returned" if any(e[2] in ("stick", "reverse") for e in res.events[1:]) else ""

    # start stuck a hair (1e-9 T_n) before break-away, so that the engine itself finds the break-away event
    th0 = p.motor.state(0.0)[0] - delta_b + rel * 1e-9 * T_n
    res = simulate(p, t_max, th0=th0, w0=p.V / p.r, stop=stop, chunk=T_n, rtol=rtol, dt_out=dt_out or T_n / 400)
    brk = [e for e in res.events if e[2] == "slip"]
    ret = [e for e in res.events if e[2] in ("stick", "reverse")]
    if not brk or not ret:
        return {"exists": False, "break_away_wind_up": delta_b}
    t_b, (t_e, _, kind, _) = brk[0][0], ret[0]
    if kind != "stick":
        return {"exists": False, "break_away_wind_up": delta_b, "returns": "reverse", "t_slip": t_e - t_b}
    i = int(np.argmin(abs(res.t - t_e)))
    delta_e = p.motor.state(t_e)[0] - res.q[i, 0]
    t_stick = (delta_b - delta_e) / rel
    slip = (res.t >= t_b) & (res.t <= t_e)
    rate = np.concatenate([res.u[slip, 0], [p.V / p.r]]) - p.omega
    r_min, r_max = _extrema(res.t[slip], rate[:-1])
    rate = np.concatenate([rate, [r_min, r_max]])
    F = np.concatenate([res.F[slip, 0], [p.friction.mu_s * p.N * s, (p.k_d * delta_e + p.c_d * rel) / p.r]])
    return {"exists": True, "period": t_e - t_b + t_stick, "t_slip": t_e - t_b, "t_stick": t_stick,
            "stick_fraction": t_stick / (t_e - t_b + t_stick), "rate_amplitude": float((rate.max() - rate.min()) / 2),
            "rate_min": float(rate.min()), "rate_max": float(rate.max()),
            "friction_amplitude": float((F.max() - F.min()) / 2), "friction_min": float(F.min()),
            "friction_max": float(F.max()), "break_away_wind_up": delta_b, "stick_wind_up": delta_e}


def cycle_limit(p: Torsion, lo, hi, rel_tol=1e-4, vary="omega"):
    """The slip speed |v0| above which the stick-slip cycle ceases to exist, by bisection of stick_slip_cycle between
    slip speeds lo (cycle) and hi (none), varying the motor speed (vary='omega') or the sheet's (vary='V')."""

    def at(s):
        v0 = math.copysign(s, p.r * p.omega - p.V)
        q = with_(p, motor_omega=(p.V + v0) / p.r) if vary == "omega" else with_(p, V=p.r * p.omega - v0)
        return stick_slip_cycle(q)["exists"]

    if not at(lo) or at(hi):
        raise ValueError(f"cycle_limit: need a cycle at slip speed {lo} and none at {hi}")
    while hi - lo > rel_tol * hi:
        mid = 0.5 * (lo + hi)
        lo, hi = (mid, hi) if at(mid) else (lo, mid)
    return 0.5 * (lo + hi)


def bistable_window(p: Torsion, hi=None):
    """The slip speeds |v0| between the linear onset v* (steady sliding stable above) and the end of the stick-slip
    cycle: the bistable band (v*, v_cycle), empty if v_cycle <= v*."""
    v_star = linear_stability(p)["onset_slip_speed"]
    lo = 0.5 * v_star if v_star else 1e-3 * p.friction.v_c
    hi = hi or 20 * max(v_star or 0, p.friction.v_c, p.r * p.N * p.friction.mu_s / math.sqrt(p.k_d * p.I))
    v_cyc = cycle_limit(p, lo, hi)
    return {"onset_slip_speed": v_star, "cycle_limit_slip_speed": v_cyc, "bistable": bool(v_star is not None and v_cyc > v_star)}


def ramp_threshold(p: Torsion, ramp="linear", rel_tol=1e-2, t_hi=None):
    """The longest motor ramp (t_ramp, the sheet at rest or at V throughout) after which the start from rest
    (hub and motor at rest, th = th' = 0) still settles into the stick-slip cycle, by bisection; 0 if even the step
    does not, None if t_hi (default 20 torsional periods) still does."""
    T_n = 2 * math.pi / p.w_n
    t_hi = t_hi or 20 * T_n
    base = with_(p, motor_t0=0.0, motor_ramp=ramp, V_ramp=0.0)

    def cyc(tr):
        return classify(with_(base, motor_t_ramp=tr), 0.0, 0.0)[0] == "cycle"

    if not cyc(0.0):
        return 0.0
    lo, hi = 0.0, T_n
    while cyc(hi):
        lo, hi = hi, 2 * hi
        if hi > t_hi:
            return None
    while hi - lo > rel_tol * hi:
        mid = 0.5 * (lo + hi)
        lo, hi = (mid, hi) if cyc(mid) else (lo, mid)
    return 0.5 * (lo + hi)


def propose(N=0.01, w_n=1.0, I_hub=0.1, I_rubber=0.092, r=0.5, xi=0.05, v0=0.5, v_d=1.5, mu_k=0.5, mu_s=1.0,
            with_thresholds=True):
    """A bistable set in roller variables (roller_set: the sheet at rest, the motor at omega) with its checks:
    the closed-form linear stability, the bistable band of slip speeds, the stick-slip cycle (period, amplitudes,
    stick fraction), the smallest kick of th' that reaches the cycle, the longest motor ramp from rest that does."""
    p = roller_set(I_rubber=I_rubber, I_hub=I_hub, r=r, N=N, w_n=w_n, xi=xi, v_d=v_d, mu_k=mu_k, mu_s=mu_s, v0=v0)
    lin = linear_stability(p)
    cyc = stick_slip_cycle(p)
    out = {"parameters": {"I": p.I, "I_hub": I_hub, "I_rubber": I_rubber, "k_d": p.k_d, "c_d": p.c_d, "r": p.r,
                          "N": p.N, "mu_k": mu_k, "mu_s": mu_s, "v_c": p.friction.v_c, "omega": p.omega, "V": p.V},
           "nondimensional": to_nondimensional(p), "steady_sliding": steady_sliding(p), "linear": lin, "cycle": cyc}
    if with_thresholds:
        out["window"] = bistable_window(p)
        out["kick_threshold"] = kick_threshold(p)
        out["ramp_threshold_linear"] = ramp_threshold(p)
    out["bistable"] = bool(lin["stable"] and cyc["exists"])
    return out


def basin_stability(p: Torsion, x_range=(-2.0, 2.0), v_range=(0.0, 2.0), n=(12, 6)):
    """Stender et al.'s basin stability on a grid (their Monte Carlo sampling replaced by an n[0] x n[1] grid of
    cell centres): the fraction of initial states that settle into the stick-slip cycle. The states are theirs,
    (x, x') in units of angle_scale r N / k_d and velocity_scale / r about the motor's angle and speed at t = 0
    (for stender(): th and th' themselves). Returns the fraction, the counts and the undecided."""
    nd = to_nondimensional(p)
    ang, vel = nd["angle_scale"], nd["velocity_scale"] / p.r
    a0, w0, _ = p.motor.state(0.0)
    xs = x_range[0] + (np.arange(n[0]) + 0.5) * (x_range[1] - x_range[0]) / n[0]
    vs = v_range[0] + (np.arange(n[1]) + 0.5) * (v_range[1] - v_range[0]) / n[1]
    counts = {"cycle": 0, "sliding": 0, "undecided": 0}
    for x in xs:
        for v in vs:
            counts[classify(p, a0 + x * ang, w0 + v * vel)[0]] += 1
    total = n[0] * n[1]
    return {"cycle_fraction": counts["cycle"] / total, "counts": counts, "grid": list(n), "x_range": list(x_range),
            "v_range": list(v_range)}
