#!/usr/bin/env python3
"""The printer roller's 10 ms transient (jobs/printer_roller_kelvin_voigt.yaml: the clamped hub and the Kelvin-Voigt rubber
the figures of docs/performance.md were measured on; with -friction_static 0.8 by default, a constant
mu: docs/squeal.md section 7) with Roller's default time scheme and dt against a fine-step reference on the same mesh
(the same scheme at dt/8): the contact force over the feeding (the second half, 5 <= t <= 10 ms), its mean and its
largest deviation (each relative to the reference's mean force), and the whole process's CPU time (user + system).

  bench/printer_schemes.py [--rounds R] [--law]     --law: the scene's own velocity-weakening law (no override)
"""
import argparse
import os
import statistics
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import benchlib  # noqa: E402

ROOT = benchlib.ROOT


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--rounds", type=int, default=1)
    ap.add_argument("--law", action="store_true")
    o = ap.parse_args()
    scene = ["-options_file", os.path.join(ROOT, "jobs", "printer_roller_kelvin_voigt.yaml")] + ([] if o.law else ["-friction_static", 0.8])
    view = benchlib.run(scene + ["-ts_view", "-ts_max_steps", 0], logview=False)["stdout"]
    dt = float(view.split("-ts_dt ")[1].split()[0])
    scheme = view.split("-ts_scheme ")[1].split()[0]
    ref = benchlib.run(scene + ["-ts_scheme", scheme, "-ts_dt", dt / 8], csv=True, logview=False)
    cpu = []
    for r in range(o.rounds):
        res = benchlib.run(scene, csv=True, logview=False)
        cpu.append(res["cpu"])
        print(f"round {r + 1}: cpu {res['cpu']:.1f} s", file=sys.stderr, flush=True)
    d, dr = res["series"], ref["series"]
    T = d["t"][-1]
    w, wr = d["t"] >= T / 2, dr["t"] >= T / 2
    mean, mean_ref = np.trapz(d["contact_force"][w], d["t"][w]) / (T / 2), np.trapz(dr["contact_force"][wr], dr["t"][wr]) / (T / 2)
    dev = np.abs(d["contact_force"][w] - np.interp(d["t"][w], dr["t"], dr["contact_force"])).max() / mean_ref
    fmean = np.trapz(d["friction_force"][w], d["t"][w]) / (T / 2)
    fmean_ref = np.trapz(dr["friction_force"][wr], dr["t"][wr]) / (T / 2)
    print(f"| scheme | dt | steps | mean contact force error | largest deviation / mean | mean friction force error | CPU [s] (median of {o.rounds}) | reference CPU [s] |")
    print("|---|---|---|---|---|---|---|---|")
    print(f"| {scheme} | {dt:.3g} | {len(d['t']) - 1} | {100 * (mean / mean_ref - 1):+.3f} % | {100 * dev:.3f} % | {100 * (fmean / fmean_ref - 1):+.3f} % | {statistics.median(cpu):.1f} | {ref['cpu']:.1f} |")


if __name__ == "__main__":
    main()
