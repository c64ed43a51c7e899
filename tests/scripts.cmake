# Post-processing scripts: scripts/spectrum.py (the amplitude of a line relative to the mean, the cogging of
# the contact force, docs/contact.md "Cogging: the force spectrum") and its CLI scripts/plot_spectrum.py, on
# synthetic signals with known lines; no roller run.
roller_test(spectrum_synthetic spectrum_synthetic.py LABELS quick TIMEOUT 120)
