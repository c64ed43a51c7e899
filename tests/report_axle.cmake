# The squeak report end to end on jobs/axle_bistable.yaml (docs/squeal.md 9.4): a scene whose steady sliding is
# linearly stable (the 1-DOF closed form standing in for the CEA, which does not take -axle) but whose start from rest
# settles into stick-slip is reported as squeaking by stick-slip; the cycle's period and amplitude against the CSV and
# docs/validation.md 10.5, squeal.wav's length (the span times the time scale, >= 0.5 s), pitch (2 %) and sustained
# envelope, the forced response against rollerref.forced's closed form (10 %), 64 propensity cases by the finite
# elements (each its CEA and its reduced start from rest) against the 1-DOF, the journal's reuse. The start from rest
# and the forced run on the reduced model; the propensity's 64 CEAs and runs on a coarser mesh on 2 ranks.
roller_test(report_axle report_axle.py LABELS long PROCESSORS 2 TIMEOUT 3600)
# The report on the printer's own scenes (issue 38, docs/squeal.md 7.10): jobs/printer_roller.yaml (the feed on the axle)
# and jobs/printer_pick.yaml (the pick from rest) with the report's defaults: SPEC section 10's keys, squeal.wav of
# 0.51 s against its source (level, the bounce's decay, the ripple's sustained line), stick-slip only if the patch lets
# go, forced against rollerref.forced.two_dof (5 %), the ripple swept (its 873 Hz case against the run's line, 5 %),
# the propensity's 64 cases by the finite elements (the coarse mesh), the CEA's bounce against the run's (1.5 %, 10 %),
# the page in Chromium. A CEA of 115k unknowns, the long runs on the reduced model, the feed's 64 CEAs on the coarse
# mesh (about two hours of CPU).
roller_test(report_printer report_printer.py LABELS long PROCESSORS 2 TIMEOUT 9000)
