"""Option fuzz (issue 26, "nothing passes silently"): the option list is read from roller -help (every block
headed "Roller:"), and each real option is tried with nan, inf, -1, 0, 1e300 and a word, each integer option
with -1, 0, 1e300 and a word, each enum with an unknown name. Every run either exits non-zero with a message that
names the option, or the value is listed below as valid (VALID) and the run is checked to be sane: exit 0 and a
monitor CSV whose R, alpha and energy are finite.

The runs are short: the coarse mesh -mesh_h 0.05, P1 (-degree 1, the cheap space), at most 2 steps of
-ts_dt 0.01 (so that no option's default step rule makes thousands of steps). Options of the obstacle and the
contact run with -obstacle, the friction's with -friction 0.5 too, the modes' with -modes."""
import math
import re
import sys

from rollertest import Checker, read_csv, run

BASE = ["-mesh_h", "0.05", "-degree", "1", "-ts_dt", "0.01", "-ts_max_steps", "2", "-quiet"]
CONTEXT = {  # the options an option needs to be read at all
    "obstacle": ["-obstacle"],
    "contact": ["-obstacle"],
    "friction": ["-obstacle", "-friction", "0.5", "-friction_static", "0.6", "-friction_decay", "0.1"],
    "modes": ["-modes", "-modes_nev", "2"],
    "axle": ["-obstacle", "-axle", "-drive_stiffness", "0.1", "-nip_force", "0.001", "-ts_scheme", "trapezoidal"],
}
# (option, value): valid, with the reason; the run must then be sane
VALID = {
    ("-omega", "-1"): "rotation the other way", ("-omega", "0"): "at rest",
    ("-theta_a", "-1"): "a signed amplitude", ("-theta_a", "0"): "no perturbation", ("-theta_b", "0"): "no perturbation",
    ("-theta_start", "0"): "the drive from t = 0", ("-damping", "0"): "undamped", ("-viscosity", "0"): "elastic",
    ("-ts_dt", "0"): "chosen from -ts_phase_error", ("-mesh_h", "0"): "chosen from -ts_phase_error",
    ("-mesh_h_contact", "0"): "uniform mesh", ("-mesh_contact_layer", "0"): "2 h_c (no grading: unused)",
    ("-ts_max_time", "0"): "the initial state only", ("-ts_max_steps", "-1"): "no cap", ("-ts_max_steps", "0"): "the initial state only",
    ("-solver_redundant_max", "0"): "MUMPS for the non-symmetric step matrices on several ranks (one rank: unused)",
    ("-ic_amplitude", "0"): "zero amplitude", ("-checkpoint_every", "0"): "only on a signal",
    ("-ts_max_wall", "0"): "no limit", ("-ts_max_wall", "1e300"): "never reached",
    ("-sheet_speed", "-1"): "the sheet backwards", ("-sheet_speed", "0"): "a still sheet",
    ("-obstacle_depth", "0"): "touching only", ("-friction", "0"): "frictionless",
    ("-rom_modes", "0"): "the modes below -rom_cutoff", ("-rom_cutoff", "0"): "the default cutoff",
    ("-rom_cutoff", "1e300"): "unused without -rom (with it: refused above the step's Nyquist frequency 1/(2 dt))",
    ("-friction_decay", "0"): "no weakening (needs -friction_static = -friction: refused here)",
    ("-contact_max_resolves", "0"): "no re-solve", ("-contact_margin", "0"): "the predicted gap only",
    ("-contact_margin", "-1"): "shrinks the candidate set (refused: > -r_outer)",
    ("-contact_margin", "1e300"): "every node a candidate",
    ("-initial_mode", "0"): "unused without -initial_condition mode",
    ("-modes_stick_eps", "0"): "rigid stick (the default)", ("-modes_stick_margin", "0"): "every stick node stuck (the default)", ("-modes_stick_eps", "1e300"): "stick nodes slide freely (unused without -obstacle)",
    ("-young", "1e300"): "stiff: dt and h are given", ("-density", "1e300"): "heavy: dt and h are given",
    ("-obstacle_speed", "1e300"): "the press at once", ("-ts_max_time", "1e300"): "capped by -ts_max_steps 2",
    ("-checkpoint_every", "1e300"): None, ("-output_every", "1e300"): None,
    ("-contact_friction_max_it", "1e300"): None, ("-contact_max_resolves", "1e300"): None, ("-contact_pcg_max_it", "1e300"): None,
    ("-sheet_speed", "1e300"): None, ("-theta_a", "1e300"): None, ("-theta_start", "1e300"): "the drive never starts",
    ("-viscosity", "1e300"): None, ("-damping", "1e300"): None, ("-poisson", "0"): "no lateral contraction",
    ("-theta_b", "1e300"): "no perturbation (-theta_a 0)", ("-friction_static", "1e300"): None,
    ("-friction_decay", "1e300"): "the weakening never reached", ("-ic_amplitude", "1e300"): "unused at rest (the default initial condition)",
    ("-drive_ramp", "0"): "no ramp", ("-drive_ramp", "1e300"): "the motor never gets going",
    ("-drive_ripple", "0"): "no ripple", ("-drive_ripple_frequency", "0"): "no ripple",
    ("-drive_ripple_frequency", "1e300"): "unused without -drive_ripple",
    ("-axle_mass", "0"): "the rubber's mass", ("-axle_mass", "1e300"): "a hub that does not move",
    ("-axle_inertia", "0"): "the rubber's inertia", ("-axle_inertia", "1e300"): "a hub that does not turn",
    ("-axle_stiffness", "0"): "the preload only", ("-axle_stiffness", "1e300"): "a rigid spring from the end of -nip_ramp",
    ("-nip_force", "0"): "no preload", ("-nip_ramp", "0"): "the preload at once", ("-nip_ramp", "1e300"): "the preload never rises",
    ("-drive_stiffness", "1e300"): "a rigid drive", ("-sheet_mass", "0"): "the kinematic sheet", ("-sheet_resistance", "0"): "no resistance", ("-drive_damping", "0"): "an undamped drive", ("-drive_damping", "1e300"): None,
    ("-drive_kick", "-1"): "a kick against the motor", ("-drive_kick", "0"): "no kick", ("-drive_kick_time", "0"): "the kick at the first step",
    ("-drive_kick_time", "1e300"): "unused without -drive_kick", ("-output_start", "0"): "fields from the start (the default)",
    ("-output_start", "1e300"): "no fields written (unused without -output)",
}
VALUES_REAL = ["nan", "inf", "-1", "0", "1e300", "word"]
VALUES_INT = ["-1", "0", "1e300", "word"]


def options_from_help():
    """(name, kind, section, choices) of every option in the Roller blocks of -help."""
    _, out, err = run(BASE + ["-help"])
    opts, section = [], None
    for line in (out + err).splitlines():
        if line.startswith("Roller:") or line.startswith("Roller contact") or re.match(r"^\S.*:$", line):
            section = line if "Roller" in line else None
            continue
        m = re.match(r"^  (-[a-z][a-z0-9_]*)(:)? <(now )?([^:>]*) : (formerly )?([^>]*)>", line)
        if not section or not m:
            continue
        name, now = m.group(1), m.group(4).strip()
        if m.group(2):
            kind, choices = "bool", []
        elif "(choose one of)" in line or "(one of)" in line:
            choices = re.search(r"\((?:choose )?one of\) ([^(]*)", line).group(1).split()
            kind = "enum"
        elif m.group(3) and re.fullmatch(r"-?\d+", now):
            kind, choices = "int", []
        elif not m.group(3) and re.fullmatch(r"-?[\d.e+-]+", now):
            kind, choices = "real", []
        else:
            kind, choices = "string", []
        opts.append((name, kind, section, choices))
    return opts


def context(name, section):
    low = section.lower()
    if name.startswith("-friction") or "friction" in name:
        return CONTEXT["friction"]
    if "contact" in low or name.startswith("-obstacle") or name.startswith("-sheet") or name.startswith("-contact"):
        return CONTEXT["contact"]
    if name.startswith("-modes"):
        return CONTEXT["modes"]
    if "axle" in low:
        return CONTEXT["axle"]
    return []


def sane(csv):
    d = read_csv(csv)
    return all(all(math.isfinite(x) for x in d[q]) for q in ("R", "alpha", "energy"))


c = Checker("options_fuzz")
opts = [o for o in options_from_help() if o[1] in ("real", "int", "enum") and not o[0].startswith("-sweep")]
c.check(len([o for o in opts if o[1] == "real"]) >= 20, f"-help lists {len(opts)} real, integer and enum options")
silent = []
for name, kind, section, choices in opts:
    values = VALUES_REAL if kind == "real" else VALUES_INT if kind == "int" else ["no_such_" + name[1:]]
    for value in values:
        args = BASE + context(name, section) + [name, value]
        code, out, err = run(args + ["-monitor_csv", "fuzz.csv"], check=False)
        text = out + err
        named = name in text and (kind != "enum" or all(ch in text for ch in choices))
        if code != 0:
            ok = named
            what = f"{name} {value}: exit {code}, " + next((ln.strip()[:140] for ln in text.splitlines() if name in ln), "no line names it")
        elif (name, value) in VALID:
            ok = kind == "modes" or "-modes" in args or sane("fuzz.csv")
            what = f"{name} {value}: valid ({VALID[(name, value)] or 'a large but legal value'}), the run is sane"
        else:
            ok, what = False, f"{name} {value}: exit 0, not listed as valid"
            silent.append((name, value))
        c.check(ok, what)
if silent:
    print("accepted silently:", " ".join(f"{n} {v}" for n, v in silent), file=sys.stderr)
c.close()
