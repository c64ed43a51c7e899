# Coulomb friction between the roller and the sheet (src/contact/contact_friction.c, docs/friction.md): the law
# holds at every node and step, the energy identity with the shaft, sheet and friction works closes, the Tresca
# QP solvers agree, -friction 0 is the frictionless code bit for bit, and 1 and 2 ranks agree.
roller_test(friction_law friction_law.py LABELS quick TIMEOUT 600)
roller_test(friction_mpi friction_mpi.py LABELS mpi PROCESSORS 2 TIMEOUT 300)
