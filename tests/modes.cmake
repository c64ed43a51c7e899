# The modes of the free rotating annulus (docs/squeal.md section 2): scripts/rollerref/annulus_modes.py, the 1D reference
# per signed circumferential order m (Bessel roots at n = 0, frame shift, Bryan's splitting); no roller run.
roller_test(modes_reference_unit modes_reference_unit.py LABELS quick)
# roller -modes against it: n = 0..4, both frames, omega = pi/10 (1e-3), Bryan's splitting, the torsional period 8.69
roller_test(modes_splitting modes_splitting.py LABELS quick TIMEOUT 600)
# damping in the lab frame: Kelvin-Voigt and mass damping, lab = co-rotating + Doppler, n = 0..4 (decay rates 1e-2);
# 1 = 2 ranks
roller_test(modes_damped modes_damped.py LABELS quick PROCESSORS 2 TIMEOUT 300)
# the steady rolling/sliding state of -modes -obstacle against the long-time transient (frictionless rolling and
# sliding to t = 30; rolling with stick zones on Carter's scene at three creeps to t = 70; about 8 min)
roller_test(squeal_steady squeal_steady.py LABELS long TIMEOUT 2400)
# -modes with -axle (docs/squeal.md section 3.1): the hub's torsion and bounce in the stiff-rubber limit against the closed
# forms, at rest and turning (the lab frame's borders), rolling on the sheet on 1 and 2 ranks, the refusals
roller_test(axle_modes axle_modes.py LABELS quick mpi PROCESSORS 2 TIMEOUT 600)
# -modes with -axle and -rubber maxwell (the branches over the bordered body): the bounce's growth rate and frequency
# against the transient at rest and rolling (frozen branches), its modal loss factor, 1 = 2 ranks, the refused transport
roller_test(axle_modes_maxwell axle_modes_maxwell.py LABELS quick mpi PROCESSORS 2 TIMEOUT 600)
# the CEA on the axle's stick-slip onset scenes (tests/axle_stickslip.py (a)): the drive's growth rate against the closed
# form and the finite elements' transient, the onset slip
roller_test(axle_modes_onset axle_modes_onset.py LABELS long PROCESSORS 2 TIMEOUT 1800)
# -modes with the generalized Maxwell rubber (-rubber maxwell: the augmented state of src/modes/branches.c): the free
# roller at rest, modal loss factors 2|sigma|/omega within 5 % of the model's, the torsional eigenvalue against its
# closed form, the frames at rest; a seeded transient decays at the CEA's rate (5 %); the rotating roller's lab frame
# (the branches transported) against the co-rotating one
roller_test(modes_maxwell modes_maxwell.py LABELS quick TIMEOUT 300)
roller_test(modes_maxwell_transient modes_maxwell_transient.py LABELS quick TIMEOUT 300)
roller_test(modes_maxwell_lab modes_maxwell_lab.py LABELS quick TIMEOUT 1200)
