"""Spectra of Roller's time series (the -monitor_csv CSV, docs/model.md section 6.1): the functions behind
scripts/rollerplots/spectrum.py, importable by tests (tests/spectrum_synthetic.py) and other scripts.

Amplitudes are amplitudes of sinusoids: a signal c + a cos(2 pi f t + phi) sampled over the window has the
line a at f. The mean is removed, the signal multiplied by a Hann window w and the discrete-time Fourier
transform evaluated at any frequency (not only the FFT's bins),

    A(f) = 2 |sum_n w_n (y_n - mean) exp(-2 pi i f t_n)| / sum_n w_n,

which is 2|FFT|/N with the window's coherent gain sum(w)/N divided out. At the frequency of a pure sinusoid
this is its amplitude exactly, up to the leakage of its negative-frequency image (Hann side lobes fall as
1/k^3: below 1e-6 with 20 periods in the window). Between the FFT's bins the Hann main lobe loses up to 15 %
(scalloping), so a line is measured at the maximum of A within a band around the frequency asked for
(line_amplitude; the band defaults to one resolution bin 1/T on either side), not at the nearest bin. Two
lines closer than about 2/T (the main lobe's half width) are not resolved.

Time steps of Roller are uniform; a non-uniform t is resampled linearly onto a uniform grid of the median
step (uniform_series).

The element-passing frequency (docs/contact.md, "Cogging"): a point of Gamma_C moves at omega r_C in the
co-rotating frame relative to the obstacle, so the contact zone passes one element edge of length h every
h / (omega r_C) time units:

    f_e = omega r_C / h     (cycles per unit time; element_passing_frequency)

h is the arc length of a Gamma_C edge, 2 pi r_C / N_C with N_C the Gamma_C vertices, which differs from
-mesh_h by gmsh's rounding (default rolling scene: -mesh_h 0.0223607, 142 edges, h = 0.0221239).
"""
import csv
import math

import numpy as np


def read_csv(path):
    """A CSV with a header row as a dict of float arrays (nan for empty or non-numeric cells), in column
    order."""
    with open(path, newline="") as f:
        rows = list(csv.reader(f))
    if not rows:
        raise ValueError(f"{path} is empty")
    head, body = rows[0], [r for r in rows[1:] if r]

    def num(v):
        try:
            return float(v)
        except ValueError:
            return math.nan

    return {name: np.array([num(r[i]) if i < len(r) else math.nan for r in body]) for i, name in enumerate(head)}


def column(data, name, path="the CSV"):
    """data[name], or a ValueError naming the column and listing the available ones."""
    if name not in data:
        raise ValueError(f"{path} has no column '{name}'; available columns: {', '.join(data)}")
    return data[name]


def window(t, y, tmin=None, tmax=None):
    """The samples with tmin <= t <= tmax (default: the second half of the run, t >= (t[0] + t[-1]) / 2)."""
    t, y = np.asarray(t, float), np.asarray(y, float)
    if tmin is None:
        tmin = 0.5 * (t[0] + t[-1])
    if tmax is None:
        tmax = t[-1]
    keep = (t >= tmin - 1e-12 * max(1.0, abs(tmin))) & (t <= tmax + 1e-12 * max(1.0, abs(tmax)))
    keep &= np.isfinite(y) & np.isfinite(t)
    if keep.sum() < 8:
        raise ValueError(f"only {int(keep.sum())} finite samples in the window {tmin:g} <= t <= {tmax:g}")
    return t[keep], y[keep]


def uniform_series(t, y, rtol=1e-6):
    """(t, y, resampled) on a uniform grid: unchanged if the steps agree to rtol, otherwise linearly
    interpolated onto t[0] + k dt, dt the median step."""
    t, y = np.asarray(t, float), np.asarray(y, float)
    order = np.argsort(t, kind="stable")
    t, y = t[order], y[order]
    d = np.diff(t)
    dt = float(np.median(d))
    if dt <= 0:
        raise ValueError("the time column does not increase")
    if np.all(np.abs(d - dt) <= rtol * dt):
        return t, y, False
    t, first = np.unique(t, return_index=True)
    y = y[first]
    n = int(math.floor((t[-1] - t[0]) / dt + 1e-9)) + 1
    tu = t[0] + dt * np.arange(n)
    return tu, np.interp(tu, t, y), True


def hann(n):
    """The symmetric Hann window of n samples, 0 at both ends."""
    return 0.5 - 0.5 * np.cos(2 * math.pi * np.arange(n) / (n - 1))


def dtft_amplitude(t, y, freqs, detrend="mean"):
    """A(f) of the module docstring at every f of freqs (cycles per unit time): the amplitude of a sinusoid.
    t uniform (uniform_series); detrend 'mean' or 'linear' (a least-squares line removed first)."""
    t, y = np.asarray(t, float), np.asarray(y, float)
    if detrend == "linear":
        y = y - np.polyval(np.polyfit(t - t[0], y, 1), t - t[0])
    else:
        y = y - y.mean()
    w = hann(len(y))
    wy = w * y
    tc = t - t[0]
    freqs = np.atleast_1d(np.asarray(freqs, float))
    out = np.empty(freqs.shape)
    for i0 in range(0, freqs.size, 256):  # blocks: a (256 x N) complex matrix at a time
        f = freqs.ravel()[i0:i0 + 256]
        out.ravel()[i0:i0 + 256] = 2 * np.abs(np.exp(-2j * math.pi * np.outer(f, tc)) @ wy) / w.sum()
    return out


def spectrum(t, y, pad=8, detrend="mean"):
    """(f, A): the amplitude spectrum of the uniform series on the FFT grid refined pad times (zero padding),
    0 <= f <= the Nyquist frequency."""
    t, y = np.asarray(t, float), np.asarray(y, float)
    dt = (t[-1] - t[0]) / (len(t) - 1)
    if detrend == "linear":
        y = y - np.polyval(np.polyfit(t - t[0], y, 1), t - t[0])
    else:
        y = y - y.mean()
    w = hann(len(y))
    nfft = pad * len(y)
    a = 2 * np.abs(np.fft.rfft(w * y, nfft)) / w.sum()
    return np.fft.rfftfreq(nfft, dt), a


def line_amplitude(t, y, f0, band=None, detrend="mean"):
    """(A, f): the largest A(f) with |f - f0| <= band (default one resolution bin 1/T, T = t[-1] - t[0];
    band = 0 evaluates at f0 only), located by a dense scan of the band and a golden-section refinement."""
    t, y = np.asarray(t, float), np.asarray(y, float)
    T = t[-1] - t[0]
    if band is None:
        band = 1.0 / T
    if band <= 0:
        return float(dtft_amplitude(t, y, [f0], detrend)[0]), float(f0)
    lo, hi = max(0.0, f0 - band), f0 + band
    grid = np.linspace(lo, hi, max(9, int(math.ceil(16 * (hi - lo) * T)) + 1))
    a = dtft_amplitude(t, y, grid, detrend)
    k = int(np.argmax(a))
    step = grid[1] - grid[0]
    a_lo, a_hi = max(lo, grid[k] - step), min(hi, grid[k] + step)
    g = (math.sqrt(5) - 1) / 2

    def amp(f):
        return float(dtft_amplitude(t, y, [f], detrend)[0])

    c, d = a_hi - g * (a_hi - a_lo), a_lo + g * (a_hi - a_lo)
    fc, fd = amp(c), amp(d)
    for _ in range(60):
        if a_hi - a_lo <= 1e-10 * max(1.0, f0):
            break
        if fc > fd:
            a_hi, d, fd = d, c, fc
            c = a_hi - g * (a_hi - a_lo)
            fc = amp(c)
        else:
            a_lo, c, fc = c, d, fd
            d = a_lo + g * (a_hi - a_lo)
            fd = amp(d)
    best = max((a[k], grid[k]), (fc, c), (fd, d))
    return float(best[0]), float(best[1])


def background(t, y, f0, halfwidth=None, exclude=None, detrend="mean"):
    """The median of A(f) over exclude <= |f - f0| <= halfwidth (default 20 and 3 resolution bins 1/T): the
    level of the spectrum around a line, to tell a line at f0 from the broadband floor."""
    t = np.asarray(t, float)
    T = t[-1] - t[0]
    halfwidth = 20.0 / T if halfwidth is None else halfwidth
    exclude = 3.0 / T if exclude is None else exclude
    f = np.linspace(max(0.0, f0 - halfwidth), f0 + halfwidth, int(16 * 2 * halfwidth * T) + 1)
    f = f[np.abs(f - f0) >= exclude]
    return float(np.median(dtft_amplitude(t, y, f, detrend)))


def relative_amplitude(t, y, f0, band=None, detrend="mean"):
    """(A / |mean|, f): line_amplitude at f0 relative to the mean of y over the same samples. For Roller's
    columns: the cogging of the contact force is relative_amplitude(t, force, f_e)."""
    a, f = line_amplitude(t, y, f0, band, detrend)
    return a / abs(float(np.mean(y))), f


def strongest_line(t, y, fmin=None, fmax=None, detrend="mean"):
    """(A, f): the largest line of the spectrum with fmin <= f <= fmax (default fmin = 3/T, beyond the main
    lobe of what is left at f = 0 by a drift of the mean; fmax the Nyquist frequency), refined as in
    line_amplitude."""
    t, y = np.asarray(t, float), np.asarray(y, float)
    T = t[-1] - t[0]
    f, a = spectrum(t, y, detrend=detrend)
    if fmin is None:
        fmin = 3.0 / T
    sel = (f >= fmin) & (f <= (fmax if fmax is not None else f[-1]))
    if not sel.any():
        raise ValueError(f"no frequency in [{fmin:g}, {fmax}]")
    k = np.flatnonzero(sel)[np.argmax(a[sel])]
    return line_amplitude(t, y, f[k], band=2 * (f[1] - f[0]), detrend=detrend)


def element_passing_frequency(omega, h, r_outer):
    """f_e = omega r_C / h, cycles per unit time (module docstring)."""
    return abs(omega) * r_outer / h


def omega_from_theta(t, theta):
    """omega as the least-squares slope of theta(t) (theta = omega t for steady rolling), or None."""
    t, theta = np.asarray(t, float), np.asarray(theta, float)
    ok = np.isfinite(t) & np.isfinite(theta)
    if ok.sum() < 2 or np.ptp(t[ok]) == 0:
        return None
    return float(np.polyfit(t[ok], theta[ok], 1)[0])


def flicker(n, within=3):
    """Step-to-step changes of an integer series (contact_nodes): a dict with 'changes' (steps where it
    changes), 'reversals' (consecutive changes of opposite sign, e.g. a node on then off, at most `within`
    steps apart: the flicker), 'immediate' (reversals in successive steps: on at step k, off at k + 1) and
    'max_jump' (the largest change in one step). Steady rolling changes the count regularly too, as nodes
    enter and leave the contact zone: about 2 (P1) or 4 (P2) f_e changes per unit time; the flicker is what
    exceeds that, and the immediate reversals."""
    n = np.asarray(n, float)
    d = np.diff(n)
    idx = np.flatnonzero(d != 0)
    gaps = np.diff(idx)
    flips = np.sign(d[idx[:-1]]) != np.sign(d[idx[1:]])
    return {"changes": int(idx.size), "reversals": int(np.sum(flips & (gaps <= within))), "within": within,
            "immediate": int(np.sum(flips & (gaps == 1))), "max_jump": int(np.abs(d).max()) if d.size else 0}


def summary(t, y, f_e=None, band=None, detrend="mean"):
    """The numbers of rollerplots.spectrum --table for one series in its window: mean, std/mean, largest
    |y - mean|/mean, the line at f_e (and 2 f_e: P2 has nodes every h/2) relative to the mean and to the
    background level around it, the strongest line."""
    t, y = np.asarray(t, float), np.asarray(y, float)
    m = float(np.mean(y))
    s = {"tmin": float(t[0]), "tmax": float(t[-1]), "samples": int(len(t)), "dt": float((t[-1] - t[0]) / (len(t) - 1)),
         "mean": m, "std_rel": float(np.std(y) / abs(m)) if m else math.nan,
         "maxdev_rel": float(np.abs(y - m).max() / abs(m)) if m else math.nan}
    a, f = strongest_line(t, y, detrend=detrend)
    s["strongest_f"], s["strongest_amp"] = f, a
    s["strongest_rel"] = a / abs(m) if m else math.nan
    if f_e:
        for key, mult in (("fe", 1), ("2fe", 2)):
            # 2 f_e is sought about twice the f_e found: a nominal f_e from a rounded h is off twice as much there
            f0 = mult * (s["fe_f"] if mult == 2 and "fe_f" in s else f_e)
            if f0 < 0.5 / s["dt"]:
                a, f = line_amplitude(t, y, f0, band, detrend)
                s[key] = mult * f_e
                s[key + "_f"], s[key + "_amp"] = f, a
                s[key + "_rel"] = a / abs(m) if m else math.nan
                s[key + "_over_background"] = a / background(t, y, f0, detrend=detrend)
    return s
