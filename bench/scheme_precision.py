#!/usr/bin/env python3
"""Work-precision of the time schemes and elements on the obstacle-free scene (figure 4, E = 0.1, 0 <= t <= 20):
each scheme (-ts_scheme dmf, trapezoidal, composed) at a ladder of dt on the former default P2 mesh (h = 0.0348), the
composed scheme on finer P2 meshes and on P3 meshes, the default (P3), and the paper's configuration (jobs/paper/fig4.yaml). Each run's error is the
larger of max|R - R_exact| / max|R_exact| and the same for alpha, against the exact axisymmetric reference
(scripts/rollerref/axisym.py, n = 256); its cost the CPU time (user + system) of the whole process. With --rounds R
the runs are interleaved R times and the median CPU is kept. Writes bench/results/scheme_precision.{md,png} and
docs/figures/perf_schemes.png.

Usage: /usr/bin/python3 bench/scheme_precision.py [--rounds 1] [--extra LABEL=opt,value,...]"""
import argparse
import os
import platform
import statistics
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import benchlib  # noqa: E402

ROOT = benchlib.ROOT
sys.path.insert(0, os.path.join(ROOT, "scripts"))
from rollerref import axisym as ar  # noqa: E402

H = 0.0347906  # the default P2 mesh of this scene (-ts_phase_error 0.01)
LADDER = {"dmf": [0.0069, 0.00344, 0.00172, 0.00086], "trapezoidal": [0.0144, 0.0072, 0.0036, 0.0018],
          "composed": [0.0578, 0.0289, 0.0145, 0.0072]}


def runs():
    out = [("paper", "paper (P1, dmf, CG)", ["-options_file", os.path.join(ROOT, "jobs", "paper", "fig4.yaml")])]
    for s, dts in LADDER.items():
        out += [(s, f"{s} P2 h {H:.4f} dt {dt:g}", ["-ts_scheme", s, "-mesh_h", H, "-ts_dt", dt]) for dt in dts]
    for h in (0.025, 0.0174):
        out += [("composed finer", f"composed P2 h {h:g} dt {dt:g}", ["-ts_scheme", "composed", "-mesh_h", h, "-ts_dt", dt])
                for dt in (0.0289, 0.0145)]
    out += [("composed P3", f"composed P3 h {h:g} dt {dt:g}", ["-ts_scheme", "composed", "-degree", 3, "-mesh_h", h, "-ts_dt", dt])
            for h, dt in ((0.075, 0.0289), (0.06, 0.0145), (0.047, 0.013))]
    out.append(("default", "default (no option: P3 h 0.0902, composed dt 0.0289)", []))
    return out


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--rounds", type=int, default=1)
    ap.add_argument("--extra", action="append", default=[], help="another run: LABEL=opt,value,opt,...")
    o = ap.parse_args()
    rs = runs() + [("extra", e.split("=", 1)[0], e.split("=", 1)[1].split(",")) for e in o.extra]
    p = dict(ar.DEFAULTS)
    p["young"], p["n"] = 0.1, 256
    cpu, err, steps = {r[1]: [] for r in rs}, {}, {}
    for k in range(o.rounds):
        for group, label, args in rs:
            res = benchlib.run(args + ["-young", 0.1, "-ts_max_time", 20.0], csv=True, logview=False)
            d = res["series"]
            if label not in err:
                Rx, ax = ar.reference(p, np.asarray(d["t"]), scheme="exact")
                err[label] = max(np.abs(d["R"] - Rx).max() / np.abs(Rx).max(), np.abs(d["alpha"] - ax).max() / np.abs(ax).max())
                steps[label] = len(d["t"]) - 1
            cpu[label].append(res["cpu"])
            print(f"  round {k + 1}: {label}: cpu {res['cpu']:.2f} s, err {err[label]:.2e}", file=sys.stderr, flush=True)
    med = {label: statistics.median(v) for label, v in cpu.items()}
    paper = med[rs[0][1]]
    lines = [f"obstacle-free scene, E = 0.1, 0 <= t <= 20; error = max of the relative max errors of R and alpha against the "
             f"exact reference; CPU (user + system) of the whole process, median of {o.rounds} interleaved round(s); "
             f"machine: {platform.node()}, {os.cpu_count()} cores, load {os.getloadavg()[0]:.1f} at the end", "",
             "| run | steps | error | CPU [s] | CPU / paper | command |", "|---|---|---|---|---|---|"]
    for group, label, args in rs:
        cmd = benchlib.shell([str(a) for a in args + ["-young", 0.1, "-ts_max_time", 20.0]]).replace(ROOT + "/", "")
        lines.append(f"| {label} | {steps[label]} | {err[label]:.2e} | {med[label]:.2f} | {med[label] / paper:.3f} | `{cmd}` |")
    text = "\n".join(lines) + "\n"
    print(text)
    with open(os.path.join(ROOT, "bench", "results", "scheme_precision.md"), "w") as f:
        f.write(text)
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(figsize=(6.4, 4.6))
    style = {"paper": ("r*", 12), "dmf": ("o-", 6), "trapezoidal": ("s-", 6), "composed": ("^-", 7),
             "composed finer": ("v--", 7), "composed P3": ("P-", 8), "default": ("kX", 11), "extra": ("D", 7)}
    for group in dict.fromkeys(g for g, _, _ in rs):
        xs = [med[label] / paper for g, label, _ in rs if g == group]
        ys = [err[label] for g, label, _ in rs if g == group]
        m, ms = style.get(group, ("o", 6))
        ax.loglog(xs, ys, m, ms=ms, label=group)
    ax.axhline(0.01, color="0.6", lw=0.8)
    ax.axhline(0.001, color="0.6", lw=0.8, ls=":")
    ax.axvline(1.0, color="0.6", lw=0.8)
    ax.set_xlabel("CPU time / paper configuration's")
    ax.set_ylabel("max relative error of R and alpha")
    ax.set_title("Figure-4 scene, t <= 20: work-precision of the schemes")
    ax.legend(fontsize=8)
    fig.tight_layout()
    for path in (os.path.join(ROOT, "bench", "results", "scheme_precision.png"), os.path.join(ROOT, "docs", "figures", "perf_schemes.png")):
        fig.savefig(path, dpi=110)


if __name__ == "__main__":
    main()
