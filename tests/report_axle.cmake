# The squeak report end to end on jobs/axle_bistable.yaml (docs/squeal.md 9.4): a scene whose steady sliding is
# linearly stable (the 1-DOF closed form standing in for the CEA, which does not take -axle) but whose start from rest
# settles into stick-slip is reported as squeaking by stick-slip; the cycle's period and amplitude against the CSV and
# docs/validation.md 10.5, squeal.wav's length (the span times the time scale, >= 0.5 s), pitch (2 %) and sustained
# envelope, the forced response against rollerref.forced's closed form (10 %), 64 propensity cases, the journal's
# reuse. Two finite-element runs of about 4100 steps (about 8 CPU minutes).
roller_test(report_axle report_axle.py LABELS long TIMEOUT 2400)
