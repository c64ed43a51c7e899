# -sweep (src/app/sweep.c, docs/squeal.md section 6): a 3 x 2 map of the free annulus by one mpiexec on two
# sub-communicators: every case present, each equal to its own -modes run, 1 and 2 ranks the same, the Campbell
# splitting growing with omega, two -sweep_slice parts merged (scripts/merge_sweep.py) equal to the whole map, and
# scripts/plot_sweep.py's picture.
roller_test(modes_sweep modes_sweep.py LABELS mpi PROCESSORS 2 TIMEOUT 300)
