"""The scene on -axle as rollerref's torsional oscillator (docs/validation.md 10.1, 10.5): the stated cross-check of
the CEA's drive mode (`roller -modes -axle`, docs/squeal.md 3.1 and 9.4), the closed form of the forced response, and the classifier of the
propensity's cases.

    I th'' = k_d (th_m - th) + c_d (th_m' - th') - r F,   I = axle_inertia + density pi (r_outer^4 - r_inner^4) / 2,

F = mu(|v|) N, v = r_outer th' - V, N = -nip_force, mu(s) = mu + (mu_s - mu) exp(-s / v_c) (Roller's law). It holds
when the drive is much softer than the rubber (k_d << the annulus's torsional k_r, rollerref.forced.annulus_torsion)
and the nip force's spurious torsional stiffness N r_outer << k_d (docs/validation.md 10.5: the FE cycle's period
2.2 % shorter than this model's on jobs/axle_bistable.yaml).
"""
import math

# roller's defaults (src/app/options.c, src/model/axle.c, src/model/forcing.c) for what a scene may leave out
DEFAULTS = {"r_inner": 0.25, "r_outer": 0.5, "density": 1.0, "poisson": 0.49, "young": 0.1, "omega": math.pi / 10,
            "sheet_speed": 0.0, "friction": 0.0, "axle_inertia": 0.0, "drive_stiffness": 0.0, "drive_damping": 0.0,
            "nip_force": 0.0, "theta_start": 0.0, "drive_ramp": 0.0, "drive_ripple": 0.0, "drive_ripple_frequency": 0.0}


def value(opts, name):
    v = opts.get(name)
    if v is None:
        if name == "friction_static":
            return value(opts, "friction")
        if name == "friction_decay":
            return 0.0
        return float(DEFAULTS[name])
    return float(v)


def is_axle(opts):
    return str(opts.get("axle", "false")).lower() in ("true", "1", "yes")


def rubber_inertia(opts):
    return value(opts, "density") * math.pi * (value(opts, "r_outer") ** 4 - value(opts, "r_inner") ** 4) / 2


def torsion(opts, ripple=True, **override):
    """rollerref.stickslip.Torsion of the scene's options ({name: string}; override: {name: float} replacing them),
    the motor started at theta_start with the cubic ramp over drive_ramp (and the ripple when `ripple`)."""
    from rollerref import stickslip
    from rollerref.drive import Motor
    from rollerref.friction import Friction

    o = dict(opts)
    o.update({k: repr(float(v)) for k, v in override.items()})
    mu, mu_s, v_c = value(o, "friction"), value(o, "friction_static"), value(o, "friction_decay")
    motor = Motor(omega=value(o, "omega"), t0=value(o, "theta_start"), t_ramp=value(o, "drive_ramp"), ramp="cubic",
                  ripple=value(o, "drive_ripple") if ripple else 0.0,
                  ripple_frequency=value(o, "drive_ripple_frequency") if ripple else 0.0)
    return stickslip.Torsion(I=value(o, "axle_inertia") + rubber_inertia(o), k_d=value(o, "drive_stiffness"),
                             c_d=value(o, "drive_damping"), r=value(o, "r_outer"), N=value(o, "nip_force"),
                             friction=Friction(mu, mu_s if v_c > 0 else mu, v_c if v_c > 0 else 1.0), V=value(o, "sheet_speed"),
                             motor=motor)


def stability(opts):
    """The closed-form linear stability of steady sliding (rollerref.stickslip.linear_stability) of the scene: growth
    rate and frequency per unit time, the slip speed, the onset slip speed; 'stable'."""
    from rollerref import stickslip

    p = torsion(opts, ripple=False)
    lin = stickslip.linear_stability(p)
    return {"growth_rate": lin["growth_rate"], "frequency": lin["frequency"], "slip_speed": lin["slip_speed"],
            "c_eff": lin["c_eff"], "stable": bool(lin["stable"]), "onset_slip_speed": lin["onset_slip_speed"],
            "w_n": p.w_n, "inertia": p.I}


def start_from_rest(opts, **override):
    """rollerref's event-driven start from rest of the scene (rollerref.basin.classify: 'cycle' (stick-slip),
    'sliding' (decays to steady sliding), ...)."""
    from rollerref import basin

    p = torsion(opts, ripple=False, **override)
    return basin.classify(p, 0.0, 0.0, t0=0.0)[0]
