#!/usr/bin/env python3
"""Per-step cost as ratios measured in one run (-log_view): an obstacle-free step against one application
of the reused factorization (MatSolve), and, with --contact, a contact step against a free step on the
same mesh. Usage: bench/step_cost.py [roller options ...]; prints a small table."""
import os
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from logview import parse  # noqa: E402

EXE = os.environ.get("ROLLER_EXE", os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), "build", "roller"))


def measure(args, nproc=1):
    cmd = [EXE] + args + ["-quiet", "-log_view"]
    if nproc > 1:
        cmd = ["mpiexec", "-n", str(nproc)] + cmd
    out = subprocess.run(cmd, capture_output=True, text=True, check=True).stdout
    return parse(out)


def main():
    args = sys.argv[1:] or ["-options_file", "jobs/free.yaml"]
    log = measure(args)
    st, ev = log["stages"], log["events"]
    nsteps, solve_time = ev[("Roller step", "KSPSolve")]
    msolve = ev.get(("Roller step", "MatSolve"), (nsteps, solve_time))
    step = st["Roller step"] / nsteps
    print(f"steps                         {nsteps}")
    print(f"time per step (Roller step)   {1e3 * step:.3f} ms")
    print(f"one MatSolve (factor applied) {1e3 * msolve[1] / msolve[0]:.3f} ms")
    print(f"step / MatSolve               {step / (msolve[1] / msolve[0]):.2f}")
    for name in ("Roller setup", "Roller step", "Roller contact", "Roller diagnostics", "Roller output"):
        if name in st:
            print(f"stage {name:24s} {st[name]:.3f} s  ({100 * st[name] / sum(st.values()):.0f}%)")


if __name__ == "__main__":
    main()
