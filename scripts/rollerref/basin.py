"""Bistability of the torsional 1-DOF (stickslip.Torsion; docs/validation.md section 10.1): where a disturbance of
steady sliding settles, the smallest kick and the longest start-up ramp that reach the stick-slip cycle, the band
of slip speeds where sliding is stable and the cycle exists, Stender et al.'s basin stability, a proposed bistable
set in roller variables."""
import math

import numpy as np

from .stickslip import (Torsion, initial_sliding, limit_cycle, linear_stability, roller_set, simulate, steady_copy,
                        steady_sliding, stick_slip_cycle, to_nondimensional, with_)


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
    kick of size `kick` in th' toward stick. A small kick (1e-3 |v0|/r) must decay."""
    lin = linear_stability(p)
    T_n = 2 * math.pi / p.w_n
    if start_from_rest:
        th0, w0 = 0.0, 0.0
    else:
        p = steady_copy(p)
        th0, w0 = initial_sliding(p, -math.copysign(kick, p.r * p.omega - p.V))
    res = simulate(p, 300 * T_n + p.motor.t0 + p.motor.t_ramp + p.V_ramp, th0=th0, w0=w0, dt_out=T_n / 400)
    cyc = limit_cycle(p, res, t_min=res.t[-1] - 60 * T_n)
    q = steady_copy(p)
    small = classify(q, *initial_sliding(q, -1e-3 * abs(p.r * p.omega - p.V) / p.r))[0]
    big = cyc.get("periodic") and cyc.get("stick_every_period")
    return {"linear": lin, "cycle": cyc, "small_kick": small, "bistable": bool(lin["stable"] and big and small == "sliding")}


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
