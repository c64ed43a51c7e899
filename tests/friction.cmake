# Coulomb friction between the roller and the sheet (src/contact/contact_friction.c, docs/friction.md): the law
# holds at every node and step, the energy identity with the shaft, sheet and friction works closes, the
# solvers agree, -friction 0 is the frictionless code bit for bit, and 1 and 2 ranks agree.
roller_test(friction_law friction_law.py LABELS quick TIMEOUT 600)
roller_test(friction_mpi friction_mpi.py LABELS mpi PROCESSORS 2 TIMEOUT 300)
# -friction_table (docs/friction.md section 1): the sampled exponential law reproduces its transient and its complex
# eigenvalues within tolerances from the interpolation error; the slope's sign of a rise-then-fall table in the CEA
roller_test(friction_table friction_table.py LABELS quick TIMEOUT 600)
# Cattaneo-Mindlin (docs/friction.md 5.1): pressed frictionless, the shaft turned with the sheet held: the stick
# zone c/a = sqrt(1 - Q/(mu P)) within a mesh spacing, Cattaneo's traction, full sliding at Q = mu P, the
# reversal's b/a = sqrt(1 - (Q* - Q)/(2 mu P)); twice slower, Q within 0.03 (not the quasi-static limit: the mass
# damping's rate effect, up to 0.046 at T = 40, section 5.1). long: finer meshes.
roller_test(friction_cattaneo friction_cattaneo.py LABELS quick TIMEOUT 400)
roller_test(friction_cattaneo_long friction_cattaneo.py LABELS long ARGS long TIMEOUT 3600)
# Carter's steady rolling contact: at low speed the stick zone sits at the leading edge and Q/(mu P) follows Carter's
# creep curve (section 5.2); quick: h_c = 0.003 (about 2 minutes); long: h_c = 0.002 and a dt check.
roller_test(friction_carter friction_carter.py LABELS quick TIMEOUT 600)
roller_test(friction_carter_long friction_carter.py LABELS long ARGS long TIMEOUT 3600)
# stick-slip of the roller turned slowly on the resting sheet with velocity-weakening friction, and steady
# sliding with constant mu (jobs/stickslip.yaml, docs/friction.md section 5.3; two runs of about 4 minutes)
roller_test(friction_stickslip friction_stickslip.py LABELS long TIMEOUT 1200)
# the printer roller's 10 ms transient with its steep velocity weakening (jobs/printer_roller.yaml, SI): feeding and
# the jam, Newton on >= 98 % of the steps, the rest with mu of the last step (docs/friction.md section 3; about 1 min)
roller_test(friction_printer friction_printer.py LABELS long TIMEOUT 1200)
# the axle and the drive (-axle, docs/model.md section 10): torsion and bounce in the stiff-rubber limit, the ripple's
# forced response, the nip force against -static, the energy balance of rolling on the axle, 1 and 2 ranks
roller_test(axle axle.py LABELS quick mpi PROCESSORS 2 TIMEOUT 600)
# the sheet's own motion (-sheet_mass, -sheet_resistance): held, picked (its momentum every step, the full-sliding
# acceleration, the settled friction F_r), the energy balance with its kinetic energy, a restart on 2 ranks; long: the
# settled creep against the steady rolling state's at F_r on a finer contact mesh
roller_test(sheet sheet.py LABELS quick mpi PROCESSORS 2 TIMEOUT 600)
roller_test(sheet_long sheet.py LABELS long ARGS long TIMEOUT 1800)
# stick-slip on the axle against the one-degree-of-freedom model (docs/validation.md 9.5, issue 36): the growth rates
# about steady sliding and the onset slip within 5 % of the closed form, set 1's bistability (linearly stable, the
# start from rest into the cycle, period and amplitude within 10 % of rollerref's, a small disturbance decays at the
# closed-form rate); five runs, two at a time (about 5 minutes of CPU on each core)
roller_test(axle_stickslip axle_stickslip.py LABELS long PROCESSORS 2 TIMEOUT 2400)
