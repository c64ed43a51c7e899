# Golden outputs (tests/data/golden/, written by tests/regression.py --regenerate before the redesign): the
# reference scenes on P1 and P2, 1 and 2 ranks, reproduced to 1e-12 relative.
roller_test(regression regression.py LABELS quick regression ARGS --nproc 1 TIMEOUT 300)
roller_test(regression_mpi regression.py LABELS mpi regression ARGS --nproc 2 PROCESSORS 2 TIMEOUT 300)

# The shape of the code: layers, include circles, file and struct sizes (docs/architecture.md).
roller_test(architecture architecture.py LABELS quick TIMEOUT 60)
