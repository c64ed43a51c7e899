# Bad input, restarts, signals and hard cases (issue: it keeps working, says clearly what is wrong).
roller_test(bad_input bad_input.py LABELS quick)
