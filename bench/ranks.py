#!/usr/bin/env python3
"""More ranks never slower (issue 27, docs/performance.md): the scenes of jobs/ that a user runs with the README's
`mpiexec -n 2` line, on 1 and 2 ranks, interleaved over R rounds; the median wall time of each and the ratio
(2 ranks / 1 rank: below 1 is faster), against both
baselines: `mpiexec -n 1 roller` (the issue's: the same launcher as the parallel run) and the bare `roller` (Open MPI's
singleton start-up). Wall time is what a user waits for; the CPU time (user + system of the whole
process tree) is printed beside it (2 ranks spend more CPU in total, the question is the wall). Also the 2-rank run
with the former layouts for comparison: the whole factor on every rank (-solver_schur false) and MUMPS
(-solver_schur false -solver_redundant_max 0).

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
    # (label, ranks, options, under mpiexec): the baseline is `mpiexec -n 1`; the bare command (Open MPI's
    # singleton start-up) is measured beside it
    variants = [("1 rank", 1, [], False), ("mpiexec -n 1", 1, [], True), ("2 ranks", 2, [], True)] + ([] if o.no_mumps else [("2 ranks, whole factor on every rank", 2, ["-solver_schur", "false"], True),
                                                  ("2 ranks, MUMPS", 2, ["-solver_schur", "false", "-solver_redundant_max", 0], True)])
    rows = []
    for scene in o.scenes.split(","):
        args = ["-options_file", os.path.join(ROOT, "jobs", f"{scene}.yaml"), "-ts_max_time", o.t_end]
        wall = {v[0]: [] for v in variants}
        cpu = {v[0]: [] for v in variants}
        for r in range(o.rounds):
            for label, n, extra, launcher in variants:
                res = benchlib.run(args + extra, nproc=n, logview=False, launcher=launcher)
                wall[label].append(res["wall"])
                cpu[label].append(res["cpu"])
                print(f"  {scene} round {r + 1}: {label}: wall {res['wall']:.2f} s, cpu {res['cpu']:.2f} s, load {os.getloadavg()[0]:.1f}", file=sys.stderr, flush=True)
        for label, n, extra, launcher in variants:
            w = statistics.median(wall[label])
            per = {b: [x / y for x, y in zip(wall[label], wall[b])] for b in ("1 rank", "mpiexec -n 1")}
            rows.append(f"| {scene} | {label} | {w:.2f} | {statistics.median(per['1 rank']):.3f} ({min(per['1 rank']):.3f}-{max(per['1 rank']):.3f}) | "
                        f"{statistics.median(per['mpiexec -n 1']):.3f} ({min(per['mpiexec -n 1']):.3f}-{max(per['mpiexec -n 1']):.3f}) | "
                        f"{statistics.median(cpu[label]):.2f} | `{benchlib.shell(args + extra, n, launcher)}` |")
    out = [f"-ts_max_time {o.t_end:g}; median of {o.rounds} interleaved rounds; machine: {platform.node()}, {os.cpu_count()} cores, "
           f"load {os.getloadavg()[0]:.1f} at the end", "",
           "Ratios: the median over the rounds of this run's wall time over the same round's baseline (range in brackets).", "",
           "| scene | run | wall [s] (median) | / `roller` (bare) | / `mpiexec -n 1 roller` | CPU [s] | command |", "|---|---|---|---|---|---|---|"] + rows
    benchlib.save("ranks.md", "\n".join(out) + "\n")


if __name__ == "__main__":
    main()
