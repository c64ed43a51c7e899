# Frequencies from transients (docs/squeal.md section 4): roller -modes (co-rotating and lab frames), then transients
# seeded with single modes (-initial_condition mode); rollerref.mode_transient measures their frequency and growth
# rate: the time-discretization shift of the DMF, dt^2, the lab-frame probe, Kelvin-Voigt decay.
roller_test(modes_transient modes_transient.py LABELS quick TIMEOUT 600)
