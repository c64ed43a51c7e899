"""Merge the parts of a sweep run as a job array (jobs/slurm/sweep.sbatch: task i wrote `-sweep part_i.csv
-sweep_slice i,k`) into one CSV sorted by case, as one `roller -sweep` would have written it: the rows of each case
in their order, one header. Refuses parts with different columns or a case in two parts, and with --cases N a map
with a case missing; writes F.part and renames it when complete.

Usage: PYTHONPATH=scripts python3 -m rollertools.merge_sweep part_0.csv part_1.csv ... -o sweep.csv [--cases N]"""
import argparse
import os
import sys


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("parts", nargs="+")
    ap.add_argument("-o", "--out", required=True)
    ap.add_argument("--cases", type=int, help="the number of cases of the map: fail if any is missing")
    a = ap.parse_args()
    header, cases, owner = None, {}, {}
    for path in a.parts:
        with open(path) as f:
            lines = f.read().splitlines()
        if header is None:
            header = lines[0]
        if lines[0] != header or not header.startswith("case,"):
            sys.exit(f"merge_sweep: {path}: columns {lines[0]!r} differ from {header!r}")
        for line in lines[1:]:
            case = int(line.split(",", 1)[0])
            if owner.setdefault(case, path) != path:
                sys.exit(f"merge_sweep: case {case} is in {owner[case]} and {path}: parts of different slicings?")
            cases.setdefault(case, []).append(line)
    if a.cases is not None:
        missing = sorted(set(range(a.cases)) - set(cases))
        if missing:
            sys.exit(f"merge_sweep: {len(missing)} of {a.cases} cases missing: {missing[:20]} (a failed array task?)")
    part = a.out + ".part"
    with open(part, "w") as f:
        f.write(header + "\n")
        for case in sorted(cases):
            f.write("\n".join(cases[case]) + "\n")
    os.replace(part, a.out)
    print(f"merge_sweep: {len(cases)} cases, {sum(len(v) for v in cases.values())} rows from {len(a.parts)} parts -> {a.out}")


if __name__ == "__main__":
    main()
