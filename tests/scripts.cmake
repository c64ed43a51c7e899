# Post-processing scripts: scripts/rollerreport/spectrum.py (the amplitude of a line relative to the mean, the cogging of
# the contact force, docs/contact.md "Cogging: the force spectrum") and its CLI scripts/rollerplots/spectrum.py, on
# synthetic signals with known lines; no roller run.
roller_test(spectrum_synthetic spectrum_synthetic.py LABELS quick TIMEOUT 120)
# scripts/rollerplots/traction.py (pressure, traction and stick zone across the contact patch, docs/friction.md 5.1)
# on a small friction run: its P and Q are the CSV's, every theory option draws.
roller_test(plot_traction_smoke plot_traction_smoke.py LABELS quick TIMEOUT 180)
# The report package scripts/rollerreport (docs/squeal.md section 9) on synthetic folders: the radiation model against
# the pulsating and oscillating cylinder's closed forms, the finite width's limits, A-weighting; verdict, mechanisms,
# report.json's SPEC keys, the WAV of the simulated span at its stated level and envelope, the journal's reuse.
roller_test(rollerreport_unit rollerreport_unit.py LABELS quick TIMEOUT 300)
# scripts/rollerreport/squeal_fit.py on a synthetic monitor CSV (docs/squeal.md 4.4.3): the seed's response of a mode of any order
# fitted in the contact force (seeded minus unseeded, the start's own line at the same frequency cancelled), growth
# within 5 %, frequency 0.5 %; an unknown column is an error naming it; no roller run.
roller_test(squeal_fit_synthetic squeal_fit_synthetic.py LABELS quick TIMEOUT 120)
# The packages of scripts/ (rollerref, rollerreport, rollerplots, rollertools): every module imports, every command
# answers --help, no loose .py file in scripts/.
roller_test(scripts_packages scripts_packages.py LABELS quick TIMEOUT 300)
# report.html in headless Chromium (scripts/install-deps.sh installs it): its audio element loads squeal.wav with the
# WAV's duration, every image loads, every link is a relative file of the folder.
roller_test(report_page report_page.py LABELS quick TIMEOUT 300)
