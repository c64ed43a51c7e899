"""Frequency and growth rate of a mode from a transient run (docs/squeal.md section 4).

A run seeded with one mode (`roller -initial_condition mode -initial_mode_file m.h5 -initial_mode j
-output run.h5 -output_every N`) should oscillate at that mode's eigenvalue lambda = growth + i w. This
module reads the run's HDF5 output (docs/output.md) and measures it three ways:

(a) the rotating probe: the radial displacement xi . e_r at one vertex of Gamma_C (r = r_outer) in the
    co-rotating frame; its frequency is the strongest line of the Hann-windowed DTFT (rollerreport.spectrum).
(b) the order-n projection: the Fourier coefficients along Gamma_C of the radial and tangential displacement,
    c_m(t) = 1/(2 pi) int xi_r(phi, t) e^{-i m phi} dphi (and the same for xi_phi), trapezoidal in the vertex
    angles. For a real field Re(Z e^{i m phi} e^{lambda t}), c_m(t) = Z/2 e^{lambda t} exactly and c_-m
    holds the conjugate: a travelling mode (n >= 1) is a single complex exponential in c_n, with
    e^{-i w t} if it travels forward (with the rotation, dominant order -n) and e^{+i w t} backward. lambda is
    fitted by a matrix pencil (both components together, a few extra poles for the constant steady state and
    small other content); for a travelling mode also by least squares on log|c_n| and the unwrapped phase.
(c) the lab probe: the radial displacement at a FIXED lab point Phi0 of Gamma_C. The lab displacement
    displacement_lab = R(theta)(x + xi) - x holds the rigid rotation; R(theta) xi = displacement_lab + x -
    R(theta) x is the deformation in lab components, and its radial component at a vertex of material angle
    phi is that of xi. At time t the material point at Phi0 has the co-rotating angle phi = Phi0 - theta(t);
    the radial component is interpolated there along the circle (periodic cubic spline in the vertex angles).
    A co-rotating mode Re(Z e^{i(m phi + w t)}) is Re(Z e^{i(m Phi + (w - m theta') t)}) in the lab: its line
    is at |w - m omega|, the lab-frame eigenvalue of `roller -modes -modes_frame lab`.

The time discretization (docs/model.md section 2) shifts the frequency; `discrete_shift` gives the
first-order prediction of the DMF (three-level Newmark beta = 1/2, explicit centrifugal term, extrapolated
Coriolis velocity) for an undamped gyroscopic mode, from the mode's gyroscopic ratio g (`gyro_ratio`):

    dW/W      = -(W dt)^2 (5/12 (1 + 2 g) + omega^2/(2 W^2)) / (2 + g)      (5/24 (W dt)^2 without rotation)
    growth/W  = -(W dt)^3 g / (4 (2 + g))                                  (the explicit Coriolis velocity)
    x^H C x = i gamma (C = -2 omega rho G skew), g = gamma/(W x^H M x), |g| <= 2 omega/W

CLI: PYTHONPATH=scripts python3 -m rollerref.mode_transient run.h5 [--modes m.h5 --mode j] [--order n] [--lab-csv ml.csv] [--json]
     [--figure F.png --amplitude A]  (the probe against the eigenvalue's prediction, and its spectrum)
"""
import argparse
import json
import math
import os
import sys

import h5py
import numpy as np

from rollerreport import spectrum


# ---------------------------------------------------------------------------------------------- reading

class Run:
    """A run's HDF5 output: t [ns], x [nv, 2], xi [ns, nv, 2] (co-rotating), lab [ns, nv, 2], parameters."""

    def __init__(self, path):
        with h5py.File(path, "r") as f:
            self.x = f["geometry/vertices"][:, :2]
            self.t = f["time"][:, 0]
            self.xi = f["vertex_fields/displacement_displacement"][:, :, :2]
            self.lab = f["vertex_fields/displacement_lab_displacement"][:, :, :2]
            self.par = {k: float(np.asarray(v).ravel()[0]) for k, v in f["parameters"].attrs.items()}
        self.path = path
        self.r_outer = self.par.get("r_outer", 0.5)
        r = np.hypot(self.x[:, 0], self.x[:, 1])
        on = np.flatnonzero(np.abs(r - self.r_outer) < 1e-6 * self.r_outer)
        if on.size < 8:
            raise ValueError(f"{path}: only {on.size} vertices on r = {self.r_outer}")
        phi = np.mod(np.arctan2(self.x[on, 1], self.x[on, 0]), 2 * math.pi)
        order = np.argsort(phi)
        self.outer, self.phi = on[order], phi[order]
        # trapezoidal weights in angle (periodic), normalized to 1: c_m = sum_j w_j f_j e^{-i m phi_j}
        gap = np.diff(np.concatenate([self.phi, [self.phi[0] + 2 * math.pi]]))
        self.weight = 0.5 * (gap + np.roll(gap, 1)) / (2 * math.pi)

    def theta(self, t=None):
        """theta(t) = omega (t - t0) + a cos(b (t - t0)) (src/model/forcing.c), a before t0 > 0."""
        t = self.t if t is None else np.asarray(t, float)
        p = self.par
        s = t - p.get("theta_start", 0.0)
        th = p["omega"] * s + p.get("theta_a", 0.0) * np.cos(p.get("theta_b", 0.0) * s)
        if p.get("theta_start", 0.0) > 0:
            th = np.where(s < 0, p.get("theta_a", 0.0), th)
        return th

    def polar(self):
        """(xi_r, xi_phi) [ns, nC] on Gamma_C in the co-rotating frame, vertices sorted by angle."""
        c, s = np.cos(self.phi), np.sin(self.phi)
        u = self.xi[:, self.outer, :]
        return u[..., 0] * c + u[..., 1] * s, -u[..., 0] * s + u[..., 1] * c


def read_modes_csv(path):
    """The -modes_csv file as a list of dicts (re, im, frequency, growth_rate, order, wave, error)."""
    import csv
    with open(path, newline="") as f:
        rows = list(csv.DictReader(f))
    for r in rows:
        for k in ("re", "im", "frequency", "growth_rate", "error"):
            r[k] = float(r[k])
        r["order"] = int(r["order"])
    return rows


def read_mode(path, j):
    """(lambda, shape at the vertices [nv, 2] complex, x [nv, 2], parameters) of mode j of a -modes_output file."""
    with h5py.File(path, "r") as f:
        a = f[f"modes/{j}"].attrs
        lam = complex(float(np.ravel(a["re"])[0]), float(np.ravel(a["im"])[0]))
        z = f["vertex_fields/mode_re_shape"][j, :, :2] + 1j * f["vertex_fields/mode_im_shape"][j, :, :2]
        x = f["geometry/vertices"][:, :2]
        cells = f["viz/topology/cells"][:]
        par = {k: float(np.asarray(v).ravel()[0]) for k, v in f["parameters"].attrs.items()}
    return lam, z, x, cells, par


# ---------------------------------------------------------------------------------------------- estimators

def component(run, which="radial"):
    """xi_r or xi_phi [ns, nC] on Gamma_C (co-rotating); 'auto': the one that moves more (std in time), e.g.
    the tangential one for the n = 0 torsional mode, whose radial motion is 250 times smaller."""
    ur, up = run.polar()
    if which == "auto":
        which = "radial" if ur.std(0).mean() >= up.std(0).mean() else "tangential"
    return (ur if which == "radial" else up), which


def probe_rotating(run, phi0=0.0, which="radial"):
    """(t, xi_r (or xi_phi)) at the Gamma_C vertex nearest the co-rotating angle phi0, and that vertex's index."""
    k = int(np.argmin(np.abs(np.angle(np.exp(1j * (run.phi - phi0))))))
    u, _ = component(run, which)
    return run.t, u[:, k], run.outer[k]


def steady_part(run, u, lam):
    """The constant of the least-squares fit u_j(t) = s_j + e^{g t}(a_j cos w t + b_j sin w t), lam = g + i w, at
    every Gamma_C vertex j: the steady centrifugal state, constant in the co-rotating frame."""
    t = run.t - run.t[0]
    e = np.exp(lam.real * t)
    B = np.stack([np.ones_like(t), e * np.cos(lam.imag * t), e * np.sin(lam.imag * t)], 1)
    return np.linalg.lstsq(B, u, rcond=None)[0][0]


def probe_lab(run, Phi0=0.0, which="radial", steady=None):
    """(t, radial (or tangential) displacement at the fixed lab angle Phi0 of Gamma_C) from displacement_lab
    (module doc, (c)). steady [nC]: a co-rotating constant per Gamma_C vertex (steady_part) removed before the
    interpolation: the steady state of the rotation is axisymmetric only up to the mesh, and its mesh-scale
    variation along Gamma_C would pass the fixed lab point at multiples of omega (2.5 % of the torsional mode's
    tangential amplitude at h = 0.05, with a line at 2 omega next to its frequency)."""
    from scipy.interpolate import CubicSpline
    th = run.theta()
    xo = run.x[run.outer]
    out = np.empty(run.t.size)
    for k in range(run.t.size):
        c, s = math.cos(th[k]), math.sin(th[k])
        Rx = np.stack([c * xo[:, 0] - s * xo[:, 1], s * xo[:, 0] + c * xo[:, 1]], 1)
        d = run.lab[k, run.outer, :] + xo - Rx            # R(theta) xi, lab components
        ang = run.phi + th[k]                             # lab angle of each vertex
        if which == "radial":
            dr = d[:, 0] * np.cos(ang) + d[:, 1] * np.sin(ang)
        else:
            dr = -d[:, 0] * np.sin(ang) + d[:, 1] * np.cos(ang)
        if steady is not None:
            dr = dr - steady
        sp = CubicSpline(np.concatenate([run.phi, [run.phi[0] + 2 * math.pi]]), np.concatenate([dr, [dr[0]]]),
                         bc_type="periodic")
        out[k] = sp(np.mod(Phi0 - th[k] - run.phi[0], 2 * math.pi) + run.phi[0])
    return run.t, out


def dtft_frequency(t, y, w_guess=None, tmin=None):
    """(w, amplitude): the strongest line of the Hann-windowed DTFT (rollerreport.spectrum), in rad per time unit;
    near w_guess (within 15 %) if given. Window: t >= tmin (default the whole run)."""
    t, y = spectrum.window(t, y, t[0] if tmin is None else tmin, t[-1])
    t, y, _ = spectrum.uniform_series(t, y)
    if w_guess:
        f0 = w_guess / (2 * math.pi)
        a, f = spectrum.strongest_line(t, y, fmin=0.85 * f0, fmax=1.15 * f0)
    else:
        a, f = spectrum.strongest_line(t, y)
    return 2 * math.pi * f, a


def fourier_coefficients(run, m):
    """(c_m of xi_r, c_m of xi_phi) [ns] complex (module doc, (b))."""
    ur, up = run.polar()
    e = run.weight * np.exp(-1j * m * run.phi)
    return ur @ e, up @ e


def matrix_pencil(t, channels, order=12, pencil=None):
    """Poles lambda_k and amplitudes [channels, order] of sum_k a_k e^{lambda_k t} fitted to the uniform samples
    of every channel together (Hua and Sarkar's matrix pencil, SVD truncated to `order`)."""
    t = np.asarray(t, float)
    dt = float(np.median(np.diff(t)))
    Y = [np.asarray(c, complex) for c in channels]
    N = t.size
    L = pencil or N // 3
    H = np.vstack([np.array([y[i:i + L + 1] for i in range(N - L)]) for y in Y])
    _, s, Vh = np.linalg.svd(H, full_matrices=False)
    V = Vh[:order].conj().T                               # (L+1) x order
    V1, V2 = V[:-1], V[1:]
    z = np.linalg.eigvals(np.linalg.pinv(V1) @ V2)
    lam = np.log(z) / dt
    B = np.exp(np.outer(t - t[0], lam))
    amp = np.array([np.linalg.lstsq(B, y, rcond=None)[0] for y in Y])
    return lam, amp


def fit_log_phase(t, c):
    """lambda = growth + i w of a single complex exponential c(t) = C e^{lambda t}: least squares on log|c| and
    the unwrapped phase."""
    t = np.asarray(t, float)
    g = np.polyfit(t, np.log(np.abs(c)), 1)[0]
    w = np.polyfit(t, np.unwrap(np.angle(c)), 1)[0]
    return complex(g, w)


def order_of(run, nmax=12):
    """The circumferential order n of the motion about the mean state: the largest power of xi_r, xi_phi (minus
    their time means) over the orders 0..nmax."""
    ur, up = run.polar()
    ur, up = ur - ur.mean(0), up - up.mean(0)
    p = [np.sum(np.abs(ur @ (run.weight * np.exp(-1j * m * run.phi))) ** 2 + np.abs(up @ (run.weight * np.exp(-1j * m * run.phi))) ** 2)
         for m in range(nmax + 1)]
    return int(np.argmax(p))


def projection_eigenvalue(run, n, tmin=None, order=12, decimate=None):
    """The order-n projection's eigenvalue (module doc, (b)): a dict with lambda (growth + i w, w >= 0, by the
    matrix pencil), the travelling direction ('forward', 'backward' or 'standing': the sign of the phase
    velocity of c_n relative to the rotation), and lambda by the log/phase fit for travelling modes."""
    t = run.t
    keep = slice(None) if tmin is None else (t >= tmin)
    cr, cp = fourier_coefficients(run, n)
    t, cr, cp = t[keep], cr[keep], cp[keep]
    if decimate is None:
        decimate = max(1, t.size // 1500)
    t, cr, cp = t[::decimate], cr[::decimate], cp[::decimate]
    lam, amp = matrix_pencil(t, [cr, cp], order=order)
    size = np.sqrt((np.abs(amp) ** 2).sum(0))
    osc = np.abs(lam.imag) > 1e-3 * max(1e-12, np.abs(lam).max())
    if not osc.any():
        raise ValueError("no oscillating pole in the projection")
    k = np.flatnonzero(osc)[np.argmax(size[osc])]
    res = {"n": n, "lambda": complex(lam[k].real, abs(lam[k].imag)), "pole_signed": complex(lam[k]),
           "amplitude": float(size[k]), "poles": [complex(v) for v in lam], "pole_amplitudes": [float(v) for v in size]}
    omega = run.par.get("omega", 0.0)
    res["wave"] = "standing"
    if n > 0:
        other = [i for i in np.flatnonzero(osc) if i != k and abs(abs(lam[i].imag) - abs(lam[k].imag)) < 1e-3 * abs(lam[k].imag)]
        conj_size = max([size[i] for i in other], default=0.0)
        if conj_size < size[k] / 3 and omega != 0:
            # c_n ~ e^{-i w t}: dominant order -n, forward for omega > 0
            res["wave"] = ("forward" if lam[k].imag < 0 else "backward") if omega > 0 else ("backward" if lam[k].imag < 0 else "forward")
            big = cr if np.abs(cr).mean() >= np.abs(cp).mean() else cp
            lp = fit_log_phase(t, big)
            res["lambda_logphase"] = complex(lp.real, abs(lp.imag))
    return res


# ---------------------------------------------------------------------------------------------- prediction

def gyro_ratio(z, x, cells, lam, omega, rho=1.0):
    """g = gamma/(W m) of the mode shape z [nv, 2] (complex vertex values): m = rho int |z|^2, x^H C x = i gamma,
    C = -2 omega rho G, G = (R(-pi/2) u, v): gamma = -4 omega rho int Im(conj(z1) z2). Integrals of the P1
    interpolant of the vertex values (exact P1 mass on the straight triangles): an approximation of the P2 field's."""
    p = x[cells]
    area = 0.5 * np.abs((p[:, 1, 0] - p[:, 0, 0]) * (p[:, 2, 1] - p[:, 0, 1]) - (p[:, 2, 0] - p[:, 0, 0]) * (p[:, 1, 1] - p[:, 0, 1]))
    Mloc = (np.ones((3, 3)) + np.eye(3)) / 12.0

    def inner(a, b):  # int conj(a) b for P1 scalar fields
        A, B = a[cells], b[cells]
        return np.sum(area * np.einsum("ci,ij,cj->c", A.conj(), Mloc, B))

    m = rho * (inner(z[:, 0], z[:, 0]) + inner(z[:, 1], z[:, 1])).real
    gamma = -4 * omega * rho * inner(z[:, 0], z[:, 1]).imag
    W = abs(lam.imag)
    return gamma / (W * m)


def discrete_shift(W, omega, dt, g):
    """(dW/W, growth/W) of the DMF for an undamped mode of frequency W with gyroscopic ratio g (module doc)."""
    a = (W * dt) ** 2
    return (-a * (5.0 / 12 * (1 + 2 * g) + omega ** 2 / (2 * W ** 2)) / (2 + g),
            -(W * dt) ** 3 * g / (4 * (2 + g)))


def shift_bound(W, omega, dt):
    """max |dW/W| over the admissible |g| <= min(2 omega/W, 1.9): a bound on the time-discretization shift that
    needs no mode shape."""
    gmax = min(2 * abs(omega) / W, 1.9)
    gs = np.linspace(-gmax, gmax, 401)
    return float(max(abs(discrete_shift(W, omega, dt, g)[0]) for g in gs)), \
        float(max(abs(discrete_shift(W, omega, dt, g)[1]) for g in gs))


def lab_frequency(w, n, wave, omega):
    """|w - m omega| of a co-rotating mode of order n: m = -n forward, +n backward (docs/squeal.md section 4)."""
    m = {"forward": -n, "backward": n}.get(wave, 0)
    return abs(w - m * omega)


def analyse(run_path, modes_path=None, mode=None, n=None, lab_csv=None, tmin=None, phi0=0.0, Phi0=-math.pi / 2, which="auto"):
    """Everything the CLI prints, as a dict."""
    run = Run(run_path)
    out = {"run": run_path, "dt": run.par.get("dt"), "omega": run.par.get("omega"), "samples": int(run.t.size),
           "T": float(run.t[-1] - run.t[0])}
    lam = z = None
    if modes_path is not None and mode is not None:
        lam, z, xm, cells, mpar = read_mode(modes_path, mode)
        out["eigenvalue"] = [lam.real, lam.imag]
        if n is None:
            with h5py.File(modes_path, "r") as f:
                n = int(np.ravel(f[f"modes/{mode}"].attrs["order"])[0])
    if n is None:
        n = order_of(run)
    out["order"] = n
    wg = abs(lam.imag) if lam is not None else None
    t, y, vertex = probe_rotating(run, phi0, which)
    out["probe_component"] = component(run, which)[1]
    out["probe_w"], out["probe_amp"] = dtft_frequency(t, y, wg, tmin)
    pr = projection_eigenvalue(run, n, tmin)
    out["lambda"] = [pr["lambda"].real, pr["lambda"].imag]
    out["wave"] = pr["wave"]
    if "lambda_logphase" in pr:
        out["lambda_logphase"] = [pr["lambda_logphase"].real, pr["lambda_logphase"].imag]
    omega = run.par.get("omega", 0.0)
    wl = lab_frequency(pr["lambda"].imag, n, pr["wave"], omega)
    u, comp = component(run, which)
    tl, yl = probe_lab(run, Phi0, comp, steady_part(run, u, pr["lambda"]))
    out["lab_probe_w"], out["lab_probe_amp"] = dtft_frequency(tl, yl, wl, tmin)
    out["lab_expected_from_rotating"] = wl
    if lam is not None:
        W, dt = abs(lam.imag), run.par["dt"]
        out["rel_error"] = (pr["lambda"].imag - W) / W
        out["probe_rel_error"] = (out["probe_w"] - W) / W
        out["wdt2_12"] = (W * dt) ** 2 / 12
        out["shift_bound"], out["growth_bound"] = shift_bound(W, omega, dt)
        if run.par.get("viscosity", 0.0) == 0 and run.par.get("damping", 0.0) == 0:
            g = gyro_ratio(z, xm, cells, lam, omega, run.par.get("density", 1.0))
            out["gyro_ratio"] = g
            out["predicted_rel_shift"], out["predicted_growth_over_w"] = discrete_shift(W, omega, dt, g)
    if lab_csv:
        rows = read_modes_csv(lab_csv)
        cand = [r for r in rows if r["order"] == n]
        if cand:
            best = min(cand, key=lambda r: abs(r["frequency"] - wl))
            out["lab_eigen_w"] = best["frequency"]
            out["lab_rel_error"] = (out["lab_probe_w"] - best["frequency"]) / best["frequency"]
    return out


def figure(run_path, modes_path, mode, out, amplitude=1e-3, which="auto", phi0=0.0):
    """The probe signal against the eigenvalue's prediction steady + A Re(z_probe e^{lambda t}) (whole run, and
    its last fifth), and the probe's spectrum with the eigenfrequency marked."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    run = Run(run_path)
    lam, z, _, _, _ = read_mode(modes_path, mode)
    u, comp = component(run, which)
    t, y, v = probe_rotating(run, phi0, comp)
    k = int(np.flatnonzero(run.outer == v)[0])
    ph = run.phi[k]
    e = np.array([math.cos(ph), math.sin(ph)]) if comp == "radial" else np.array([-math.sin(ph), math.cos(ph)])
    zp = z[v] @ e
    s0 = steady_part(run, u, lam)[k]
    pred = s0 + amplitude * np.real(zp * np.exp(lam * (t - t[0])))
    a = analyse(run_path, modes_path, mode, which=which)
    fig, ax = plt.subplots(3, 1, figsize=(8, 9))
    for i, (lo, hi) in enumerate(((t[0], t[-1]), (t[-1] - (t[-1] - t[0]) / 5, t[-1]))):
        sel = (t >= lo) & (t <= hi)
        ax[i].plot(t[sel], y[sel], "-", lw=1.2, label=f"roller, dt = {run.par['dt']:g}")
        ax[i].plot(t[sel], pred[sel], "--", lw=1.2, label=f"steady + A Re(z e^(lambda t)), lambda = {lam.real:.2g} + {lam.imag:.6f} i")
        ax[i].set_xlabel("t")
        ax[i].set_ylabel(f"xi_{'r' if comp == 'radial' else 'phi'} at phi = {math.degrees(ph):.0f} deg")
    ax[0].set_title(f"mode {mode} (order {a['order']}, {a['wave']}): measured {a['lambda'][1]:.6f} "
                    f"({a['rel_error']:+.2e}; predicted shift {a.get('predicted_rel_shift', math.nan):+.2e})", fontsize=10)
    ax[0].legend(fontsize=8, loc="upper right")
    tt, yy, _ = spectrum.uniform_series(t, y)
    f, A = spectrum.spectrum(tt, yy, pad=32)
    w = 2 * math.pi * f
    sel = w <= 3 * abs(lam.imag)
    ax[2].semilogy(w[sel], A[sel], "-", lw=1)
    ax[2].axvline(abs(lam.imag), color="C1", ls="--", label=f"eigenfrequency {abs(lam.imag):.6f}")
    ax[2].axvline(a["probe_w"], color="C2", ls=":", label=f"DTFT line {a['probe_w']:.6f}")
    ax[2].set_xlabel("angular frequency (rad per time unit)")
    ax[2].set_ylabel("amplitude (Hann)")
    ax[2].legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(out, dpi=110)
    return a


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("run", help="the transient's -output HDF5 file")
    ap.add_argument("--modes", help="the -modes_output file the run was seeded from (co-rotating)")
    ap.add_argument("--mode", type=int, help="the mode's row (-initial_mode)")
    ap.add_argument("--order", type=int, help="circumferential order n (default: the mode's, or the run's dominant)")
    ap.add_argument("--lab-csv", help="the -modes_csv of -modes_frame lab, to compare the lab probe with")
    ap.add_argument("--tmin", type=float, help="analyse t >= tmin only")
    ap.add_argument("--component", default="auto", choices=["auto", "radial", "tangential"],
                    help="the probes' displacement component (auto: the one that moves more)")
    ap.add_argument("--figure", help="write the probe/prediction/spectrum figure here (needs --modes, --mode)")
    ap.add_argument("--amplitude", type=float, default=1e-3, help="the run's -ic_amplitude (for the figure's prediction)")
    ap.add_argument("--json", action="store_true", help="print JSON")
    a = ap.parse_args(argv)
    if a.figure:
        figure(a.run, a.modes, a.mode, a.figure, a.amplitude, a.component)
    out = analyse(a.run, a.modes, a.mode, a.order, a.lab_csv, a.tmin, which=a.component)
    if a.json:
        print(json.dumps(out, indent=1, default=str))
        return 0
    for k, v in out.items():
        print(f"{k:28s} {v}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
