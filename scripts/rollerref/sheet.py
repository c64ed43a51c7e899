"""The sheet picked from rest (issue 36; docs/validation.md section 10.2).

The sheet (mass m_s per unit width, speed V) is driven by the roller's friction F and held back by the stack's
resistance F_r (a Coulomb bound: stuck at rest while |F| <= F_r):

    m_s V' = F - F_r sgn(V)   (moving),      F = mu(|v|) N sgn(v),   v = r omega - V   (roller over sheet, slip).

Kinematic roller (`pick`): the roller's surface moves at r omega (the motor's speed, drive.py). Coupled (`coupled`):
the roller is torsion.py's hub, I th'' = k_d (th_m - th) + c_d (th_m' - th') - r F, v = r th' - V. Both are
integrated by engine.py with exact stick/slip switching at both contacts (roller-sheet and sheet-stack).

Closed forms for the kinematic roller at constant speed, the sheet at rest at t = 0 (`closed_form`):
- it moves iff mu(r omega) N > F_r;
- constant mu (v_c = 0): V = a t, a = (mu_k N - F_r) / m_s, until it reaches r omega at t* = m_s r omega /
  (mu_k N - F_r), then sticks to the roller (F = F_r <= mu_s N) for good;
- velocity weakening: with a = (mu_k N - F_r)/m_s, b = (mu_s - mu_k) N/m_s and z = exp(v/v_c),
  dv/dt = -(a + b/z) integrates to z(t) = ((a z0 + b) exp(-a t/v_c) - b)/a (a != 0; z0 - b t/v_c if a = 0),
  v(t) = v_c ln z(t), and the sheet sticks to the roller at t* = (v_c/a) ln((a z0 + b)/(a + b));
- settle points of the slip: mu(v*) N = F_r, v* = v_c ln((mu_s - mu_k) N / (F_r - mu_k N)) when
  mu_k N < F_r < mu_s N; it is unstable (dv/dt = -(mu(v) N - F_r)/m_s grows at rate -mu'(v*) N/m_s > 0): a slip
  below v* closes to stick, above it opens until the sheet stops. From rest: picked iff r omega < v*.
"""
import math
from dataclasses import dataclass

import numpy as np

from .drive import Motor
from .engine import Contact, Integrator, System
from .friction import Friction
from .stickslip import Torsion


@dataclass(frozen=True)
class Sheet:
    m_s: float  # mass per unit width
    F_r: float  # resistance per unit width (the stack, the separation pad)


def _ground(sheet: Sheet, w):
    return Contact(w=w, friction=Friction(1.0, 1.0, 0.0), N=sheet.F_r, name="sheet-stack")


def closed_form(sheet: Sheet, friction: Friction, N, r, omega, t=None):
    """The kinematic roller at constant speed picks the resting sheet: times, speeds, settle points (see module)."""
    w = r * omega
    mu0 = friction.mu(w)
    out = {"roller_speed": w, "moves": mu0 * N > sheet.F_r, "initial_force": mu0 * N}
    v_star = friction.speed_at(sheet.F_r / N)
    if v_star is not None:
        out["settle_slip_speed"] = v_star
        out["settle_growth_rate"] = -friction.dmu(v_star) * N / sheet.m_s
        out["settle_stable"] = False
    out["stick_holds"] = sheet.F_r <= friction.mu_s * N
    if not out["moves"]:
        out.update(t_stick=math.inf, final_speed=0.0)
        return out
    a, b, vc = (friction.mu_k * N - sheet.F_r) / sheet.m_s, (friction.mu_s - friction.mu_k) * N / sheet.m_s, friction.v_c
    if vc == 0.0:
        t_star = w / a
        out.update(t_stick=t_star, final_speed=w, acceleration=a, slip_distance=0.5 * w * t_star)

        def V(tt):
            return np.minimum(a * np.asarray(tt, dtype=float), w)
    else:
        z0 = math.exp(w / vc)
        t_star = (vc / a) * math.log((a * z0 + b) / (a + b)) if a != 0 else vc * (z0 - 1) / b
        out.update(t_stick=t_star, final_speed=w)

        def V(tt):
            tt = np.minimum(np.asarray(tt, dtype=float), t_star)
            z = ((a * z0 + b) * np.exp(-a * tt / vc) - b) / a if a != 0 else z0 - b * tt / vc
            return w - vc * np.log(np.maximum(z, 1.0))
    if t is not None:
        out["V"] = V(t)
    out["V_of_t"] = V
    return out


def pick(sheet: Sheet, friction: Friction, N, r, motor: Motor, t_end, V0=0.0, dt_out=None, rtol=1e-10):
    """Integrate the kinematic roller (surface speed r theta_m'(t)) picking the sheet from speed V0."""

    def belt(t):
        _, w, acc = motor.state(t)
        return -r * w, -r * acc

    contacts = [Contact(w=[-1.0], friction=friction, N=N, belt=belt, name="roller-sheet")]
    if sheet.F_r > 0:
        contacts.append(_ground(sheet, [1.0]))
    integ = Integrator(System(M=np.array([[sheet.m_s]]), force=lambda t, q, u: np.zeros(1), contacts=contacts),
                       rtol=rtol, atol=1e-15)
    g0 = [r * motor.state(0.0)[1] - V0] + ([V0] if sheet.F_r > 0 else [])
    return integ.run([0.0], [V0], t_end, dt_out=dt_out or t_end / 2000, g0=g0)


def coupled(sheet: Sheet, p: Torsion, t_end, th0=0.0, w0=0.0, V0=0.0, dt_out=None, rtol=1e-10):
    """Integrate the driven roller (Torsion p; its V is ignored) and the sheet together. q = (th, X)."""
    m = p.motor

    def force(t, q, u):
        a, v, _ = m.state(t)
        return np.array([p.k_d * (a - q[0]) + p.c_d * (v - u[0]), 0.0])

    contacts = [Contact(w=[p.r, -1.0], friction=p.friction, N=p.N, name="roller-sheet")]
    if sheet.F_r > 0:
        contacts.append(_ground(sheet, [0.0, 1.0]))
    integ = Integrator(System(M=np.diag([p.I, sheet.m_s]), force=force, contacts=contacts), rtol=rtol, atol=1e-15)
    g0 = [p.r * w0 - V0] + ([V0] if sheet.F_r > 0 else [])
    return integ.run([th0, 0.0], [w0, V0], t_end, dt_out=dt_out or t_end / 2000, g0=g0)


def coupled_steady(sheet: Sheet, p: Torsion):
    """Steady states of the coupled roller and sheet at the motor's final speed omega:
    - 'stuck': the sheet rides with the roller at V = r omega, F = F_r (valid if F_r <= mu_s N), the drive wound
      up by r F_r / k_d; its torsional frequency sqrt(k_d / (I + m_s r^2)) (the sheet's inertia joins the hub's);
    - 'sliding' at the settle slip v* (mu(v*) N = F_r) with the eigenvalues of the linearization
      (dth, dw, dV): I dw' = -k_d dth - c_d dw - r N mu'(v*) (r dw - dV), m_s dV' = N mu'(v*) (r dw - dV)."""
    out = {"stuck": {"valid": sheet.F_r <= p.friction.mu_s * p.N, "V": p.r * p.omega, "friction_force": sheet.F_r,
                     "wind_up": p.r * sheet.F_r / p.k_d,
                     "w_n": math.sqrt(p.k_d / (p.I + sheet.m_s * p.r ** 2))}}
    v_star = p.friction.speed_at(sheet.F_r / p.N)
    if v_star is not None:
        d = p.friction.dmu(v_star) * p.N
        J = np.array([[0.0, 1.0, 0.0],
                      [-p.k_d / p.I, -(p.c_d + p.r ** 2 * d) / p.I, p.r * d / p.I],
                      [0.0, p.r * d / sheet.m_s, -d / sheet.m_s]])
        ev = np.linalg.eigvals(J)
        out["sliding"] = {"slip_speed": v_star, "V": p.r * p.omega - v_star, "eigenvalues": [complex(e) for e in ev],
                          "growth_rate": float(max(ev.real)), "stable": bool(max(ev.real) < 0)}
    return out
