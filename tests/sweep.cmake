# -sweep (src/sweep/sweep.c, docs/squeal.md section 6): a 3 x 2 map of the free annulus by one mpiexec on two
# sub-communicators: every case present, each equal to its own -modes run, 1 and 2 ranks the same, the Campbell
# splitting growing with omega, two -sweep_slice parts merged (scripts/rollertools/merge_sweep.py) equal to the whole map, and
# scripts/rollerplots/sweep.py's picture.
roller_test(modes_sweep modes_sweep.py LABELS mpi PROCESSORS 2 TIMEOUT 300)
# -sweep without -modes (src/sweep/sweep_transient.c, docs/squeal.md section 6.5): a 2 x 3 transient map of the feeder
# (creep x friction) by one and two ranks, the same but for wall_time; each row its single run's window means; a map
# killed by SIGKILL resumed from its journals equal to the whole; two slices merged; Q = -mu P where the contact slips.
roller_test(transient_sweep transient_sweep.py LABELS mpi PROCESSORS 2 TIMEOUT 300)
