"""Reference modes of the free rotating annulus, one circumferential Fourier order at a time (docs/squeal.md section 2).

Plane strain, linear isotropic elasticity (Lame lam = E nu/((1+nu)(1-2nu)), mu = E/(2(1+nu))), density rho,
annulus r_i < r < r_o clamped (xi = 0) at r_i and traction-free at r_o, rotation speed Omega = theta', optional
Kelvin-Voigt viscosity tau (sigma = C : (eps + tau eps_t)). The static centrifugal prestress is dropped (linear
problem, no geometric stiffness), as in the 2D code's modes.

Co-rotating frame (xi = Cartesian components in the rotating basis), modes xi = e^{lambda t} xhat(x):
  lambda^2 rho xhat - 2 lambda Omega rho R(-pi/2) xhat + tau lambda (-div sigma[xhat]) + (-div sigma[xhat] - rho Omega^2 xhat) = 0,
  R(-pi/2)(a, b) = (b, -a), i.e. e_r -> -e_phi, e_phi -> e_r in polar components.
Lab (Eulerian) frame, u(y, t) = R(theta) xi(R(-theta) y, t) at fixed lab points, D/Dt = d/dt + Omega d_phi with
d_phi = y1 d/dy2 - y2 d/dy1 acting on the Cartesian components; modes u = e^{lambda t} uhat:
  lambda^2 rho uhat + 2 lambda Omega rho d_phi uhat + Omega^2 rho d_phi d_phi uhat - div sigma[uhat]
    - tau div sigma[(lambda + Omega d_phi) uhat] = 0        (--lab-viscosity material, the default)
  weak form of rho Omega^2 d_phi d_phi u: -rho Omega^2 int d_phi u . d_phi v (d_phi is divergence-free and
  tangent to both circles, so it is skew in L2).
  NOTE on tau in the lab frame: (d/dt + Omega d_phi) u = R xi_t + Omega J u (J = R(pi/2): the lab components
  also turn with the basis), so eps[(d/dt + Omega d_phi) u] is NOT R eps[xi_t] R^T: a deformation that is
  steady in the rotating frame (xi_t = 0) gets the viscous stress tau Omega C : eps[J u] != 0 from it. The
  rate that equals the rotating frame's Kelvin-Voigt term (objective: docs/model.md says a rigid motion
  dissipates nothing) is (d/dt + Omega d_phi - Omega J) u: --lab-viscosity objective. With tau = 0 the two
  are the same problem.

One Fourier order: polar components xhat_r = U(r) e^{i m phi}, xhat_phi = V(r) e^{i m phi} (U, V complex,
m signed: m and -m are different travelling waves once Omega != 0). Strain of (U, V) e^{i m phi}:
  eps_rr = U',  eps_pp = (U + i m V)/r,  2 eps_rp = i m U/r + V' - V/r.
The 2D energy integrated over phi (the 2 pi dropped) gives the Hermitian forms, weighted by r dr:
  k_m(x, y) = int [(lam + 2mu)(eps_rr conj(eps_rr') + eps_pp conj(eps_pp')) + lam (eps_rr conj(eps_pp')
               + eps_pp conj(eps_rr')) + mu (2eps_rp) conj(2eps_rp')] r dr     (traction-free r_o: natural)
  m(x, y)   = int rho (U conj(U') + V conj(V')) r dr
Coriolis: R(-pi/2)(U, V) = (V, -U), g(x, y) = int rho (V conj(U') - U conj(V')) r dr (real skew: G).
Lab: d_phi on Cartesian components of (U e_r + V e_phi) e^{i m phi} is, in polar components,
  D_m (U, V) = (i m U - V, i m V + U) = (i m + J)(U, V), J(U, V) = (-V, U) = R(pi/2) = -R(-pi/2),
  gyroscopic int rho D_m x . conj(y) r dr = (M (x) D_m), convective stiffness int rho D_m x . conj(D_m y) r dr
  = (M (x) D_m^H D_m), D_m^H D_m = [[m^2+1, 2im], [-2im, m^2+1]] (D_m^H = -D_m).
Discrete (x = the nodal values of (U, V)): lambda^2 M + lambda C + K~ = 0 with
  rotating: C = -2 Omega G + tau K_m,                       K~ = K_m - Omega^2 M
  lab:      C = 2 Omega (M (x) D_m) + tau K_m,               K~ = K_m - Omega^2 (M (x) D_m^H D_m) + tau Omega K_m D_m
            (objective: the last term is tau Omega K_m (D_m - J) = i m tau Omega K_m)
D_m acts pointwise on (U, V) with constant coefficients, so it maps the discrete space into itself and
(lambda_lab + Omega D_m)^2 = (lambda_lab + i m Omega + Omega J)^2 = (lambda_rot - Omega R(-pi/2))^2 holds exactly
in the discrete problem too: lambda_lab = lambda_rot - i m Omega (tau = 0, or --lab-viscosity objective).
K(-m) = conj(K(m)) and M, G, tau are real: the eigenvalues of -m are the conjugates of those of m; the pair
(lambda, m), (conj lambda, -m) is one real motion, so each signed m keeps its eigenvalues with Im > 0.

Space: Galerkin with ONE spectral element of degree n in r (Lagrange basis on Chebyshev-Lobatto points, the
Dirichlet node at r_i removed; --inner free keeps it: a free-free annulus, for the thin-ring check), Gauss-
Legendre with n + 32 points (exact for the r-weighted polynomial terms, spectrally accurate for the 1/r ones).
The eigenfunctions are analytic on [r_i, r_o], so the eigenvalues converge exponentially in n (--verify).
Quadratic eigenproblem: inverted companion linearization mu = 1/lambda,
  [[0, I], [-K~^-1 M, -K~^-1 C]] (x, mu x) = mu (x, mu x),
whose dominant eigenvalues are the low modes (computed to full relative accuracy), scipy.linalg.eig.

Bryan's effect (first order in Omega, rotating frame, tau = 0): with (K_m - w0^2 M) x0 = 0 (Hermitian),
lambda = i w0 + Omega lambda1 + O(Omega^2), and x0^H (2 i w0 lambda1 M - 2 i w0 G) x0 = 0 gives
  lambda1 = x0^H G x0 / x0^H M x0,  x0^H G x0 = int rho (V conj U - U conj V) r dr = 2 i int rho Im(conj(U) V) r dr,
  w(m) = w0 + g_m Omega,  g_m = 2 int rho Im(conj(U) V) r dr / int rho (|U|^2 + |V|^2) r dr,  g_{-m} = -g_m.
With Omega > 0, m = n > 0 is the backward wave, so w_b - w_f = w(n) - w(-n) = 2 gamma_n Omega, gamma_n = g_n
(> 0 for the annulus: the pattern of a standing mode precesses against the rotation, Bryan 1890).
Thin inextensible ring (hand check): eps_pp = (U + i n V)/r = 0 gives U = -i n V, Im(conj(U) V) = n |V|^2,
|U|^2 + |V|^2 = (n^2+1)|V|^2, so gamma_n = 2n/(n^2+1) (--verify: a free-free ring r_i = 0.495 r_o).

Exact n = 0, Omega = 0 modes (U and V decouple):
  torsion   mu (V'' + V'/r - V/r^2) + rho w^2 V = 0, V = A J1(kr) + B Y1(kr), k = w/c_s, c_s^2 = mu/rho;
            V(r_i) = 0, V'(r_o) - V(r_o)/r_o = -k (A J2 + B Y2)(k r_o) = 0  =>  J1(k r_i) Y2(k r_o) = Y1(k r_i) J2(k r_o)
  breathing (lam+2mu)(U'' + U'/r - U/r^2) + rho w^2 U = 0, U = A J1 + B Y1, k = w/c_p, c_p^2 = (lam+2mu)/rho;
            U(r_i) = 0, sigma_rr = (lam+2mu) U' + lam U/r = (lam+2mu) k Z0(k r_o) - 2mu Z1(k r_o)/r_o = 0 (Z = J, Y).

Output (the 2D code's modes CSV, docs/squeal.md section 2, plus m): one row per eigenvalue lambda = re + i im with im > 0:
`re,im,frequency,growth_rate,order,wave,m`, frequency = im, growth_rate = re, order = |m|; the motion
Re(xhat e^{lambda t}) ~ e^{i(m phi + im t)} travels toward -sign(m) phi, so wave = forward (with the rotation)
iff m Omega < 0, backward iff m Omega > 0, standing if Omega == 0 or m == 0. Sorted by frequency.
--count K keeps, per signed m, the K eigenvalues of smallest |lambda| (the lowest frequencies when tau = 0).
Python: eigenvalues(p, m, frame) (all, Im > 0, by |lambda|), modes(p, orders, frame, count) -> rows,
bryan_gamma(n, p), torsion_exact(p), breathing_exact(p), verify(p).
"""
import argparse
import sys

import numpy as np
import scipy.linalg as sla
from scipy.optimize import brentq
from scipy.special import jv, yv

DEFAULTS = dict(young=0.1, poisson=0.49, density=1.0, omega=np.pi / 10, r_inner=0.25, r_outer=0.5,
                viscosity=0.0, n=32)


def lame(p):
    E, nu = p["young"], p["poisson"]
    return E * nu / ((1 + nu) * (1 - 2 * nu)), E / (2 * (1 + nu))


def params(p=None, **kw):
    q = dict(DEFAULTS, **(p or {}))
    q.update(kw)
    return q


class Basis:
    """Lagrange basis of degree n on Chebyshev-Lobatto points of [r_i, r_o] at n + 32 Gauss points:
    phi, dphi (nq x nb; the node r_i dropped unless inner == 'free'), r, the weights w (no r factor)."""

    def __init__(self, p, inner="clamped"):
        n = int(p["n"])
        ri, ro = p["r_inner"], p["r_outer"]
        h, rm = (ro - ri) / 2, (ro + ri) / 2
        s = -np.cos(np.pi * np.arange(n + 1) / n)
        bw = (-1.0) ** np.arange(n + 1)
        bw[0] *= 0.5
        bw[-1] *= 0.5
        dif = s[:, None] - s[None, :]
        np.fill_diagonal(dif, 1.0)
        D = (bw[None, :] / bw[:, None]) / dif
        np.fill_diagonal(D, 0.0)
        np.fill_diagonal(D, -D.sum(axis=1))
        sq, wq = np.polynomial.legendre.leggauss(n + 32)
        c = bw[None, :] / (sq[:, None] - s[None, :])
        L = c / c.sum(axis=1, keepdims=True)
        keep = slice(0, None) if inner == "free" else slice(1, None)
        self.phi, self.dphi = L[:, keep], (L @ D)[:, keep] / h
        self.r, self.w = rm + h * sq, h * wq
        self.nodes = (rm + h * s)[keep]
        self.nb = self.phi.shape[1]


def matrices(p, m, inner="clamped"):
    """M (rho included), K_m (complex Hermitian), G (real skew, the Coriolis form) on x = (U nodes, V nodes)."""
    lam, mu = lame(p)
    b = Basis(p, inner)
    r, wr, phi, dphi, nb = b.r, b.w * b.r, b.phi, b.dphi, b.nb
    Z = np.zeros_like(phi)
    Brr = np.hstack([dphi, Z])                                            # eps_rr
    Bpp = np.hstack([phi / r[:, None], 1j * m * phi / r[:, None]])        # eps_pp
    Bg = np.hstack([1j * m * phi / r[:, None], dphi - phi / r[:, None]])  # 2 eps_rp

    def form(A, B):                                                       # int conj(A_i) B_j r dr
        return A.conj().T @ (wr[:, None] * B)
    K = (lam + 2 * mu) * (form(Brr, Brr) + form(Bpp, Bpp)) + lam * (form(Brr, Bpp) + form(Bpp, Brr)) \
        + mu * form(Bg, Bg)
    K = (K + K.conj().T) / 2
    Mm = p["density"] * (phi.T @ (wr[:, None] * phi))
    O = np.zeros((nb, nb))
    M = np.block([[Mm, O], [O, Mm]])
    G = np.block([[O, Mm], [-Mm, O]])                                     # (P x, y), P(U, V) = (V, -U)
    return M, K, G, b


def quadratic(p, m, frame="rotating", lab_viscosity="material", inner="clamped"):
    """(M, C, K~) of lambda^2 M + lambda C + K~ for the signed order m."""
    om, tau = p["omega"], p["viscosity"]
    M, K, G, b = matrices(p, m, inner)
    nb = b.nb
    if frame == "rotating":
        return M, -2 * om * G + tau * K, K - om * om * M, b
    I, O = np.eye(nb), np.zeros((nb, nb))
    Dm = np.block([[1j * m * I, -I], [I, 1j * m * I]])                    # d_phi on the nodal (U, V)
    Jm = np.block([[O, -I], [I, O]])
    Mm = M[:nb, :nb]
    Gl = np.block([[1j * m * Mm, -Mm], [Mm, 1j * m * Mm]])                # int rho D_m x . conj(y)
    Mdd = np.block([[(m * m + 1) * Mm, 2j * m * Mm], [-2j * m * Mm, (m * m + 1) * Mm]])
    rate = Dm if lab_viscosity == "material" else Dm - Jm
    return M, 2 * om * Gl + tau * K, K - om * om * Mdd + tau * om * K @ rate, b


def solve_quadratic(M, C, Kt, vectors=False):
    """All eigenvalues (and x) of lambda^2 M + lambda C + Kt, by the inverted companion (mu = 1/lambda)."""
    N = M.shape[0]
    lu = sla.lu_factor(Kt)
    A = np.block([[np.zeros((N, N)), np.eye(N)], [-sla.lu_solve(lu, M), -sla.lu_solve(lu, C)]])
    if vectors:
        mu, Z = sla.eig(A)
        return 1 / mu, Z[:N]
    return 1 / sla.eigvals(A)


def eigenvalues(p, m, frame="rotating", lab_viscosity="material", inner="clamped", tol=1e-10):
    """The eigenvalues with Im > tol |lambda| of the signed order m, sorted by |lambda| (= by frequency when
    tau = 0; with tau > 0 this puts the overdamped modes, which accumulate at lambda = -1/tau and get a
    small Im from the rotation, after the oscillating low modes instead of first)."""
    lam = solve_quadratic(*quadratic(p, m, frame, lab_viscosity, inner)[:3])
    lam = lam[lam.imag > tol * np.abs(lam)]
    return lam[np.argsort(np.abs(lam))]


def wave(m, omega):
    if omega == 0 or m == 0:
        return "standing"
    return "forward" if m * omega < 0 else "backward"


def parse_orders(s):
    out = []
    for part in s.split(","):
        a, _, b = part.partition("-")
        out += list(range(int(a), int(b) + 1)) if b else [int(a)]
    return sorted(set(abs(o) for o in out))


def modes(p, orders, frame="rotating", count=2, lab_viscosity="material"):
    """Rows (re, im, frequency, growth_rate, order, wave, m): the K smallest |lambda| of each signed m, sorted
    by frequency."""
    rows = []
    for n in orders:
        for m in ([0] if n == 0 else [n, -n]):
            for lam in eigenvalues(p, m, frame, lab_viscosity)[:count]:
                rows.append((lam.real, lam.imag, lam.imag, lam.real, abs(m), wave(m, p["omega"]), m))
    return sorted(rows, key=lambda row: (row[2], row[6]))


def write_csv(rows, f):
    f.write("re,im,frequency,growth_rate,order,wave,m\n")
    for re, im, fr, g, o, w, m in rows:
        f.write(f"{re:.17g},{im:.17g},{fr:.17g},{g:.17g},{o},{w},{m}\n")


def bryan_gamma(n, p=None, index=0, inner="clamped", shape=False):
    """gamma_n = g_n = 2 int rho Im(conj(U) V) r dr / int rho (|U|^2 + |V|^2) r dr of the index-th Omega = 0
    mode of order n (m = +n); the rotating frame's first-order splitting is w_b - w_f = 2 gamma_n Omega.
    Returns gamma (and w0, (nodes, U, V) if shape)."""
    p = params(p)
    M, K, _, b = matrices(p, n, inner)
    w2, X = sla.eigh(K, M)
    rigid = 1 if inner == "free" and abs(n) <= 1 else 0                  # free-free: rotation (0), translation (1)
    k = rigid + index
    x = X[:, k]
    nb = b.nb
    Uq, Vq = b.phi @ x[:nb], b.phi @ x[nb:]
    wr = b.w * b.r * p["density"]
    g = 2 * np.sum(wr * np.imag(Uq.conj() * Vq)) / np.sum(wr * (np.abs(Uq) ** 2 + np.abs(Vq) ** 2))
    if shape:
        return g, np.sqrt(w2[k]), (b.nodes, x[:nb], x[nb:])
    return g


def _roots(f, kmax, count):
    ks = np.linspace(1e-3, kmax, 20000)
    fs = f(ks)
    out = []
    for i in np.flatnonzero(np.sign(fs[:-1]) != np.sign(fs[1:])):
        k = brentq(f, ks[i], ks[i + 1], xtol=1e-15, rtol=1e-15)
        if abs(f(k)) < 1e-6 * (abs(fs[i]) + abs(fs[i + 1])):               # a root, not a pole
            out.append(k)
    return out[:count]


def torsion_exact(p=None, count=3):
    """Angular frequencies of the n = 0 torsional modes at Omega = 0: J1(k r_i) Y2(k r_o) = Y1(k r_i) J2(k r_o)."""
    p = params(p)
    lam, mu = lame(p)
    ri, ro = p["r_inner"], p["r_outer"]
    f = lambda k: jv(1, k * ri) * yv(2, k * ro) - yv(1, k * ri) * jv(2, k * ro)
    return np.array(_roots(f, 60 / (ro - ri), count)) * np.sqrt(mu / p["density"])


def breathing_exact(p=None, count=3):
    """Angular frequencies of the n = 0 radial (breathing) modes at Omega = 0 (U = A J1 + B Y1, k = w/c_p)."""
    p = params(p)
    lam, mu = lame(p)
    ri, ro, C = p["r_inner"], p["r_outer"], lam + 2 * mu
    s = lambda Z, k: C * k * Z(0, k * ro) - 2 * mu * Z(1, k * ro) / ro
    f = lambda k: jv(1, k * ri) * s(yv, k) - yv(1, k * ri) * s(jv, k)
    return np.array(_roots(f, 60 / (ro - ri), count)) * np.sqrt(C / p["density"])


def verify(p=None, count=2, out=sys.stdout):
    """Print the checks of the module docstring; returns a dict of the numbers (the unit test reads it)."""
    p = params(p)
    res = {}
    pr = lambda s: print(s, file=out, flush=True)
    lam, mu = lame(p)
    pr(f"parameters: E = {p['young']}, nu = {p['poisson']}, rho = {p['density']}, r = [{p['r_inner']}, "
       f"{p['r_outer']}], Omega = {p['omega']:.12g}, tau = {p['viscosity']}, degree n = {p['n']}; "
       f"lam = {lam:.12g}, mu = {mu:.12g}")
    # 1. convergence in the degree: the lowest `count` of each signed m = -4..4, both frames
    degs, nref = [8, 10, 12, 16, 24, 32], 40
    pr(f"1. convergence in the degree n (max over m = -4..4, the lowest {count}, of |dlambda|/|lambda| "
       f"against n = {nref}; the floor ~1e-11 is rounding), rotating frame, Omega = {p['omega']:.6g}, tau = {p['viscosity']}:")
    ref = {m: eigenvalues(params(p, n=nref), m)[:count] for m in range(-4, 5)}
    conv = []
    for d in degs:
        e = max(np.max(np.abs(eigenvalues(params(p, n=d), m)[:count] - ref[m]) / np.abs(ref[m]))
                for m in range(-4, 5))
        conv.append(e)
        pr(f"   n = {d:3d} ({2 * d} unknowns): {e:.2e}")
    res["convergence"] = dict(zip(degs, conv))
    # 2./3. n = 0 at Omega = 0 against the Bessel roots
    p0 = params(p, omega=0.0, viscosity=0.0)
    lam0 = eigenvalues(p0, 0)
    num = np.sort(lam0.imag)
    for name, exact in (("torsion", torsion_exact(p0)), ("breathing", breathing_exact(p0))):
        errs = [np.min(np.abs(num - w)) / w for w in exact]
        res[name] = (exact, errs)
        pr(f"2. n = 0 {name}, Omega = 0: exact w = " + ", ".join(f"{w:.12f}" for w in exact)
           + f" (periods " + ", ".join(f"{2 * np.pi / w:.6f}" for w in exact) + ")"
           + "; relative error of the nearest discrete: " + ", ".join(f"{e:.1e}" for e in errs))
    # 4. frame shift
    worst = 0.0
    for m in range(-4, 5):
        lr = eigenvalues(params(p, viscosity=0.0), m)[:6]
        ll = solve_quadratic(*quadratic(params(p, viscosity=0.0), m, "lab")[:3])
        for z in lr:
            worst = max(worst, np.min(np.abs(ll - (z - 1j * m * p["omega"]))) / abs(z))
    res["shift"] = worst
    pr(f"3. frame shift, tau = 0, Omega = {p['omega']:.6g}: max over m = -4..4 (lowest 6) of "
       f"min|lambda_lab - (lambda_rot - i m Omega)|/|lambda_rot| = {worst:.2e}")
    tau = p["viscosity"] or 0.0115
    pv = params(p, viscosity=tau)
    dev = {"objective": 0.0, "material": 0.0}
    for m in range(-4, 5):
        lr = eigenvalues(pv, m)[:2] - 1j * m * p["omega"]
        for kind in dev:
            ll = solve_quadratic(*quadratic(pv, m, "lab", kind)[:3])
            dev[kind] = max(dev[kind], max(np.min(np.abs(ll - z)) / abs(z.real) for z in lr))
    res["shift_tau"] = dev
    pr(f"   with tau = {tau:g}: max (lowest 2, m = -4..4) of min|lambda_lab - (lambda_rot - i m Omega)|/|Re lambda_rot|"
       f" = {dev['objective']:.2e} (--lab-viscosity objective), {dev['material']:.2e} (material: not frame-equivalent)")
    # 5. Bryan splitting at small Omega
    om = 1e-4
    pr(f"4. splitting at Omega = {om:g} (rotating frame, tau = 0) against 2 gamma_n Omega (lowest mode per n):")
    res["split"] = {}
    for n in range(1, 5):
        ps = params(p, omega=om, viscosity=0.0)
        wb, wf = eigenvalues(ps, n)[0].imag, eigenvalues(ps, -n)[0].imag
        g = bryan_gamma(n, p)
        rel = abs((wb - wf) - 2 * g * om) / abs(2 * g * om)
        res["split"][n] = (g, wb - wf, rel)
        pr(f"   n = {n}: gamma_n = {g:.10f}, w_b - w_f = {wb - wf:.10e}, 2 gamma_n Omega = {2 * g * om:.10e}, "
           f"relative difference {rel:.1e}")
    # 6. thin free-free ring: gamma_n -> 2n/(n^2+1)
    pt = params(p, r_inner=0.99 * p["r_outer"], n=16)
    res["ring"] = {}
    pr(f"5. thin free-free ring r_i = 0.99 r_o: gamma_n of the lowest flexural mode vs 2n/(n^2+1):")
    for n in range(2, 6):
        g = bryan_gamma(n, pt, inner="free")
        res["ring"][n] = (g, 2 * n / (n * n + 1))
        pr(f"   n = {n}: gamma_n = {g:.6f}, 2n/(n^2+1) = {2 * n / (n * n + 1):.6f}")
    return res


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--frame", choices=["rotating", "lab"], default="rotating")
    ap.add_argument("--orders", default="0-4", help="circumferential orders n, e.g. 0-4 or 1,3 (both signs of m)")
    ap.add_argument("--count", type=int, default=2, help="eigenvalues kept per signed m (smallest |lambda|: the lowest frequencies if tau = 0)")
    ap.add_argument("--lab-viscosity", choices=["material", "objective"], default="material",
                    help="the lab frame's Kelvin-Voigt rate: (d/dt + Omega d_phi) u, or minus Omega J u")
    for k, v in DEFAULTS.items():
        ap.add_argument("--" + k.replace("_", "-"), type=int if k == "n" else float, default=v)
    ap.add_argument("--csv", default="-")
    ap.add_argument("--verify", action="store_true", help="print the checks of the docstring")
    a = ap.parse_args(argv)
    p = {k: getattr(a, k) for k in DEFAULTS}
    if a.verify:
        verify(p, a.count)
        return
    rows = modes(p, parse_orders(a.orders), a.frame, a.count, a.lab_viscosity)
    f = sys.stdout if a.csv == "-" else open(a.csv, "w")
    write_csv(rows, f)
    if f is not sys.stdout:
        f.close()


if __name__ == "__main__":
    main()
