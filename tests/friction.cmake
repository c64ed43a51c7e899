# Coulomb friction (docs/friction.md section 5).
# Carter's steady rolling contact: at low speed the stick zone sits at the leading edge and Q/(mu P) follows Carter's
# creep curve (section 5.2); quick: h_c = 0.003 (about 2 minutes); long: h_c = 0.002 and a dt check.
roller_test(friction_carter friction_carter.py LABELS quick TIMEOUT 600)
roller_test(friction_carter_long friction_carter.py LABELS long ARGS long TIMEOUT 1800)
