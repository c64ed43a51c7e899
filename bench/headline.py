#!/usr/bin/env python3
"""The headline in one invocation: the obstacle-free scene (figure 4) over 0 <= t <= 20, the paper's
configuration (jobs/paper/fig4.yaml: P1, h = dt = 0.0125, backward Coriolis, unpreconditioned CG), the same
discretization with Roller's solver (one Cholesky factorization), and Roller's default (no discretization
option: P2 curved, extrapolated Coriolis, dt and h from -ts_phase_error 0.01), run in interleaved rounds; prints each run's error and its time as a ratio to the paper's configuration measured in
the same invocation (the machine is shared: the ratio is robust, absolute seconds are not).

Usage: /usr/bin/python3 bench/headline.py [--rounds 2]
"""
import argparse
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import work_precision as wp  # noqa: E402

RUNS = [
    wp.cfg(1, 0.0125, 0.0125, "backward", wp.PAPER_CG, label="paper (jobs/paper/fig4.yaml): P1 h=dt=0.0125 backward, CG"),
    wp.cfg(1, 0.0125, 0.0125, "backward", label="P1 h=dt=0.0125 backward, Cholesky (the paper's discretization, Roller's solver)"),
    wp.DEFAULT,
]


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--rounds", type=int, default=2)
    opt = ap.parse_args()
    best = {}
    for r in range(opt.rounds):
        paper = None
        for c in RUNS:
            row, _ = wp.measure("free", c, 20.0, None)
            if c is RUNS[0]:
                paper = row
            row["cpu_ratio"] = row["cpu_s"] / paper["cpu_s"]
            row["wall_ratio"] = row["wall_s"] / paper["wall_s"]
            b = best.setdefault(c["label"], row)
            if row["cpu_s"] < b["cpu_s"]:
                best[c["label"]] = row
            print(f"  round {r + 1}: {c['label']}: cpu {row['cpu_s']:.1f} s ({row['cpu_ratio']:.2f} x paper), wall {row['wall_s']:.1f} s "
                  f"({row['wall_ratio']:.2f} x paper), load {row['load1']:.1f}", file=sys.stderr, flush=True)
    p = best[RUNS[0]["label"]]
    for row in best.values():
        row["cpu_ratio"], row["wall_ratio"] = row["cpu_s"] / p["cpu_s"], row["wall_s"] / p["wall_s"]
    print(f"obstacle-free scene, 0 <= t <= 20; each run's fastest of {opt.rounds} interleaved rounds (by CPU time), ratios to the "
          "paper's configuration's fastest; 2-core machine shared with other jobs\n")
    print("| run | err R | err alpha | CPU [s] | CPU / paper | wall / paper | peak RSS [MB] | command |")
    print("|---|---|---|---|---|---|---|---|")
    for label, row in best.items():
        print(f"| {label} | {row['err_R']:.2e} | {row['err_alpha']:.2e} | {row['cpu_s']:.1f} | {row['cpu_ratio']:.2f} | {row['wall_ratio']:.2f} | {row['maxrss_mb']:.0f} | "
              f"`{row['command']}` |")


if __name__ == "__main__":
    main()
