"""Reference solution for the rotating annulus WITHOUT obstacle (docs/model.md sections 1, 2, 4, 5).

For an axisymmetric displacement xi = u(r,t) e_r + v(r,t) e_phi the model (P) of docs/model.md section 1 is exactly
(R(-pi/2) maps e_r -> -e_phi, e_phi -> e_r; theta(t) = omega t + a cos(b t)):

  rho u_tt = (lam+2mu)(u_rr + u_r/r - u/r^2) + rho( theta'' v + theta'^2 (r+u) + 2 theta' v_t )
  rho v_tt =       mu (v_rr + v_r/r - v/r^2) + rho(-theta'' (r+u) + theta'^2 v - 2 theta' u_t )
  u = v = 0 at r = r_i;  sigma_rr = (lam+2mu) u_r + lam u/r = 0, sigma_rphi = mu (v_r - v/r) = 0 at r = r_o;
  u = v = u_t = v_t = 0 at t = 0;   R(t) = u(r_o, t), alpha(t) = v(r_o, t)   (docs/model.md section 4).

Space: Galerkin with ONE spectral element of degree n (Lagrange basis on Chebyshev-Lobatto points, Dirichlet
node at r_i removed), weak form weighted by r dr, i.e. the 2D energy restricted to axisymmetric fields:
  a_u(u,w) = int [(lam+2mu)(u_r w_r + u w/r^2) + lam (u_r w + u w_r)/r] r dr   (natural BC sigma_rr = 0)
  a_v(v,w) = int mu (v_r - v/r)(w_r - w/r) r dr                                 (natural BC sigma_rphi = 0)
  m(u,w)   = int rho u w r dr,  Gauss-Legendre with n+24 points (exact for m, spectrally accurate for 1/r).
With x = (U, V), P(U, V) = (V, -U) (= R(-pi/2)) and x_r = (r, 0) (the position, exact in the space):
  M x'' + K x = theta'' M P (x_r + x) + theta'^2 M (x_r + x) + 2 theta' M P x'.
--scheme exact: exact in time. theta' = omega: the state is diagonalised once (modal(): B z' = H z + F with
  B SPD and H skew, Hermitian eigen-problem) and evaluated as a sum of exp(-i mu_j t), no time stepping.
  a b != 0: plus the perturbation (theta' - omega, theta''), integrated in the modal basis by DOP853 below
  --cutoff (rad/s; non-stiff there) and in closed form (Duhamel, exponential load) above it.
  Accuracy: the suddenly applied load rho theta'^2 r does not vanish at r_i, so u_tt jumps across P (and S)
  fronts and the convergence in n is algebraic, ~n^-2.2 for R: n = 256 gives ~1e-9 in R, ~1e-11 in alpha.
  --verify prints the change between n and 2n, the static state against its closed form
  u = -r + A J1(kr) + B Y1(kr), k^2 = rho omega^2/(lam+2mu) (and the classical Lame disk, which drops the
  rho omega^2 u term), and the modes carrying R and alpha (periods vs the paper's 4d/c).
--scheme dmf: the same semi-discretization advanced by the paper's DMF exactly as docs/model.md section 2 writes it:
  rho M (x^k - 2x^{k-1} + x^{k-2})/dt^2 = -K (x^k + x^{k-2})/2 + rho M f^{k-1},  x^{-1} = x^0 = 0,
  f^{k-1} with theta', theta'' at t_{k-1} (analytic, as src/model/forcing.c), rigid part loaded exactly, Coriolis
  velocity --coriolis backward (x^{k-1}-x^{k-2})/dt [paper], extrapolated (3x^{k-1}-4x^{k-2}+x^{k-3})/(2dt)
  or centered (x^k-x^{k-2})/(2dt) (implicit), as -coriolis_velocity of the 2D code. --start symmetric
  replaces the paper's x^{-1} = x^0 (a dt/2 time shift of the suddenly loaded response: first order) by
  x^{-1} = x^1, i.e. (2 rho M/dt^2 + K) x^1 = rho M f^0 (zero centred initial velocity).
Output: CSV `t,R,alpha` (%.17g) at t = k dt_out.  Python: reference(params, times) -> (R, alpha).
"""
import argparse
import sys

import numpy as np
import scipy.linalg as sla
from scipy.integrate import solve_ivp
from scipy.special import jv, yv

DEFAULTS = dict(young=0.1, poisson=0.49, density=1.0, omega=np.pi / 10, theta_a=0.0, theta_b=0.0,
                r_inner=0.25, r_outer=0.5, n=256, cutoff=100.0)


def lame(p):
    E, nu = p["young"], p["poisson"]
    return E * nu / ((1 + nu) * (1 - 2 * nu)), E / (2 * (1 + nu))


def rates(p, t):
    """theta'(t), theta''(t) for theta = omega t + a cos(b t)."""
    a, b = p["theta_a"], p["theta_b"]
    return p["omega"] - a * b * np.sin(b * t), -a * b * b * np.cos(b * t)


class Radial:
    """Spectral Galerkin semi-discretization: M (rho included), K, the rotation P and x_r on 2n unknowns."""

    def __init__(self, p):
        self.p, n = p, int(p["n"])
        lam, mu = lame(p)
        ri, ro = p["r_inner"], p["r_outer"]
        h, rm = (ro - ri) / 2, (ro + ri) / 2
        s = -np.cos(np.pi * np.arange(n + 1) / n)                    # Chebyshev-Lobatto, ascending
        w = (-1.0) ** np.arange(n + 1)
        w[0] *= 0.5
        w[-1] *= 0.5                                                # barycentric weights
        dif = s[:, None] - s[None, :]
        np.fill_diagonal(dif, 1.0)
        D = (w[None, :] / w[:, None]) / dif                         # differentiation matrix
        np.fill_diagonal(D, 0.0)
        np.fill_diagonal(D, -D.sum(axis=1))
        sq, wq = np.polynomial.legendre.leggauss(n + 24)
        c = w[None, :] / (sq[:, None] - s[None, :])
        L = c / c.sum(axis=1, keepdims=True)                        # l_j(sq), sq never equals a node
        phi, dphi = L[:, 1:], (L @ D)[:, 1:] / h                    # drop the Dirichlet node r_i
        r, wr = rm + h * sq, h * wq

        def gram(f, g, wt):
            return f.T @ (wt[:, None] * g)
        Mm = p["density"] * gram(phi, phi, wr * r)
        Ku = (lam + 2 * mu) * (gram(dphi, dphi, wr * r) + gram(phi, phi, wr / r)) \
            + lam * (gram(phi, dphi, wr) + gram(dphi, phi, wr))
        sv = dphi - phi / r[:, None]
        Kv = mu * gram(sv, sv, wr * r)
        Z = np.zeros((n, n))
        self.n, self.nodes = n, rm + h * s[1:]
        self.M = np.block([[Mm, Z], [Z, Mm]])
        self.K = np.block([[Ku, Z], [Z, Kv]])
        self.xr = np.concatenate([self.nodes, np.zeros(n)])
        self.iR, self.iA = n - 1, 2 * n - 1                         # u(r_o), v(r_o)

    def P(self, x):
        n = self.n
        return np.concatenate([x[n:], -x[:n]])

    def load(self, td, tdd):
        """M (theta'^2 x_r + theta'' P x_r): the rigid part of rho (f, w), exact."""
        return self.M @ (td * td * self.xr + tdd * self.P(self.xr))


def modal(m):
    """Eigen-decomposition of the system at theta' = omega. With K~ = K - omega^2 M (SPD below the
    centrifugal limit), G = -2 omega M P (skew) and z = (x, x'): B z' = H z + F, B = diag(K~, M) SPD,
    H = [[0, K~], [-K~, -G]] skew, F = (0, omega^2 M x_r). With B = L L^T, S = L^-1 H L^-T is real skew and
    i S = Q diag(mu) Q^H (eigh, Q unitary): w = Q^H L^T z decouples, w' = -i mu w + Q^H L^-1 F."""
    om, N = m.p["omega"], 2 * m.n
    Kt = m.K - om * om * m.M
    Z, MP = np.zeros((N, N)), m.M @ np.vstack([m.P(e) for e in np.eye(N)]).T
    H = np.block([[Z, Kt], [-Kt, 2 * om * MP]])
    try:
        L = np.linalg.cholesky(np.block([[Kt, Z], [Z, m.M]]))
    except np.linalg.LinAlgError:
        sys.exit(f"omega = {om} is beyond the centrifugal-softening limit (K - omega^2 M not SPD)")
    S = sla.solve_triangular(L, sla.solve_triangular(L, H, lower=True).T, lower=True).T
    mu, Q = np.linalg.eigh(1j * (S - S.T) / 2)
    proj = lambda v: Q.conj().T @ sla.solve_triangular(L, v, lower=True)     # Q^H L^-1 v
    zero = np.zeros(N)
    return dict(mu=mu, L=L, Q=Q, MP=MP, proj=proj, fa=proj(np.concatenate([zero, m.M @ m.xr])),
                fb=proj(np.concatenate([zero, MP @ m.xr])),
                rows=np.array([proj(np.eye(2 * N)[i]).conj() for i in (m.iR, m.iA)]),   # e_i^T L^-T Q
                xs=np.linalg.solve(Kt, om * om * m.M @ m.xr))


def exact_modal(m, times, md=None):
    """theta' = omega: z = z_s + L^-T Q diag(exp(-i mu t)) Q^H L^T (z(0) - z_s), exact in t."""
    md = md or modal(m)
    om, mu = m.p["omega"], md["mu"]
    E = np.exp(-1j * np.outer(np.asarray(times), mu))
    w = om * om * md["fa"] / (1j * mu)                              # w(t) = w_s (1 - exp(-i mu t))
    R, al = ((E @ (-md["rows"][k] * w)).real + md["xs"][i] for k, i in enumerate((m.iR, m.iA)))
    modes = sorted((2 * np.pi / mu[j], 2 * abs(md["rows"][0, j] * w[j]), 2 * abs(md["rows"][1, j] * w[j]))
                   for j in range(len(mu)) if mu[j] > 0)
    return R, al, md["xs"], modes


def perturbation(m, md, times, cutoff):
    """Effect of a b != 0, added to exact_modal: c1 = theta'', c2 = theta'^2 - omega^2, c3 = 2(theta'-omega)
    load M(c2 x_r + c1 P x_r) and couple through c1 M P x + c2 M x + c3 M P x'. In the modes |mu| < cutoff
    the coupled system for dw = w - w_omega is integrated by DOP853 (rtol 1e-12, non-stiff); above it the
    (tiny) coupling is dropped and the exponential load is integrated in closed form (Duhamel)."""
    p, om, mu, Q, L = m.p, m.p["omega"], md["mu"], md["Q"], md["L"]
    a, b, N = p["theta_a"], p["theta_b"], 2 * m.n
    J = np.abs(mu) < cutoff
    Phi = sla.solve_triangular(L.T, Q[:, J], lower=False)           # L^-T Q_J
    Z, MP = np.zeros((N, N)), md["MP"]
    C = [md["proj"](np.block([[Z, Z], blk]) @ Phi)[J] for blk in ([MP, Z], [m.M, Z], [Z, MP])]
    muJ, fa, fb, wsJ = mu[J], md["fa"][J], md["fb"][J], om * om * md["fa"][J] / (1j * mu[J])

    def coeffs(t):
        td, tdd = rates(p, t)
        return tdd, td * td - om * om, 2 * (td - om)

    def rhs(t, dw):
        c1, c2, c3 = coeffs(t)
        w = wsJ * (1 - np.exp(-1j * muJ * t)) + dw
        return -1j * muJ * dw + c1 * (C[0] @ w) + c2 * (C[1] @ w) + c3 * (C[2] @ w) + c2 * fa + c1 * fb
    sol = solve_ivp(rhs, (0.0, float(np.max(times))), np.zeros(J.sum(), complex), method="DOP853",
                    t_eval=times, rtol=1e-12, atol=1e-16 * max(1.0, np.abs(wsJ).max()))
    assert sol.success, sol.message
    dR, dA = (md["rows"][k][J] @ sol.y for k in (0, 1))
    # above the cutoff: dw_j' = -i mu_j dw_j + sum_nu g_nu e^{i nu t}, c1 and c2 as exponentials
    muH, faH, fbH = mu[~J], md["fa"][~J], md["fb"][~J]
    for nu, g1, g2 in ((b, -a * b * b / 2, 1j * om * a * b), (-b, -a * b * b / 2, -1j * om * a * b),
                       (0.0, 0.0, a * a * b * b / 2), (2 * b, 0.0, -a * a * b * b / 4), (-2 * b, 0.0, -a * a * b * b / 4)):
        g = (g1 * fbH + g2 * faH) / (1j * (nu + muH))
        ph = np.exp(1j * nu * times)[:, None] - np.exp(-1j * np.outer(times, muH))
        dR, dA = dR + ph @ (md["rows"][0][~J] * g), dA + ph @ (md["rows"][1][~J] * g)
    return dR.real, dA.real


def exact_ivp(m, times):
    """Cross-check only (stiff, slow): the whole system x'' = -M^-1 K x + theta'' P(x_r+x)
    + theta'^2 (x_r+x) + 2 theta' P x' by DOP853."""
    N, MK = 2 * m.n, np.linalg.solve(m.M, m.K)

    def rhs(t, z):
        td, tdd = rates(m.p, t)
        x, y = z[:N], z[N:]
        return np.concatenate([y, -MK @ x + tdd * m.P(m.xr + x) + td * td * (m.xr + x) + 2 * td * m.P(y)])
    sol = solve_ivp(rhs, (0.0, float(np.max(times))), np.zeros(2 * N), method="DOP853", t_eval=times,
                    rtol=1e-12, atol=1e-15)
    assert sol.success, sol.message
    return sol.y[m.iR], sol.y[m.iA]


def dmf(m, times, dt, coriolis="backward", start="paper"):
    """docs/model.md section 2 on the radial semi-discretization; returns R, alpha at the steps nearest to times."""
    p, M, K = m.p, m.M, m.K
    ks = np.rint(np.asarray(times) / dt).astype(int)
    if not np.allclose(ks * dt, times, atol=1e-9 * dt + 1e-12):
        sys.exit("dmf: the sample times (--dt-out) must be multiples of --dt")
    Pm = np.vstack([m.P(e) for e in np.eye(2 * m.n)]).T
    A0 = M / dt**2 + K / 2
    varying = p["theta_a"] * p["theta_b"] != 0
    fac = None if coriolis == "centered" else sla.cho_factor(A0)
    x1 = np.zeros(2 * m.n)                                          # x^{k-1}
    if start == "symmetric":                                        # x^{-1} = x^1: zero centred velocity
        x2 = np.linalg.solve(2 * M / dt**2 + K, m.load(*rates(p, 0.0)))
    else:
        x2 = np.zeros(2 * m.n)                                      # x^{-1} = x^0 = 0 (the paper's start)
    x3 = 4 * x2                                                     # x^{-2} (extrapolated): x^{-2} = x^2
    R, al = np.empty(len(ks)), np.empty(len(ks))
    want = {k: i for i, k in enumerate(ks)}
    for k in range(0, ks.max() + 1):
        if k in want:
            R[want[k]], al[want[k]] = x1[m.iR], x1[m.iA]
        td, tdd = rates(p, k * dt)                                  # t_{k-1} for the step to x^{k+1}
        if coriolis == "backward":
            c = tdd * x1 + 2 * td * (x1 - x2) / dt
        elif coriolis == "extrapolated":
            c = tdd * x1 + td * (3 * x1 - 4 * x2 + x3) / dt
        else:
            c = tdd * x1 - td * x2 / dt
        b = M @ ((2 / dt**2 + td * td) * x1 - x2 / dt**2 + m.P(c)) - K @ x2 / 2 + m.load(td, tdd)
        if coriolis == "centered":
            if fac is None or varying:
                fac = sla.lu_factor(A0 - td / dt * M @ Pm)
            x = sla.lu_solve(fac, b)
        else:
            x = sla.cho_solve(fac, b)
        x1, x2, x3 = x, x1, x2
    return R, al


def reference(params=None, times=None, scheme="exact", dt=None, coriolis="backward", start="paper"):
    """(R, alpha) at `times` for params (keys of DEFAULTS; missing ones take the paper's Table 1 values)."""
    p = dict(DEFAULTS, **(params or {}))
    times = np.arange(0, 20 + 1e-9, 0.0125) if times is None else np.asarray(times, dtype=float)
    m = Radial(p)
    if scheme == "dmf":
        return dmf(m, times, dt if dt else 0.0125, coriolis, start)
    md = modal(m)
    R, al = exact_modal(m, times, md)[:2]
    if p["theta_a"] * p["theta_b"] != 0:
        dR, dA = perturbation(m, md, times, p["cutoff"])
        R, al = R + dR, al + dA
    return R, al


def static_closed_form(p, r):
    """u_s(r): (lam+2mu)(u'' + u'/r - u/r^2) + rho omega^2 (r + u) = 0, u(r_i) = 0, sigma_rr(r_o) = 0.
    Returns (with the rho omega^2 u term: Bessel form; without it: classical Lame disk)."""
    lam, mu = lame(p)
    ri, ro, C = p["r_inner"], p["r_outer"], lam + 2 * mu
    k = np.sqrt(p["density"] * p["omega"] ** 2 / C)
    d1 = lambda f, z: (f(0, z) - f(1, z) / z) * k                   # d/dr f1(k r)
    Ab = np.linalg.solve([[jv(1, k * ri), yv(1, k * ri)],
                          [C * d1(jv, k * ro) + lam * jv(1, k * ro) / ro, C * d1(yv, k * ro) + lam * yv(1, k * ro) / ro]],
                         [ri, C + lam])                            # u = -r + A J1 + B Y1
    bessel = -r + Ab[0] * jv(1, k * r) + Ab[1] * yv(1, k * r)
    q = k * k                                                       # Lame: u = -q r^3/8 + A r + B/r
    Al = np.linalg.solve([[ri, 1 / ri], [C + lam, (lam - C) / ro**2]],
                         [q * ri**3 / 8, q * (3 * C + lam) * ro**2 / 8])
    return bessel, -q * r**3 / 8 + Al[0] * r + Al[1] / r


def verify(p, times):
    """Print n -> 2n convergence, the static check and the modes (stderr)."""
    out = sys.stderr
    R1, A1 = reference(p, times)
    R2, A2 = reference(dict(p, n=2 * int(p["n"])), times)
    print(f"n={p['n']} -> {2 * int(p['n'])}: max|dR| = {np.abs(R2 - R1).max():.3e}, "
          f"max|dalpha| = {np.abs(A2 - A1).max():.3e} (max|R| = {np.abs(R2).max():.6e}, "
          f"max|alpha| = {np.abs(A2).max():.6e})", file=out)
    lam, mu = lame(p)
    d = p["r_outer"] - p["r_inner"]
    cp, cs = np.sqrt((lam + 2 * mu) / p["density"]), np.sqrt(mu / p["density"])
    print(f"paper estimates: tau_p = 4d/c_p = {4 * d / cp:.6f}, tau_s = 4d/c_s = {4 * d / cs:.6f}", file=out)
    m = Radial(p)
    _, _, xs, modes = exact_modal(m, times[:1])
    bes, lm = static_closed_form(p, m.nodes)
    print(f"static u(r_o): discrete {xs[m.iR]:.15e}, Bessel closed form {bes[-1]:.15e}, "
          f"max nodal diff {np.abs(xs[:m.n] - bes).max():.2e}; classical Lame disk {lm[-1]:.15e}; "
          f"time mean of R over the samples {R2.mean():.6e}", file=out)
    for name, col in (("R", 1), ("alpha", 2)):
        top = sorted(modes, key=lambda mo: -mo[col])[:3]
        print(f"modes of the omega={p['omega']:.6g} system, largest in {name}: " +
              ", ".join(f"period {mo[0]:.6f} amp {mo[col]:.3e}" for mo in top), file=out)
    return R1, A1


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--scheme", choices=["exact", "dmf"], default="exact")
    ap.add_argument("--dt", type=float, default=0.0125, help="DMF time step")
    ap.add_argument("--coriolis", choices=["backward", "extrapolated", "centered"], default="backward")
    ap.add_argument("--start", choices=["paper", "symmetric"], default="paper")
    for k, v in DEFAULTS.items():
        ap.add_argument("--" + k.replace("_", "-"), type=int if k == "n" else float, default=v)
    ap.add_argument("--t-end", type=float, default=20.0)
    ap.add_argument("--dt-out", type=float, default=0.0125)
    ap.add_argument("--out", default="-")
    ap.add_argument("--verify", action="store_true", help="exact: print n->2n change, static check, modes")
    a = ap.parse_args(argv)
    p = {k: getattr(a, k) for k in DEFAULTS}
    times = a.dt_out * np.arange(int(np.floor(a.t_end / a.dt_out + 1e-9)) + 1)
    if a.verify and a.scheme == "exact":
        R, al = verify(p, times)
    else:
        R, al = reference(p, times, a.scheme, a.dt, a.coriolis, a.start)
    f = sys.stdout if a.out == "-" else open(a.out, "w")
    f.write("t,R,alpha\n")
    for row in zip(times, R, al):
        f.write("%.17g,%.17g,%.17g\n" % row)
    if f is not sys.stdout:
        f.close()


if __name__ == "__main__":
    main()
