"""python3 -m rollerreport.run SCENE.yaml OUTDIR: does the scene squeal? The one-command answer of issue 25
(docs/squeal.md section 9.2): runs every step with build/roller and writes the report into OUTDIR.

1. the CEA: `roller -options_file SCENE -modes` (the steady rolling state and its complex eigenvalues, section 3);
2. the map over creep and friction around the scene: `roller ... -modes -sweep` (section 6; with --ranks N > 1
   under `mpiexec -n N`, the cases on sub-communicators);
3. the seeded transient of the least stable mode (the largest growth rate): `-initial_condition mode` on the CEA's
   modes file (sections 4.2, 4.4), on the CEA's mesh (its /parameters mesh_h, mesh_h_contact, mesh_contact_layer and
   degree are given again: the accurate default mesh follows -ts_max_time), dt and duration from the mode's
   frequency (--steps-per-period, --periods); then the same run unseeded (transient_base.csv), so that the report
   fits the seed's own response;
4. the starts (a clamped scene): its start from rest and every divergent cell's of the map (a real positive
   eigenvalue), one `-sweep -sweep_cases` map on the reduced model (the CEA's mesh; its basis), each run until the
   CEA's least stable mode has died out and classified (rollerreport.divergent);
5. scene.json from the scene (units, Kelvin-Voigt tau, friction, creep, the audio time and length scales, the
   listener);
6. the report (rollerreport.report: report.md, report.json, report.html, map.png, squeal.wav, spectrogram.png,
   vibration.gif), with every step's command (commands.json) so that each can be run again.

Each part (cea, map, transient, transient_base, basis, divergent_runs, divergent, sound, animation; an axle scene's own)
is journalled (journal.json: its inputs' hash, its
outputs, its cost): a re-run reuses a part whose inputs are unchanged and whose outputs are there, so a run after a
crash, or with another map, does not redo the rest; --parts runs some alone, --fresh redoes all.

Options after `--` go to every roller run (e.g. a coarser mesh: `-- -mesh_h 0.05 -mesh_h_contact 0.0112`). A step
that fails is named in the report with its error line; the later steps still run where they can, and the driver
exits 1.
"""
import argparse
import csv
import itertools
import json
import math
import os
import shlex
import subprocess
import sys
import time

import numpy as np

from . import journal, onedof, report

# Non-dimensional scenes are heard as the same roller at a real size and rubber: the printer roller's (docs/squeal.md
# 7.1: r_outer 12.5 mm, shear wave speed 23.6 m/s). Time then scales as length / wave speed.
REF_R_OUTER, REF_SHEAR_SPEED, REF_DENSITY = 0.0125, 23.6, 1200.0
# roller's defaults (src/app/options.c) for what the scene may leave out
DEFAULTS = {"r_inner": 0.25, "r_outer": 0.5, "young": 0.1, "poisson": 0.49, "density": 1.0, "omega": math.pi / 10,
            "obstacle_depth": 0.025, "sheet_speed": 0.0, "friction": 0.0, "viscosity": 0.0, "damping": 0.0}


def scene_options(path, extra):
    """The scene's options as {name: string}: the YAML file's (flat `name: value`) overridden by the extra
    command-line options (`-name value`, or `-flag` alone)."""
    import yaml

    with open(path) as f:
        opts = {str(k): ("true" if v is True else "false" if v is False else str(v)) for k, v in (yaml.safe_load(f) or {}).items()}
    k = 0
    while k < len(extra):
        name = extra[k].lstrip("-")
        if k + 1 < len(extra) and not (extra[k + 1].startswith("-") and not _is_number(extra[k + 1])):
            opts[name], k = extra[k + 1], k + 2
        else:
            opts[name], k = "true", k + 1
    return opts


def _is_number(s):
    try:
        float(s)
        return True
    except ValueError:
        return False


def value(opts, name):
    return float(opts.get(name, DEFAULTS[name]))


def detect_units(opts):
    """'si' when the modulus is a real rubber's in Pa (>= 1e3: the non-dimensional scenes have young ~ 0.1 and
    r_outer 0.5, an SI roller young ~ 1e6 and r_outer ~ 0.01), else 'nd'."""
    return "si" if value(opts, "young") >= 1e3 else "nd"


def scene_json(name, opts, units, listener=None, seconds_per_unit=None):
    """scene.json (docs/squeal.md 9.1) from the scene's options; listener: {distance_m, width_m, angle_deg};
    seconds_per_unit: the time scale of a non-dimensional scene given explicitly (default: the printer roller's size
    and rubber, below)."""
    omega, r = value(opts, "omega"), value(opts, "r_outer")
    surface = omega * r
    scene = {"name": name, "units": units, "friction": value(opts, "friction"), "sheet_speed": value(opts, "sheet_speed"),
             "surface_speed": surface, "creep": 1.0 - value(opts, "sheet_speed") / surface if surface else float("nan"),
             "r_outer": r, "metres_per_unit": 1.0 if units == "si" else REF_R_OUTER / r}
    if opts.get("rubber", "kelvin_voigt") == "maxwell":  # the modes' CSV gives each mode's loss factor (rubber_loss_factor)
        scene["rubber"] = "maxwell"
        if "rubber_loss_factor" in opts:
            scene["loss_factor"] = float(opts["rubber_loss_factor"])
    else:
        scene["kelvin_voigt_tau"] = value(opts, "viscosity")
    if listener:
        scene["listener"] = dict(listener)
    if "friction_static" in opts:
        scene["friction_static"] = float(opts["friction_static"])
    if units == "nd":  # the roller at the reference size and rubber: t_si = s t_nd
        c_nd = math.sqrt(value(opts, "young") / (2 * (1 + value(opts, "poisson"))) / value(opts, "density"))
        scene["seconds_per_unit"] = (REF_R_OUTER / r) * (c_nd / REF_SHEAR_SPEED)
        scene["time_scale_note"] = (f"the roller heard at the printer roller's size and rubber: r_outer {REF_R_OUTER} m, "
                                    f"shear wave speed {REF_SHEAR_SPEED} m/s")
        if seconds_per_unit:
            scene["seconds_per_unit"] = float(seconds_per_unit)
            scene["time_scale_note"] = "given: rollerreport.run --seconds-per-unit"
        # forces: stress = rho (L / s)^2 at the reference rubber's density, times the length scale (per unit width)
        speed = scene["metres_per_unit"] / scene["seconds_per_unit"]
        scene["newtons_per_metre_per_unit"] = REF_DENSITY / value(opts, "density") * speed ** 2 * scene["metres_per_unit"]
    if onedof.is_axle(opts):
        scene["axle"] = True
        scene["drive_started"] = onedof.value(opts, "theta_start") + onedof.value(opts, "drive_ramp")
        if onedof.value(opts, "drive_stiffness") > 0:  # the 1-DOF needs the drive's spring
            lin = onedof.stability(opts)
            lin["start_from_rest"] = onedof.start_from_rest(opts)
            scene["onedof"] = lin
    return scene


def map_grid(scene, creeps=None, frictions=None):
    """(creeps, sheet speeds, frictions) of the map: by default the creeps c/2, c, 2c and 1 (the sheet held: full
    sliding, a jam) around the scene's c, and the frictions mu/2, mu and the largest allowed (the static coefficient
    of a weakening law, which -friction may not exceed, else 1.5 mu). The scene's own creep and friction are always
    in the map (its cell is the CEA's case: the scene's -sheet_speed as given)."""
    c, mu = scene["creep"], scene["friction"]
    if creeps is None:
        creeps = [c / 2, 2 * c, 1.0] if c > 0 else [0.01, 0.1, 1.0]
    if frictions is None:
        top = scene.get("friction_static", mu)
        frictions = [mu / 2, top if top > mu else 1.5 * mu]
    creeps = sorted(set([c] + [x for x in creeps if abs(x - c) > 1e-9]))
    speeds = [scene["sheet_speed"] if x == c else scene["surface_speed"] * (1 - x) for x in creeps]
    return creeps, speeds, sorted(set([mu] + [x for x in frictions if abs(x - mu) > 1e-12]))


def leading_row(path):
    """(row index in the CSV, row) of the least stable mode (rollerreport.report.leading_mode)."""
    rows = report.read_rows(path)
    mode = report.leading_mode(rows)
    return rows.index(mode), mode


def modes_parameter(modes_h5, name):
    """A value of the CEA's /parameters (modes.h5)."""
    import h5py

    with h5py.File(modes_h5, "r") as f:
        return float(np.asarray(f["parameters"].attrs[name]).ravel()[0])


def mesh_options(modes_h5, extra):
    """The CEA's mesh as options (its /parameters), except those the extra options give."""
    import h5py

    with h5py.File(modes_h5, "r") as f:
        par = dict(f["parameters"].attrs)
    out = []
    for name in ("mesh_h", "mesh_h_contact", "mesh_contact_layer", "degree"):
        if name in par and f"-{name}" not in extra:
            v = np.asarray(par[name]).ravel()[0]
            out += [f"-{name}", repr(float(v)) if name != "degree" else str(int(v))]
    return out


class Steps:
    """Runs the commands of the report, each with its log in OUTDIR/logs, as journalled parts (journal.json: reused
    when their inputs are unchanged), and records them (commands.json)."""

    def __init__(self, out, roller, only=None):
        self.out, self.done, self.only = out, [], only
        self.journal = journal.Journal(out)
        self.roller = roller
        self.env = dict(os.environ)
        if hasattr(os, "geteuid") and os.geteuid() == 0:  # Open MPI refuses root unless told (containers, CI)
            self.env.setdefault("OMPI_ALLOW_RUN_AS_ROOT", "1")
            self.env.setdefault("OMPI_ALLOW_RUN_AS_ROOT_CONFIRM", "1")
        self.env.setdefault("OMPI_MCA_rmaps_base_oversubscribe", "1")
        os.makedirs(os.path.join(out, "logs"), exist_ok=True)

    def run(self, name, cmd, what, outputs=(), inputs=(), ranks=1):
        """Run cmd as part `name` unless the journal has it done with the same command, scene, executable and input
        files (then reused; a part left out of --parts is reused too when it is done); True when it succeeded."""
        self.journal = journal.Journal(self.out)
        if self.only is not None and name not in self.only:
            entry = self.journal.parts.get(name)
            if entry and entry.get("command_record"):
                self.done.append(dict(entry["command_record"], step=name, reused=True))
                self.save()
            return bool(entry and entry.get("status") == "ok")
        files = [self.roller] + [a for a in cmd if a.endswith((".yaml", ".yml"))] + list(inputs)
        digest = journal.inputs_hash({"command": cmd}, files)
        record = {}

        def go():
            ok = self._run(name, cmd, what, record)
            return ok, {"command_record": dict(record)}

        entry = self.journal.run(name, digest, list(outputs), go, ranks=ranks, what=what)
        if entry.get("reused"):
            record = dict(entry.get("command_record", {}), reused=True)
            print(f"rollerreport.run: {name}: reused (its inputs unchanged: journal.json)", flush=True)
        self.done.append(dict(record, step=name))
        self.save()
        return entry.get("status") == "ok"

    def _run(self, name, cmd, what, record):
        log = os.path.join(self.out, "logs", f"{name}.log")
        print(f"rollerreport.run: {name}: {shlex.join(cmd)}", flush=True)
        t0 = time.time()
        with open(log, "w") as f:
            rc = subprocess.run(cmd, stdout=f, stderr=subprocess.STDOUT, cwd=self.out, env=self.env).returncode
        seconds = time.time() - t0
        error = ""
        if rc:
            with open(log, errors="replace") as f:
                lines = f.read().splitlines()
            skip = ("#", "Option Table", "See https", "Petsc Release", "Configure options", " on a ", "---")
            err = []
            for ln in lines:  # the error's lines up to PETSc's option table (its entries start with "-")
                if "PETSC ERROR" not in ln:
                    continue
                if any(w in ln for w in ("Option Table", "Option left", "option(s) set that were not used")):
                    break
                err.append(ln.split("ERROR:")[-1].strip())
            err = [e for e in err if e and not e.startswith("---") and not any(w in e for w in skip)]
            error = ": ".join(err[:2]) if err else (lines[-1] if lines else f"exit {rc}")
        record.update({"step": name, "what": what, "command": shlex.join(cmd), "cwd": self.out,
                       "seconds": round(seconds, 1), "returncode": rc, "error": error, "log": f"logs/{name}.log"})
        if rc and REFUSED in error:  # roller does not carry the scene here (PETSC_ERR_SUP): "not run", not a failure
            record["refused"] = True
        print(f"rollerreport.run: {name}: {'ok' if not rc else 'FAILED (' + error + ')'} in {seconds:.1f} s", flush=True)
        return rc == 0

    def save(self):
        with open(os.path.join(self.out, "commands.json"), "w") as f:
            json.dump(self.done, f, indent=1)


def map_command(base, scene, a, extra, out):
    """The map's sweep command and its description."""
    creeps, speeds, mus = map_grid(scene, [float(x) for x in a.creeps.split(",")] if a.creeps else None,
                                   [float(x) for x in a.frictions.split(",")] if a.frictions else None)
    mpi = [a.mpiexec, "-n", str(a.ranks)] if a.ranks > 1 else []
    cmd = mpi + base + ["-modes", "-modes_nev", str(a.nev), "-sweep", os.path.join(out, "sweep.csv"), "-sweep_sheet_speed",
                        ",".join(repr(v) for v in speeds), "-sweep_friction", ",".join(repr(v) for v in mus), "-quiet"]
    return cmd + extra, f"the map over creep {[round(x, 6) for x in creeps]} (sheet_speed) and friction {mus} (docs/squeal.md 6)"


def transient_command(base, opts, a, extra, out, scene):
    """The seeded transient's command and its description; records the seeded mode in scene."""
    j = lambda f: os.path.join(out, f)  # noqa: E731
    rows = report.read_rows(j("modes.csv"))
    k, mode = leading_row(j("modes.csv")) if a.mode is None else (a.mode, rows[a.mode])
    if not float(mode["im"]) > 0:
        raise SystemExit(f"rollerreport.run: --mode {k}: row {k} of modes.csv has Im lambda = {mode['im']}; allowed: a "
                         "row with Im lambda > 0 (an oscillating mode)")
    f = float(mode["im"]) / (2 * math.pi)
    dt = 1.0 / (f * a.steps_per_period)
    n = int(math.ceil(a.periods * a.steps_per_period))
    amp = a.amplitude if a.amplitude is not None else 0.02 * value(opts, "obstacle_depth")
    scene["seeded_mode"] = {"row": k, "re": float(mode["re"]), "im": float(mode["im"]), "dt": dt, "steps": n}
    cmd = base + mesh_options(j("modes.h5"), extra) + [
        "-ts_scheme", "dmf", "-ts_dt", repr(dt), "-ts_max_time", repr(n * dt), "-ts_max_steps", str(n),
        "-obstacle_speed", "1e6", "-initial_condition", "mode", "-initial_mode_file", j("modes.h5"), "-initial_mode",
        str(k), "-ic_amplitude", repr(amp), "-monitor_csv", j("transient.csv"), "-monitor_surface_csv", j("surface.csv"), "-output", j("transient.h5"),
        "-output_every", str(output_every(a)), "-checkpoint", j("checkpoint.h5"), "-quiet"]
    what = (f"the transient seeded on mode {k} ({'the least stable' if a.mode is None else 'chosen'}) about the CEA's "
            f"steady state, {a.steps_per_period:g} steps per period, {a.periods:g} periods (docs/squeal.md 4.2)")
    return cmd + extra, what


def cea_command(base, a, extra, out):
    """The CEA: `roller -options_file SCENE -modes` with the scene's options (on an axle scene -modes takes -axle:
    docs/squeal.md 3.1; what it refuses there, e.g. -rubber maxwell or -sheet_mass, fails the part with roller's
    message, which the report gives as flutter's "not run")."""
    j = lambda f: os.path.join(out, f)  # noqa: E731
    return base + ["-modes", "-modes_nev", str(a.nev), "-modes_csv", j("modes.csv"), "-modes_output", j("modes.h5"),
                   "-modes_steady_csv", j("steady.csv")] + extra


def output_every(a):
    """The fields' stride: 10 frames per period of the seeded mode (the animation's frames)."""
    return max(1, int(round(a.steps_per_period / 10)))


def base_command(cmd):
    """The seeded transient's command unseeded (-ic_amplitude 0), its monitor into transient_base.csv and its fields
    into transient_base.h5 at the same steps: the report fits the seed's own response, the seeded run's columns
    minus these (the start, the contact law settling from the CEA's steady state, excites the same lines in both:
    docs/squeal.md 4.4.1, 4.4.4), and the animation shows the seeded run's displacement minus this one's."""
    out, k = [], 0
    while k < len(cmd):
        name = cmd[k]
        if name in ("-ic_amplitude", "-monitor_csv", "-monitor_surface_csv", "-checkpoint", "-output") and k + 1 < len(cmd):
            d = os.path.dirname(cmd[k + 1])
            value = {"-ic_amplitude": "0", "-monitor_csv": os.path.join(d, "transient_base.csv"),
                     "-monitor_surface_csv": os.path.join(d, "surface_base.csv"),
                     "-checkpoint": os.path.join(d, "checkpoint_base.h5"), "-output": os.path.join(d, "transient_base.h5")}[name]
            out += [name, value]
            k += 2
            continue
        out.append(name)
        k += 1
    return out, "the same transient unseeded (-ic_amplitude 0): the report fits the seeded run minus this one"


# what a run writes into OUTDIR: --fresh removes them first; else each part removes its own before it runs again
OUTPUTS = ("modes.csv", "modes.h5", "modes.xmf", "steady.csv", "sweep.csv", "transient.csv", "surface.csv", "transient_base.csv", "surface_base.csv",
           "transient.h5", "transient.xmf", "transient_base.h5", "transient_base.xmf", "scene.json", "commands.json",
           "journal.json", "report.md", "report.json", "report.html", "map.png", "squeal.wav", "sound.csv", "spectrogram.png",
           "vibration.gif", "vibration.mp4", "mesh.h5", "mesh.xmf", "stickslip.h5", "stickslip.xmf", "basis.h5", "propensity_basis.h5", "propensity_cases.csv",
           "propensity_table.json", "propensity_runs.csv", "propensity_cea.csv", "propensity.json", "propensity.csv", "propensity.png",
           "ripple_sweep_cases.csv", "ripple_sweep_runs.csv", "ripple_sweep.csv", "ripple_sweep.json", "ripple_sweep.png",
           "disturbances_cases.csv", "disturbances_runs.csv", "disturbances.csv", "disturbances.json", "disturbances.png",
           "divergent_cases.csv", "divergent_runs.csv", "divergent.csv", "divergent.json")
# PETSc's message for PETSC_ERR_SUP: what roller refuses as not carried (e.g. -modes with -rubber maxwell or
# -sheet_mass): the part is "not run" with roller's reason, and the driver does not count it as failed
REFUSED = "No support for this operation"
ROLLER_PARTS = ("cea", "map", "transient", "transient_base", "mesh", "basis", "stickslip", "forced", "ripple_sweep_runs",
                "ripple_sweep", "disturbances_runs", "disturbances", "divergent_runs", "divergent", "propensity_table",
                "propensity_basis", "propensity_cea", "propensity_runs", "propensity")


def parse(argv):
    p = argparse.ArgumentParser(prog="python3 -m rollerreport.run", description=__doc__,
                                formatter_class=argparse.RawDescriptionHelpFormatter,
                                epilog="-- OPTIONS: roller options for every run (after the driver's own)")
    p.add_argument("scene", help="the scene's YAML options file (jobs/*.yaml)")
    p.add_argument("out", help="the output folder (created)")
    p.add_argument("--roller", default=None, help="the executable (default: build/roller of this source tree)")
    p.add_argument("--ranks", type=int, default=1, help="ranks of the map's sweep (mpiexec -n N; default 1)")
    p.add_argument("--mpiexec", default="mpiexec")
    p.add_argument("--units", choices=("auto", "si", "nd"), default="auto",
                   help="si (Pa, m, s: the pitch is the mode's frequency) or nd (non-dimensional: heard at the printer "
                        "roller's size and rubber); auto: si when -young >= 1e3")
    p.add_argument("--nev", type=int, default=40, help="-modes_nev of the CEA and the map (default 40)")
    p.add_argument("--creeps", default=None, help="the map's creeps besides the scene's c, comma-separated (default c/2, "
                   "2c, 1: 1 is the sheet held, full sliding)")
    p.add_argument("--frictions", default=None, help="the map's frictions besides the scene's mu (default mu/2 and mu_s, "
                   "else 1.5 mu)")
    p.add_argument("--no-map", action="store_true", help="skip the map")
    p.add_argument("--steps-per-period", type=float, default=100, help="transient: dt = period / this (default 100)")
    p.add_argument("--periods", type=float, default=8, help="transient: its length in periods of the mode (default 8)")
    p.add_argument("--amplitude", type=float, default=None,
                   help="-ic_amplitude of the seeded mode (default 2 %% of -obstacle_depth)")
    p.add_argument("--mode", type=int, default=None, help="the seeded mode's row in modes.csv (default the least stable)")
    p.add_argument("--parts", default=None, help="the parts to run, comma-separated, of "
                   f"{', '.join(ROLLER_PARTS + report.PARTS)} (default all; the others are reused if done: journal.json)")
    p.add_argument("--fresh", action="store_true", help="remove what an earlier run wrote and redo every part")
    p.add_argument("--distance", type=float, default=1.0, help="the listener's distance from the roller's axis in m "
                   "(default 1: the bystander position of ISO 7779 / ECMA-74)")
    p.add_argument("--width", type=float, default=0.030, help="the roller's width in m (default 0.030, the printer "
                   "roller's: docs/squeal.md 7.1); nd scenes: at the printer roller's size")
    p.add_argument("--angle", type=float, default=90.0, help="the listener's direction in degrees (default 90: above the "
                   "roller; the sheet is at -90)")
    p.add_argument("--seconds-per-unit", type=float, default=None, help="non-dimensional scenes: seconds of audio per unit "
                   "of the scene's time (default: the printer roller's size and rubber, docs/squeal.md 9.2)")
    p.add_argument("--wav-full-scale-db", type=float, default=None, help="squeal.wav's full scale, a sine of this dB SPL "
                   "(default 94; raised by 10 dB steps when the peak does not fit; stated in report.json)")
    p.add_argument("--stickslip-time", type=float, default=None, help="axle scenes: the start from rest's -ts_max_time "
                   "(default the scene's, at least 0.5 s of audio)")
    p.add_argument("--ripple", default=None, help="axle scenes: AMPLITUDE,FREQUENCY of the motor's ripple for the forced "
                   "run (-drive_ripple, -drive_ripple_frequency; default the scene's, none if it has none)")
    p.add_argument("--ripple-sweep", type=int, default=24, help="axle scenes with a ripple: the forced response swept "
                   "over this many log-spaced frequencies of the audible band (100 Hz-5 kHz) plus the CEA's modes, each a "
                   "run of one -sweep map (default 24, 0: none)")
    p.add_argument("--disturbance-periods", type=float, default=40, help="axle scenes: kicks of growing size about the "
                   "steady state (rollerreport.disturbances), each run this many periods of the drive's mode after the kick, "
                   "one -sweep map on the reduced model (default 40, 0: none)")
    p.add_argument("--starts", type=int, choices=(0, 1), default=1, help="clamped scenes: the scene's start from rest and "
                   "its map's divergent cells' run on the reduced model until the CEA's least stable mode has died out, and "
                   "classified (rollerreport.divergent; default 1, 0: none)")
    p.add_argument("--forced-options", default="", help="axle scenes: roller options of the forced run besides the "
                   "ripple, e.g. '-theta_start 0 -drive_ramp 0 -nip_ramp 60' (a start sliding)")
    p.add_argument("--model", choices=("full", "rom"), default="full", help="axle scenes: the heard runs (the start from "
                   "rest, the forced run) on the full finite elements or the reduced model (-rom -rom_input basis.h5; the "
                   "maps, the ripple sweep and the propensity, always run on it). Default full: the reduced contact's "
                   "friction force rings near a quarter of the step's rate, 10-15 times the full model's, which the WAV "
                   "would carry (docs/squeal.md 9.4)")
    p.add_argument("--propensity-cases", type=int, default=64, help="axle scenes: the propensity study's cases (Latin "
                   "hypercube; default 64, 0: none)")
    p.add_argument("--propensity-seed", type=int, default=38, help="the propensity's sampling seed (default 38)")
    p.add_argument("--propensity-model", choices=("fe", "onedof"), default="fe", help="the propensity's classifier: fe, "
                   "every case's CEA and its start from rest on the reduced model (roller -sweep -sweep_cases on --ranks), "
                   "the 1-DOF's class beside it; onedof, rollerref's 1-DOF alone (seconds; default fe)")
    p.add_argument("--propensity-periods", type=float, default=40, help="fe: each case's start from rest runs this many "
                   "periods of the drive's mode after the motor started (default 40)")
    p.add_argument("--propensity-nev", type=int, default=None, help="fe: -modes_nev of each case's CEA (default --nev)")
    p.add_argument("--propensity-options", default="", help="fe: roller options of the propensity's runs besides the "
                   "scene's and those after --, e.g. a coarser mesh '-mesh_h 0.0012 -mesh_h_contact 3e-4' (its own basis)")
    cut = argv.index("--") if "--" in argv else len(argv)
    return p.parse_args(argv[:cut]), argv[cut + 1 :]


def main(argv=None):
    a, extra = parse(sys.argv[1:] if argv is None else list(argv))
    src = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
    roller = os.path.abspath(a.roller or os.path.join(src, "build", "roller"))
    scene_path, out = os.path.abspath(a.scene), os.path.abspath(a.out)
    only = None if a.parts is None else [x for x in a.parts.split(",") if x]
    bad = [x for x in only or [] if x not in ROLLER_PARTS + report.PARTS]
    if bad:
        raise SystemExit(f"rollerreport.run: --parts {a.parts}: unknown {', '.join(bad)}; allowed: "
                         f"{', '.join(ROLLER_PARTS + report.PARTS)}")
    os.makedirs(out, exist_ok=True)
    if a.fresh:
        for name in OUTPUTS:
            for stale in (name, name + ".part"):
                if os.path.exists(os.path.join(out, stale)):
                    os.remove(os.path.join(out, stale))
    opts = scene_options(scene_path, extra)
    listener = {"distance_m": a.distance, "width_m": a.width, "angle_deg": a.angle}
    scene = scene_json(os.path.splitext(os.path.basename(scene_path))[0], opts,
                       detect_units(opts) if a.units == "auto" else a.units, listener, a.seconds_per_unit)
    if a.wav_full_scale_db is not None:
        scene["wav_full_scale_db"] = a.wav_full_scale_db
    steps = Steps(out, roller, only)
    base = [roller, "-options_file", scene_path]
    j = lambda f: os.path.join(out, f)  # noqa: E731
    cea_ok = steps.run("cea", cea_command(base, a, extra, out),
                       "the steady state and its complex eigenvalues (docs/squeal.md 3" + (", 3.1: on the axle)" if scene.get("axle") else ")"),
                       outputs=["modes.csv", "modes.h5", "modes.xmf", "steady.csv"])
    if scene.get("axle"):
        axle_parts(steps, base, opts, scene, a, extra, out)
        finish = report_step(steps, scene, out, src, only)
        return finish

    if not a.no_map:
        steps.run("map", *map_command(base, scene, a, extra, out), outputs=["sweep.csv"], ranks=a.ranks)
    if cea_ok:
        seeded, what = transient_command(base, opts, a, extra, out, scene)
        if steps.run("transient", seeded, what, outputs=["transient.csv", "surface.csv", "transient.h5", "transient.xmf"],
                     inputs=[j("modes.h5")]):
            steps.run("transient_base", *base_command(seeded), outputs=["transient_base.csv", "surface_base.csv", "transient_base.h5",
                                                                        "transient_base.xmf"], inputs=[j("modes.h5")])
    divergent_part(steps, base, opts, scene, a, extra, out)
    return report_step(steps, scene, out, src, only)


def axle_parts(steps, base, opts, scene, a, extra, out):
    """The parts of a scene on the axle besides the CEA (run by main as for any scene; scene.json's "onedof", the 1-DOF
    closed form, is its cross-check on the drive's mode): the start from rest to its limit cycle (stickslip.csv, stickslip_surface.csv), long enough for
    0.5 s of audio; the forced run with the ripple (the start from rest itself when the scene carries that ripple:
    scene.json's ripple "files"); the propensity study (rollerreport.propensity)."""
    j = lambda f: os.path.join(out, f)  # noqa: E731
    s = scene.get("seconds_per_unit", 1.0)
    # at least 0.5 s of audio after the first row (the state before the first contact solve, left out) and whatever
    # the last step falls short of -ts_max_time: 2 % more
    T = a.stickslip_time or max(float(opts.get("ts_max_time", 0.0)), 0.5 / s * 1.02)
    steps.run("mesh", base + ["-ts_max_steps", "0", "-output", j("mesh.h5"), "-quiet"] + extra,
              "the mesh alone (no step): its vertices on the outer circle set the mesh-passing lines the sound leaves out "
              "(rollerreport.lines)", outputs=["mesh.h5", "mesh.xmf"])
    # the reduced model's basis, read by the maps (the ripple sweep, the propensity) and, with --model rom, by the heard
    # runs too (full by default: the reduced contact rings near a quarter of the step's rate, docs/squeal.md 9.4)
    reduced = ["-rom", "-rom_input", j("basis.h5")]
    basis_part(steps, base, extra, j("basis.h5"), "basis")
    rom, inputs = (reduced, [j("basis.h5")]) if a.model == "rom" else ([], [])
    window = animation_window(opts, T, j("stickslip.h5"))
    steps.run("stickslip", base + rom + ["-ts_max_time", repr(T), "-monitor_csv", j("stickslip.csv"), "-monitor_surface_csv",
                                         j("stickslip_surface.csv")] + window + ["-quiet"] + extra,
              f"the start from rest on the axle to t = {T:.5g} ({T * s:.3g} s of audio){' on the reduced model' if rom else ''}: "
              "the stick-slip limit cycle (docs/squeal.md 9.4); its fields over the last periods for the animation",
              outputs=["stickslip.csv", "stickslip_surface.csv"] + (["stickslip.h5", "stickslip.xmf"] if window else []), inputs=inputs)
    ripple = [float(x) for x in a.ripple.split(",")] if a.ripple else (
        [onedof.value(opts, "drive_ripple"), onedof.value(opts, "drive_ripple_frequency")])
    if ripple[0] and ripple[1] and "onedof" in scene:
        from rollerref import forced as ref_forced

        lin = scene["onedof"]
        p = onedof.torsion(opts, ripple=False)
        ref = ref_forced.one_dof(p.I, p.k_d, p.c_d, ripple[1], ripple[0], c_f=lin["c_eff"] - p.c_d)
        scene["ripple"] = {"amplitude": ripple[0], "frequency": ripple[1], "one_dof": ref}
        own = [onedof.value(opts, "drive_ripple"), onedof.value(opts, "drive_ripple_frequency")]
        if not a.forced_options and ripple == own:  # the scene runs with its own ripple: the start from rest is the forced run
            scene["ripple"]["files"] = ["stickslip.csv", "stickslip_surface.csv"]
            ripple_sweep_part(steps, base + reduced, opts, scene, a, extra, out, ripple, [j("basis.h5")])
            disturbances_part(steps, base + reduced, opts, scene, a, extra, out, [j("basis.h5")])
            return propensity_part(steps, base, opts, a, extra, out)
        more = a.forced_options.split()
        steps.run("forced", base + rom + more + ["-drive_ripple", repr(ripple[0]), "-drive_ripple_frequency", repr(ripple[1]),
                                                 "-ts_max_time", repr(T), "-monitor_csv", j("forced.csv"), "-monitor_surface_csv",
                                                 j("forced_surface.csv"), "-quiet"] + extra,
                  f"the motor's ripple {ripple[0]:g} rad at {ripple[1]:g} per unit time: the forced response "
                  "(docs/squeal.md 9.4)", outputs=["forced.csv", "forced_surface.csv"], inputs=inputs)
        ripple_sweep_part(steps, base + reduced + more, opts, scene, a, extra, out, ripple, [j("basis.h5")])
    disturbances_part(steps, base + reduced, opts, scene, a, extra, out, [j("basis.h5")])
    propensity_part(steps, base, opts, a, extra, out)


ANIMATION_PERIODS, ANIMATION_FRAMES = 3, 150  # the axle's animation: the heard run's last periods of the drive's mode


def animation_window(opts, t_end, h5):
    """The heard run's fields for the animation (rollerreport.animation.load_window): -output over its last
    ANIMATION_PERIODS periods of the drive's mode (the 1-DOF's frequency), about ANIMATION_FRAMES frames; none without a
    drive or a -ts_dt to count the steps by."""
    f = onedof.stability(opts)["frequency"] if onedof.value(opts, "drive_stiffness") > 0 else 0.0
    if not f or f <= 0 or "ts_dt" not in opts:
        return []
    window = min(ANIMATION_PERIODS / f, 0.5 * t_end)
    every = max(1, int(round(window / float(opts["ts_dt"]) / ANIMATION_FRAMES)))
    return ["-output", h5, "-output_every", str(every), "-output_start", repr(t_end - window)]


def ripple_sweep_part(steps, base, opts, scene, a, extra, out, ripple, inputs):
    """The forced mechanism's sweep (rollerreport.ripple_sweep): the ripple's amplitude at --ripple-sweep frequencies
    over the audible band and the CEA's modes, one -sweep -sweep_cases map on --ranks (part ripple_sweep_runs), then the
    response read from each case's series (part ripple_sweep)."""
    if a.ripple_sweep <= 0:
        return
    from . import ripple_sweep

    j = lambda f: os.path.join(out, f)  # noqa: E731
    modes = report.read_rows(j("modes.csv")) if os.path.exists(j("modes.csv")) else []
    dt = float(opts["ts_dt"]) if "ts_dt" in opts else None
    if dt is None and os.path.exists(j("stickslip.csv")):  # the run's step: its rows 1 and 2 (not the whole 0.5 s CSV)
        with open(j("stickslip.csv"), newline="") as f:
            t = [float(r["t"]) for r in itertools.islice(csv.DictReader(f), 1, 3)]
        dt = t[1] - t[0]
    s = scene.get("seconds_per_unit", 1.0)
    freqs, cea_modes = ripple_sweep.frequencies(modes, s, dt, a.ripple_sweep, also=[ripple[1]])
    started = scene.get("drive_started", 0.0)
    t_end = ripple_sweep.run_length(started, freqs)
    ripple_sweep.write_cases(out, freqs, ripple[0])
    os.makedirs(j("ripple_sweep"), exist_ok=True)
    steps.run("ripple_sweep_runs", ripple_sweep.command(base, extra, out, t_end, a.ranks, a.mpiexec),
              f"the motor's ripple {ripple[0]:g} rad swept over {len(freqs)} frequencies {freqs[0] / s:.4g}-{freqs[-1] / s:.4g} Hz "
              f"and the CEA's modes, each run to t = {t_end:.5g} (docs/squeal.md 9.4)", outputs=[ripple_sweep.RUNS],
              inputs=[j(ripple_sweep.CASES)] + list(inputs), ranks=a.ranks)
    if steps.only is not None and "ripple_sweep" not in steps.only:
        return
    src = [os.path.join(os.path.dirname(__file__), f) for f in ("ripple_sweep.py", "cycle.py")]
    digest = journal.inputs_hash({"part": "ripple_sweep", "freqs": freqs, "ripple": ripple}, src + [j(ripple_sweep.RUNS)])

    def go():
        if not os.path.exists(j(ripple_sweep.RUNS)):
            return False, {"error": "the sweep's map is missing (logs/ripple_sweep_runs.log)"}
        r = ripple_sweep.classify(out, freqs, ripple[0], cea_modes, started, s, ripple[1])
        ripple_sweep.figure(out)
        return True, {"result": {"peak_hz": (r["peak"] or {}).get("frequency_hz")}}

    steps.journal = journal.Journal(out)
    steps.journal.run("ripple_sweep", digest, ["ripple_sweep.json", "ripple_sweep.csv", "ripple_sweep.png"], go,
                      what=f"the forced response against the ripple's frequency ({len(freqs)} runs; docs/squeal.md 9.4)")


def disturbances_part(steps, base, opts, scene, a, extra, out, inputs):
    """The stick-slip mechanism's kicks of growing size about the steady state (rollerreport.disturbances): one -sweep
    -sweep_cases map on the reduced model and --ranks (part disturbances_runs), then each case read (part
    disturbances)."""
    from . import disturbances

    p = disturbances.plan(opts, a.disturbance_periods) if a.disturbance_periods > 0 else None
    if p is None:
        return
    j = lambda f: os.path.join(out, f)  # noqa: E731
    disturbances.write_cases(out, p)
    os.makedirs(j("disturbances"), exist_ok=True)
    steps.run("disturbances_runs", disturbances.command(base, extra, out, p, a.ranks, a.mpiexec),
              f"{len(p['kicks']) - 1} kicks of the hub of growing size (0.1-150 % of the motor's rate) about the steady state "
              f"at t = {p['t_kick']:.5g} and the undisturbed approach, each run to t = {p['t_end']:.5g} (docs/squeal.md 9.5)",
              outputs=[disturbances.RUNS], inputs=[j(disturbances.CASES)] + list(inputs), ranks=a.ranks)
    if steps.only is not None and "disturbances" not in steps.only:
        return
    src = [os.path.join(os.path.dirname(__file__), f) for f in ("disturbances.py", "propensity_fe.py", "cycle.py", "onedof.py")]
    digest = journal.inputs_hash({"part": "disturbances", "plan": p, "options": opts}, src + [j(disturbances.RUNS), j("modes.csv")])

    def go():
        if not os.path.exists(j(disturbances.RUNS)):
            return False, {"error": "the kicks' map is missing (logs/disturbances_runs.log)"}
        rows = report.read_rows(j("modes.csv")) if os.path.exists(j("modes.csv")) else []
        cea_stable = bool(all(report.num(r.get("re")) <= 0 for r in rows)) if rows else None  # no eigenvalue in the right half-plane
        r = disturbances.classify(out, opts, p, scene.get("seconds_per_unit", 1.0), cea_stable)
        disturbances.figure(out)
        return True, {"result": {"coexists": r["coexists"], "smallest_kick": (r["smallest_kick"] or {}).get("kick_rate_fraction")}}

    steps.journal = journal.Journal(out)
    steps.journal.run("disturbances", digest, ["disturbances.json", "disturbances.csv", "disturbances.png"], go,
                      what=f"kicks of growing size about the steady state ({len(p['kicks'])} runs; docs/squeal.md 9.5)")


def divergent_part(steps, base, opts, scene, a, extra, out):
    """A clamped scene's starts (rollerreport.divergent): its own start from rest and its map's divergent cells', one
    -sweep -sweep_cases map on the reduced model (the CEA's mesh, its basis: part basis) and --ranks, each run until the
    CEA's least stable oscillating mode has died out (part divergent_runs), then each read (part divergent); none with
    --starts 0 or without the scene's -ts_max_time."""
    from . import divergent

    j = lambda f: os.path.join(out, f)  # noqa: E731
    rows = report.read_rows(j("modes.csv")) if os.path.exists(j("modes.csv")) else []
    osc = [report.num(r["growth_rate"]) for r in rows if report.num(r.get("im")) > 0]
    decay = -max(osc) if osc and max(osc) < 0 else None
    p = divergent.plan(opts, scene, j("sweep.csv"), decay) if a.starts else None
    if p is None:
        return
    divergent.write_cases(out, p)
    os.makedirs(j("divergent"), exist_ok=True)
    mesh = mesh_options(j("modes.h5"), extra) if os.path.exists(j("modes.h5")) else []
    # the scene's own step (the CEA's /parameters dt: from the scene's -ts_max_time), not the longer run's (whose
    # accuracy rule would shorten it, and raise the reduced model's cutoff with it)
    step = ["-ts_dt", repr(modes_parameter(j("modes.h5"), "dt"))] if mesh and "-ts_dt" not in extra and "ts_dt" not in opts else []
    basis_part(steps, base + mesh + step + ["-ts_max_time", repr(p["t_end"])], extra, j("basis.h5"), "basis")
    steps.run("divergent_runs", divergent.command(base + mesh + step, extra, out, p, a.ranks, a.mpiexec, j("basis.h5")),
              f"the scene's start from rest and its map's {len(p['cases']) - 1} other divergent cells' (a real positive "
              f"eigenvalue), each run to t = {p['t_end']:.5g} on the reduced model (docs/squeal.md 9.6)",
              outputs=[divergent.RUNS], inputs=[j(divergent.CASES), j("basis.h5")], ranks=a.ranks)
    if steps.only is not None and "divergent" not in steps.only:
        return
    src = [os.path.join(os.path.dirname(__file__), f) for f in ("divergent.py", "cycle.py", "propensity_fe.py", "lines.py")]
    digest = journal.inputs_hash({"part": "divergent", "plan": p}, src + [j(divergent.RUNS), j("steady.csv"), j("transient.h5")])

    def go():
        if not os.path.exists(j(divergent.RUNS)):
            return False, {"error": "the starts' map is missing (logs/divergent_runs.log)"}
        from .lines import mesh_passing

        f_m = mesh_passing(j("transient.h5")) if os.path.exists(j("transient.h5")) else None
        r = divergent.classify(out, p, scene.get("seconds_per_unit", 1.0), f_m)
        return True, {"result": {"scene": r["scene"], "squeak": r["squeak"]}}

    steps.journal = journal.Journal(out)
    steps.journal.run("divergent", digest, ["divergent.json", "divergent.csv"], go,
                      what=f"the starts read: stick-slip, growing, chatter or settled ({len(p['cases'])} runs; docs/squeal.md 9.6)")


def basis_part(steps, base, extra, path, name):
    """The reduced model's basis (roller -rom -rom_output, no step): the modes and the residual flexibility once, read by
    every reduced run on the same mesh and rubber (docs/model.md 11)."""
    steps.run(name, base + ["-rom", "-rom_output", path, "-ts_max_steps", "0", "-quiet"] + extra,
              "the reduced model's basis (-rom -rom_output, no step): read by the reduced runs (-rom_input)",
              outputs=[os.path.basename(path)])


def propensity_part(steps, base, opts, a, extra, out):
    """The propensity study, journalled: on the finite elements (rollerreport.propensity_fe) the table of cases and its
    plan (propensity_cases.csv, propensity_table.json: written whenever the study runs, seconds), the propensity's own
    basis when its options differ, the reduced transients' map and, when the scene's CEA ran, the CEA map (roller parts,
    each journalled; a Slurm array can write the maps instead: jobs/slurm/propensity.sh), then the classification of
    what the maps wrote; or the 1-DOF alone (rollerreport.propensity.run)."""
    if a.propensity_cases <= 0:
        return
    from . import propensity, propensity_fe

    j = lambda f: os.path.join(out, f)  # noqa: E731
    cases = propensity.sample(opts, a.propensity_cases, a.propensity_seed)
    sources = [os.path.join(os.path.dirname(__file__), f) for f in ("propensity.py", "propensity_fe.py", "onedof.py", "cycle.py")]
    plan, maps = {}, []
    if a.propensity_model == "fe":
        more = a.propensity_options.split()
        basis = j("propensity_basis.h5" if more else "basis.h5")  # the propensity's own mesh: its own basis
        plan = {"run_time": propensity_fe.run_length(opts, a.propensity_periods), "nev": a.propensity_nev or a.nev,
                "with_cea": steps.journal.parts.get("cea", {}).get("status") == "ok", "basis": os.path.basename(basis),
                "options": more, "cases": a.propensity_cases, "seed": a.propensity_seed}
        propensity_fe.write_cases(out, cases)
        with open(j("propensity_table.json"), "w") as f:
            json.dump(plan, f, indent=1)
        if more:
            basis_part(steps, base, more + extra, basis, "propensity_basis")
        os.makedirs(j("propensity"), exist_ok=True)
        for name, (cmd, what) in propensity_fe.commands(base, more + extra, out, basis, plan["run_time"], a.ranks, a.mpiexec,
                                                        plan["nev"], plan["with_cea"]).items():
            maps.append(propensity_fe.RUNS if name == "propensity_runs" else propensity_fe.CEA)
            steps.run(name, cmd, what, outputs=[maps[-1]], inputs=[j(propensity_fe.CASES)] + ([basis] if name == "propensity_runs" else []),
                      ranks=a.ranks)
        what = f"the propensity: {a.propensity_cases} cases, each by its CEA and its reduced start from rest (docs/squeal.md 9.4)"
    else:
        what = f"the propensity: {a.propensity_cases} cases, classified by rollerref's 1-DOF (docs/squeal.md 9.4)"
    if steps.only is not None and "propensity" not in steps.only:
        return
    digest = journal.inputs_hash({"part": "propensity", "options": opts, "plan": plan, "model": a.propensity_model},
                                 sources + [j(m) for m in maps])

    def go():
        missing = [m for m in maps if not os.path.exists(j(m))]
        if missing:
            return False, {"error": f"the propensity's maps {', '.join(missing)} are missing (their parts' logs in logs/)"}
        if a.propensity_model == "fe":
            rows = propensity_fe.classify(out, opts, cases, plan["with_cea"])
            r = propensity_fe.summarize(out, rows, a.propensity_seed, plan["with_cea"], plan["run_time"], plan["nev"])
        else:
            r = propensity.run(opts, out, a.propensity_cases, a.propensity_seed)
        propensity.figure(out)
        return True, {"result": {"fraction": r["fraction"], "cases": r["cases"]}}

    steps.journal = journal.Journal(out)
    steps.journal.run("propensity", digest, ["propensity.json", "propensity.csv", "propensity.png"], go, what=what)


def report_step(steps, scene, out, src, only):
    """scene.json, then the report (rollerreport.report) with every step's command; 1 when a step failed."""
    j = lambda f: os.path.join(out, f)  # noqa: E731
    with open(j("scene.json"), "w") as fh:
        json.dump(scene, fh, indent=1)
    parts = [p for p in report.PARTS if only is None or p in only]
    cmd = ["env", f"PYTHONPATH={os.path.join(src, 'scripts')}", sys.executable, "-m", "rollerreport", out, "--parts", ",".join(parts)]
    steps.done.append({"step": "report", "what": "the report (docs/squeal.md 9.1)", "command": shlex.join(cmd),
                       "cwd": out, "seconds": None, "returncode": 0, "error": "", "log": ""})
    steps.save()
    t0 = time.time()
    r = report.write(out, parts)
    steps.done[-1]["seconds"] = round(time.time() - t0, 1)
    steps.save()
    failed = [s["step"] for s in steps.done if s.get("returncode") and not s.get("refused")]
    print(f"rollerreport.run: {r['verdict']}; wrote {', '.join(r['files'])} in {out}" + (f"; failed: {', '.join(failed)}" if failed else ""))
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
