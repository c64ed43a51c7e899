#!/usr/bin/env python3
"""Throughput of a sweep (docs/squeal.md section 6): the same stability map by `mpiexec -n 1` and `mpiexec -n 2` (one
rank per case, cases round-robin over the sub-communicators), the wall-time ratio (ideal 0.5 on 2 cores) and the
check that both CSVs are identical (each case runs on one rank either way).

Usage: bench/sweep.py [--np 1,2] [--rounds 1] [roller options ...]
Default map: -modes -sweep_omega_range 0,0.45,10 -sweep_young 0.05,0.075,0.1,0.15,0.2 (50 cases, the mesh from
the default -ts_phase_error; omega stays below 0.95 of the softest roller's lowest frequency, 0.51 at young 0.05,
which RollerCheckRotation demands). Extra options replace the default map. CPU time is that of the whole process
tree; the load average of the machine is printed with each run. Each time is the minimum over
--rounds interleaved repetitions; the development machine has 2 cores shared with other jobs.
"""
import argparse
import os
import resource
import subprocess
import sys
import tempfile
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import benchlib  # noqa: E402

DEFAULT = ["-modes", "-sweep_omega_range", "0,0.45,10", "-sweep_young", "0.05,0.075,0.1,0.15,0.2"]


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
    opts, extra = ap.parse_known_args()
    args = extra if extra else DEFAULT
    nps = [int(n) for n in opts.np.split(",")]
    best, cpus, per_case, files = {}, {}, {}, {}
    with tempfile.TemporaryDirectory() as tmp:
        for _ in range(opts.rounds):
            for n in nps:
                files[n] = os.path.join(tmp, f"sweep_np{n}.csv")
                wall, cpu, cases = sweep(args, n, files[n])
                if wall < best.get(n, float("inf")):
                    best[n], cpus[n], per_case[n] = wall, cpu, cases
        texts = {n: open(files[n]).read() for n in nps}
    ncases = len(per_case[nps[0]])
    print(f"sweep of {ncases} cases: mpiexec -n N build/roller -sweep F.csv {' '.join(args)}\n")
    print("| ranks | wall (s) | CPU (s) | sum of case times (s) | mean case (s) | wall / wall(1 rank) |")
    print("|---|---|---|---|---|---|")
    for n in nps:
        print(f"| {n} | {best[n]:.1f} | {cpus[n]:.1f} | {sum(per_case[n]):.1f} | {sum(per_case[n]) / max(1, len(per_case[n])):.2f} | {best[n] / best[nps[0]]:.3f} |")
    same = all(texts[n] == texts[nps[0]] for n in nps)
    print(f"\nCSVs identical on {', '.join(map(str, nps))} ranks: {same}")


if __name__ == "__main__":
    main()
