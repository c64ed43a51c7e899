#!/usr/bin/env python3
"""Work-precision study for the obstacle-free scene (paper figure 4, Table 1 values, 0 <= t <= 20):
error of R(t) and alpha(t) against the exact axisymmetric reference (scripts/axisym_reference.py) versus
wall time, for P1/P2, several h and dt, and the Coriolis treatments; plus the paper's configuration
(P1, h = dt = 0.0125, unpreconditioned CG for every step, its historical solver).
Usage: bench/work_precision.py [--quick] [--out bench/results/free]
Writes OUT.csv (one row per run) and OUT.png (error against wall time), prints a markdown table."""
import argparse
import os
import subprocess
import sys
import tempfile
import time

import numpy as np

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
EXE = os.environ.get("ROLLER_EXE", os.path.join(ROOT, "build", "roller"))
sys.path.insert(0, os.path.join(ROOT, "tests"))
from rollertest import read_csv  # noqa: E402

T = 20.0


def reference(tmp):
    path = os.path.join(tmp, "reference.csv")
    subprocess.run(["/usr/bin/python3", os.path.join(ROOT, "scripts", "axisym_reference.py"), "--scheme", "exact",
                    "--t-end", str(T), "--dt-out", "0.0015625", "--out", path], check=True, capture_output=True)
    return read_csv(path)


def measure(args, ref, tmp):
    csv = os.path.join(tmp, "run.csv")
    start = time.perf_counter()
    subprocess.run([EXE] + args + ["-ts_max_time", str(T), "-quiet", "-monitor_csv", csv], check=True, capture_output=True)
    wall = time.perf_counter() - start
    d = read_csv(csv)
    eR = np.abs(d["R"] - np.interp(d["t"], ref["t"], ref["R"])).max() / np.abs(ref["R"]).max()
    ea = np.abs(d["alpha"] - np.interp(d["t"], ref["t"], ref["alpha"])).max() / np.abs(ref["alpha"]).max()
    return wall, eR, ea


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--quick", action="store_true", help="fewer runs")
    ap.add_argument("--out", default=os.path.join(ROOT, "bench", "results", "free"))
    opt = ap.parse_args()
    os.makedirs(os.path.dirname(opt.out), exist_ok=True)
    configs = [("paper: P1, h = dt = 0.0125, CG", ["-mesh_h", 0.0125, "-ts_dt", 0.0125, "-ksp_type", "cg", "-pc_type", "none", "-ksp_rtol", 1e-10])]
    hs = [0.05, 0.025] if opt.quick else [0.05, 0.025, 0.0125]
    for degree in (1, 2):
        for h in hs:
            for div in (1, 2, 4, 8):
                if degree == 2 and h == 0.0125 and div > 4:
                    continue
                for cor in ("backward", "centered"):
                    configs.append((f"P{degree} h={h} dt=h/{div} {cor}",
                                    ["-degree", degree, "-mesh_h", h, "-ts_dt", h / div, "-coriolis_velocity", cor]))
    rows = []
    with tempfile.TemporaryDirectory() as tmp:
        ref = reference(tmp)
        for name, args in configs:
            wall, eR, ea = measure([str(a) for a in args], ref, tmp)
            rows.append((name, wall, eR, ea))
            print(f"| {name} | {wall:.2f} | {eR:.2e} | {ea:.2e} |", flush=True)
    with open(opt.out + ".csv", "w") as f:
        f.write("config,wall_s,err_R,err_alpha\n")
        for r in rows:
            f.write(f"{r[0]},{r[1]:.4f},{r[2]:.6e},{r[3]:.6e}\n")
    plot(rows, opt.out + ".png")


def plot(rows, path):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, axes = plt.subplots(1, 2, figsize=(12, 5), sharey=True)
    for ax, col, q in ((axes[0], 2, "R"), (axes[1], 3, "alpha")):
        for name, *vals in rows:
            err, wall = vals[col - 1], vals[0]
            if name.startswith("paper"):
                ax.loglog(err, wall, "k*", ms=14, label=name)
                continue
            marker = "o" if name.startswith("P1") else "s"
            color = "tab:blue" if "backward" in name else "tab:orange"
            ax.loglog(err, wall, marker, color=color, alpha=0.8)
        ax.axvline(0.01, color="gray", ls="--", lw=1)
        ax.set_xlabel(f"max error in {q}(t), relative, 0 <= t <= {T:g}")
        ax.grid(True, which="both", alpha=0.3)
    axes[0].set_ylabel("wall time of the run [s]")
    from matplotlib.lines import Line2D
    handles = [Line2D([], [], marker="o", ls="", color="gray", label="P1"), Line2D([], [], marker="s", ls="", color="gray", label="P2"),
               Line2D([], [], marker="o", ls="", color="tab:blue", label="backward Coriolis (paper)"),
               Line2D([], [], marker="o", ls="", color="tab:orange", label="centred Coriolis"),
               Line2D([], [], marker="*", ls="", color="k", ms=12, label="paper's configuration")]
    axes[1].legend(handles=handles, loc="upper right", fontsize=8)
    fig.suptitle("Obstacle-free scene (figure 4): error against wall time")
    fig.tight_layout()
    fig.savefig(path, dpi=120)


if __name__ == "__main__":
    main()
