"""Limit cycles and forced responses in a monitor CSV (docs/squeal.md 9.4): the evidence of the stick-slip and forced
mechanisms, read from what roller wrote (`-monitor_csv`: t, hub_rate, drive_torque, stick_nodes, slip_nodes, ...).

- `detect`: a limit cycle in a series (the hub's rate on -axle): its periods between upward crossings of the tail's
  mean (with a hysteresis of a quarter of the tail's half peak-to-peak, so that the node passing's ripple does not
  count as a crossing), the half peak-to-peak of each period, whether the patch stuck in each period (stick_nodes > 0),
  the envelope's growth rate (the slope of log amplitude over the last periods). Sustained: the amplitude changes by
  less than SUSTAINED_PER_PERIOD per period and the periods agree within PERIOD_SPREAD; stick-slip: sustained, stuck and slipping whole
  once in every one of those periods.
- `fundamental`: the pitch of a periodic sound (the stick-slip saw-tooth's harmonics may be louder than its
  fundamental): the first peak of the normalized autocorrelation above 0.5, refined by a parabola.
- `lock_in`: the amplitude and phase of a series at a known frequency over whole periods (the forced response).
"""
import math

import numpy as np

SUSTAINED_PER_PERIOD = 0.02  # |amplitude change| per period below which a cycle is sustained
PERIOD_SPREAD = 0.05  # the periods of a cycle within 5 % of their mean
MIN_PERIODS = 3


def crossings(t, y, level, hysteresis):
    """Times of the upward crossings of `level` (linear interpolation at the last crossing of level before y exceeds
    level + hysteresis, after it was below level - hysteresis)."""
    t, y = np.asarray(t, float), np.asarray(y, float)
    out, armed, last = [], False, None
    for k in range(1, len(y)):
        if y[k] < level - hysteresis:
            armed, last = True, None
        if armed and y[k - 1] < level <= y[k]:
            last = t[k - 1] + (level - y[k - 1]) * (t[k] - t[k - 1]) / (y[k] - y[k - 1])
        if armed and last is not None and y[k] > level + hysteresis:
            out.append(last)
            armed, last = False, None
    return np.array(out)


def detect(t, y, stick=None, t_min=None, tail=1.0 / 3, periods=8):
    """The limit cycle of y(t) (from t_min on; default the whole series): dict with period, frequency (cycles per unit
    time), amplitude (mean half peak-to-peak of the last `periods` periods), growth_rate (of the amplitude, per unit
    time), sustained, stick_every_period (None without `stick`), stick_slip, the crossing times and the per-period
    amplitudes and stick counts used, and `why` (a sentence)."""
    t, y = np.asarray(t, float), np.asarray(y, float)
    m = t >= (t[0] if t_min is None else t_min)
    t, y = t[m], y[m]
    st = None if stick is None else np.asarray(stick, float)[m]
    last = t >= t[0] + (1 - tail) * (t[-1] - t[0])
    level = float(np.mean(y[last])) if last.any() else float(np.mean(y))
    half = 0.5 * float(np.ptp(y[last])) if last.any() else 0.0
    out = {"period": math.nan, "frequency": math.nan, "amplitude": half, "growth_rate": math.nan, "sustained": False,
           "stick_every_period": None, "stick_slip": False, "crossings": [], "amplitudes": [], "sticks": [],
           "level": level, "periods_used": 0}
    if half <= 0:
        out["why"] = "no oscillation: the series is constant over its last third"
        return out
    tc = crossings(t, y, level, 0.25 * half)
    tc = tc[-(periods + 1):]
    if len(tc) < MIN_PERIODS + 1:
        out["why"] = f"{max(len(tc) - 1, 0)} whole periods in the series (at least {MIN_PERIODS} needed)"
        out["crossings"] = tc.tolist()
        return out
    per = np.diff(tc)
    amps, sticks, slips, mids = [], [], [], []
    for a, b in zip(tc[:-1], tc[1:]):
        w = (t >= a) & (t < b)
        amps.append(0.5 * float(np.ptp(y[w])))
        sticks.append(int(np.max(st[w])) if st is not None else None)
        slips.append(bool(np.min(st[w]) == 0) if st is not None else None)  # the whole patch slipping at some step
        mids.append(0.5 * (a + b))
    amps = np.array(amps)
    g = float(np.polyfit(mids, np.log(amps), 1)[0]) if len(amps) >= 2 and np.all(amps > 0) else math.nan
    T = float(np.mean(per))
    spread = float(np.max(np.abs(per / T - 1)))
    sustained = bool(math.isfinite(g) and abs(g) * T < SUSTAINED_PER_PERIOD and spread < PERIOD_SPREAD)
    # stick-slip: the patch sticks and slips whole in every period (a rolling patch's stick zone that never lets go
    # while a forced oscillation rides on it is not stick-slip)
    every = None if st is None else all(s > 0 for s in sticks) and all(slips)
    out.update(period=T, frequency=1.0 / T, amplitude=float(np.mean(amps)), growth_rate=g, sustained=sustained,
               stick_every_period=every, stick_slip=bool(sustained and every), crossings=tc.tolist(),
               amplitudes=amps.tolist(), sticks=sticks, period_spread=spread, periods_used=len(per))
    out["why"] = (f"{len(per)} periods of {T:.5g} (spread {100 * spread:.2f} %), amplitude {out['amplitude']:.4g}, "
                  f"envelope {g:+.3g} per unit time ({100 * g * T:+.2f} % per period)"
                  + ("" if st is None else f", stuck in {sum(s > 0 for s in sticks)} of them, slipping whole in {sum(slips)}"))
    return out


def fundamental(samples, rate, fmin=5.0, fmax=2000.0):
    """The pitch (Hz) of a periodic signal: the lag of the first peak of its normalized autocorrelation that exceeds
    0.5 (between 1/fmax and 1/fmin), refined by the parabola through its neighbours; nan when there is none."""
    x = np.asarray(samples, float) - np.mean(samples)
    n = len(x)
    if n < 4 or not np.any(x):
        return math.nan
    spec = np.fft.rfft(x, 2 * n)
    ac = np.fft.irfft(spec * np.conj(spec))[:n]
    ac = ac / ac[0] / (1.0 - np.arange(n) / n)  # unbiased: each lag's sum over the overlap only
    lo, hi = max(1, int(rate / fmax)), min(n - 2, int(rate / fmin))
    for k in range(lo + 1, hi):
        if ac[k] > 0.5 and ac[k] >= ac[k - 1] and ac[k] >= ac[k + 1]:
            a, b, c = ac[k - 1], ac[k], ac[k + 1]
            d = 0.5 * (a - c) / (a - 2 * b + c) if (a - 2 * b + c) != 0 else 0.0
            return float(rate / (k + d))
    return math.nan


def lock_in(t, y, f, periods=None, free=()):
    """(amplitude, phase) of y at the frequency f (cycles per unit time) over the last whole periods (all of them by
    default): the least-squares fit of a + b cos + c sin (phase of y = A sin(2 pi f t + phase)), beside the free
    oscillations `free` [(frequency, growth rate), ...] (each a cos and a sin times its exponential, amplitudes
    fitted: a decaying start-up transient near f would leak into the line otherwise)."""
    t, y = np.asarray(t, float), np.asarray(y, float)
    T = 1.0 / f
    n = int((t[-1] - t[0]) / T) if periods is None else int(periods)
    m = t >= t[-1] - n * T
    tm = t[m] - t[m][0]
    W = 2 * math.pi * f
    basis = [np.ones(m.sum()), np.cos(W * t[m]), np.sin(W * t[m])]
    for fr, g in free:
        e = np.exp(g * tm)
        basis += [e * np.cos(2 * math.pi * fr * tm), e * np.sin(2 * math.pi * fr * tm)]
    coef = np.linalg.lstsq(np.stack(basis, 1), y[m], rcond=None)[0]
    b, c = coef[1], coef[2]
    return float(math.hypot(b, c)), float(math.atan2(b, c))
