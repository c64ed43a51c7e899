#!/usr/bin/env python3
"""The cost of the eigenvalues (docs/squeal.md, docs/performance.md): `roller -modes` (the 20 eigenvalues nearest
the target 0: one LU factorization of the shifted operator and TOAR's Krylov iterations) against one time step of
the same scene on the same mesh, for a sequence of meshes.

  bench/modes_cost.py [--hs 0.0447,0.0316,0.0224,0.0158] [--steps 200] [--rounds 2] [--nev 20]

For every h: the "Roller modes" stage of -log_view (the eigensolve: operators, factorization, iterations,
classification; not the mesh or the output), and the time per step of the free annulus (-ts_max_steps N,
stages "Roller step" + "Roller diagnostics" over N steps); their ratio; the number of dofs. Each figure is the
minimum over --rounds interleaved rounds (the machine is shared). ROLLER_EXE selects the executable.
"""
import argparse
import os
import re
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import logview  # noqa: E402

EXE = os.environ.get("ROLLER_EXE", "build/roller")


def run(args):
    out = subprocess.run([EXE] + args + ["-log_view", "-quiet"], capture_output=True, text=True, check=True).stdout
    return out, logview.parse(out)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--hs", default="0.0447,0.0316,0.0224,0.0158")
    ap.add_argument("--steps", type=int, default=200)
    ap.add_argument("--rounds", type=int, default=2)
    ap.add_argument("--nev", type=int, default=20)
    a = ap.parse_args()
    rows = []
    for h in [float(x) for x in a.hs.split(",")]:
        best_m, best_s, dofs = float("inf"), float("inf"), 0
        for _ in range(a.rounds):
            out, lv = run(["-modes", "-mesh_h", str(h), "-modes_nev", str(a.nev)])
            best_m = min(best_m, lv["stages"]["Roller modes"])
            m = re.search(r"(\d+) unknowns", subprocess.run([EXE, "-modes", "-mesh_h", str(h), "-modes_nev", str(a.nev)], capture_output=True, text=True, check=True).stdout)
            dofs = int(m.group(1))
            _, lv = run(["-mesh_h", str(h), "-ts_max_steps", str(a.steps), "-ts_max_time", "1e9"])
            step = (lv["stages"].get("Roller step", 0) + lv["stages"].get("Roller diagnostics", 0)) / a.steps
            best_s = min(best_s, step)
        rows.append((h, dofs, best_m, best_s))
        print(f"h {h:.4f}: {dofs} dofs, modes {best_m:.3f} s, step {1e3 * best_s:.2f} ms, ratio {best_m / best_s:.0f} steps", flush=True)
    print("\n| h | dofs | 20 eigenvalues (s) | one step (ms) | ratio (steps) |\n|---|---|---|---|---|")
    for h, n, m, s in rows:
        print(f"| {h:.4f} | {n} | {m:.2f} | {1e3 * s:.2f} | {m / s:.0f} |")


if __name__ == "__main__":
    main()
