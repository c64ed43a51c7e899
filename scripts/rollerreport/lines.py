"""The lines of a seeded transient: which are the seeded mode's and which are the mesh's (docs/squeal.md 7.7).

The contact patch stands still in the lab and the mesh turns through it at omega, so the N vertices of Gamma_C
cross it at the mesh-passing frequency f_m = omega N / (2 pi) = omega r_outer / h. Each time one enters or
leaves the patch the contact set (and the contact force) steps: lines at f_m and its harmonics whatever dt is, a
discretization artefact, not a mode (the printer roller: N = 524, f_m = 1587.9 Hz; at the jam the contact force's
loudest line, 0.06 N/m on 104.5 N/m). The report removes them before it fits the seeded mode and before it plays
the force, and fits the mode on the monitor column that carries it (alpha, the mean tangential displacement of
Gamma_C, for an order-0 mode at the jam, where the friction force is mu N and hardly moves).
"""
import math

import numpy as np

CARRIERS = ("contact_force", "friction_force", "alpha", "R")


def mesh_passing(h5):
    """f_m = omega N / (2 pi) in cycles per unit time of the run (N: the vertices on the outer circle), or None."""
    try:
        import h5py

        with h5py.File(h5, "r") as f:
            par = f["parameters"].attrs
            omega, r_outer = float(par["omega"]), float(par["r_outer"])
            x = f["geometry/vertices"][:]
    except (OSError, KeyError, ImportError):
        return None
    n = int(np.sum(np.abs(np.hypot(x[:, 0], x[:, 1]) - r_outer) < 1e-6 * r_outer))
    return abs(omega) * n / (2 * math.pi) if omega and n else None


def notch(t, y, f_m, keep=None, width=0.1, f_max=None):
    """y - mean(y) without the lines k f_m, k = 1, 2, ... (|f - k f_m| < width f_m), except a harmonic within
    width f_m of `keep` (the seeded mode's frequency: never removed), and without what lies above f_max (when given).
    Filtered as its even extension (y then y reversed), so that a growing or decaying series does not ring where the
    FFT wraps around."""
    y = np.asarray(y, float) - np.mean(y)
    if not f_m and not f_max:
        return y
    n = len(y)
    F = np.fft.rfft(np.concatenate([y, y[::-1]]))  # the even extension: no jump where the FFT wraps around
    f = np.fft.rfftfreq(2 * n, t[1] - t[0])
    for k in range(1, int(f[-1] / f_m) + 2) if f_m else ():
        if keep is None or abs(keep - k * f_m) >= width * f_m:
            F[np.abs(f - k * f_m) < width * f_m] = 0
    if f_max:
        F[f > f_max] = 0
    return np.fft.irfft(F, 2 * n)[:n]


def band_share(t, y, f0, band=0.2):
    """The fraction of y's variance within band f0 of f0 (y mean-free)."""
    P = np.abs(np.fft.rfft(y)) ** 2
    f = np.fft.rfftfreq(len(y), t[1] - t[0])
    total = P[1:].sum()
    return float(P[np.abs(f - f0) < band * f0].sum() / total) if total > 0 else 0.0


def is_mesh_line(f, f_m, tol=0.02):
    """The harmonic k of f_m that f is (within tol of k f_m), or 0."""
    if not f_m or not f:
        return 0
    k = max(1, int(round(f / f_m)))
    return k if abs(f / (k * f_m) - 1) < tol else 0


def carrier(t, cols, f0, f_m):
    """(column, its mesh-free signal): of the monitor's columns, the one whose variance, mesh lines removed, lies most
    within 20 % of the seeded mode's frequency f0."""
    best = None
    for name in CARRIERS:
        if name in cols and np.all(np.isfinite(cols[name])) and np.ptp(cols[name]) > 0:
            y = notch(t, cols[name], f_m, keep=f0)
            share = band_share(t, y, f0)
            if best is None or share > best[2]:
                best = (name, y, share)
    return best[:2] if best else (None, None)
