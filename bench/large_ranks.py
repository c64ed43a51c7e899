#!/usr/bin/env python3
"""Large meshes on 1 and 2 ranks (issue 27, docs/performance.md "Large meshes on several ranks"): P2 at h = 0.005
(221k unknowns), the free scene (jobs/free.yaml) and the rolling scene (jobs/rolling.yaml, uniform mesh), short runs
of --steps steps; from -log_view the set-up (stage "Roller setup"), the time per step (stages step + contact +
diagnostics) and the step solver's share; the whole run to the scene's end time estimated as set-up + steps x per
step (the scene's number of steps printed by -ts_view), on 1 rank (serial Cholesky, nested dissection) and on 2 ranks
with the substructured Cholesky (the default above -solver_redundant_max) and with MUMPS (-solver_schur false).
Interleaved rounds, the median of each figure; wall times, CPU beside them. Measure on a quiet machine.

Usage: /usr/bin/python3 bench/large_ranks.py [--rounds 3] [--steps 20] [--scenes free,rolling] [--h 0.005] [--no-mumps] [--out large_ranks.md]"""
import argparse
import os
import platform
import re
import statistics
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import benchlib  # noqa: E402
from benchlib import event, stage  # noqa: E402

ROOT = benchlib.ROOT
VARIANTS = [("1 rank", 1, []), ("2 ranks, substructured", 2, []), ("2 ranks, MUMPS", 2, ["-solver_schur", "false", "-solver_redundant_max", 0])]


def steps_to_end(text, scheme_dt):
    """The scene's number of steps to its end time, from -ts_view's 'solves to reach t = T' line."""
    m = re.search(r"solves to reach t = ([\d.e+-]+)", text)
    return float(m.group(1)) / scheme_dt if m else float("nan")


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--rounds", type=int, default=3)
    ap.add_argument("--steps", type=int, default=20)
    ap.add_argument("--scenes", default="free,rolling")
    ap.add_argument("--h", default="0.005")
    ap.add_argument("--no-mumps", action="store_true", help="leave out the MUMPS variant")
    ap.add_argument("--out", default="large_ranks.md", help="the table's file in bench/results/")
    o = ap.parse_args()
    variants = [v for v in VARIANTS if not (o.no_mumps and "MUMPS" in v[0])]
    rows = []
    for scene in o.scenes.split(","):
        args = ["-options_file", os.path.join(ROOT, "jobs", f"{scene}.yaml"), "-degree", 2, "-mesh_h", o.h, "-ts_max_steps", o.steps, "-ts_view"]
        if scene != "free":
            args += ["-mesh_h_contact", o.h]
        fig = {v[0]: {"setup": [], "step": [], "solve": [], "wall": [], "cpu": [], "end": []} for v in variants}
        for r in range(o.rounds):
            for label, n, extra in variants:
                res = benchlib.run(args + extra, nproc=n)
                nsteps = o.steps
                step = (stage(res, "Roller step") + stage(res, "Roller contact") + stage(res, "Roller diagnostics")) / nsteps
                dt = float(re.search(r"-ts_dt ([\d.e+-]+)", res["stdout"]).group(1))
                total = steps_to_end(res["stdout"], dt)
                f = fig[label]
                f["setup"].append(stage(res, "Roller setup"))
                f["step"].append(step)
                f["solve"].append((event(res, "Roller step", "KSPSolve")[1] + event(res, "Roller contact", "KSPSolve")[1]) / nsteps)
                f["wall"].append(res["wall"])
                f["cpu"].append(res["cpu"])
                f["end"].append(f["setup"][-1] + total * step)
                print(f"  {scene} round {r + 1} {label}: set-up {f['setup'][-1]:.1f} s, {1e3 * step:.1f} ms/step, whole run ~{f['end'][-1]:.0f} s "
                      f"({total:.0f} steps); wall {res['wall']:.1f} s, load {os.getloadavg()[0]:.1f}", file=sys.stderr, flush=True)
        base = statistics.median(fig["1 rank"]["end"])
        for label, n, extra in variants:
            f = {k: statistics.median(v) for k, v in fig[label].items()}
            rows.append(f"| {scene} | {label} | {f['setup']:.1f} | {1e3 * f['step']:.1f} | {1e3 * f['solve']:.1f} | {f['wall']:.1f} ({f['cpu']:.1f}) | "
                        f"{f['end']:.0f} | {base / f['end']:.2f} | `{benchlib.shell(args + extra, n)}` |")
    out = [f"P2 h = {o.h}, {o.steps} steps a run, median of {o.rounds} interleaved rounds; machine: {platform.node()}, {os.cpu_count()} cores, "
           f"load {os.getloadavg()[0]:.1f} at the end", "",
           "| scene | run | set-up [s] | per step [ms] | step solves per step [ms] | wall (CPU) of the short run [s] | whole run, estimated [s] | speed-up | command |",
           "|---|---|---|---|---|---|---|---|---|"] + rows
    benchlib.save(o.out, "\n".join(out) + "\n")


if __name__ == "__main__":
    main()
