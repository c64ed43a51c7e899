#!/usr/bin/env python3
"""What the generalized Maxwell rubber's branches cost a step (issue 35, docs/performance.md): 200 steps of the same
scene and dt with Kelvin-Voigt (no branches) and with -rubber maxwell, CPU user + system of the whole process, the
same with 0 steps (the set-up: the difference is the steps' CPU), and the -log_view stages "Roller step" + "Roller
contact" + "Roller diagnostics" (the steps and their CSV rows: the least wall time of the rounds, and their flops, which
a loaded machine does not change), R interleaved rounds.

Scenes: the feeder (jobs/feed.yaml: contact, Coulomb friction; the graded mesh of its Kelvin-Voigt default, given,
since the default h follows the rubber's torsional frequency, P2) and the free roller (no obstacle: -mesh_h 0.035, P2), both -ts_scheme trapezoidal -ts_dt 0.005, 200 steps, a CSV row every step. Rubbers:
Kelvin-Voigt (tau 0.0115, the scenes'), the fit of a loss factor 0.1 over 0.1-10 (4 branches), 16 given branches.

  bench/maxwell_cost.py [--rounds R]     a table on stdout and bench/results/maxwell_cost.md"""
import argparse
import os
import re
import statistics
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import benchlib  # noqa: E402

ROOT = benchlib.ROOT
STEPS = ["-ts_scheme", "trapezoidal", "-ts_dt", 0.005, "-ts_max_steps", 200, "-ts_max_time", 1.0]
SCENES = {
    "feeder": ["-options_file", os.path.join(ROOT, "jobs", "feed.yaml"), "-mesh_h", 0.035, "-mesh_h_contact", 0.008, "-mesh_contact_layer", 0.016],
    "free": ["-mesh_h", 0.035, "-degree", 2],
}
TAU16 = ",".join(f"{10 ** (-3 + 4 * i / 15):.6g}" for i in range(16))
RUBBERS = {
    "Kelvin-Voigt (0 branches)": ["-viscosity", 0.0115],
    "Maxwell, fit 0.1 over 0.1-10 (4 branches)": ["-viscosity", 0, "-rubber", "maxwell", "-rubber_loss_factor", 0.1, "-rubber_band", "0.1,10"],
    "Maxwell, 16 branches": ["-viscosity", 0, "-rubber", "maxwell", "-maxwell_tau", TAU16, "-maxwell_weight", ",".join(["0.05"] * 16)],
}
STAGES = ("Roller step", "Roller contact", "Roller diagnostics")


def stage_flops(text):
    """The flops of the step stages, from -log_view's summary of stages."""
    flops = {m.group(1).strip(): float(m.group(2)) for m in re.finditer(r"^\s*\d+:\s+(.+?):\s+[0-9.e+-]+\s+[0-9.]+%\s+([0-9.e+-]+)", text, re.M)}
    return sum(flops.get(s, 0.0) for s in STAGES)


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--rounds", type=int, default=3)
    args = parser.parse_args()
    cpu, setup, steps, flops = {}, {}, {}, {}
    for r in range(args.rounds):
        for scene, sargs in SCENES.items():
            for rubber, rargs in RUBBERS.items():
                key = (scene, rubber)
                res = benchlib.run(sargs + rargs + STEPS, csv=True)
                zero = benchlib.run(sargs + rargs + STEPS + ["-ts_max_steps", 0], csv=True)
                cpu.setdefault(key, []).append(res["cpu"])
                setup.setdefault(key, []).append(zero["cpu"])
                steps.setdefault(key, []).append(sum(res["stages"].get(s, 0.0) for s in STAGES))
                flops[key] = stage_flops(res["logview_text"])
                print(f"round {r + 1} {scene}, {rubber}: CPU {res['cpu']:.2f} s (0 steps: {zero['cpu']:.2f} s), steps {steps[key][-1]:.3f} s, {flops[key]:.3e} flops", flush=True)
    lines = ["| scene | rubber | CPU, 200 steps (s) | CPU, 0 steps (s) | a step (ms, the stages' least wall time) | against Kelvin-Voigt | flops a step | against Kelvin-Voigt |",
             "|---|---|---|---|---|---|---|---|"]
    for scene in SCENES:
        first = (scene, next(iter(RUBBERS)))
        for rubber in RUBBERS:
            key = (scene, rubber)
            c, z, s = statistics.median(cpu[key]), statistics.median(setup[key]), min(steps[key])
            lines.append(f"| {scene} | {rubber} | {c:.2f} | {z:.2f} | {5 * s:.2f} | {s / min(steps[first]):.2f}x | {flops[key] / 200:.3e} | {flops[key] / flops[first]:.2f}x |")
    text = "\n".join(lines)
    print(text)
    with open(os.path.join(ROOT, "bench", "results", "maxwell_cost.md"), "w") as f:
        f.write(f"bench/maxwell_cost.py --rounds {args.rounds} (CPU user + system of the process: medians of the interleaved rounds; the steps' "
                f"stages: the least of the rounds; flops: exact)\n\n" + text + "\n")


if __name__ == "__main__":
    main()
