"""A seeded squeal transient on the reduced model (issue 37: "a seeded squeal transient's growth rate within 5 %"):
the unstable order-1 whirl of tests/squeal_transient.py (the DMF in the co-rotating frame, Coulomb's law mu = 0.3,
undamped, V = 0, the CEA's coarse graded mesh), started on the CEA's steady sliding state plus its order-1 backward mode
(amplitude 1e-3) and run to t = 60, by the full model and by -rom at its default cutoff (the modes the step resolves to
-ts_phase_error: 595 + 2) with the residual flexibility. The seeded start is a state held by contact forces: the
reduced levels are its K-orthogonal projection and carry the Gamma_C remainder as residual (docs/model.md 11).
- the whirl's growth rate (matrix pencil over t in [0, 60], scripts/rollerreport/squeal_fit.py) within 5 % of the full
  transient's and of the CEA's eigenvalue; its frequency within 2 %;
- the mean normal and friction forces within 1 % of the full run's; no penetration; the reduced model's energy balance
  (with the residual's energy and dissipation) to 1e-8 of its largest energy over the 6,000 steps (the full run's own
  identity is 9e-11 here).
The growth converges with the cutoff only once the modes up to where the step resolves them are kept: 67 modes (1
cycle per unit time) +35 %, 227 (2) -110 %, 399 (2.75) +8 %, 595 (the default, 3.5) +1.0 % (docs/performance.md);
about 4 min of CPU."""
import csv
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from rollertest import SOURCE, Checker, energy_defect, read_csv, run  # noqa: E402

sys.path.insert(0, os.path.join(SOURCE, "scripts"))
from rollerreport import squeal_fit as sf  # noqa: E402

MESH = ["-mesh_h", "0.05", "-mesh_h_contact", "0.0112", "-mesh_contact_layer", "0.0224"]
c = Checker("rom_seeded")
run(["-modes", "-obstacle", "-friction", 0.3, "-modes_nev", 40, "-modes_csv", "cea.csv", "-modes_output", "cea.h5"] + MESH)
with open("cea.csv") as f:
    rows = [{k: (v if k == "wave" else float(v)) for k, v in r.items()} for r in csv.DictReader(f)]
j, p1 = max(((k, r) for k, r in enumerate(rows) if int(r["order"]) == 1 and r["wave"] == "backward"), key=lambda kr: kr[1]["growth_rate"])
g, w = p1["growth_rate"], p1["frequency"]
SCENE = ["-ts_scheme", "dmf", "-obstacle", "-friction", 0.3, "-sheet_speed", 0, "-viscosity", 0, "-damping", 0, "-ts_dt", 0.01, "-ts_max_time", 60,
         "-output_every", 20, "-quiet", "-initial_condition", "mode", "-initial_mode_file", "cea.h5", "-initial_mode", j, "-ic_amplitude", 1e-3,
         "-obstacle_speed", 1e6] + MESH
run(SCENE + ["-monitor_csv", "full.csv", "-output", "full.h5"])
run(SCENE + ["-rom", "-monitor_csv", "rom.csv", "-output", "rom.h5"])
fit = {}
for name in ("full", "rom"):
    t, U = sf.whirl(f"{name}.h5")
    fit[name] = sf.fit(t, U, -w, 0.0, 60.0)
gf, gr = fit["full"]["pencil_growth"], fit["rom"]["pencil_growth"]
c.check(abs(gr / gf - 1) < 0.05 and abs(gr / g - 1) < 0.05,
        f"whirl growth: reduced {gr:.6f}, full {gf:.6f} ({100 * (gr / gf - 1):+.2f} %), CEA {g:.6f} ({100 * (gr / g - 1):+.2f} %): within 5 %")
wr, wf = fit["rom"]["pencil_frequency"], fit["full"]["pencil_frequency"]
c.check(wr < 0 and abs(wr / wf - 1) < 0.02, f"whirl frequency: reduced {wr:+.5f}, full {wf:+.5f} ({100 * (wr / wf - 1):+.2f} %, 2 %; backward)")
a, b = read_csv("full.csv"), read_csv("rom.csv")
m = a["t"] > 0
for col in ("contact_force", "friction_force"):
    x, y = a[col][m].mean(), b[col][m].mean()
    c.check(abs(y / x - 1) < 0.01, f"mean {col}: reduced {y:.6g}, full {x:.6g} ({100 * (y / x - 1):+.2f} %, 1 %)")
c.check(b["gap_min"].min() > -1e-12, f"no penetration in the reduced run (least gap {b['gap_min'].min():.1e})")
defect = energy_defect(b)
c.check(defect < 1e-8, f"the reduced model's energy balance over {len(b['t']) - 1} steps: {defect:.1e} of its largest energy (< 1e-8)")
c.close()
