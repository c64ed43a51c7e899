"""The motor's angle theta_m(t): a start from rest at t0 whose speed ramps to omega over t_ramp, and a ripple.

    omega_m(t) = omega R((t - t0) / t_ramp),   theta_m(t) = int_0^t omega_m + a sin(2 pi f t),

R(s) = 0 before the start (s < 0), 1 after the ramp (s >= 1); in between R = s ('linear', the speed's kink is a
jump in the motor's acceleration), R = (1 - cos(pi s)) / 2 ('cosine', smooth speed and acceleration) or
R = s^2 (3 - 2 s) ('cubic': Roller's -drive_ramp, src/model/forcing.c; continuous acceleration, its jerk jumps). t_ramp = 0
is a step in speed at t0 (the motor already at omega at t0; the integrator takes a speed step only at its initial
time: start it at t0). The ripple a sin(2 pi f t) (radians, f in cycles per unit time) acts from t = 0 whatever
the start, as written in issue 36; the integrator sees it through theta_m, theta_m' and theta_m''.
"""
import math
from dataclasses import dataclass


@dataclass(frozen=True)
class Motor:
    omega: float = 0.0  # final speed (rad per unit time)
    t0: float = 0.0  # the start; before it the motor is at rest at angle 0
    t_ramp: float = 0.0  # duration of the speed ramp (0: a step)
    ramp: str = "linear"  # 'linear', 'cosine' or 'cubic' (Roller's -drive_ramp)
    ripple: float = 0.0  # a, radians
    ripple_frequency: float = 0.0  # f, cycles per unit time

    def __post_init__(self):
        if self.ramp not in ("linear", "cosine", "cubic") or self.t_ramp < 0 or self.t0 < 0:
            raise ValueError(f"motor: ramp must be 'linear', 'cosine' or 'cubic', t_ramp >= 0, t0 >= 0, got {self}")

    def _base(self, t):
        """(angle, speed, acceleration) of the ramped rotation without the ripple."""
        w, tr, s = self.omega, self.t_ramp, t - self.t0
        if s < 0.0 or (s == 0.0 and tr > 0.0):
            return 0.0, 0.0, 0.0
        if tr == 0.0 or s >= tr:
            return w * (s - 0.5 * tr), w, 0.0
        x = s / tr
        if self.ramp == "linear":
            return 0.5 * w * s * x, w * x, w / tr
        if self.ramp == "cubic":
            return w * tr * x ** 3 * (1.0 - 0.5 * x), w * x * x * (3.0 - 2.0 * x), 6.0 * w * x * (1.0 - x) / tr
        return (0.5 * w * (s - tr / math.pi * math.sin(math.pi * x)), 0.5 * w * (1.0 - math.cos(math.pi * x)),
                0.5 * w * math.pi / tr * math.sin(math.pi * x))

    def state(self, t):
        """(theta_m, theta_m', theta_m'') at time t."""
        a, v, acc = self._base(t)
        if self.ripple:
            W = 2.0 * math.pi * self.ripple_frequency
            a += self.ripple * math.sin(W * t)
            v += self.ripple * W * math.cos(W * t)
            acc -= self.ripple * W * W * math.sin(W * t)
        return a, v, acc

    def steady(self):
        """True when the speed is constant (no ramp left to run at t > t0 + t_ramp and no ripple)."""
        return self.ripple == 0.0 or self.ripple_frequency == 0.0
