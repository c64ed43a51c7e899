# Bad input, restarts, signals and hard cases (issue: it keeps working, says clearly what is wrong).
roller_test(bad_input bad_input.py LABELS quick)
roller_test(hard_long_run hard_long_run.py LABELS quick hard)
roller_test(hard_large_steps hard_large_steps.py LABELS quick hard)
roller_test(hard_fast_rotation hard_fast_rotation.py LABELS quick hard)
roller_test(restart restart.py LABELS quick)
# issue 37: a checkpoint restarts on any number of ranks (1 -> 2, 2 -> 1, 2 -> 3 to 1e-8), refusals by name, -ts_max_wall
roller_test(restart_ranks restart_ranks.py LABELS mpi PROCESSORS 2 TIMEOUT 300)
roller_test(hard_incompressible hard_incompressible.py LABELS quick hard)
roller_test(hard_divergence hard_divergence.py LABELS quick hard)
roller_test(hard_impact hard_impact.py LABELS quick hard)
roller_test(options_fuzz options_fuzz.py LABELS hard TIMEOUT 1800)
roller_test(hard_crash hard_crash.py LABELS hard)
