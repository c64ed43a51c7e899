"""The sound pressure at a listener radiated by the roller's surface (docs/squeal.md section 9.3).

The model, stated:

1. **Each circumferential order of the surface's normal velocity radiates as from an infinitely long circular
   cylinder** (2-D, exact, linear acoustics, free field: no baffle, no reflecting floor or frame). The roller's
   outer circle r = a moves with the normal velocity v(phi, t) = sum_n V_n(t) e^{i n phi} (lab angle phi; the
   lab-frame Fourier orders of d/dt of the radial displacement of Gamma_C). At the angular frequency w
   (time factor e^{-i w t}, k = w / c) the order n radiates the exact outgoing field

       p_n(r, phi) = i rho c V_n H_n(k r) / H_n'(k a) e^{i n phi}           (H_n = H_n^(1), Hankel)

   (Euler: -i w rho v = -dp/dr at r = a). Its specific radiation impedance is z_n = p_n(a) / V_n =
   i rho c H_n(ka) / H_n'(ka); Re z_n = rho c 2 / (pi ka |H_n'(ka)|^2) exactly (the Wronskian). The closed
   forms it is checked against (tests/rollerreport_unit.py; Morse & Ingard, Theoretical Acoustics, 7.3; Junger &
   Feit, Sound, Structures and Their Interaction, 10): the pulsating cylinder (n = 0) has the mechanical
   impedance per unit length 2 pi a z_0, resistance -> rho c (pi ka / 2) 2 pi a and -> rho c 2 pi a; the
   oscillating (rigidly translating, n = +-1) cylinder the force per unit length pi a z_1 U, whose reactance is
   the added mass rho pi a^2 (the displaced air's) for ka << 1 and resistance rho c pi^2 a (ka)^3 / 2.

2. **The roller's finite width W** (the listener on the perpendicular bisector of the axis at distance d): the
   exact 2-D field of each order is multiplied by the factor of a line of monopoles of length W against the
   infinite line, F_W = G_W / G_inf with G_W = int_{-W/2}^{W/2} e^{i k R} / (4 pi R) dz, R = sqrt(d^2 + z^2),
   G_inf = (i/4) H_0(k d) (the same integral over the whole axis). W -> infinity gives the 2-D field; W << d
   with kW << 1 the compact source: a pulsating roller radiates as a point monopole of volume velocity
   2 pi a W V, a translating one as a point dipole of force (2 rho pi a^2 W) dU/dt (the displaced plus the added
   mass), both checked. It holds where the surface velocity is uniform across the width (the plane-strain model's
   assumption), the end faces' own motion is negligible, and, for n >= 1, each slice of the roller radiates its
   order's far-field pattern toward the listener (k d >> n^2; n = 0 is exact at every k d).
3. The orders and the sheet: tangential motion of a circle (the torsional mode's alpha, the sheet's in-plane
   speed) has no normal velocity and radiates nothing in this model; the hub's vertical motion (-axle) is a rigid
   translation, order 1, already in the surface's displacement (the body's whole motion). The sheet's bending is not
   modelled.

Time series: radiate() takes the orders' displacement (metres) sampled uniformly in seconds, fades its ends in
and out (2 ms, at most 5 % of the span), goes to the frequency domain (zero-padded; numpy's e^{+i w t}: the fields
above conjugated), multiplies by i w (the velocity) and the transfer function within the audible band (20 kHz),
and returns the pressure at the listener in Pa.
"""
import math

import numpy as np
from scipy.special import hankel1, h1vp

RHO_AIR, C_AIR = 1.204, 343.2  # dry air at 20 degrees C, 101.325 kPa
P_REF = 20e-6  # Pa: 0 dB SPL
DEFAULT_LISTENER = {"distance_m": 1.0, "angle_deg": 90.0}  # ISO 7779 / ECMA-74 bystander distance; 90: above the
# roller, away from the sheet (the sheet is the obstacle below it, at angle -90)


def impedance(n, ka):
    """Specific radiation impedance z_n / (rho c) = i H_n(ka) / H_n'(ka) of order n (e^{-i w t})."""
    ka = np.asarray(ka, float)
    return 1j * hankel1(n, ka) / h1vp(n, ka)


def pressure_2d(n, k, a, r, rho=RHO_AIR, c=C_AIR):
    """p_n(r) / V_n: the exact 2-D pressure at radius r per unit normal velocity amplitude of order n (e^{-i w t},
    the angular factor e^{i n phi} left out)."""
    k = np.asarray(k, float)
    return 1j * rho * c * hankel1(n, k * r) / h1vp(n, k * a)


def line_integral(k, d, W, nodes=64):
    """G_W = int_{-W/2}^{W/2} e^{i k R} / (4 pi R) dz, R = sqrt(d^2 + z^2), for an array of k (Gauss-Legendre in
    panels of at most a quarter wavelength)."""
    k = np.atleast_1d(np.asarray(k, float))
    kmax = float(np.max(np.abs(k))) if k.size else 0.0
    panels = max(1, int(math.ceil(kmax * W / (0.5 * math.pi))))
    x, w = np.polynomial.legendre.leggauss(nodes)
    edges = np.linspace(0.0, W / 2, panels + 1)
    z = np.concatenate([0.5 * (edges[i + 1] - edges[i]) * x + 0.5 * (edges[i + 1] + edges[i]) for i in range(panels)])
    wz = np.concatenate([0.5 * (edges[i + 1] - edges[i]) * w for i in range(panels)])
    R = np.sqrt(d * d + z * z)
    return 2.0 * (np.exp(1j * np.outer(k, R)) / (4 * math.pi * R)) @ wz  # symmetric in z


def width_factor(k, d, W):
    """F_W = G_W / G_inf: the finite width's factor on the 2-D field (1 for W = inf; k > 0)."""
    k = np.atleast_1d(np.asarray(k, float))
    if not math.isfinite(W):
        return np.ones(k.shape, complex)
    return line_integral(k, d, W) / (0.25j * hankel1(0, k * d))


def transfer(n, k, a, d, W, rho=RHO_AIR, c=C_AIR):
    """The pressure at the listener (distance d, on the bisector) per unit normal velocity of order n
    (e^{-i w t}; the angular factor left out): the 2-D field times the width factor."""
    return pressure_2d(n, k, a, d, rho, c) * width_factor(k, d, W)


def taper(n, m):
    """A window of n samples rising over its first m and falling over its last m (half Hann), 1 between."""
    w = np.ones(n)
    if m > 0:
        ramp = 0.5 - 0.5 * np.cos(np.pi * (np.arange(m) + 0.5) / m)
        w[:m], w[n - m :] = ramp, ramp[::-1]
    return w


def radiate(t, orders, a, d, W, angle_deg=90.0, rho=RHO_AIR, c=C_AIR, fade=2e-3, fmax=20e3):
    """The pressure (Pa) at the listener from the orders' radial displacement of the surface.

    t: uniform times in s; orders: {n: (cos part, sin part)} of the lab-frame radial displacement (m),
    w(phi, t) = w0 + sum_n c_n(t) cos(n phi) + s_n(t) sin(n phi) (n = 0: one series, the sin part None); a: the
    roller's outer radius (m); d, W: the listener's distance and the roller's width (m); angle_deg: the
    listener's direction in the lab (90: above). Each series' mean is removed (a static deformation is silent), its
    ends faded in and out over `fade` seconds (at most 5 % of the span; half Hann: the series is finite, and a cut
    would click at every frequency), zero-padded to twice its length (no wrap-around), and the audible band kept
    (f <= fmax).
    """
    t = np.asarray(t, float)
    dt = t[1] - t[0]
    N = len(t)
    M = 2 * N
    w = 2 * math.pi * np.fft.rfftfreq(M, dt)
    k = w / c
    phi = math.radians(angle_deg)
    win = taper(N, int(min(fade, 0.05 * (t[-1] - t[0])) / dt))
    band = (w > 0) & (w <= 2 * math.pi * fmax)
    P = np.zeros(len(w), complex)
    for n, (cn, sn) in orders.items():
        # the order's displacement at the listener's angle, its velocity, the transfer (conjugated: numpy's e^{+iwt})
        y = np.asarray(cn, float) * (math.cos(n * phi) if n else 1.0)
        if n and sn is not None:
            y = y + np.asarray(sn, float) * math.sin(n * phi)
        Y = np.fft.rfft((y - y.mean()) * win, M)
        T = np.zeros(len(w), complex)
        T[band] = np.conj(transfer(n, k[band], a, d, W, rho, c))
        P += T * 1j * w * Y
    return np.fft.irfft(P, M)[:N]


def a_weighting_db(f):
    """IEC 61672-1 A-weighting in dB at the frequencies f (Hz): 0.0 at 1 kHz, -19.1 at 100 Hz."""
    f = np.asarray(f, float)
    f2 = f * f
    ra = 12194.0**2 * f2 * f2 / ((f2 + 20.6**2) * np.sqrt((f2 + 107.7**2) * (f2 + 737.9**2)) * (f2 + 12194.0**2))
    with np.errstate(divide="ignore"):
        return 20 * np.log10(np.maximum(ra, 1e-300)) + 2.0


def a_weighted(t, p):
    """The A-weighted pressure series (the weighting applied in the frequency domain)."""
    t = np.asarray(t, float)
    F = np.fft.rfft(p)
    f = np.fft.rfftfreq(len(p), t[1] - t[0])
    g = np.zeros(len(f))
    g[1:] = 10 ** (a_weighting_db(f[1:]) / 20)
    return np.fft.irfft(F * g, len(p))


def band(t, p, f0, f1):
    """The pressure series within the band f0 <= f <= f1 (Hz; the frequency domain, zero-padded)."""
    t = np.asarray(t, float)
    n = len(p)
    F = np.fft.rfft(p, 2 * n)
    f = np.fft.rfftfreq(2 * n, t[1] - t[0])
    F[(f < f0) | (f > f1)] = 0
    return np.fft.irfft(F, 2 * n)[:n]


def level_db(p, t=None, window=0.125):
    """(Leq over the series, the loudest level over windows of `window` seconds (IEC 'fast': 125 ms; the whole
    series when shorter)) in dB re 20 uPa; -inf for silence."""
    p = np.asarray(p, float)

    def db(x):
        ms = float(np.mean(x * x)) if len(x) else 0.0
        return 10 * math.log10(ms / P_REF**2) if ms > 0 else -math.inf

    leq = db(p)
    if t is None or len(p) < 2:
        return leq, leq
    m = max(1, int(round(window / (t[1] - t[0]))))
    if m >= len(p):
        return leq, leq
    c = np.concatenate([[0.0], np.cumsum(p * p)])
    ms = (c[m:] - c[:-m]) / m
    peak = float(ms.max())
    return leq, (10 * math.log10(peak / P_REF**2) if peak > 0 else -math.inf)
