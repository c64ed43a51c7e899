"""python3 -m rollerreport FOLDER [--parts sound,animation]: the squeak report of FOLDER (docs/squeal.md 9.1):
report.md, report.json, report.html, map.png and the parts asked for (default both), each reused when its inputs
are the ones the folder's journal.json recorded."""
import argparse

from . import report

p = argparse.ArgumentParser(prog="rollerreport", description=__doc__)
p.add_argument("folder")
p.add_argument("--parts", default=",".join(report.PARTS), help="the report's parts to write, comma-separated, of "
               f"{', '.join(report.PARTS)} (default all; '' for none: the verdict, map and pages only)")
a = p.parse_args()
parts = [x for x in a.parts.split(",") if x]
bad = [x for x in parts if x not in report.PARTS]
if bad:
    p.error(f"--parts {a.parts}: unknown {', '.join(bad)}; allowed: {', '.join(report.PARTS)}")
r = report.write(a.folder, parts)
print(f"rollerreport: {r['verdict']}; wrote {', '.join(r['files'])} in {a.folder}" + (f"; missing {', '.join(r['missing'])}" if r["missing"] else ""))
