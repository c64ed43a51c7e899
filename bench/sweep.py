#!/usr/bin/env python3
"""Throughput of a sweep (docs/squeal.md sections 6.4 and 6.5): the same map by `mpiexec -n 1` and `mpiexec -n 2` (one
rank per case, cases round-robin over the sub-communicators), the wall-time ratio (ideal 0.5 on 2 cores), the CPU
time of the whole process tree (user + sys; ideal: the same on any number of ranks) and the check that the CSVs are
identical (each case runs on one rank either way; a transient map's wall_time column left out).

Usage: bench/sweep.py [--np 1,2] [--rounds 1] [--transient] [roller options ...]
Default map: -modes -sweep_omega_range 0,0.45,10 -sweep_young 0.05,0.075,0.1,0.15,0.2 (50 cases, the mesh from
the default -ts_phase_error; omega stays below 0.95 of the softest roller's lowest frequency, 0.51 at young 0.05,
which RollerCheckRotation demands). --transient: the transient map of the feeder, -options_file jobs/feed.yaml
-ts_max_time 4 -sweep_sheet_speed 0.05,0.1,0.1555 -sweep_friction 0.3,0.8 (6 cases, the default discretization).
Extra options replace the default map. The load average of the machine is printed with each run. Each round runs
every rank count once (interleaved); the table has the minimum and the median over the rounds and every round's
CPU ratio. The development machine has 2 cores shared with other jobs.
"""
import argparse
import os
import resource
import subprocess
import sys
import tempfile
import time

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import benchlib  # noqa: E402

DEFAULT = ["-modes", "-sweep_omega_range", "0,0.45,10", "-sweep_young", "0.05,0.075,0.1,0.15,0.2"]
TRANSIENT = ["-options_file", "jobs/feed.yaml", "-ts_max_time", "4", "-sweep_sheet_speed", "0.05,0.1,0.1555", "-sweep_friction", "0.3,0.8"]


def without_wall(text):
    """The CSV's text with a wall_time column left out (a transient map's)"""
    lines = [line.split(",") for line in text.splitlines()]
    if not lines or "wall_time" not in lines[0]:
        return text
    k = lines[0].index("wall_time")
    return "\n".join(",".join(f[:k] + f[k + 1:]) for f in lines)


def sweep(args, nproc, csv):
    cmd = [benchlib.MPIEXEC, "-n", str(nproc), benchlib.EXE, "-sweep", csv] + args
    load = os.getloadavg()[0]
    ru0 = resource.getrusage(resource.RUSAGE_CHILDREN)
    start = time.perf_counter()
    proc = subprocess.run(cmd, capture_output=True, text=True, cwd=benchlib.ROOT)
    wall = time.perf_counter() - start
    ru1 = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = (ru1.ru_utime + ru1.ru_stime) - (ru0.ru_utime + ru0.ru_stime)
    if proc.returncode:
        sys.stderr.write(proc.stdout[-4000:] + proc.stderr[-4000:])
        raise RuntimeError(f"{' '.join(cmd)} exited {proc.returncode}")
    cases = [float(line.rsplit(",", 1)[1].split()[0]) for line in proc.stdout.splitlines() if line.startswith("sweep: case ")]
    print(f"  -n {nproc}: wall {wall:.1f} s, cpu {cpu:.1f} s, load average before {load:.2f} after {os.getloadavg()[0]:.2f}", file=sys.stderr)
    return wall, cpu, cases


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--np", default="1,2")
    ap.add_argument("--rounds", type=int, default=1)
    ap.add_argument("--transient", action="store_true")
    opts, extra = ap.parse_known_args()
    args = extra if extra else (TRANSIENT if opts.transient else DEFAULT)
    nps = [int(n) for n in opts.np.split(",")]
    walls, cpus, per_case, texts = {n: [] for n in nps}, {n: [] for n in nps}, {}, {}
    with tempfile.TemporaryDirectory() as tmp:
        for _ in range(opts.rounds):
            for n in nps:
                path = os.path.join(tmp, f"sweep_np{n}.csv")
                wall, cpu, cases = sweep(args, n, path)
                walls[n].append(wall)
                cpus[n].append(cpu)
                per_case[n] = cases
                texts[n] = without_wall(open(path).read())
                os.remove(path)
    ncases = len(per_case[nps[0]])
    med = {n: (float(np.median(walls[n])), float(np.median(cpus[n]))) for n in nps}
    print(f"sweep of {ncases} cases, {opts.rounds} interleaved rounds: mpiexec -n N build/roller -sweep F.csv {' '.join(args)}\n")
    print("| ranks | wall min (s) | wall median (s) | CPU median (s) | wall / wall(1 rank), medians | CPU(1 rank) / CPU, medians |")
    print("|---|---|---|---|---|---|")
    for n in nps:
        print(f"| {n} | {min(walls[n]):.1f} | {med[n][0]:.1f} | {med[n][1]:.1f} | {med[n][0] / med[nps[0]][0]:.3f} | {med[nps[0]][1] / med[n][1]:.3f} |")
    for n in nps[1:]:
        print(f"\nper round, CPU(1 rank) / CPU({n} ranks): " + ", ".join(f"{a / b:.3f}" for a, b in zip(cpus[nps[0]], cpus[n])))
        print(f"per round, wall({n} ranks) / wall(1 rank): " + ", ".join(f"{b / a:.3f}" for a, b in zip(walls[nps[0]], walls[n])))
    same = all(texts[n] == texts[nps[0]] for n in nps)
    print(f"\nCSVs identical on {', '.join(map(str, nps))} ranks{' (but for wall_time)' if opts.transient or '-modes' not in args else ''}: {same}")


if __name__ == "__main__":
    main()
