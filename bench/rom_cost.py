#!/usr/bin/env python3
"""Issue 37's cost target (docs/performance.md "Reduced-order transient"): `jobs/printer_roller_kelvin_voigt.yaml -rom
-ts_max_time T` against the full model's 10 ms, whole-process CPU (user + system), candidate and reference
interleaved over R rounds, medians; the ratio against the target 2 (T = 1: a simulated second for at most twice the
full 10 ms). Also the reduced run's time by stage (-log_view: set-up, step, contact, diagnostics, per step) so a
shorter T extrapolates: CPU(1 s) ~ set-up + steps(1 s) x (CPU - set-up)/steps(T), stated as such.

  bench/rom_cost.py [--rounds 3] [--max-time 1] [--rom-options "-rom_cutoff 9888"]
"""
import argparse
import os
import platform
import statistics
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import benchlib  # noqa: E402
from benchlib import stage  # noqa: E402

ROOT = benchlib.ROOT
# the 10 ms run's mesh and dt held: -ts_max_time 1 alone would choose a 10x finer h from -ts_phase_error (7.7e-5,
# finer than -mesh_h_contact: refused at the mesh)
SCENE = ["-options_file", os.path.join(ROOT, "jobs", "printer_roller_kelvin_voigt.yaml"), "-mesh_h", "0.000773335", "-ts_dt", "5.63063e-06"]


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--rounds", type=int, default=3)
    ap.add_argument("--max-time", type=float, default=1.0)
    ap.add_argument("--rom-options", default="")
    o = ap.parse_args()
    rom_args = SCENE + ["-rom", "-ts_max_time", o.max_time] + o.rom_options.split()
    full, red = [], []
    for _ in range(o.rounds):  # interleaved: the machine's load falls on both alike
        full.append(benchlib.run(SCENE + ["-ts_max_time", 0.01]))
        red.append(benchlib.run(rom_args))
    cf, cr = statistics.median(r["cpu"] for r in full), statistics.median(r["cpu"] for r in red)
    steps_t = round(o.max_time / 5.63063e-06)
    setup = statistics.median(stage(r, "Roller setup") for r in red)
    per = {s: statistics.median(stage(r, s) for r in red) for s in ("Roller step", "Roller contact", "Roller diagnostics", "Roller output")}
    wall = statistics.median(r["wall"] for r in red)
    run_cpu = cr * (1 - setup / wall) if wall > 0 else float("nan")  # the set-up's share of the wall time, applied to CPU
    est = cr if o.max_time == 1.0 else cr * setup / wall + run_cpu * (1.0 / o.max_time)
    lines = [
        f"# bench/rom_cost.py --rounds {o.rounds} --max-time {o.max_time} {o.rom_options}",
        f"# machine: {platform.node()}, {os.cpu_count()} cores, load average at the end {os.getloadavg()[0]:.1f} (shared)",
        f"full model, 10 ms: CPU median {cf:.1f} s (rounds {', '.join('%.1f' % r['cpu'] for r in full)})",
        f"reduced, {o.max_time:g} s: CPU median {cr:.1f} s (rounds {', '.join('%.1f' % r['cpu'] for r in red)}), wall {wall:.1f} s",
        f"reduced by stage (wall, median): set-up {setup:.1f} s; per step ({steps_t} steps): " + ", ".join(f"{k.split()[1]} {1e3 * v / steps_t:.3f} ms" for k, v in per.items()),
        f"reduced 1 s {'measured' if o.max_time == 1.0 else 'extrapolated from the stages'}: {est:.1f} s CPU = {est / cf:.2f} x the full 10 ms (target <= 2)",
    ]
    benchlib.save(f"rom_cost_{o.max_time:g}.txt", "\n".join(lines) + "\n")


if __name__ == "__main__":
    main()
