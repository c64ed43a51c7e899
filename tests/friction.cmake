# Friction (docs/friction.md section 5).
# stick-slip of the roller turned slowly on the resting sheet with velocity-weakening friction, and steady
# sliding with constant mu (jobs/stickslip.yaml, docs/friction.md section 5.3; two runs of about 4 minutes)
roller_test(friction_stickslip friction_stickslip.py LABELS long TIMEOUT 1200)
