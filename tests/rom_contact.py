"""Contact and friction on the reduced model (-rom -obstacle, docs/model.md "The reduced model", docs/performance.md
"Reduced-order transient"): the printer roller (jobs/printer_roller_kelvin_voigt.yaml: press by the sheet, then feeding with
velocity-weakening Coulomb friction) on a coarse mesh (h 1.2 mm, 0.3 mm at Gamma_C), 4 ms, the 150 lowest modes
clamped at the shaft and the two static load responses.

The contact is the full model's QP with the Gamma_C rows of the basis in place of the injection E (a Galerkin
projection), so the scheme's discrete energy identity holds for the reduced model with contact and friction:
E^k - E^0 = shaft work + sheet work - friction work - the contact, Kelvin-Voigt and mass-damping dissipations (the
CSV's columns, as tests/friction_printer.py) to round-off. Every step: no penetration beyond round-off, the KKT
residual and Coulomb's law (friction_residual) to 1e-9, no fallback of the Coulomb solve.
How close its forces come to the full model's is tests/rom_printer.py's (long) and docs/performance.md's."""
import numpy as np

from rollertest import SOURCE, Checker, read_csv, run

c = Checker("rom_contact")
R_OUTER = 0.0125
SCENE = ["-options_file", f"{SOURCE}/jobs/printer_roller_kelvin_voigt.yaml", "-mesh_h", "0.0012", "-mesh_h_contact", "3e-4", "-ts_max_time", "0.004", "-quiet"]
run(SCENE + ["-rom", "-rom_modes", "150", "-monitor_csv", "rom_contact.csv"])
d = read_csv("rom_contact.csv")
on = d["contact_nodes"] > 0
c.check(abs(d["t"][-1] - 0.004) < 1e-12, f"the reduced transient reaches t = {d['t'][-1]:.6g} (4 ms)")
c.check(on.sum() > 0.5 * len(on), f"the sheet touches the roller in {on.sum()} of {len(on)} steps (> half: press, then feeding)")
c.check(d["friction_force"][on].min() < 0 or d["friction_force"][on].max() > 0, "the friction force is not zero in contact")
diss = np.cumsum(d["contact_dissipation"] + d["damping_dissipation"] + d["viscous_dissipation"])
bal = d["energy"] - d["energy"][0] - (d["shaft_work"] + d["sheet_work"] - d["friction_work"] - diss)
defect = float(np.abs(bal).max() / np.abs(d["energy"]).max())
c.check(defect < 1e-11, f"the reduced model's energy identity with contact and friction holds to {defect:.1e} of its largest energy (< 1e-11)")
c.check(d["gap_min"].min() > -1e-12 * R_OUTER, f"no penetration: least gap {d['gap_min'].min():.2e} m (> -1e-12 r_C)")
c.check(d["kkt_residual"].max() < 1e-9, f"the contact QP's KKT residual {d['kkt_residual'].max():.1e} (< 1e-9) at every step")
c.check(d["friction_residual"][on].max() < 1e-9, f"Coulomb's law holds to {d['friction_residual'][on].max():.1e} (< 1e-9) at every step in contact")
c.check(d["coulomb_fallback"].max() == 0, f"every Coulomb solve by the semismooth Newton method (largest coulomb_fallback {d['coulomb_fallback'].max():.0f})")
c.close()
