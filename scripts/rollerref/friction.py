"""Roller's velocity-weakening Coulomb law (docs/friction.md, eq. of section 1):

    mu(s) = mu_k + (mu_s - mu_k) exp(-s / v_c),   s = |v| >= 0 the slip speed,

mu(0) = mu_s is the static coefficient (the bound on the stuck force); v_c = 0 (or mu_s = mu_k) is constant friction.
In slip the force opposing a slip velocity v is F = mu(|v|) N sgn(v), and d/dv [mu(|v|) sgn(v)] = mu'(|v|) for either
sign of v: velocity weakening (mu' < 0) is a negative viscous damping whatever the direction of slip.
"""
import math
from dataclasses import dataclass


@dataclass(frozen=True)
class Friction:
    mu_k: float  # kinetic coefficient, the limit at large slip speed (Roller's -friction)
    mu_s: float  # static coefficient mu(0) (-friction_static)
    v_c: float = 0.0  # decay speed (-friction_decay); 0: constant mu_k in slip

    def __post_init__(self):
        if self.mu_k < 0 or self.mu_s < self.mu_k or self.v_c < 0:
            raise ValueError(f"friction needs 0 <= mu_k <= mu_s and v_c >= 0, got {self}")

    def mu(self, s):
        """The coefficient at slip speed s >= 0."""
        if self.v_c == 0.0:
            return self.mu_s if s == 0.0 else self.mu_k
        return self.mu_k + (self.mu_s - self.mu_k) * math.exp(-s / self.v_c)

    def dmu(self, s):
        """d mu / d s at slip speed s > 0 (<= 0: velocity weakening)."""
        if self.v_c == 0.0:
            return 0.0
        return -(self.mu_s - self.mu_k) / self.v_c * math.exp(-s / self.v_c)

    def weakening_speed(self, slope):
        """The slip speed s at which -mu'(s) = slope (> 0); None if -mu' never reaches it (mu'(0) is the steepest)."""
        if self.v_c == 0.0 or slope <= 0:
            return None
        x = (self.mu_s - self.mu_k) / (self.v_c * slope)
        return self.v_c * math.log(x) if x > 1.0 else None

    def speed_at(self, mu_target):
        """The slip speed s > 0 with mu(s) = mu_target, for mu_k < mu_target < mu_s; None otherwise."""
        if self.v_c == 0.0 or not (self.mu_k < mu_target < self.mu_s):
            return None
        return self.v_c * math.log((self.mu_s - self.mu_k) / (mu_target - self.mu_k))
