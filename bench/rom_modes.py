#!/usr/bin/env python3
"""The reduced model's error against the number of modes, and its CPU (issue 37, docs/performance.md "Reduced-order
transient"): jobs/printer_roller_kelvin_voigt.yaml over T (default 30 ms: the press, then feeding), the full model
once and -rom with -rom_modes N for each N, with MacNeal's residual flexibility (the default) and without it
(-rom_residual false, the same basis read back with -rom_input). Per run: the mean contact and friction forces over
the feeding (t > 3 ms) and the friction force's largest line (frequency, level) against the full model's, and the
whole-process CPU (user + system) split into the set-up (-log_view's stage, scaled to CPU) and the steps. One round:
the errors are deterministic; the CPU times are single runs on a shared machine (stated as such).

  bench/rom_modes.py [--modes 40,80,160,243,400] [--max-time 0.03]    -> bench/results/rom_modes.txt, docs/figures/rom_modes.png
"""
import argparse
import os
import platform
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import benchlib  # noqa: E402
from benchlib import stage  # noqa: E402
from rollertest import friction_line  # noqa: E402

ROOT = benchlib.ROOT
SCENE = ["-options_file", os.path.join(ROOT, "jobs", "printer_roller_kelvin_voigt.yaml"), "-mesh_h", "0.000773335", "-ts_dt", "5.63063e-06"]


def measures(d):
    feed = d["t"] > 0.003
    f, level = friction_line(d)
    return {"N": d["contact_force"][feed].mean(), "T": d["friction_force"][feed].mean(), "f": f, "L": level}


def setup_cpu(r):
    return r["cpu"] * stage(r, "Roller setup") / r["wall"] if r["wall"] > 0 else float("nan")


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--modes", default="40,80,160,243,400")
    ap.add_argument("--max-time", type=float, default=0.03)
    o = ap.parse_args()
    T = ["-ts_max_time", o.max_time]
    full = benchlib.run(SCENE + T, csv=True)
    ref = measures(full["series"])
    rows = []
    with tempfile.TemporaryDirectory() as tmp:
        for n in [int(x) for x in o.modes.split(",")]:
            basis = os.path.join(tmp, f"basis{n}.h5")
            for residual in (True, False):
                extra = ["-rom", "-rom_modes", n] + (["-rom_output", basis] if residual else ["-rom_input", basis, "-rom_residual", "false"])
                try:
                    r = benchlib.run(SCENE + T + extra, csv=True)
                except RuntimeError as e:  # the modes alone: the condensed S of neighbouring candidates is ill-conditioned
                    rows.append({"modes": n, "residual": residual, "failed": str(e).split(" exited ")[-1]})
                    continue
                m = measures(r["series"])
                rows.append({"modes": n, "residual": residual, "cpu": r["cpu"], "setup": setup_cpu(r), **m,
                             "eN": m["N"] / ref["N"] - 1, "eT": m["T"] / ref["T"] - 1, "ef": m["f"] / ref["f"] - 1, "eL": m["L"] - ref["L"]})
    lines = [f"# bench/rom_modes.py --modes {o.modes} --max-time {o.max_time}",
             f"# machine: {platform.node()}, {os.cpu_count()} cores, load average at the end {os.getloadavg()[0]:.1f} (shared); one round, single runs",
             f"full model: {len(full['series']['t']) - 1} steps, CPU {full['cpu']:.1f} s (set-up {setup_cpu(full):.1f} s); contact {ref['N']:.4g} N/m, friction {ref['T']:.4g} N/m, "
             f"friction line {ref['f']:.1f} Hz {ref['L']:.1f} dB",
             "modes | residual | contact force | friction force | line frequency | line level | CPU s (set-up + steps)"]
    for r in rows:
        if "failed" in r:
            lines.append(f"{r['modes']} | {'R' if r['residual'] else 'modes alone'} | failed (exit {r['failed']}: the Coulomb solve's Lemke method ended on a ray) | | | | ")
            continue
        lines.append(f"{r['modes']} | {'R' if r['residual'] else 'modes alone'} | {100 * r['eN']:+.3f} % | {100 * r['eT']:+.2f} % | {100 * r['ef']:+.2f} % | {r['eL']:+.2f} dB | "
                     f"{r['cpu']:.1f} ({r['setup']:.1f} + {r['cpu'] - r['setup']:.1f})")
    benchlib.save("rom_modes.txt", "\n".join(lines) + "\n")
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(1, 2, figsize=(10, 4))
    for residual, mk in ((True, "o-"), (False, "s--")):
        rr = [r for r in rows if r["residual"] == residual and "failed" not in r]
        lab = "with R (default)" if residual else "modes alone"
        n = [r["modes"] for r in rr]
        ax[0].semilogy(n, [max(abs(r["eN"]), 1e-6) for r in rr], mk, label=f"contact force, {lab}")
        ax[0].semilogy(n, [max(abs(r["eT"]), 1e-6) for r in rr], mk, alpha=0.6, label=f"friction force, {lab}")
        ax[1].plot(n, [r["cpu"] for r in rr], mk, label=f"CPU, {lab}")
        ax[1].plot(n, [r["setup"] for r in rr], ":", alpha=0.6, label=f"of it set-up, {lab}")
    ax[0].axhline(0.01, color="k", lw=0.5)
    ax[0].axhline(0.02, color="k", lw=0.5, ls=":")
    ax[0].set_xlabel("kept modes")
    ax[0].set_ylabel("|relative error| of the mean over the feeding")
    ax[0].legend(fontsize=7)
    ax[1].axhline(full["cpu"], color="k", lw=0.8)
    ax[1].text(n[0], full["cpu"], f" full model {full['cpu']:.0f} s", va="bottom", fontsize=8)
    ax[1].set_xlabel("kept modes")
    ax[1].set_ylabel(f"CPU s for {1e3 * o.max_time:g} ms (one run)")
    ax[1].legend(fontsize=7)
    fig.suptitle(f"printer roller (Kelvin-Voigt), {1e3 * o.max_time:g} ms: reduced model vs full, {platform.node()}")
    fig.tight_layout()
    fig.savefig(os.path.join(ROOT, "docs", "figures", "rom_modes.png"), dpi=110)


if __name__ == "__main__":
    main()
