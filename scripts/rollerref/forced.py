"""The hub's forced response to the motor's ripple th_m = a sin(Omega t), Omega = 2 pi f (issue 36; docs/validation.md
section 9.3), about steady rotation (perturbations; the mean speed and wind-up drop out of the linear equations).

One degree of freedom (the roller rigid): I th'' + (c_d + c_f) th' + k_d th = k_d th_m + c_d th_m', with c_f the
linearized friction about steady sliding (r^2 N mu'(|v0|); 0 for constant mu, stickslip.linear_stability's
c_eff - c_d). The complex amplitude th = H a e^{i Omega t}:

    H1 = (k_d + i Omega c_d) / (k_d - I Omega^2 + i Omega (c_d + c_f)),

amplitude a |H1|, phase arg H1 (of the hub's angle against the motor's, negative: a lag); the drive torque
k_d (th_m - th) + c_d (th_m' - th') has the amplitude a |k_d + i Omega c_d| |1 - H1|.

Two degrees of freedom (the rubber's torsional compliance between the hub, inertia I_h, and the tyre, I_t:
stiffness k_r and damping c_r, the lead computes k_r; `annulus_torsion` gives docs/friction.md 5.3's estimate):

    [Z11  Z12] [th_h]   [(k_d + i Omega c_d) a]     Z11 = k_d + k_r - I_h Omega^2 + i Omega (c_d + c_r),
    [Z12  Z22] [th_t] = [0                    ],    Z12 = -(k_r + i Omega c_r),
                                                    Z22 = k_r - I_t Omega^2 + i Omega (c_r + c_f),

th_h = Z22 (k_d + i Omega c_d) a / D, th_t = -Z12 (k_d + i Omega c_d) a / D, D = Z11 Z22 - Z12^2. With the tyre
stuck to a kinematic sheet (tyre='stuck') th_t = 0 and th_h = (k_d + i Omega c_d) a / Z11. Undamped natural
frequencies: free tyre I_h I_t w^4 - (I_h k_r + I_t (k_d + k_r)) w^2 + k_d k_r = 0; stuck tyre w^2 = (k_d + k_r)/I_h.
"""
import cmath
import math


def _pack(H, a, Omega):
    return {"amplitude": abs(H) * a, "phase": cmath.phase(H), "ratio": abs(H), "rate_amplitude": Omega * abs(H) * a,
            "re": H.real, "im": H.imag}


def one_dof(I, k_d, c_d, f, a=1.0, c_f=0.0):
    """The hub's response to the ripple a sin(2 pi f t): amplitude, phase (radians), |H1|, the hub rate's
    amplitude and the drive torque's amplitude."""
    W = 2 * math.pi * f
    drive = complex(k_d, W * c_d)
    H = drive / complex(k_d - I * W * W, W * (c_d + c_f))
    out = _pack(H, a, W)
    out["drive_torque_amplitude"] = abs(drive) * abs(1 - H) * a
    return out


def two_dof(I_h, I_t, k_d, c_d, k_r, f, a=1.0, c_r=0.0, c_f=0.0, tyre="free"):
    """Hub and tyre responses to the ripple through the drive and the rubber (tyre 'free': sliding, or 'stuck')."""
    W = 2 * math.pi * f
    drive = complex(k_d, W * c_d) * a
    Z11 = complex(k_d + k_r - I_h * W * W, W * (c_d + c_r))
    if tyre == "stuck":
        Hh, Ht = drive / Z11 / a, 0j
    elif tyre == "free":
        Z12 = -complex(k_r, W * c_r)
        Z22 = complex(k_r - I_t * W * W, W * (c_r + c_f))
        D = Z11 * Z22 - Z12 * Z12
        Hh, Ht = Z22 * drive / D / a, -Z12 * drive / D / a
    else:
        raise ValueError(f"two_dof: tyre must be 'free' or 'stuck', got {tyre!r}")
    return {"hub": _pack(Hh, a, W), "tyre": _pack(Ht, a, W),
            "drive_torque_amplitude": abs(complex(k_d, W * c_d)) * abs(1 - Hh) * a}


def natural_frequencies(I_h, I_t, k_d, k_r):
    """Undamped angular frequencies (rad per unit time): the 1-DOF sqrt(k_d/(I_h + I_t)), the two of the free tyre,
    the stuck tyre's sqrt((k_d + k_r)/I_h)."""
    b = I_h * k_r + I_t * (k_d + k_r)
    disc = math.sqrt(b * b - 4 * I_h * I_t * k_d * k_r)
    return {"one_dof": math.sqrt(k_d / (I_h + I_t)), "free_low": math.sqrt((b - disc) / (2 * I_h * I_t)),
            "free_high": math.sqrt((b + disc) / (2 * I_h * I_t)), "stuck": math.sqrt((k_d + k_r) / I_h)}


def annulus_torsion(E, nu, r_i, r_o):
    """Torsional stiffness per unit width of the elastic annulus clamped at r_i and twisted by a uniform shear at
    r_o (plane strain): k_r = 4 pi G / (1/r_i^2 - 1/r_o^2), G = E / (2 (1 + nu)) (docs/friction.md section 5.3's
    k_t, in rotational units k_r = r_o^2 k_t). E = 0.1, nu = 0.49, 0.25/0.5: 0.0352."""
    G = E / (2 * (1 + nu))
    return 4 * math.pi * G / (1 / r_i ** 2 - 1 / r_o ** 2)


def annulus_inertia(rho, r_i, r_o):
    """Polar moment of inertia per unit width of the annulus, rho pi (r_o^4 - r_i^4) / 2."""
    return rho * math.pi * (r_o ** 4 - r_i ** 4) / 2
