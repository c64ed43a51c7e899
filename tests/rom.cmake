# The reduced-order transient (-rom, docs/performance.md "Reduced-order transient"), without contact: the reduced
# model's eigenvalues below the cutoff against the full model's (0.1 %), its energy balance to round-off, and its
# transient against the full one (about 40 s)
roller_test(rom_free rom_free.py LABELS quick TIMEOUT 600)
# Contact and friction on the reduced model: the printer on a coarse mesh, 4 ms, 150 modes: its energy identity with
# contact and friction to round-off, no penetration, KKT and Coulomb residuals (about 1 min)
roller_test(rom_contact rom_contact.py LABELS quick TIMEOUT 900)
# The issue's agreement over 30 ms of the printer: the reduced model's mean contact and friction forces within 1 % and
# 2 % of the full model's, the friction force's largest line within 1 % and 2 dB (about 10 min of CPU)
roller_test(rom_printer rom_printer.py LABELS long TIMEOUT 5400)
# -rom_output / -rom_input: the basis and the residual flexibility reused bit for bit, on 2 ranks to round-off, and
# refused by name for another rubber, mode count or mesh (about 30 s)
roller_test(rom_io rom_io.py LABELS quick mpi TIMEOUT 600)
# A seeded squeal transient on the reduced model: the order-1 whirl's growth within 5 % of the full transient's and the
# CEA's (about 4 min of CPU)
roller_test(rom_seeded rom_seeded.py LABELS long TIMEOUT 1800)
# The agreement where the full model converges in the time step: the clamped Kelvin-Voigt printer at dt and dt/2 (its
# friction force converged to 0.5 %, the reduced model's within 2 % at both), and on the issue's scene (where the full
# model's friction force is not converged: docs/friction.md 5.4) the contact force, the ripple line and the reduced
# model's own convergence and clean rolling at constant mu; the issue's lines on that scene with -viscosity 3.2e-7
# beside the branches, where the full model converges (about 12 min of CPU)
roller_test(rom_printer_dt rom_printer_dt.py LABELS long TIMEOUT 3600)
