"""python3 -m rollerreport FOLDER [--signal auto|COLUMN]: the squeal report of FOLDER (docs/squeal.md 9.1)."""
import argparse

from . import report

p = argparse.ArgumentParser(prog="rollerreport", description=__doc__)
p.add_argument("folder")
p.add_argument("--signal", default="auto", help="the transient CSV's column heard (default auto: of contact_force "
               "and friction_force the one that fluctuates most)")
a = p.parse_args()
r = report.write(a.folder, a.signal)
print(f"rollerreport: wrote {', '.join(r['files'])} in {a.folder}" + (f"; missing {', '.join(r['missing'])}" if r["missing"] else ""))
