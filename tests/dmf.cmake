# The DMF elastodynamics without obstacle (issue: the rotating roller, verified).
roller_test(dmf_energy dmf_energy.py LABELS quick)
roller_test(dmf_mms dmf_mms.py LABELS quick TIMEOUT 900)
roller_test(dmf_paper dmf_paper.py LABELS quick)
roller_test(dmf_axisym dmf_axisym.py LABELS quick)
roller_test(accurate_defaults accurate_defaults.py LABELS quick TIMEOUT 600)
roller_test(accurate_defaults_long accurate_defaults.py LABELS long ARGS long TIMEOUT 1800)
