"""Contact and friction on the reduced model (-rom -obstacle, docs/model.md "The reduced model", docs/performance.md
"Reduced-order transient"): the printer roller (jobs/printer_roller_kelvin_voigt.yaml: press by the sheet, then feeding with
velocity-weakening Coulomb friction) on a coarse mesh (h 1.2 mm, 0.3 mm at Gamma_C), 4 ms, the 150 lowest modes
clamped at the shaft and the two static load responses.

With the modes alone (-rom_residual false) the contact is the full model's QP with the Gamma_C rows of the basis in
place of the injection E (a Galerkin projection), so the scheme's discrete energy identity holds for the reduced model
with contact and friction: E^k - E^0 = shaft work + sheet work - friction work - the contact, Kelvin-Voigt and
mass-damping dissipations (the CSV's columns, as tests/friction_printer.py) to round-off. Every step: no penetration
beyond round-off, the KKT residual and Coulomb's law (friction_residual) to 1e-9, no fallback of the Coulomb solve.

With MacNeal's static residual flexibility at Gamma_C (the default) the patch has the full model's width: against the
full model on the same mesh, over the 3 ms from the first touch, the mean contact force within 1 %, the friction force
within 2 %, the contact nodes, R and alpha within 1 %, the energy (modal + the residual's static energy) within 1 %; its
balance (the residual's static energy in E, the dissipation of its memoryless update in the contact's) closes to
round-off; no penetration, KKT 1e-9. The printer's own mesh over 30 ms is tests/rom_printer.py's (long).

The printer itself (jobs/printer_roller.yaml: the Maxwell EPDM, the hub on its pick spring and gear drive), 6 ms: the
branches reduced by Galerkin (K_d,r = V^T K_d V, dense; the step matrix factored), the hub's three unknowns kept with
its constraint modes (the rigid fields) in the basis: the balance with the branches, the hub and the residual to
round-off; against the full model the mean contact force within 1 %, the friction force within 2 %, the hub's
vertical position within 2 % and its rate within 0.5 % (measured -0.11 %, +1.15 %, -0.17 %, -0.01 %; the full model
itself moves by 0.3 % in friction between 1 and 2 ranks); the viscoelastic residual (-rom_residual_branches: its
branches as standard linear solids) gives the patch's width and the rubber's loss in it within 1 % (measured -0.13 %,
-0.20 %; the elastic residual's +4.1 %, -3.6 %), its branches' dissipation >= 0 at every step; the surface's lab-frame
orders 0, 1, 2 (-monitor_surface_csv, the sound's source) within 3 %."""

from rollertest import SOURCE, Checker, energy_defect, read_csv, run

c = Checker("rom_contact")
R_OUTER = 0.0125
SCENE = ["-options_file", f"{SOURCE}/jobs/printer_roller_kelvin_voigt.yaml", "-mesh_h", "0.0012", "-mesh_h_contact", "3e-4", "-ts_max_time", "0.004", "-quiet"]
run(SCENE + ["-rom", "-rom_modes", "150", "-rom_residual", "false", "-monitor_csv", "rom_contact.csv"])
d = read_csv("rom_contact.csv")
on = d["contact_nodes"] > 0
c.check(abs(d["t"][-1] - 0.004) < 1e-12, f"the reduced transient reaches t = {d['t'][-1]:.6g} (4 ms)")
c.check(on.sum() > 0.5 * len(on), f"the sheet touches the roller in {on.sum()} of {len(on)} steps (> half: press, then feeding)")
c.check(d["friction_force"][on].min() < 0 or d["friction_force"][on].max() > 0, "the friction force is not zero in contact")
defect = energy_defect(d)
c.check(defect < 1e-11, f"the modal reduced model's energy identity with contact and friction holds to {defect:.1e} of its largest energy (< 1e-11)")
c.check(d["gap_min"].min() > -1e-12 * R_OUTER, f"no penetration: least gap {d['gap_min'].min():.2e} m (> -1e-12 r_C)")
c.check(d["kkt_residual"].max() < 1e-9, f"the contact QP's KKT residual {d['kkt_residual'].max():.1e} (< 1e-9) at every step")
c.check(d["friction_residual"][on].max() < 1e-9, f"Coulomb's law holds to {d['friction_residual'][on].max():.1e} (< 1e-9) at every step in contact")
c.check(d["coulomb_fallback"].max() == 0, f"every Coulomb solve by the semismooth Newton method (largest coulomb_fallback {d['coulomb_fallback'].max():.0f})")

# MacNeal's residual flexibility (the default) against the full model
run(SCENE + ["-rom", "-rom_modes", "150", "-monitor_csv", "rom_contact_res.csv"])
run(SCENE + ["-monitor_csv", "rom_contact_full.csv"])
r, f = read_csv("rom_contact_res.csv"), read_csv("rom_contact_full.csv")
c.check(len(r["t"]) == len(f["t"]), f"the reduced run has the full run's {len(f['t']) - 1} steps")
w = f["t"] >= 0.001
for col, tol in (("contact_force", 0.01), ("friction_force", 0.02), ("contact_nodes", 0.01), ("R", 0.01), ("alpha", 0.01), ("energy", 0.01)):
    a, b = f[col][w].mean(), r[col][w].mean()
    c.check(abs(b - a) <= tol * abs(a), f"with the residual flexibility, mean {col} over t >= 1 ms: reduced {b:.5g}, full {a:.5g} ({100 * (b - a) / abs(a):+.3f} %, bound {100 * tol:.0f} %)")
defect = energy_defect(r)
c.check(defect < 1e-11, f"its energy balance (modal + the residual's static energy; its update's dissipation) closes to {defect:.1e} of its largest energy (< 1e-11)")
c.check(r["gap_min"].min() > -1e-12 * R_OUTER, f"no penetration: least gap {r['gap_min'].min():.2e} m")
c.check(r["kkt_residual"].max() < 1e-9, f"KKT residual {r['kkt_residual'].max():.1e} (< 1e-9) at every step")

# the printer itself: the Maxwell rubber, the hub on its spring and drive
MX = ["-options_file", f"{SOURCE}/jobs/printer_roller.yaml", "-mesh_h", "0.0012", "-mesh_h_contact", "3e-4", "-ts_max_time", "0.006", "-quiet"]
run(MX + ["-rom", "-rom_modes", "150", "-monitor_csv", "rom_contact_axle.csv", "-monitor_surface_csv", "rom_contact_axle_surface.csv"])
run(MX + ["-monitor_csv", "rom_contact_axle_full.csv", "-monitor_surface_csv", "rom_contact_axle_full_surface.csv"])
r, f = read_csv("rom_contact_axle.csv"), read_csv("rom_contact_axle_full.csv")
defect = energy_defect(r)
c.check(defect < 1e-11, f"axle + Maxwell: the reduced balance with the branches, the hub and the residual closes to {defect:.1e} of its largest energy (< 1e-11)")
w = f["t"] >= 0.001
for col, tol in (("contact_force", 0.01), ("friction_force", 0.02), ("axle_y", 0.02), ("hub_rate", 0.005)):
    a, b = f[col][w].mean(), r[col][w].mean()
    c.check(abs(b - a) <= tol * abs(a), f"axle + Maxwell: mean {col} over t >= 1 ms: reduced {b:.6g}, full {a:.6g} ({100 * (b - a) / abs(a):+.2f} %, bound {100 * tol:g} %)")
# the viscoelastic residual (-rom_residual_branches, the default): the patch's width and the rubber's loss in it are the
# full model's (the elastic residual's: +4.1 % contact nodes, -3.6 % viscous dissipation)
a, b = f["contact_nodes"][w].mean(), r["contact_nodes"][w].mean()
c.check(abs(b - a) <= 0.01 * a, f"axle + Maxwell: mean contact_nodes over t >= 1 ms: reduced {b:.4f}, full {a:.4f} ({100 * (b - a) / a:+.2f} %, bound 1 %)")
a, b = f["viscous_dissipation"].sum(), r["viscous_dissipation"].sum()
c.check(abs(b - a) <= 0.01 * a, f"axle + Maxwell: the rubber's dissipation over the run: reduced {b:.6g}, full {a:.6g} ({100 * (b - a) / a:+.2f} %, bound 1 %)")
c.check(r["viscous_dissipation"].min() >= 0.0, f"axle + Maxwell: the branches' dissipation (the residual's included) >= 0 at every step (min {r['viscous_dissipation'].min():.2e})")
# the surface's lab-frame orders (the sound's source, -monitor_surface_csv): the reduced run adds the functionals on the
# Gamma_C residual
r, f = read_csv("rom_contact_axle_surface.csv"), read_csv("rom_contact_axle_full_surface.csv")
w = f["t"] >= 0.001
for col in ("ur0", "ur1s", "ur2c"):
    a, b = f[col][w].mean(), r[col][w].mean()
    c.check(abs(b - a) <= 0.03 * abs(a), f"axle + Maxwell: the surface's {col} over t >= 1 ms: reduced {b:.5g}, full {a:.5g} m ({100 * (b - a) / abs(a):+.2f} %, bound 3 %)")
c.close()
