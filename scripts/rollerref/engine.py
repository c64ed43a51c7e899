"""An event-driven integrator for small mechanical systems with Coulomb contacts that stick and slip.

    M u' = f(t, q, u) - sum_j w_j F_j,   q' = u,

with n generalized coordinates q and m contacts. Contact j has the slip velocity g_j = w_j . u - V_j(t) (V_j a
prescribed belt speed, 0 between two bodies that both move) and carries the friction force F_j, positive when it
opposes a positive slip:
- slip (mode s_j = sgn g_j = +-1): F_j = s_j mu_j(|g_j|) N_j, Roller's law (friction.py);
- stick (mode 0): g_j = 0 held, F_j the force that keeps g_j' = 0, valid while |F_j| <= mu_j(0) N_j = mu_s N_j.
The stuck forces solve A_SS F_S = W_S^T M^-1 (f - W_P F_P) - V_S' with A = W^T M^-1 W (the Delassus matrix).

Every smooth piece is integrated with an 8th-order Runge-Kutta (scipy's DOP853) to a tight tolerance, and its end
is an event located to rounding: a slipping contact's g_j reaching 0, a stuck contact's |F_j| reaching mu_s N_j.
At each event the next modes are the consistent set (the largest stuck set whose forces respect the bounds, the
new slips accelerating in their own direction): stick-slip switching is exact, no regularization, no smoothing.
The slip velocities g_j are integrated as states of their own (g_j' = w_j . u' - V_j'), so that a slip starting
from g_j = 0 is resolved to its own scale and not to the rounding of w_j . u - V_j.
"""
import itertools
import math
from dataclasses import dataclass, field
from typing import Callable, Optional, Sequence

import numpy as np
from scipy.integrate import solve_ivp

from .friction import Friction


@dataclass
class Contact:
    w: Sequence[float]  # g = w . u - V(t)
    friction: Friction
    N: float  # normal force (the bound on the stuck force is mu_s N)
    belt: Optional[Callable[[float], tuple]] = None  # t -> (V, V'), None: 0
    name: str = "contact"


@dataclass
class System:
    M: np.ndarray  # n x n mass matrix
    force: Callable  # f(t, q, u) -> length-n array (every force but the contacts')
    contacts: list


@dataclass
class Result:
    t: np.ndarray
    q: np.ndarray  # samples x n
    u: np.ndarray
    g: np.ndarray  # samples x m, slip velocities
    F: np.ndarray  # samples x m, contact forces
    mode: np.ndarray  # samples x m: 0 stick, +-1 slip
    events: list = field(default_factory=list)  # (t, contact, 'stick'|'slip'|'reverse', new modes)
    phases: list = field(default_factory=list)  # (t_start, t_end, modes)
    stopped: str = ""  # why the run ended before t_end ('' if it did not)

    def stick_intervals(self, j=0):
        """[(t_start, t_end)] during which contact j was stuck."""
        out = []
        for a, b, m in self.phases:
            if m[j] == 0 and b > a:
                if out and abs(out[-1][1] - a) <= 1e-12 * max(1.0, abs(a)):
                    out[-1] = (out[-1][0], b)
                else:
                    out.append((a, b))
        return out


class Integrator:
    def __init__(self, system: System, rtol=1e-10, atol=1e-13):
        self.s = system
        self.n = system.M.shape[0]
        self.m = len(system.contacts)
        self.Minv = np.linalg.inv(system.M)
        self.W = np.array([c.w for c in system.contacts], dtype=float).T.reshape(self.n, self.m)
        self.A = self.W.T @ self.Minv @ self.W
        self.rtol, self.atol = rtol, atol
        self.MW = self.Minv @ self.W

    def _belt(self, j, t):
        b = self.s.contacts[j].belt
        return b(t) if b is not None else (0.0, 0.0)

    def forces(self, t, q, u, g, modes):
        """(F, u') in the given modes."""
        cs, f = self.s.contacts, np.asarray(self.s.force(t, q, u), dtype=float)
        F = np.zeros(self.m)
        stuck = [j for j in range(self.m) if modes[j] == 0]
        for j in range(self.m):
            if modes[j] != 0:
                F[j] = modes[j] * cs[j].friction.mu(max(modes[j] * g[j], 0.0)) * cs[j].N
        free = self.Minv @ (f - self.W @ F)
        if stuck:
            b = np.array([self.W[:, j] @ free - self._belt(j, t)[1] for j in stuck])
            Ass = self.A[np.ix_(stuck, stuck)]
            Fs = np.linalg.lstsq(Ass, b, rcond=None)[0] if len(stuck) > 1 else b / Ass[0, 0]
            F[stuck] = Fs
            free = free - self.MW[:, stuck] @ Fs
        return F, free

    def _rhs(self, modes):
        n, m = self.n, self.m

        def rhs(t, y):
            q, u, g = y[:n], y[n:2 * n], y[2 * n:]
            F, ud = self.forces(t, q, u, g, modes)
            gd = self.W.T @ ud - np.array([self._belt(j, t)[1] for j in range(m)])
            gd[[j for j in range(m) if modes[j] == 0]] = 0.0
            return np.concatenate([u, ud, gd])

        return rhs

    def _events(self, modes):
        n, evs = self.n, []
        for j in range(self.m):
            c = self.s.contacts[j]
            if modes[j] != 0:
                def ev(t, y, j=j, s=modes[j]):
                    return s * y[2 * n + j]
            else:
                def ev(t, y, j=j, c=c):
                    F, _ = self.forces(t, y[:n], y[n:2 * n], y[2 * n:], modes)
                    return c.friction.mu_s * c.N - abs(F[j])
            ev.terminal, ev.direction = True, -1
            evs.append(ev)
        return evs

    def select(self, t, q, u, g, breakaway=None):
        """The consistent modes at a state; contacts with g != 0 slip in their direction. breakaway: (j, sign) of a
        contact whose stuck force just reached its bound: it slips that way (its acceleration starts at 0)."""
        cs = self.s.contacts
        zero = [j for j in range(self.m) if g[j] == 0.0 and not (breakaway and breakaway[0] == j)]
        base = [int(math.copysign(1, g[j])) if g[j] != 0.0 else 0 for j in range(self.m)]
        if breakaway:
            base[breakaway[0]] = breakaway[1]
        best, best_bad = None, math.inf
        options = sorted(itertools.product((0, 1, -1), repeat=len(zero)), key=lambda o: sum(x != 0 for x in o))
        for opt in options:
            modes = list(base)
            for j, o in zip(zero, opt):
                modes[j] = o
            F, ud = self.forces(t, q, u, g, modes)
            gd = self.W.T @ ud - np.array([self._belt(j, t)[1] for j in range(self.m)])
            bad = 0.0
            for j in range(self.m):
                bound = cs[j].friction.mu_s * cs[j].N
                if modes[j] == 0:
                    bad = max(bad, (abs(F[j]) - bound) / max(bound, 1e-300) - 1e-9)
                elif g[j] == 0.0 and j in zero:
                    bad = max(bad, -modes[j] * gd[j] / max(abs(gd[j]), 1e-300) if gd[j] != 0.0 else 1.0)
            if bad <= 0.0:
                return modes
            if bad < best_bad:
                best, best_bad = modes, bad
        return best

    def run(self, q0, u0, t_end, t0=0.0, dt_out=None, g0=None, stop=None, chunk=None, max_events=100000):
        """Integrate from (q0, u0) at t0 to t_end. Samples every dt_out (and at every event). g0: the initial slip
        velocities (default w . u0 - V(t0); pass exact zeros to start stuck). stop(result, t, y) -> str (y = [q, u, g]): checked at
        every event and every chunk (default: no chunks); a non-empty string ends the run with that reason."""
        n, m = self.n, self.m
        q, u = np.array(q0, dtype=float).reshape(n), np.array(u0, dtype=float).reshape(n)
        g = (np.array(g0, dtype=float) if g0 is not None else
             np.array([self.W[:, j] @ u - self._belt(j, t0)[0] for j in range(m)]))
        modes = self.select(t0, q, u, g)
        res = Result(t=None, q=None, u=None, g=None, F=None, mode=None)
        t, y = t0, np.concatenate([q, u, g])
        T, Y, MD = [t0], [y.copy()], [tuple(modes)]
        dt_out = dt_out or (t_end - t0) / 1000.0
        while t < t_end:
            if len(res.events) > max_events:
                raise RuntimeError(f"engine: more than {max_events} events before t = {t}")
            t_stop = min(t_end, t + chunk) if chunk else t_end
            k0, k1 = int(math.floor((t - t0) / dt_out)), int(math.floor((t_stop - t0) / dt_out))
            t_eval = t0 + dt_out * np.arange(k0, k1 + 2)
            t_eval = t_eval[(t_eval > t) & (t_eval <= t_stop)]
            sol = solve_ivp(self._rhs(modes), (t, t_stop), y, method="DOP853", rtol=self.rtol, atol=self.atol,
                            events=self._events(modes), t_eval=t_eval if len(t_eval) else None)
            if sol.status < 0:
                raise RuntimeError(f"engine: {sol.message} at t = {t}")
            if len(t_eval) and len(sol.t):
                T.extend(sol.t)
                Y.extend(sol.y.T)
                MD.extend([tuple(modes)] * len(sol.t))
            hit = [(te[0], j, ye[0]) for j, (te, ye) in enumerate(zip(sol.t_events, sol.y_events)) if len(te)]
            if hit:
                te, j, ye = min(hit, key=lambda h: h[0])
                res.phases.append((t, te, tuple(modes)))
                y = np.array(ye, dtype=float)
                qq, uu, gg = y[:n], y[n:2 * n], y[2 * n:]
                if modes[j] != 0:  # a slip ends: g_j = 0 exactly, then stick or reverse
                    gg[j] = 0.0
                    new = self.select(te, qq, uu, gg)
                    kind = "stick" if new[j] == 0 else "reverse"
                else:  # a stuck force reaches its bound: break away in its direction
                    F, _ = self.forces(te, qq, uu, gg, modes)
                    new = self.select(te, qq, uu, gg, breakaway=(j, int(math.copysign(1, F[j]))))
                    kind = "slip"
                for i in range(m):
                    if new[i] == 0:
                        gg[i] = 0.0
                y = np.concatenate([qq, uu, gg])
                T.append(te)
                Y.append(y.copy())
                MD.append(tuple(new))
                modes = new
                res.events.append((te, j, kind, tuple(new)))
                t = te
            else:
                res.phases.append((t, sol.t[-1], tuple(modes)))
                t, y = sol.t[-1], sol.y[:, -1].copy()
            if stop is not None:
                why = stop(res, t, y)
                if why:
                    res.stopped = why
                    break
        res.t = np.array(T)
        Y = np.array(Y).reshape(len(T), 2 * n + m)
        res.q, res.u, res.g = Y[:, :n], Y[:, n:2 * n], Y[:, 2 * n:]
        res.mode = np.array(MD).reshape(len(T), m)
        res.F = np.array([self.forces(res.t[i], res.q[i], res.u[i], res.g[i], res.mode[i])[0]
                          for i in range(len(T))]).reshape(len(T), m)
        return res
