#!/usr/bin/env python3
"""Per-step cost, measured from -log_view (docs/performance.md).

  bench/step_cost.py [roller options ...]
      One run (default -options_file jobs/free.yaml -ts_max_steps 400): time per step, one MatSolve of the
      reused factorization, their ratio, the share of each -log_view stage, peak memory.

  bench/step_cost.py --ratios [--mesh-h H] [--degree K] [--steps N] [--rounds R] [--rtol TOL]
      Ratios measured in one invocation, in R interleaved rounds (each figure is the minimum over the rounds,
      so that a burst of load on the shared machine does not count):
        free step / one MatSolve (jobs/free.yaml, the default discretization unless -mesh-h/-degree);
        contact step (jobs/rolling.yaml, default condensed solver) / free step on the same mesh, same options
          without the obstacle (-obstacle false);
        each QP solver (-contact_solver condensed|vi|tao|pcg) / the paper's projected CG (pcg), all at the same
          tolerance TOL (-contact_rtol and -contact_pcg_rtol; condensed is exact);
      and the stage shares and peak memory of each run.

  bench/step_cost.py --friction [--time T] [--rounds R]
      Whole runs of jobs/feed.yaml (the feeder: rolling with Coulomb friction) to t = T on its default mesh and dt,
      against the same runs with -friction 0 (frictionless contact) and -obstacle false (free steps on the same
      mesh and dt, given explicitly): time per step of each and their ratios, and the iterations of the
      Coulomb solve per step (coulomb_iterations of the CSV: semismooth Newton iterations by default).

  bench/step_cost.py --table [--steps N]
      Time per step, setup time, stage shares and peak memory for P1/P2 and several h, free and rolling.

"Per step" counts every stage a step runs: "Roller step" (right-hand side, the solve, K xi), "Roller contact"
(the QP, nested in the step) and "Roller diagnostics" (R, alpha, energy, contact data); not set-up, not output.
ROLLER_EXE selects the executable (default build/roller). The machine is shared: see benchlib.py.
"""
import argparse
import os
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import benchlib  # noqa: E402
from benchlib import event, stage  # noqa: E402

ROOT = benchlib.ROOT
FREE = ["-options_file", os.path.join(ROOT, "jobs", "free.yaml")]
ROLLING = ["-options_file", os.path.join(ROOT, "jobs", "rolling.yaml")]
STAGES = ("Roller setup", "Roller step", "Roller contact", "Roller diagnostics", "Roller output")


def dofs(res):
    """Free dofs from -mesh_view_info (annulus: E = V + C edges; Gamma_D removed)."""
    for line in res["stdout"].splitlines():
        if line.startswith("mesh: vertices"):
            w = line.split()
            V, C, Vi = int(w[2]), int(w[4]), int(w[6])
            return V, C, Vi
    return None


def summary(res, degree=1):
    st = res["stages"]
    nsteps = max(event(res, "Roller step", "KSPSolve")[0], event(res, "Roller contact", "KSPSolve")[0], 1)
    # steps: count of RollerStep calls = MatMult of K after each step in the step stage, robust for contact too
    nsteps = res.get("nsteps", nsteps)
    per = {k: stage(res, k) / nsteps for k in STAGES}
    step = per["Roller step"] + per["Roller contact"] + per["Roller diagnostics"]
    ms_count, ms_time = event(res, "Roller step", "MatSolve")
    ks_count, ks_time = event(res, "Roller step", "KSPSolve")
    ck_count, ck_time = event(res, "Roller contact", "KSPSolve")
    out = dict(nsteps=nsteps, step=step, step_only=per["Roller step"] + per["Roller contact"], per=per,
               setup=stage(res, "Roller setup"), maxrss=res["maxrss_mb"], wall=res["wall"], cpu=res["cpu"],
               matsolve=ms_time / ms_count if ms_count else (ck_time / ck_count if ck_count else float("nan")),
               ksp=(ks_time + ck_time) / max(ks_count + ck_count, 1), ksp_per_step=(ks_count + ck_count) / nsteps)
    m = dofs(res)
    if m:
        V, C, Vi = m
        out["dofs"] = 2 * (V - Vi) if degree == 1 else 2 * (V + (V + C) - 2 * Vi)
    return out


def run(args, nsteps, degree=1):
    args = list(args)
    if "-ts_max_steps" not in args:
        args += ["-ts_max_steps", nsteps]
    res = benchlib.run(args + ["-mesh_view_info"])
    res["nsteps"] = nsteps
    return summary(res, degree), res


def shares(s):
    tot = sum(s["per"][k] for k in STAGES[1:4])
    return ", ".join(f"{k.replace('Roller ', '')} {100 * s['per'][k] / tot:.0f}%" for k in STAGES[1:4] if s["per"][k] > 0)


def single(args):
    s, res = run(args, 400 if "-ts_max_steps" not in args else int(args[args.index("-ts_max_steps") + 1]))
    cmd = benchlib.shell(args).replace(ROOT + "/", "")
    print(f"command                        {cmd}{'' if '-ts_max_steps' in args else ' -ts_max_steps %d' % s['nsteps']} -log_view")
    print(f"steps                          {s['nsteps']}")
    print(f"time per step (all stages)     {1e3 * s['step']:.3f} ms")
    print(f"  step stage only              {1e3 * s['step_only']:.3f} ms")
    print(f"one MatSolve (factor applied)  {1e3 * s['matsolve']:.3f} ms")
    print(f"step / MatSolve                {s['step'] / s['matsolve']:.2f}  (step stage only: {s['step_only'] / s['matsolve']:.2f})")
    print(f"per-step stage shares          {shares(s)}")
    print(f"set-up                         {s['setup']:.2f} s")
    print(f"peak resident memory           {s['maxrss']:.0f} MB")


def ratios(opt):
    disc = ["-degree", opt.degree, "-mesh_h", opt.mesh_h]
    tol = ["-contact_rtol", opt.rtol, "-contact_pcg_rtol", opt.rtol]
    runs = {"free": FREE + disc, "rolling, no obstacle": ROLLING + disc + ["-obstacle", "false"]}
    for solver in ("condensed", "vi", "tao", "pcg"):
        runs[f"rolling, {solver}"] = ROLLING + disc + ["-contact_solver", solver] + tol
    best = {}
    for r in range(opt.rounds):
        for name, args in runs.items():
            s, _ = run(args, opt.steps, int(opt.degree))
            if name not in best or s["step"] < best[name]["step"]:
                best[name] = s
            print(f"  round {r + 1}: {name}: {1e3 * s['step']:.3f} ms/step", file=sys.stderr, flush=True)
    f, rf, pcg = best["free"], best["rolling, no obstacle"], best["rolling, pcg"]
    print(f"P{opt.degree}, h = {opt.mesh_h}, {opt.steps} steps, QP tolerance {opt.rtol}, min over {opt.rounds} interleaved rounds; "
          f"shared 2-core machine\n")
    print("| run | ms / step | step / MatSolve | ratio | solves / step | per-step stage shares | set-up [s] | peak RSS [MB] |")
    print("|---|---|---|---|---|---|---|---|")
    for name, s in best.items():
        if name == "free":
            ratio = f"step / MatSolve = {f['step'] / f['matsolve']:.2f} (step stage only {f['step_only'] / f['matsolve']:.2f})"
        elif name == "rolling, no obstacle":
            ratio = f"/ free.yaml step = {s['step'] / f['step']:.2f}"
        else:
            ratio = f"/ free step = {s['step'] / rf['step']:.2f}; / pcg = {s['step'] / pcg['step']:.3f}"
        print(f"| {name} | {1e3 * s['step']:.3f} | {s['step'] / s['matsolve']:.2f} | {ratio} | {s['ksp_per_step']:.2f} | {shares(s)} | "
              f"{s['setup']:.2f} | {s['maxrss']:.0f} |")
    print("\ncommands (each with -ts_max_steps N -log_view):")
    for name, args in runs.items():
        print(f"  {name}: {benchlib.shell(args).replace(ROOT + '/', '')}")


def friction(opt):
    feed = ["-options_file", os.path.join(ROOT, "jobs", "feed.yaml"), "-ts_max_time", opt.time]
    series = os.path.join(tempfile.gettempdir(), "roller_bench_feed.csv")
    # the feeder's default discretization (-ts_view), given explicitly so that -obstacle false keeps mesh and dt
    disc = ["-mesh_h", 0.0347906, "-mesh_h_contact", 0.00798596, "-mesh_contact_layer", 0.0159719, "-ts_dt", 0.00171757]
    nsteps = int(round(opt.time / 0.00171757))
    runs = {"free (no obstacle)": feed + disc + ["-obstacle", "false", "-friction", 0, "-sheet_speed", 0],
            "frictionless contact": feed + disc + ["-friction", 0], "friction (feed.yaml)": feed + disc + ["-monitor_csv", series]}
    best = {}
    for r in range(opt.rounds):
        for name, args in runs.items():
            s, _ = run(args + ["-ts_max_steps", nsteps], nsteps, 2)
            if name not in best or s["step"] < best[name]["step"]:
                best[name] = s
            print(f"  round {r + 1}: {name}: {1e3 * s['step']:.3f} ms/step", file=sys.stderr, flush=True)
    its = [float(row.split(",")[26]) for row in open(series).read().splitlines()[1:]]
    contact_its = [i for i in its if i > 0]
    free = best["free (no obstacle)"]
    print(f"jobs/feed.yaml to t = {opt.time} ({nsteps} steps), P2, h 0.0348, h_c 0.0080, dt 0.00172; min over {opt.rounds} interleaved rounds; shared 2-core machine\n")
    print("| run | ms / step | / free step | per-step stage shares | set-up [s] |")
    print("|---|---|---|---|---|")
    for name, s in best.items():
        print(f"| {name} | {1e3 * s['step']:.3f} | {s['step'] / free['step']:.2f} | {shares(s)} | {s['setup']:.2f} |")
    print(f"\nCoulomb solve: {sum(contact_its) / max(len(contact_its), 1):.1f} iterations per contact step on average, at most {max(its):.0f}")
    print("\ncommands (each with -log_view):")
    for name, args in runs.items():
        print(f"  {name}: {benchlib.shell(args + ['-ts_max_steps', nsteps]).replace(ROOT + '/', '')}")


def table(opt):
    cases = [(1, 0.025), (1, 0.0125), (1, 0.00625), (2, 0.025), (2, 0.0125), (2, 0.01)]
    print(f"{opt.steps} steps each (dt = 0.0025 free, the scene's dt = 0.0125 rolling); shared 2-core machine\n")
    print("| scene | P | h | dofs | set-up [s] | ms / step | MatSolve [ms] | step / MatSolve | per-step stage shares | peak RSS [MB] |")
    print("|---|---|---|---|---|---|---|---|---|---|")
    for scene in ("free", "free, centred (LU)", "rolling"):
        for degree, h in cases:
            if scene.startswith("free"):
                args = FREE + ["-degree", degree, "-mesh_h", h, "-ts_dt", 0.0025,
                               "-coriolis_velocity", "centered" if "centred" in scene else "extrapolated"]
                if "centred" in scene and (degree, h) not in ((1, 0.0125), (2, 0.0125)):
                    continue
            else:
                args = ROLLING + ["-degree", degree, "-mesh_h", h]
            s, _ = run(args, opt.steps, degree)
            print(f"| {scene} | {degree} | {h} | {s.get('dofs', '')} | {s['setup']:.2f} | {1e3 * s['step']:.3f} | {1e3 * s['matsolve']:.3f} | "
                  f"{s['step'] / s['matsolve']:.2f} | {shares(s)} | {s['maxrss']:.0f} |", flush=True)


def main():
    if len(sys.argv) > 1 and sys.argv[1] not in ("--ratios", "--friction", "--table", "-h", "--help"):
        return single(sys.argv[1:])
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--ratios", action="store_true")
    ap.add_argument("--friction", action="store_true")
    ap.add_argument("--time", type=float, default=20.0)
    ap.add_argument("--table", action="store_true")
    ap.add_argument("--mesh-h", default="0.0125")
    ap.add_argument("--degree", default="1")
    ap.add_argument("--steps", type=int, default=200)
    ap.add_argument("--rounds", type=int, default=3)
    ap.add_argument("--rtol", default="1e-12")
    opt = ap.parse_args()
    if opt.table:
        table(opt)
    elif opt.ratios:
        ratios(opt)
    elif opt.friction:
        friction(opt)
    else:
        single(FREE)


if __name__ == "__main__":
    main()
