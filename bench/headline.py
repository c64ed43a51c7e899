#!/usr/bin/env python3
"""The headline in one invocation: the obstacle-free scene (figure 4) over 0 <= t <= 20 with the paper's
configuration (jobs/paper/fig4.yaml: P1, h = dt = 0.0125, backward Coriolis, the DMF, unpreconditioned CG), Roller's
default (no discretization option: the scheme, dt and h from -ts_phase_error 0.01), the former default (the DMF at
dt = 0.00172 on the same mesh), and the option sets that reach 0.1 % (-ts_phase_error 0.001 and the given ones),
run in R interleaved rounds; each run's errors of R(t) and alpha(t) against the exact axisymmetric reference
(scripts/rollerref/axisym.py, n = 256), its CPU time (user + system of the whole process) as the median over the
rounds, and the ratio to the paper configuration's median (the machine is shared: the ratio is the measurement,
absolute seconds are not). Writes the table to stdout and bench/results/headline.md.

Usage: /usr/bin/python3 bench/headline.py [--rounds 3] [--young E] [--t-end T]"""
import argparse
import os
import platform
import statistics
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import benchlib  # noqa: E402

ROOT = benchlib.ROOT
sys.path.insert(0, os.path.join(ROOT, "scripts"))
from rollerref import axisym as ar  # noqa: E402

RUNS = [
    ("paper (jobs/paper/fig4.yaml): P1 h=dt=0.0125, dmf, CG", ["-options_file", os.path.join(ROOT, "jobs", "paper", "fig4.yaml")]),
    ("default (no discretization option, -ts_phase_error 0.01)", []),
    ("former default: dmf dt=0.00172, P2 h=0.0348", ["-ts_scheme", "dmf", "-ts_dt", 0.00171757, "-mesh_h", 0.0347906]),
    ("-ts_phase_error 0.001", ["-ts_phase_error", 0.001]),
]


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--rounds", type=int, default=3)
    ap.add_argument("--young", type=float, default=0.1)
    ap.add_argument("--t-end", type=float, default=20.0)
    ap.add_argument("--extra", action="append", default=[], help="another run: LABEL=opt,value,opt,...")
    o = ap.parse_args()
    runs = RUNS + [(e.split("=", 1)[0], e.split("=", 1)[1].split(",")) for e in o.extra]
    p = dict(ar.DEFAULTS)
    p["young"], p["n"] = o.young, 256
    cpu, err, steps = {k: [] for k, _ in runs}, {}, {}
    for r in range(o.rounds):
        for label, args in runs:
            res = benchlib.run(args + ["-young", o.young, "-ts_max_time", o.t_end], csv=True, logview=False)
            d = res["series"]
            if label not in err:
                Rx, ax = ar.reference(p, np.asarray(d["t"]), scheme="exact")
                err[label] = (np.abs(d["R"] - Rx).max() / np.abs(Rx).max(), np.abs(d["alpha"] - ax).max() / np.abs(ax).max())
                steps[label] = len(d["t"]) - 1
            cpu[label].append(res["cpu"])
            print(f"  round {r + 1}: {label}: cpu {res['cpu']:.2f} s, load {os.getloadavg()[0]:.1f}", file=sys.stderr, flush=True)
    paper = statistics.median(cpu[runs[0][0]])
    out = [f"obstacle-free scene, E = {o.young:g}, 0 <= t <= {o.t_end:g}; CPU time (user + system) of each whole process, median of "
           f"{o.rounds} interleaved rounds, ratio to the paper configuration's median; machine: {platform.node()}, "
           f"{os.cpu_count()} cores, load {os.getloadavg()[0]:.1f} at the end", "",
           "| run | steps | err R | err alpha | CPU [s] | CPU / paper | command |", "|---|---|---|---|---|---|---|"]
    for label, args in runs:
        c = statistics.median(cpu[label])
        cmd = benchlib.shell([str(a) for a in args + ["-young", o.young, "-ts_max_time", o.t_end]]).replace(ROOT + "/", "")
        out.append(f"| {label} | {steps[label]} | {err[label][0]:.2e} | {err[label][1]:.2e} | {c:.2f} | {c / paper:.3f} | `{cmd}` |")
    print("\n".join(out))
    with open(os.path.join(ROOT, "bench", "results", "headline.md"), "w") as f:
        f.write("\n".join(out) + "\n")


if __name__ == "__main__":
    main()
