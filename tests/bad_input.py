"""Bad input: every option out of range, a bad restart, an unwritable output path, fail at once with one
message that names the option (or file), the value and what is allowed, a non-zero exit, and no output
file left behind that looks complete.

-ts_dt 0 and -mesh_h 0 are no longer bad input: they mean "chosen from -ts_phase_error" (the default), so the
-ts_dt case is a negative step. The runs use the default discretization (P2 curved, extrapolated Coriolis
velocity, default dt) on the coarse mesh -mesh_h 0.05 for at most 2 steps: what is checked is the refusal."""
import os

from rollertest import SOURCE, Checker, run

c = Checker("bad_input")
cases = [
    (["-mesh_h", "-0.1"], "-mesh_h", "-0.1"),
    (["-mesh_h", "0.5"], "-mesh_h", "0.5"),
    (["-r_inner", "0.6"], "-r_inner", "0.6"),
    (["-r_inner", "0"], "-r_inner", "0"),
    (["-young", "0"], "-young", "0"),
    (["-poisson", "0.5"], "-poisson", "0.5"),
    (["-poisson", "-1.5"], "-poisson", "-1.5"),
    (["-density", "-1"], "-density", "-1"),
    (["-degree", "4"], "-degree", "4"),
    (["-obstacle", "-degree", "3"], "-degree", "3"),
    (["-ts_dt", "-0.01"], "-ts_dt", "-0.01"),
    (["-ts_phase_error", "1"], "-ts_phase_error", "1"),
    (["-ts_max_time", "-1"], "-ts_max_time", "-1"),
    (["-ts_max_steps", "-5"], "-ts_max_steps", "-5"),
    (["-damping", "-1"], "-damping", "-1"),
    (["-obstacle", "-obstacle_speed", "0"], "-obstacle_speed", "0"),
    (["-obstacle", "-obstacle_depth", "0.3"], "-obstacle_depth", "0.3"),
    (["-theta_b", "-1"], "-theta_b", "-1"),
    (["-checkpoint_every", "-1"], "-checkpoint_every", "-1"),
    (["-output", "bad.h5", "-output_every", "0"], "-output_every", "0"),
    (["-monitor_surface_csv", "bad_s.csv", "-monitor_surface_orders", "0"], "-monitor_surface_orders", "0"),
    (["-omega", "0.9"], "-omega", "0.9"),
    (["-stability_margin", "2"], "-stability_margin", "2"),
    (["-restart", "no-such-checkpoint.h5"], "no-such-checkpoint.h5", "-restart"),
    (["-initial_condition", "bump"], "-initial_condition bump", "-clamp_outer"),
    (["-mesh_h_contact", "-0.01"], "-mesh_h_contact", "-0.01"),
    (["-mesh_h_contact", "0.1"], "-mesh_h_contact", "0.1"),
    (["-mesh_contact_layer", "0.05"], "-mesh_contact_layer", "0.05"),
    (["-mesh_h_contact", "0.01", "-mesh_contact_layer", "0.3"], "-mesh_contact_layer", "0.3"),
    (["-mesh_h_contact", "0.01", "-mesh_contact_layer", "0.005"], "-mesh_contact_layer", "0.005"),
    (["-mesh_h_contact", "0.01", "-dm_plex_filename", os.path.join(SOURCE, "meshes", "annulus-h0.05-v41.msh")], "-mesh_h_contact", "-dm_plex_filename"),
    (["-obstacle", "-friction", "-0.5"], "-friction", "-0.5"),
    (["-obstacle", "-friction", "0.5", "-friction_static", "0.3"], "-friction_static", "0.3"),
    (["-obstacle", "-friction", "0.5", "-friction_static", "1"], "-friction_static", "-friction_decay"),
    (["-obstacle", "-friction", "0.5", "-friction_static", "1", "-friction_decay", "-0.1"], "-friction_decay", "-0.1"),
    (["-friction", "0.5"], "-friction", "-obstacle"),
    (["-sheet_speed", "0.1"], "-sheet_speed", "-obstacle"),
    (["-obstacle", "-friction", "0.5", "-contact_solver", "vi"], "-friction", "condensed"),
    (["-obstacle", "-friction", "0.5", "-contact_check"], "-contact_check", "-friction"),
    (["-obstacle", "-friction", "0.5", "-contact_friction_rtol", "2"], "-contact_friction_rtol", "2"),
    (["-theta_start", "-1"], "-theta_start", "-1"),
    # -modes (docs/squeal.md)
    (["-modes", "-modes_nev", "0"], "-modes_nev", "0"),
    (["-modes", "-obstacle", "-modes_frame", "rotating"], "-modes_frame", "rotating"),
    (["-modes", "-obstacle", "-contact_mass", "redistributed"], "-contact_mass", "redistributed"),
    (["-modes", "-theta_a", "0.1"], "-modes", "-theta_a"),
    (["-initial_condition", "mode"], "-initial_condition mode", "-initial_mode_file"),
    (["-initial_condition", "mode", "-initial_mode_file", "no-such-modes.h5"], "-initial_mode_file", "no-such-modes.h5"),
    (["-modes", "-sweep", "bad_sweep.csv", "-sweep_omega", "0,0.1x,0.2"], "-sweep_omega", "0.1x"),
    (["-modes", "-sweep", "bad_sweep.csv", "-sweep_young_range", "0.05,0.2"], "-sweep_young_range", "0.05,0.2"),
    (["-modes", "-sweep", "bad_sweep.csv", "-sweep_poisson", "0.3,0.4"], "-sweep_poisson", "omega, young"),
    (["-obstacle", "-sweep", "bad_sweep.csv", "-sweep_friction", "0.3,0.8", "-sweep_window", "0"], "-sweep_window", "(0, 1]"),
    # issue 26: nothing passes silently
    (["-youngg", "0.2"], "-youngg", "did you mean -young?"),
    (["-frictoin", "0.8"], "-frictoin", "did you mean -friction?"),
    (["-obstacle", "-friction", "0.5", "-sheet_speed", "nan"], "-sheet_speed", "nan"),
    (["-young", "inf"], "-young", "must be finite"),
    (["-young", "abc"], "-young", "not a number"),
    (["-ts_max_steps", "1e300"], "-ts_max_steps", "not an integer"),
    (["-modes", "-friction", "0.8"], "-friction", "-obstacle"),
    (["-coriolis_velocity", "foo"], "-coriolis_velocity", "backward"),
    (["-ts_scheme", "foo"], "-ts_scheme", "trapezoidal"),
    (["-obstacle", "-contact_solver", "foo"], "-contact_solver", "condensed"),
    (["-ts_dt", "100", "-ts_max_time", "20"], "-ts_dt", "no step"),
    (["-monitor_csv", "unused.csv", "-modes"], "-monitor_csv", "not used"),
    # the generalized Maxwell rubber (issue 35)
    (["-rubber", "foo"], "-rubber", "maxwell"),
    (["-rubber_loss_factor", "0.1"], "-rubber_loss_factor", "-rubber maxwell"),
    (["-rubber", "maxwell"], "-rubber maxwell", "-rubber_loss_factor"),
    (["-rubber", "maxwell", "-rubber_loss_factor", "0.1"], "-rubber_band", "missing"),
    (["-rubber", "maxwell", "-rubber_loss_factor", "2", "-rubber_band", "1,10"], "-rubber_loss_factor", "(0, 1]"),
    (["-rubber", "maxwell", "-rubber_loss_factor", "0.1", "-rubber_band", "10,1"], "-rubber_band", ">= F1"),
    (["-rubber", "maxwell", "-rubber_loss_factor", "0.1", "-rubber_band", "10"], "-rubber_band", "two frequencies"),
    (["-rubber", "maxwell", "-maxwell_tau", "1,2", "-maxwell_weight", "0.5"], "-maxwell_weight", "one per -maxwell_tau"),
    (["-rubber", "maxwell", "-maxwell_tau", "-1", "-maxwell_weight", "0.5"], "-maxwell_tau", "-1"),
    (["-rubber", "maxwell", "-maxwell_tau", "1", "-maxwell_weight", "0"], "-maxwell_weight", "> 0"),
    (["-rubber", "maxwell", "-maxwell_tau", "1", "-maxwell_weight", "0.5", "-rubber_loss_factor", "0.1"], "-rubber maxwell", "not both"),
    (["-rubber", "maxwell", "-rubber_loss_factor", "0.1", "-rubber_band", "100,5000", "-viscosity", "1e-5"], "-viscosity", "half of -rubber_loss_factor"),
    (["-rubber", "maxwell", "-maxwell_tau", "1", "-maxwell_weight", "0.5", "-ts_scheme", "composed"], "-ts_scheme composed", "-rubber maxwell"),
    # issue 36: -friction_table, each error naming the option and the offending entry
    (["-obstacle", "-friction_table", "0:1"], "-friction_table", "1 point"),
    (["-obstacle", "-friction_table", "0:1,0.1:x"], "-friction_table", "entry 2 '0.1:x'"),
    (["-obstacle", "-friction_table", "0:1,0.2:0.8,0.1:0.7"], "-friction_table", "entry 3 '0.1:0.7'"),
    (["-obstacle", "-friction_table", "0:1,0.1:0"], "-friction_table", "must be > 0"),
    (["-obstacle", "-friction_table", "-0.1:1,0.1:0.5"], "-friction_table", "entry 1 '-0.1:1'"),
    (["-obstacle", "-friction_table", "0:1,0.1:0.5,"], "-friction_table", "entry 3 ''"),
    (["-obstacle", "-friction", "0.5", "-friction_table", "0:1,0.1:0.5"], "-friction_table", "without -friction"),
    (["-obstacle", "-friction_decay", "0.1", "-friction_table", "0:1,0.1:0.5"], "-friction_table", "without -friction_decay"),
    (["-friction_table", "0:1,0.1:0.5"], "-friction_table", "-obstacle"),
    (["-obstacle", "-sweep", "bad_sweep.csv", "-sweep_friction", "0.3,0.8", "-friction_table", "0:1,0.1:0.5"], "-sweep_friction", "-friction_table"),
    (["-rom", "-rom_modes", "10", "-modes", "-axle", "-drive_stiffness", "1"], "-modes with -rom and -axle", "without -rom"),
    (["-rom", "-obstacle", "-contact_solver", "vi"], "-contact_solver", "not vi"),
    (["-rom", "-rom_modes", "10", "-modes", "-rubber", "maxwell", "-rubber_loss_factor", "0.1", "-rubber_band", "0.1,10"], "-modes with -rom and -rubber maxwell", "without -rom"),
    (["-rom", "-rom_modes", "10", "-obstacle", "-ts_scheme", "composed"], "-ts_scheme composed", "three-level scheme"),
    (["-rom", "-rom_input", "no_such_basis.h5"], "-rom_input", "no such readable file"),
    (["-modes", "-axle", "-drive_stiffness", "1", "-omega", "1", "-rubber", "maxwell", "-rubber_loss_factor", "0.1", "-rubber_band", "0.1,10"], "-modes_branch_transport", "got true"),
]
for args, name, value in cases:
    code, out, err = run(["-mesh_h", "0.05", "-ts_max_steps", "2", "-quiet"] + args if args[0] != "-mesh_h" else args + ["-ts_max_steps", "2"], check=False)
    text = out + err
    first = next((line for line in text.splitlines() if name in line), "")
    c.check(code != 0 and name in text and value in first, f"{' '.join(args)}: exit {code}, message: {first.strip()[:150]}")

c.check(not os.path.exists("bad_sweep.csv"), "no sweep CSV left by a refused -sweep")

# a typo refused before any output file is opened: no CSV, not even its .part
code, out, err = run(["-mesh_h", "0.05", "-ts_max_steps", "2", "-quiet", "-monitor_csv", "typo.csv", "-youngg", "0.2"], check=False)
c.check(code != 0 and not os.path.exists("typo.csv") and not os.path.exists("typo.csv.part"), f"-youngg: exit {code}, no typo.csv or typo.csv.part written")
# the opt-out: -options_left 0 runs anyway
code, out, err = run(["-mesh_h", "0.05", "-ts_max_steps", "2", "-quiet", "-youngg", "0.2", "-options_left", "0"], check=False)
c.check(code == 0, f"-youngg 0.2 -options_left 0: exit {code} (the check turned off)")
# files: a restart that is not HDF5, or truncated; an options file with a YAML error: one line naming the file
with open("not_hdf5.h5", "w") as f:
    f.write("not a checkpoint\n")
with open("bad.yaml", "w") as f:
    f.write("young: 0.1\nomega: [1\npoisson: 0.3\n")
run(["-mesh_h", "0.05", "-ts_max_steps", "3", "-quiet", "-checkpoint", "whole.h5", "-checkpoint_every", "1"])
with open("whole.h5", "rb") as f, open("truncated.h5", "wb") as g:
    g.write(f.read()[:3000])
for args, name, what in ((["-restart", "not_hdf5.h5"], "not_hdf5.h5", "not an HDF5 file"),
                         (["-restart", "truncated.h5"], "truncated.h5", "truncated"),
                         (["-initial_condition", "mode", "-initial_mode_file", "not_hdf5.h5"], "not_hdf5.h5", "not an HDF5 file"),
                         (["-options_file", "bad.yaml"], "bad.yaml", "line 3")):
    code, out, err = run(["-mesh_h", "0.05", "-ts_max_steps", "2", "-quiet"] + args, check=False)
    text = out + err
    line = next((ln for ln in text.splitlines() if name in ln), "")
    c.check(code != 0 and what in line and "HDF5-DIAG" not in text, f"{' '.join(args)}: exit {code}, one line: {line.strip()[:150]}")

# mesh files checked at read time, one message each: clockwise, one inverted cell, radii against -r_inner,
# a missing physical group, not an annulus
def mesh_variant(path, flip="none", rename=None, move=False):
    lines = open(os.path.join(SOURCE, "meshes", "annulus-h0.05-v41.msh")).read().splitlines()
    out, i, flipped = [], 0, 0
    while i < len(lines):
        ln = lines[i]
        if rename and ln.endswith(f'"{rename[0]}"'):
            ln = ln.replace(rename[0], rename[1])
        out.append(ln)
        if ln == "$Nodes" and move:  # pull node 2 (on the inner circle, x = -0.25) in to x = -0.22
            i += 1
            while lines[i] != "$EndNodes":
                out.append(lines[i].replace("-0.25 0 0", "-0.22 0 0") if lines[i].startswith("-0.25 0 0") else lines[i])
                i += 1
            continue
        if ln == "$Elements":
            out.append(lines[i + 1])
            i += 2
            while lines[i] != "$EndElements":
                head = lines[i].split()
                out.append(lines[i])
                i += 1
                for _ in range(int(head[3])):
                    p = lines[i].split()
                    if head[2] == "2" and (flip == "all" or (flip == "one" and not flipped)):
                        p, flipped = [p[0], p[1], p[3], p[2]], flipped + 1
                    elif head[2] == "1" and flip == "all":
                        p = [p[0], p[2], p[1]]
                    out.append(" ".join(p))
                    i += 1
            continue
        i += 1
    open(path, "w").write("\n".join(out) + "\n")


mesh_variant("clockwise.msh", flip="all")
mesh_variant("tangled.msh", flip="one")
mesh_variant("no_outer.msh", rename=("outer", "rim"))
mesh_variant("not_annulus.msh", move=True)
good = os.path.join(SOURCE, "meshes", "annulus-h0.05-v41.msh")
for args, name, what in ((["-dm_plex_filename", "clockwise.msh", "-obstacle"], "clockwise.msh", "clockwise"),
                         (["-dm_plex_filename", "tangled.msh"], "tangled.msh", "inverted"),
                         (["-dm_plex_filename", good, "-r_inner", "0.3"], "-r_inner", "disagrees"),
                         (["-dm_plex_filename", "no_outer.msh"], "no_outer.msh", "outer"),
                         (["-dm_plex_filename", "not_annulus.msh"], "not_annulus.msh", "circle")):
    code, out, err = run(["-ts_max_steps", "2", "-quiet"] + args, check=False)
    line = next((ln for ln in (out + err).splitlines() if name in ln), "")
    c.check(code != 0 and what in line, f"{' '.join(args[:2])}: exit {code}, {line.strip()[:150]}")

# warnings where physics says the result is meaningless (stderr, once; the run goes on)
for args, what in ((["-ts_dt", "100", "-ts_max_time", "1000"], "slowest mode"),
                   (["-obstacle", "-obstacle_depth", "0.002", "-mesh_h_contact", "0"], "contact half-width")):
    code, out, err = run(["-mesh_h", "0.05", "-ts_max_steps", "2", "-quiet"] + args, check=False)
    c.check(code == 0 and err.count(what) == 1, f"{' '.join(args)}: exit {code}, warned once: {next((ln for ln in err.splitlines() if what in ln), '')[:120]}")

# an options file's unknown option is refused (naming it); a known one the run does not use is reported, not refused
with open("typo.yaml", "w") as f:
    f.write("youngg: 0.2\n")
code, out, err = run(["-mesh_h", "0.05", "-ts_max_steps", "2", "-quiet", "-options_file", "typo.yaml"], check=False)
c.check(code != 0 and "did you mean -young?" in out + err, f"options file with youngg: exit {code}")
with open("contact_scene.yaml", "w") as f:
    f.write("obstacle: false\ncontact_solver: vi\nfriction: 0.8\n")
code, out, err = run(["-mesh_h", "0.05", "-quiet", "-options_file", "contact_scene.yaml", "-modes", "-modes_nev", "2"], check=False)
c.check(code == 0 and "-friction 0.8, set by an options file" in err and "-contact_solver vi, set by an options file" in err,
        f"a contact scene's YAML with -modes and no obstacle: exit {code}, its unused -friction and -contact_solver reported on stderr")

# a modes file of another roller: refused, naming the parameter
run(["-mesh_h", "0.05", "-modes", "-modes_output", "bad_modes.h5", "-quiet"])
code, out, err = run(["-mesh_h", "0.05", "-ts_max_steps", "2", "-quiet", "-initial_condition", "mode", "-initial_mode_file", "bad_modes.h5", "-omega", "0.2"], check=False)
first = next((line for line in (out + err).splitlines() if "-initial_mode_file" in line), "")
c.check(code != 0 and "-omega" in first and "0.2" in first, f"a modes file of another omega: exit {code}, message: {first.strip()[:150]}")

# an output path that cannot be written: no file left that looks complete
for opt in ("-monitor_csv", "-output", "-modes_csv", "-modes_output"):
    path = f"no-such-dir/out.{'h5' if opt.endswith('output') else 'csv'}"
    code, out, err = run(["-mesh_h", "0.05", "-ts_max_steps", "2", "-quiet", opt, path] + (["-modes"] if opt.startswith("-modes") else []), check=False)
    c.check(code != 0 and path in out + err and not os.path.exists(path), f"{opt} {path}: exit {code}, named in the message")
c.close()
