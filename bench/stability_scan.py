#!/usr/bin/env python3
"""Long-run stability of the three Coriolis treatments (docs/stability.md): the obstacle-free scene at
h = 0.05 for 0 <= t <= T, growth = max|alpha| over the last quarter / over the first quarter.
Usage: bench/stability_scan.py [T]  (default 2000); prints a markdown table."""
import os
import subprocess
import sys
import tempfile

import numpy as np

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
EXE = os.environ.get("ROLLER_EXE", os.path.join(ROOT, "build", "roller"))
sys.path.insert(0, os.path.join(ROOT, "tests"))
from rollertest import read_csv  # noqa: E402

T = float(sys.argv[1]) if len(sys.argv) > 1 else 2000.0
dts = [0.0125, 0.025, 0.05, 0.1, 0.2]
schemes = ["backward", "extrapolated", "centered"]
print(f"| dt | omega dt | " + " | ".join(schemes) + " |")
print("|---|---|" + "---|" * len(schemes))
with tempfile.TemporaryDirectory() as tmp:
    for dt in dts:
        row = []
        for s in schemes:
            csv = os.path.join(tmp, "s.csv")
            subprocess.run([EXE, "-mesh_h", "0.05", "-ts_dt", str(dt), "-ts_max_time", str(T), "-coriolis_velocity", s,
                            "-quiet", "-monitor_csv", csv], check=True, capture_output=True)
            a = read_csv(csv)["alpha"]
            q = len(a) // 4
            g = np.abs(a[-q:]).max() / np.abs(a[:q]).max()
            row.append(f"{g:.3g}" if np.isfinite(g) else "inf")
        print(f"| {dt} | {np.pi / 10 * dt:.4f} | " + " | ".join(row) + " |", flush=True)
