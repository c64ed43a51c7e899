"""The torsional one-degree-of-freedom model of a driven roller on a sheet (issue 36, docs/validation.md section 10.1).

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
