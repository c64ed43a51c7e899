# The obstacle QP of every step (src/contact*.c, docs/contact.md): the four solvers agree and satisfy the KKT
# conditions; no penetration and non-negative force under compression; the energy cannot grow against a
# stationary obstacle; omega = 0 compression is mirror-symmetric; 1 and 2 ranks give the same time series;
# the contact pressure output integrates to the contact force; the contact force converges with h and
# obeys Hertz's line-contact law at a small indentation; in rolling without artificial damping the step's
# energy identity closes, the contact creates no energy and (with the rubber's damping) the set does not flicker.
roller_test(contact_agree contact_agree.py LABELS quick TIMEOUT 300)
roller_test(contact_compression contact_compression.py LABELS quick TIMEOUT 300)
roller_test(contact_energy contact_energy.py LABELS quick TIMEOUT 300)
roller_test(contact_balance contact_balance.py LABELS quick TIMEOUT 300)
roller_test(contact_quiet contact_quiet.py LABELS quick TIMEOUT 600)
roller_test(contact_symmetry contact_symmetry.py LABELS quick TIMEOUT 300)
roller_test(contact_pressure contact_pressure.py LABELS quick TIMEOUT 300)
roller_test(contact_static contact_static.py LABELS quick TIMEOUT 300)
roller_test(contact_static_long contact_static.py LABELS long ARGS long TIMEOUT 3600)
# the static force on a mesh graded toward Gamma_C agrees with the uniform fine mesh's (docs/contact.md, "Graded mesh")
roller_test(contact_graded contact_graded.py LABELS quick TIMEOUT 300)
roller_test(contact_mpi contact_mpi.py LABELS mpi PROCESSORS 2 TIMEOUT 300)
