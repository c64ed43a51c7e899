"""-rom_output / -rom_input (issue 37, docs/performance.md "Reduced-order transient"): the reduced basis, and with
contact the residual flexibility, saved by one run and reused by the cases of a map that share the mesh and the rubber.
The printer roller (jobs/printer_roller_kelvin_voigt.yaml) on the coarse mesh of tests/rom_contact.py, 1 ms, 150 modes:
- a run that reads the file repeats the run that wrote it bit for bit (the same basis, the same R);
- on 2 ranks (another partition: the basis read through the nodes' positions) its rows agree to round-off;
- a run of another rubber, mode count or mesh is refused in one line naming each difference, non-zero exit, no CSV (a
  Maxwell run's viscoelastic residual needs the file's kappa: a Kelvin-Voigt file is refused for it by name)."""
import os

import h5py
import numpy as np

from rollertest import SOURCE, Checker, read_csv, run

c = Checker("rom_io")
SCENE = ["-options_file", f"{SOURCE}/jobs/printer_roller_kelvin_voigt.yaml", "-mesh_h", "0.0012", "-mesh_h_contact", "3e-4", "-ts_max_time", "0.001", "-quiet", "-rom", "-rom_modes", "150"]
run(SCENE + ["-rom_output", "basis.h5", "-monitor_csv", "write.csv"])
with h5py.File("basis.h5", "r") as f:
    nq, n = int(f.attrs["coordinates"]), 2 * int(f.attrs["contact_nodes"])
    c.check(nq == 152 and f["V_151"].shape == f["nodes"].shape and f["residual_flexibility"].shape == (n * n,), f"basis.h5 holds {nq} columns of V on {f['nodes'].shape[0] // 2} nodes and the {n} x {n} residual flexibility")
run(SCENE + ["-rom_input", "basis.h5", "-monitor_csv", "read.csv"])
run(SCENE + ["-rom_input", "basis.h5", "-monitor_csv", "read2.csv"], nproc=2)
a, b, b2 = read_csv("write.csv"), read_csv("read.csv"), read_csv("read2.csv")
cols = ("contact_force", "friction_force", "energy", "R", "alpha", "gap_min", "contact_nodes")
same = all(np.array_equal(a[k], b[k]) for k in cols)
c.check(same and len(a["t"]) == len(b["t"]), f"the run that reads the basis repeats the writer's {len(a['t']) - 1} rows bit for bit ({', '.join(cols)})")
err = max(float(np.abs(a[k] - b2[k]).max() / max(np.abs(a[k]).max(), 1e-300)) for k in cols if k != "gap_min")
c.check(err < 1e-9, f"on 2 ranks the rows agree to {err:.1e} of each column's largest value (< 1e-9)")
for extra, names in ((["-young", "2.2e6"], ["-young"]), (["-rom_modes", "100"], ["-rom_modes"]), (["-young", "2.2e6", "-rom_modes", "100"], ["-young", "-rom_modes"]), (["-mesh_h", "0.0011"], ["free dofs"]),
                     (["-rubber", "maxwell", "-viscosity", "0", "-rubber_loss_factor", "0.1", "-rubber_band", "100,5000"], ["branch ratio kappa"])):
    args = [x for x in SCENE if x not in ("-rom_modes", "150")] if "-rom_modes" in extra else SCENE
    if os.path.exists("refused.csv"):
        os.remove("refused.csv")
    code, out, err_text = run(args + extra + ["-rom_input", "basis.h5", "-monitor_csv", "refused.csv"], check=False)
    line = next((ln for ln in (out + err_text).splitlines() if "-rom_input basis.h5: refused" in ln), "")
    c.check(code != 0 and all(nm in line for nm in names) and not os.path.exists("refused.csv"), f"{' '.join(extra)}: refused ({code}), naming {', '.join(names)}: {line.split('refused, ')[-1][:160]}")
# a reduced run's checkpoint holds coordinates: a full-model restart from it is refused by name
run(SCENE + ["-checkpoint_every", "50", "-checkpoint", "reduced_ck.h5"])
code, out, err_text = run([x for x in SCENE if x not in ("-rom", "-rom_modes", "150")] + ["-restart", "reduced_ck.h5", "-monitor_csv", "restart.csv"], check=False)
line = next((ln for ln in (out + err_text).splitlines() if "refused" in ln), "")
c.check(code != 0 and "reduced (-rom) 1 (checkpoint) vs 0 (this run)" in line and not os.path.exists("restart.csv"), f"a full restart from a reduced run's checkpoint: refused ({code}): {line.split('refused, ')[-1][:120]}")
c.close()
