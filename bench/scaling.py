#!/usr/bin/env python3
"""Strong scaling on 1 and 2 ranks (docs/performance.md): time per step and set-up, with the partitioner's
edge cut (-partition_view), METIS (Roller's default) against PTScotch (-petscpartitioner_type ptscotch), for
the obstacle-free scene and the rolling-contact scene on one mesh, and the step solver choices that matter
in parallel (MUMPS Cholesky, the default on several ranks; CG + GAMG).

Usage: bench/scaling.py [--mesh-h 0.005] [--degree 1] [--steps 200] [--rounds 2] [--np 1,2]
Prints a markdown table. Each figure is the minimum over --rounds interleaved repetitions. The development
machine has 2 cores shared with other jobs: a 2-rank run there competes with them for the cores.
"""
import argparse
import os
import re
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import benchlib  # noqa: E402
from benchlib import event, stage  # noqa: E402

ROOT = benchlib.ROOT


def per_step(res, nsteps):
    return (stage(res, "Roller step") + stage(res, "Roller contact") + stage(res, "Roller diagnostics")) / nsteps


def partition(text):
    m = re.search(r"partition: (\S+) ranks (\d+) edge_cut (\d+) cells_min (\d+) cells_max (\d+)", text)
    return (m.group(1), int(m.group(3)), int(m.group(4)), int(m.group(5))) if m else ("-", 0, 0, 0)


def mesh(text):
    m = re.search(r"mesh: vertices (\d+) cells (\d+) inner_vertices (\d+)", text)
    return tuple(int(g) for g in m.groups()) if m else (0, 0, 0)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--mesh-h", default="0.005")
    ap.add_argument("--degree", default="1")
    ap.add_argument("--steps", type=int, default=200)
    ap.add_argument("--rounds", type=int, default=2)
    ap.add_argument("--np", default="1,2")
    ap.add_argument("--no-contact", action="store_true")
    opt = ap.parse_args()
    nps = [int(n) for n in opt.np.split(",")]
    disc = ["-degree", opt.degree, "-mesh_h", opt.mesh_h, "-ts_max_steps", opt.steps, "-partition_view", "-mesh_view_info"]
    scenes = [("free", ["-options_file", os.path.join(ROOT, "jobs", "free.yaml")])]
    if not opt.no_contact:
        scenes.append(("rolling", ["-options_file", os.path.join(ROOT, "jobs", "rolling.yaml")]))
    cases = []
    for scene, base in scenes:
        for n in nps:
            parts = [("METIS", [])] if n == 1 else [("METIS", []), ("PTScotch", ["-petscpartitioner_type", "ptscotch"])]
            for pname, popt in parts:
                solvers = [("Cholesky (PETSc)" if n == 1 else "Cholesky (MUMPS)", [])]
                if n == 1:
                    solvers.append(("Cholesky (MUMPS)", ["-pc_factor_mat_solver_type", "mumps"]))
                if scene == "free":
                    solvers.append(("CG + GAMG, rtol 1e-10", ["-ksp_type", "cg", "-pc_type", "gamg", "-ksp_rtol", "1e-10"]))
                for sname, sopt in solvers:
                    if pname == "PTScotch" and "GAMG" in sname:
                        continue
                    cases.append((scene, n, pname, sname, base + disc + popt + sopt))
    best = {}
    for r in range(opt.rounds):
        for scene, n, pname, sname, args in cases:
            res = benchlib.run(args, nproc=n)
            key = (scene, n, pname, sname)
            t = per_step(res, opt.steps)
            print(f"  round {r + 1}: {key}: {1e3 * t:.2f} ms/step", file=sys.stderr, flush=True)
            if key not in best or t < best[key]["step"]:
                best[key] = dict(step=t, setup=stage(res, "Roller setup"), part=partition(res["stdout"]), mesh=mesh(res["stdout"]),
                                 rss=res["maxrss_mb"], args=args, its=event(res, "Roller step", "KSPSolve"))
    V, C, Vi = next(iter(best.values()))["mesh"]
    dofs = 2 * (V - Vi) if opt.degree == "1" else 2 * (2 * V + C - 2 * Vi)
    print(f"P{opt.degree}, h = {opt.mesh_h}: {V} vertices, {C} cells, {dofs} dofs; {opt.steps} steps; min over {opt.rounds} rounds; "
          f"2-core machine: a 2-rank run uses both cores\n")
    print("| scene | ranks | partitioner | edge cut | cells min/max | step solver | set-up [s] | ms / step | speed-up per step (vs 1 rank, same solver family) | peak RSS / rank [MB] |")
    print("|---|---|---|---|---|---|---|---|---|---|")
    for (scene, n, pname, sname), b in best.items():
        ref = best.get((scene, 1, "METIS", sname)) or best.get((scene, 1, "METIS", "Cholesky (PETSc)"))
        ref_mumps = best.get((scene, 1, "METIS", "Cholesky (MUMPS)"))
        if n == 1:
            sp = "1"
        elif "MUMPS" in sname:
            sp = f"{ref_mumps['step'] / b['step']:.2f} vs MUMPS, {best[(scene, 1, 'METIS', 'Cholesky (PETSc)')]['step'] / b['step']:.2f} vs PETSc Cholesky"
        else:
            sp = f"{ref['step'] / b['step']:.2f}"
        part = b["part"]
        cut = "-" if n == 1 else str(part[1])
        cells = "-" if n == 1 else f"{part[2]}/{part[3]}"
        print(f"| {scene} | {n} | {pname if n > 1 else '-'} | {cut} | {cells} | {sname} | {b['setup']:.2f} | {1e3 * b['step']:.2f} | {sp} | {b['rss']:.0f} |")
    print("\ncommands (each with -log_view):")
    for (scene, n, pname, sname), b in best.items():
        print(f"  {benchlib.shell(b['args'], n).replace(ROOT + '/', '')}")


if __name__ == "__main__":
    main()
