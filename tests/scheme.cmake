# The time schemes (-ts_scheme, docs/model.md section 2.1): their order and their discrete energy
roller_test(scheme_order scheme_order.py LABELS quick)
roller_test(scheme_energy scheme_energy.py LABELS quick ARGS quick)
roller_test(scheme_energy_long scheme_energy.py LABELS long ARGS long TIMEOUT 3600)
