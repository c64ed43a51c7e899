#!/usr/bin/env python3
"""What two processes on this machine share (issue 27, docs/performance.md "221k unknowns"): the memory bandwidth
one process gets alone and each of two gets side by side, by STREAM's triad (bench/stream.c, compiled here with
cc -O2), and the same for Roller's own step (sparse substitutions and products): the free scene at P2 h = 0.005
(221k unknowns) on one rank, alone and two copies side by side, its time per step from -log_view (stages step +
diagnostics). The ratio 2 x alone / side by side is what two processes do together against one: the bound two ranks
meet on work limited by what they share (memory bandwidth, the last-level cache), whatever the decomposition.
Interleaved rounds, medians. Measure on a quiet machine.

Usage: /usr/bin/python3 bench/bandwidth.py [--rounds 5] [--mb 200] [--roller-rounds 2] [--steps 10]"""
import argparse
import os
import platform
import statistics
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import benchlib  # noqa: E402
from benchlib import stage  # noqa: E402

ROOT = benchlib.ROOT
FREE = ["-options_file", os.path.join(ROOT, "jobs", "free.yaml"), "-degree", 2, "-mesh_h", "0.005"]


def stream(exe, mb, copies):
    """GB/s of each of `copies` STREAM triads started together."""
    procs = [subprocess.Popen([exe, str(mb), "20"], stdout=subprocess.PIPE, text=True) for _ in range(copies)]
    outs = [p.communicate()[0] for p in procs]
    if any(p.returncode for p in procs):
        raise RuntimeError("stream failed")
    return [float(o.split()[0]) for o in outs]


def roller_step(copies, steps):
    """Time per step [ms] of each of `copies` one-rank runs of the 221k free scene started together."""
    with tempfile.TemporaryDirectory() as tmp:
        procs, logs = [], []
        for c in range(copies):
            lv = os.path.join(tmp, f"log{c}.txt")
            cmd = benchlib.command(FREE + ["-ts_max_steps", steps, "-quiet", "-log_view", ":" + lv])
            procs.append(subprocess.Popen(cmd, stdout=subprocess.DEVNULL, stderr=subprocess.STDOUT, cwd=tmp))
            logs.append(lv)
        for p in procs:
            if p.wait():
                raise RuntimeError("roller failed")
        out = []
        for lv in logs:
            with open(lv) as f:
                res = benchlib.parse(f.read())
            out.append(1e3 * (stage(res, "Roller step") + stage(res, "Roller diagnostics")) / steps)
        return out


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--rounds", type=int, default=5)
    ap.add_argument("--mb", type=int, default=200)
    ap.add_argument("--roller-rounds", type=int, default=2)
    ap.add_argument("--steps", type=int, default=10)
    o = ap.parse_args()
    alone, pair = [], []
    with tempfile.TemporaryDirectory() as tmp:
        exe = os.path.join(tmp, "stream")
        subprocess.run(["cc", "-O2", "-o", exe, os.path.join(ROOT, "bench", "stream.c")], check=True)
        for _ in range(o.rounds):
            alone.append(stream(exe, o.mb, 1)[0])
            pair.append(statistics.mean(stream(exe, o.mb, 2)))
    r_alone, r_pair = [], []
    for _ in range(o.roller_rounds):
        r_alone.append(roller_step(1, o.steps)[0])
        r_pair.append(statistics.mean(roller_step(2, o.steps)))
    ma, mp = statistics.median(alone), statistics.median(pair)
    lines = [f"machine: {platform.node()}, {os.cpu_count()} cores, {platform.processor() or platform.machine()}; "
             f"load {os.getloadavg()[0]:.1f} at the end", "",
             "| work | alone | each of two side by side | two together / one alone | command |",
             "|---|---|---|---|---|",
             f"| STREAM triad, 3 x {o.mb} MB, GB/s (median of {o.rounds} rounds) | {ma:.2f} | {mp:.2f} | {2 * mp / ma:.2f} "
             f"| `cc -O2 bench/stream.c -o stream; ./stream {o.mb} 20` |"]
    if o.roller_rounds:
        ra, rp = statistics.median(r_alone), statistics.median(r_pair)
        lines.append(f"| free scene 221k, 1 rank, ms per step (median of {o.roller_rounds} rounds) | {ra:.1f} | {rp:.1f} | "
                     f"{2 * ra / rp:.2f} | `{' '.join(str(a) for a in benchlib.command(FREE + ['-ts_max_steps', o.steps]))}` |")
    lines += ["", "Per round, STREAM alone / each of two: " + ", ".join(f"{a:.2f}/{p:.2f}" for a, p in zip(alone, pair))]
    if o.roller_rounds:
        lines.append("Per round, free step alone / each of two [ms]: " + ", ".join(f"{a:.1f}/{p:.1f}" for a, p in zip(r_alone, r_pair)))
    benchlib.save("bandwidth.md", "\n".join(lines) + "\n")


if __name__ == "__main__":
    main()
