# The one-degree-of-freedom references of issue 36 (scripts/rollerref, docs/validation.md section 9): closed forms
# against the package's event-driven integrator, the integrator against Moreau's time-stepping, the bistable set,
# the sheet's pick, the ripple's forced response, the command line; no roller run (about 30 s).
roller_test(rollerref_unit rollerref_unit.py LABELS quick TIMEOUT 300)
