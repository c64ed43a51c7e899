"""Flutter read from the scene's own run when roller -modes refuses the scene (issue 38; docs/squeal.md 9.6): a sheet
with its own mass (-sheet_mass) has no steady state the CEA can linearize about (its speed is the transient's force
balance), so the start from rest on the axle (stickslip.csv), which its press and its motor's start excite at every
frequency, is read for a line that grows instead.

The run after its first tenth (the press, the motor's start) is cut into WINDOWS equal windows. On each column the
PEAKS loudest lines of the whole span (Hann, zero padded) with at least MIN_PERIODS periods in a window and outside 3 %
of the harmonics of the motor's ripple and of a limit cycle the stick-slip mechanism found (forced, or stick-slip's; at least two of a window's bins), below 20 kHz and a
quarter of the step's rate, are followed: a line's amplitude in each window is the
largest within 3 % of it (at least a bin), and its growth rate the log-linear fit over the windows where it stands above
FLOOR of its largest (a decayed line's noise floor left out; all of them when fewer than three are). A line grows when its rate is positive and its last
window's amplitude is at least GROWS times its first: flutter's signature in a transient. A decaying line decays; the
mesh passing's and the ripple's lines hold."""
import math
import os

import numpy as np

WINDOWS, PEAKS, MIN_PERIODS, HARMONICS = 8, 6, 4, 10
BAND = 0.03  # a line's band, relative
FLOOR = 1e-3  # the windows a line's fit uses: its amplitude above this fraction of its largest
GROWS = 2.0  # a growing line: its last window at least this many times its first
AUDIBLE = 20000.0  # Hz: the lines followed lie below
COLUMNS = ("contact_force", "friction_force", "hub_rate", "axle_y")


def spectrum(t, y):
    """(frequencies, amplitudes) of y less its mean, Hann-windowed, zero padded 4 times."""
    y = y - np.mean(y)
    n = len(y)
    return np.fft.rfftfreq(4 * n, (t[-1] - t[0]) / (n - 1)), np.abs(np.fft.rfft(y * np.hanning(n), 4 * n)) * 4.0 / n


def _amplitude(fr, F, f, span):
    """The largest amplitude of a window's spectrum (fr, F; the window `span` long) within the band of f (at least one
    bin either side)."""
    band = np.abs(fr - f) <= max(BAND * f, 1.0 / span)
    return float(F[band].max()) if band.any() else 0.0


def peaks(t, y, fmin, fmax, exclude, near, count=PEAKS):
    """The `count` loudest maxima of y's spectrum in [fmin, fmax] (each the largest within `near` of itself), none whose
    band (BAND f) comes within `near` of an excluded frequency's, none within BAND of a louder one: [frequency]."""
    fr, F = spectrum(t, y)
    # a line is the largest within `near` of itself (the skirt of a louder or a growing line, whose own local maxima are
    # the window's ripples, is not a line of its own)
    h = max(1, int(round(near / (fr[1] - fr[0]))))
    k = np.arange(1, len(F) - 1)
    k = k[(fr[k] >= fmin) & (fr[k] <= fmax)]
    k = np.array([i for i in k if F[i] >= F[max(0, i - h) : i + h + 1].max()], int)
    if not len(k):
        return []
    out = []
    for i in k[np.argsort(F[k])[::-1]]:
        f = float(fr[i])
        if any(abs(f - x) < BAND * max(f, x) + near for x in exclude if x > 0) or any(abs(f / x - 1) < BAND for x in out):
            continue
        out.append(f)
        if len(out) == count:
            break
    return out


def read(folder, scene, name="stickslip.csv", s=1.0, also=()):
    """{'lines': [{column, frequency, growth_rate, ratio, amplitude}] sorted by growth rate (the least stable first),
    't0', 't1', 'window', 'excluded'} (frequencies per unit time; s: seconds per unit; also: the frequencies besides the
    ripple's whose harmonics are left out, a stick-slip cycle's); None without the run."""
    from .mechanisms import _monitor

    if not os.path.exists(os.path.join(folder, name)):
        return None
    d = _monitor(folder, name, ("t",) + COLUMNS)
    t = d["t"]
    t0 = t[0] + 0.1 * (t[-1] - t[0])
    m = t >= t0
    win = (t[-1] - t0) / WINDOWS
    rip = (scene.get("ripple") or {}).get("frequency")
    exclude = [k * float(f) for f in [rip] + list(also) if f and math.isfinite(f) for k in range(1, HARMONICS + 1)]
    edges = t0 + win * np.arange(WINDOWS + 1)
    mids = 0.5 * (edges[:-1] + edges[1:])
    cut = [(t >= a) & (t < b) for a, b in zip(edges[:-1], edges[1:])]
    lines = []
    for c in COLUMNS:
        if c not in d or not np.any(d[c][m] != d[c][m][0]):
            continue
        windows = [(spectrum(t[w], d[c][w]), t[w][-1] - t[w][0]) for w in cut]  # each window's spectrum, once a column
        # in the audible band and below a quarter of the step's rate (the contact's step-scale ringing is no sound);
        # a band that a ripple harmonic's main lobe in a window reaches (its 2 bins, the band's 1 more) is the ripple's
        for f in peaks(t[m], d[c][m], MIN_PERIODS / win, min(AUDIBLE * s, 0.25 / (t[1] - t[0])), exclude, 3.0 / win):
            amps = np.array([_amplitude(fr, F, f, span) for (fr, F), span in windows])
            if not amps.max() > 0:
                continue
            use = amps > FLOOR * amps.max()
            if use.sum() < 3:  # a line that grows or decays by more than 1/FLOOR: every window is its own
                use = amps > 0
            rate = float(np.polyfit(mids[use], np.log(amps[use]), 1)[0])
            lines.append({"column": c, "frequency": f, "growth_rate": rate, "ratio": float(amps[-1] / max(amps[0], 1e-300)),
                          "amplitude": float(amps[-1]), "grows": bool(rate > 0 and amps[-1] >= GROWS * amps[0])})
    lines.sort(key=lambda r: -r["growth_rate"])
    return {"lines": lines, "t0": float(t0), "t1": float(t[-1]), "window": float(win), "excluded": exclude, "file": name}


def growing(r, s=1.0):
    """The frequencies (Hz) of the lines that grow, each once (a line in several columns)."""
    out = []
    for x in r["lines"] if r else []:
        if x["grows"] and not any(abs(x["frequency"] / s / f - 1) < BAND for f in out):
            out.append(x["frequency"] / s)
    return sorted(out)


def sentences(r, s=1.0):
    """The evidence's sentences of read()'s result (s: seconds per unit time)."""
    if not r or not r["lines"]:
        return ["the scene's own run (stickslip.csv): no line to follow"]
    top = r["lines"][0]
    grow = [x for x in r["lines"] if x["grows"]]
    ev = [f"the scene's own run read for a growing line instead (stickslip.csv, t = {r['t0']:.4g}..{r['t1']:.4g} in {WINDOWS} windows, "
          f"the {PEAKS} loudest lines of each of {', '.join(sorted({x['column'] for x in r['lines']}))} outside the ripple's "
          "and a limit cycle's harmonics): "
          + (f"lines grow at {', '.join(f'{f:.1f}' for f in growing(r, s))} Hz, the fastest at {grow[0]['frequency'] / s:.1f} Hz "
             f"({grow[0]['column']}), {grow[0]['growth_rate'] / s:+.4g} /s"
             if grow else f"none grows; the least stable at {top['frequency'] / s:.1f} Hz ({top['column']}) "
             f"{top['growth_rate'] / s:+.4g} /s, its last window {top['ratio']:.3g} times its first")]
    return ev
