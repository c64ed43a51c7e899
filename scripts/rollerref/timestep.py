"""An independent check of engine.py: Moreau's time-stepping for the torsional 1-DOF (stickslip.Torsion), first
order in the step h, with the friction law solved implicitly at the end of each step (no event location):

    I_e w1 = I w0 + h (k_d (th_m(t1) - th0) + c_d th_m'(t1)) - h r F1,   th1 = th0 + h w1,   I_e = I + h c_d + h^2 k_d,
    v1 = r w1 - V(t1),   F1 in mu(|v1|) N Sgn(v1)   (stick: v1 = 0 while |F1| <= mu_s N).

With v_free the slip speed at F1 = 0 and beta = h r^2 / I_e: stick if |v_free| <= beta mu_s N, else
|v1| + beta N mu(|v1|) = |v_free| (one root in (0, |v_free|) while h < I_e / (r^2 N |mu'(0)|)).
"""
import math

import numpy as np
from scipy.optimize import brentq

from .engine import Result


def moreau(p, t_end, h, th0=0.0, w0=0.0, t0=0.0):
    """Integrate stickslip.Torsion p from (th0, w0) at t0 with step h; returns an engine.Result (samples every step)."""
    n = int(math.ceil((t_end - t0) / h - 1e-9))
    T = t0 + h * np.arange(n + 1)
    TH, W, F, MD = np.empty(n + 1), np.empty(n + 1), np.empty(n + 1), np.zeros(n + 1, dtype=int)
    TH[0], W[0] = th0, w0
    v = p.r * w0 - p.sheet(t0)[0]
    MD[0] = 0 if v == 0 else int(math.copysign(1, v))
    F[0] = p.friction.mu(abs(v)) * p.N * math.copysign(1, v) if v != 0 else 0.0
    I_e = p.I + h * p.c_d + h * h * p.k_d
    beta = h * p.r ** 2 / I_e
    fr, N = p.friction, p.N
    for k in range(n):
        a, av, _ = p.motor.state(T[k + 1])
        w_free = (p.I * W[k] + h * (p.k_d * (a - TH[k]) + p.c_d * av)) / I_e
        v_free = p.r * w_free - p.sheet(T[k + 1])[0]
        if abs(v_free) <= beta * fr.mu_s * N:
            f, md = v_free / beta, 0
        else:
            s, x = math.copysign(1.0, v_free), abs(v_free)
            y = brentq(lambda z: z + beta * N * fr.mu(z) - x, 0.0, x, xtol=1e-15 * max(x, 1e-300), rtol=1e-14)
            f, md = s * fr.mu(y) * N, int(s)
        W[k + 1] = w_free - h * p.r * f / I_e
        TH[k + 1] = TH[k] + h * W[k + 1]
        F[k + 1], MD[k + 1] = f, md
    res = Result(t=T, q=TH[:, None], u=W[:, None], g=(p.r * W - np.array([p.sheet(x)[0] for x in T]))[:, None], F=F[:, None], mode=MD[:, None])
    start = 0
    for k in range(1, n + 2):  # runs of equal mode, each until the next run's first sample
        if k == n + 1 or MD[k] != MD[start]:
            res.phases.append((T[start], T[min(k, n)], (int(MD[start]),)))
            start = k
    return res
