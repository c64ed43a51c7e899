#!/usr/bin/env python3
"""The rolling scene (jobs/rolling.yaml, T = 20) with each time scheme and several dt, against a fine reference:
the mean contact force and the mean R over the steady half 10 <= t <= 20, their errors relative to the reference's,
and the element-passing line of the contact force (the amplitude of its spectrum at f_e = omega r_C / h_c, relative
to the mean force; docs/model.md section 6.2). CPU time of each whole process (user + system).

  bench/rolling_schemes.py --reference        the reference: the default mesh, -ts_scheme dmf, dt/4 of the default
                                              (written to bench/results/rolling_schemes_ref.csv)
  bench/rolling_schemes.py [--rounds R] [RUN ...]   the runs (default: all below), R interleaved rounds, median CPU;
                                              a table on stdout and bench/results/rolling_schemes.md

A RUN is a label of RUNS. ROLLER_EXE selects the executable; REF_EXE the one that wrote the reference."""
import argparse
import os
import statistics
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import benchlib  # noqa: E402

ROOT = benchlib.ROOT
SCENE = ["-options_file", os.path.join(ROOT, "jobs", "rolling.yaml")]
REF = os.path.join(ROOT, "bench", "results", "rolling_schemes_ref.csv")
WINDOW = (10.0, 20.0)

RUNS = {
    "default": [],
    "dmf, dt of the former default": ["-ts_scheme", "dmf", "-ts_dt", 0.00171757],
    "composed dt 0.05": ["-ts_scheme", "composed", "-ts_dt", 0.05],
    "composed dt 0.025": ["-ts_scheme", "composed", "-ts_dt", 0.025],
    "composed dt 0.0125": ["-ts_scheme", "composed", "-ts_dt", 0.0125],
    "trapezoidal default": ["-ts_scheme", "trapezoidal"],
    "trapezoidal dt 0.005": ["-ts_scheme", "trapezoidal", "-ts_dt", 0.005],
    "trapezoidal dt 0.0025": ["-ts_scheme", "trapezoidal", "-ts_dt", 0.0025],
}


def summary(d):
    t, F, R = d["t"], d["contact_force"], d["R"]
    w = (t >= WINDOW[0] - 1e-9) & (t <= WINDOW[1] + 1e-9)
    tw, Fw = t[w], F[w]
    mean_F, mean_R = np.trapz(Fw, tw) / (tw[-1] - tw[0]), np.trapz(R[w], tw) / (tw[-1] - tw[0])
    return dict(mean_F=mean_F, mean_R=mean_R, tw=tw, Fw=Fw)


def line(s, f_e):
    """The amplitude of the force's Fourier component at f_e (Hz in the scene's units), relative to the mean."""
    tw, Fw = s["tw"], s["Fw"]
    c = np.trapz((Fw - s["mean_F"]) * np.exp(-2j * np.pi * f_e * tw), tw) * 2 / (tw[-1] - tw[0])
    return abs(c) / s["mean_F"]


def element_passing(res):
    for ln in res["stdout"].splitlines():
        if "element passing f_e" in ln:
            return float(ln.split("f_e = omega r_C / h_c = ")[1].split()[0]) / (2 * np.pi)
    return float("nan")


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--reference", action="store_true")
    ap.add_argument("--rounds", type=int, default=1)
    ap.add_argument("runs", nargs="*")
    ap.add_argument("--extra", action="append", default=[], help="a labelled run: LABEL=opt,val,opt,...")
    o = ap.parse_args()
    if o.reference:
        res = benchlib.run(SCENE + ["-ts_scheme", "dmf", "-ts_view", "-ts_max_steps", 0], logview=False)
        dt = float(res["stdout"].split("-ts_dt ")[1].split()[0])
        res = benchlib.run(SCENE + ["-ts_scheme", "dmf", "-ts_dt", dt / 4, "-ts_view"], csv=True, logview=False)
        d = res["series"]
        with open(REF, "w") as f:
            f.write("t,R,contact_force\n")
            for k in range(len(d["t"])):
                f.write(f"{d['t'][k]:.17g},{d['R'][k]:.17g},{d['contact_force'][k]:.17g}\n")
        print(f"reference: dt {dt / 4:g}, {len(d['t']) - 1} steps, cpu {res['cpu']:.1f} s -> {REF}")
        return
    ref = np.genfromtxt(REF, delimiter=",", names=True)
    sref = summary(ref)
    runs = dict(RUNS)
    for e in o.extra:
        label, opts = e.split("=", 1)
        runs[label] = opts.split(",")
    labels = o.runs or list(runs)
    cpu, rows = {k: [] for k in labels}, {}
    for r in range(o.rounds):
        for k in labels:
            res = benchlib.run(SCENE + runs[k] + ["-ts_view"], csv=True, logview=False)
            cpu[k].append(res["cpu"])
            s = summary(res["series"])
            f_e = element_passing(res)
            rows[k] = dict(steps=len(res["series"]["t"]) - 1, dt=res["series"]["t"][1], err_F=s["mean_F"] / sref["mean_F"] - 1,
                           err_R=s["mean_R"] / sref["mean_R"] - 1, line=line(s, f_e), line_ref=line(sref, f_e))
            print(f"round {r + 1} {k}: cpu {res['cpu']:.1f} s, dt {rows[k]['dt']:.4g}, force {100 * rows[k]['err_F']:+.3f} %, R {100 * rows[k]['err_R']:+.3f} %, "
                  f"line {100 * rows[k]['line']:.3f} % (reference {100 * rows[k]['line_ref']:.3f} %)", file=sys.stderr, flush=True)
    out = ["| run | dt | steps | mean force error | mean R error | element-passing line / mean force (reference) | CPU [s], median of %d |" % o.rounds,
           "|---|---|---|---|---|---|---|"]
    for k in labels:
        w = rows[k]
        out.append(f"| {k} `{' '.join(str(a) for a in runs[k])}` | {w['dt']:.4g} | {w['steps']} | {100 * w['err_F']:+.3f} % | {100 * w['err_R']:+.3f} % | "
                   f"{100 * w['line']:.3f} % ({100 * w['line_ref']:.3f} %) | {statistics.median(cpu[k]):.1f} |")
    print("\n".join(out))
    with open(os.path.join(ROOT, "bench", "results", "rolling_schemes.md"), "w") as f:
        f.write("\n".join(out) + "\n")


if __name__ == "__main__":
    main()
