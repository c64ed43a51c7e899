# The generalized Maxwell rubber (-rubber maxwell, docs/model.md sections 1.1, 2.2): the energy balance with the branches
# on a frictional rolling scene (dmf, trapezoidal), the torsional mode's decay against its closed form; the fit's unit
# test is tests/unit/rubber_fit.c, the restart's tests/restart.py
roller_test(maxwell maxwell.py LABELS quick TIMEOUT 600)
