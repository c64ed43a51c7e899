#!/usr/bin/env python3
"""More ranks never slower (issue 27, docs/performance.md): the scenes of jobs/ that a user runs with the README's
`mpiexec -n 2` line, on 1 and 2 ranks, interleaved over R rounds; the median wall time of each and the ratio
(2 ranks / 1 rank: below 1 is faster). Wall time is what a user waits for; the CPU time (user + system of the whole
process tree) is printed beside it (2 ranks spend more CPU in total, the question is the wall). Also the 2-rank run
with MUMPS (-solver_redundant_max 0, the former parallel default) for comparison.

The development machine has 2 cores and is shared: a 2-rank run competes with other jobs for both cores, so
measure on a quiet machine (the load is printed).

Usage: /usr/bin/python3 bench/ranks.py [--rounds 5] [--t-end 2] [--scenes rolling,free,feed] [--no-mumps]"""
import argparse
import os
import platform
import statistics
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import benchlib  # noqa: E402

ROOT = benchlib.ROOT


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--rounds", type=int, default=5)
    ap.add_argument("--t-end", type=float, default=2.0)
    ap.add_argument("--scenes", default="rolling,free,feed")
    ap.add_argument("--no-mumps", action="store_true")
    o = ap.parse_args()
    variants = [("1 rank", 1, []), ("2 ranks", 2, [])] + ([] if o.no_mumps else [("2 ranks, MUMPS", 2, ["-solver_redundant_max", 0])])
    rows = []
    for scene in o.scenes.split(","):
        args = ["-options_file", os.path.join(ROOT, "jobs", f"{scene}.yaml"), "-ts_max_time", o.t_end]
        wall = {v[0]: [] for v in variants}
        cpu = {v[0]: [] for v in variants}
        for r in range(o.rounds):
            for label, n, extra in variants:
                res = benchlib.run(args + extra, nproc=n, logview=False)
                wall[label].append(res["wall"])
                cpu[label].append(res["cpu"])
                print(f"  {scene} round {r + 1}: {label}: wall {res['wall']:.2f} s, cpu {res['cpu']:.2f} s, load {os.getloadavg()[0]:.1f}", file=sys.stderr, flush=True)
        w1 = statistics.median(wall["1 rank"])
        for label, n, extra in variants:
            w = statistics.median(wall[label])
            rows.append(f"| {scene} | {label} | {w:.2f} | {w / w1:.3f} | {min(x / y for x, y in zip(wall[label], wall['1 rank'])):.3f}-"
                        f"{max(x / y for x, y in zip(wall[label], wall['1 rank'])):.3f} | {statistics.median(cpu[label]):.2f} | `{benchlib.shell(args + extra, n)}` |")
    out = [f"-ts_max_time {o.t_end:g}; median of {o.rounds} interleaved rounds; machine: {platform.node()}, {os.cpu_count()} cores, "
           f"load {os.getloadavg()[0]:.1f} at the end", "",
           "| scene | ranks | wall [s] | wall / 1 rank | per round | CPU [s] | command |", "|---|---|---|---|---|---|---|"] + rows
    text = "\n".join(out) + "\n"
    print(text)
    os.makedirs(os.path.join(ROOT, "bench", "results"), exist_ok=True)
    with open(os.path.join(ROOT, "bench", "results", "ranks.md"), "w") as f:
        f.write(text)


if __name__ == "__main__":
    main()
