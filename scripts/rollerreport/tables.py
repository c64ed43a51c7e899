"""A result as a pair of files in the report's folder: STEM.csv (a row per case) and STEM.json (the summary), written
and read back alike by the studies that make one (rollerreport.propensity, rollerreport.ripple_sweep)."""
import csv
import json
import os


def write(folder, stem, rows, summary):
    """STEM.csv (the rows' keys as columns, the first row's order) and STEM.json; returns the summary."""
    with open(os.path.join(folder, stem + ".csv"), "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(rows[0]))
        w.writeheader()
        w.writerows(rows)
    with open(os.path.join(folder, stem + ".json"), "w") as f:
        json.dump(summary, f, indent=1)
    return summary


def read(folder, stem):
    """(the summary, the rows as dicts of strings) of STEM.json and STEM.csv."""
    with open(os.path.join(folder, stem + ".json")) as f:
        summary = json.load(f)
    with open(os.path.join(folder, stem + ".csv"), newline="") as f:
        return summary, list(csv.DictReader(f))
