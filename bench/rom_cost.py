#!/usr/bin/env python3
"""Issue 37's cost target (docs/performance.md "Reduced-order transient"): `jobs/printer_roller.yaml -rom
-ts_max_time T` (the issue's command: the axle, the drive, the Maxwell rubber) against the full model's 10 ms,
whole-process CPU (user + system), candidate and reference interleaved over R rounds, medians; the ratio against the
target 2 (T = 1: a simulated second for at most twice the full 10 ms). With --reference EXE the reduced run of another
executable (an older build) joins each round, so a change's gain is a ratio measured in the same rounds. Also the
reduced run's time by stage (-log_view: set-up, step, contact, diagnostics, per step) so a shorter T extrapolates:
CPU(1 s) ~ set-up + steps(1 s) x (CPU - set-up)/steps(T), stated as such.

  bench/rom_cost.py [--rounds 3] [--max-time 1] [--rom-options "-rom_cutoff 9888"] [--reference EXE]
                    [--scene jobs/printer_roller_kelvin_voigt.yaml --scene-options "-mesh_h 0.000773335 -ts_dt 5.63063e-06"]
"""
import argparse
import os
import platform
import statistics
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import benchlib  # noqa: E402
from benchlib import stage  # noqa: E402
from rollerreport import run  # noqa: E402 (benchlib imports rollertest, which puts scripts/ on the path)

ROOT = benchlib.ROOT
# jobs/printer_roller.yaml gives its mesh_h and ts_dt (the 10 ms run's): -ts_max_time 1 keeps them. A scene without
# them needs --scene-options (the Kelvin-Voigt scene: "-mesh_h 0.000773335 -ts_dt 5.63063e-06"; -ts_max_time 1 alone
# would choose a 10x finer h from -ts_phase_error, finer than -mesh_h_contact: refused at the mesh)
SCENE = os.path.join(ROOT, "jobs", "printer_roller.yaml")


def dt_of(scene, options):
    """The scene's -ts_dt: its options', else its YAML file's."""
    dt = run.scene_options(scene, options).get("ts_dt")
    if dt is None:
        raise SystemExit(f"{scene}: no ts_dt (give it in --scene-options)")
    return float(dt)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--rounds", type=int, default=3)
    ap.add_argument("--max-time", type=float, default=1.0)
    ap.add_argument("--rom-options", default="")
    ap.add_argument("--scene", default=SCENE)
    ap.add_argument("--scene-options", default="")
    ap.add_argument("--reference", default=None, help="another roller executable whose reduced run joins each round")
    o = ap.parse_args()
    scene = ["-options_file", os.path.abspath(o.scene)] + o.scene_options.split()
    rom_args = scene + ["-rom", "-ts_max_time", o.max_time] + o.rom_options.split()
    full, red, ref = [], [], []
    for _ in range(o.rounds):  # interleaved: the machine's load falls on all alike
        full.append(benchlib.run(scene + ["-ts_max_time", 0.01]))
        red.append(benchlib.run(rom_args))
        if o.reference:
            ref.append(benchlib.run(rom_args, exe=o.reference))
    cf, cr = statistics.median(r["cpu"] for r in full), statistics.median(r["cpu"] for r in red)
    steps_t = round(o.max_time / dt_of(o.scene, o.scene_options.split()))
    setup = statistics.median(stage(r, "Roller setup") for r in red)
    per = {s: statistics.median(stage(r, s) for r in red) for s in ("Roller step", "Roller contact", "Roller diagnostics", "Roller output")}
    wall = statistics.median(r["wall"] for r in red)
    run_cpu = cr * (1 - setup / wall) if wall > 0 else float("nan")  # the set-up's share of the wall time, applied to CPU
    est = cr if o.max_time == 1.0 else cr * setup / wall + run_cpu * (1.0 / o.max_time)
    lines = [
        f"# bench/rom_cost.py --rounds {o.rounds} --max-time {o.max_time} --scene {os.path.relpath(o.scene, ROOT)} {o.scene_options} {o.rom_options}",
        f"# machine: {platform.node()}, {os.cpu_count()} cores, load average at the end {os.getloadavg()[0]:.1f} (shared)",
        f"full model, 10 ms: CPU median {cf:.1f} s (rounds {', '.join('%.1f' % r['cpu'] for r in full)})",
        f"reduced, {o.max_time:g} s: CPU median {cr:.1f} s (rounds {', '.join('%.1f' % r['cpu'] for r in red)}), wall {wall:.1f} s",
        f"reduced by stage (wall, median): set-up {setup:.1f} s; per step ({steps_t} steps): " + ", ".join(f"{k.split()[1]} {1e3 * v / steps_t:.3f} ms" for k, v in per.items()),
        f"reduced 1 s {'measured' if o.max_time == 1.0 else 'extrapolated from the stages'}: {est:.1f} s CPU = {est / cf:.2f} x the full 10 ms (target <= 2)",
    ]
    if ref:
        cref = statistics.median(r["cpu"] for r in ref)
        lines += [f"reference {o.reference}, reduced {o.max_time:g} s: CPU median {cref:.1f} s (rounds {', '.join('%.1f' % r['cpu'] for r in ref)}), "
                  f"set-up {statistics.median(stage(r, 'Roller setup') for r in ref):.1f} s wall = {cref / cf:.2f} x the full 10 ms; candidate/reference {cr / cref:.3f}"]
    stem = os.path.splitext(os.path.basename(o.scene))[0]  # (rom_cost_1*.txt: the Kelvin-Voigt scene, written before --scene)
    benchlib.save(f"rom_cost_{stem}_{o.max_time:g}.txt", "\n".join(lines) + "\n")


if __name__ == "__main__":
    main()
