#!/usr/bin/env python3
"""Work-precision studies: error against wall time for P1/P2, several h and dt (docs/performance.md).

Scenes
  free     the obstacle-free scene (paper figures 3-4, Table 1 values, 0 <= t <= T, T = 20). Error of R(t) and
           alpha(t) against the exact axisymmetric reference (scripts/rollerref/axisym.py, n = 256, exact in
           time), as max_t |q - q_ref| / max_t |q_ref|. Also split into a time part (the same DMF scheme on the
           spectral radial semi-discretization, n = 64, against the exact one) and a space part (the 2D run
           against that semi-discrete DMF at the same dt and Coriolis velocity).
  rolling  the rolling-contact scene (jobs/rolling.yaml, paper figure 9). Error of R, alpha and contact_force
           against the finest run (--set reference, stored as bench/results/rolling_ref.csv), at the common
           output times, max over time relative to the reference's max (rms in the CSV too).

Sets of runs (--set, repeatable): paper, default, grid, search (free: the cheapest runs below 1 %),
reference (rolling: the finest run). --t-end overrides T (the rolling study uses the scene's 20 unless
given). Each run appends one row to OUT.csv (a row with the same label is replaced), then OUT.png and
OUT.md are redrawn from the whole CSV. --plot-only redraws without running.

Usage: /usr/bin/python3 bench/work_precision.py --scene free --set paper --set search [--out PREFIX]
       (ROLLER_EXE selects the executable, default build/roller). One run at a time; the machine state
       (load average) is recorded with each row.
"""
import argparse
import csv
import datetime
import functools
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import benchlib  # noqa: E402

ROOT = benchlib.ROOT
sys.path.insert(0, os.path.join(ROOT, "scripts"))

PAPER_CG = ["-ksp_type", "cg", "-pc_type", "none", "-ksp_rtol", "1e-10"]
SERIES_DIR = None   # --series-dir: keep each run's series (t, R, alpha[, contact_force]) there
FIELDS = ["label", "scene", "degree", "h", "dt", "coriolis", "extra", "t_end", "steps", "nproc", "wall_s", "cpu_s",
          "setup_s", "step_s", "contact_s", "diag_s", "maxrss_mb", "err_R", "err_alpha", "err_force", "err_R_time",
          "err_alpha_time", "err_R_space", "err_alpha_space", "rms_R", "rms_alpha", "rms_force", "err_force_avg", "load1", "date", "command"]


def cfg(degree, h, dt, coriolis="backward", extra=(), label=None):
    """One run. degree, h, dt, coriolis = None: not given, Roller's accurate default chooses it (-ts_view)."""
    extra = list(extra)
    if label is None:
        label = f"P{degree} h={h:g} dt={dt:g} {coriolis}" + (" " + " ".join(extra) if extra else "")
        if degree == 2:
            label += ", straight boundary" if "-mesh_curved" in extra else ", curved boundary"
    return dict(label=label, degree=degree, h=h, dt=dt, coriolis=coriolis, extra=extra)


DEFAULT = cfg(None, None, None, None, label="default: no discretization option (P2 curved, extrapolated, dt and h from -ts_phase_error 0.01)")


def chosen(base, t_end):
    """What the accurate default picks for this scene: (degree, h, dt, coriolis) from -ts_view."""
    import re
    res = benchlib.run(base + ["-ts_max_time", t_end, "-ts_max_steps", 0, "-ts_view"], logview=False)
    out = res["stdout"]
    m = re.search(r"roller: P(\d)\S*.*?-mesh_h ([^,\s]+),.*?-ts_dt (\S+)", out)
    v = re.search(r"-coriolis_velocity (\w+)", out)
    return int(m.group(1)), float(m.group(2)), float(m.group(3)), v.group(1) if v else "exact (composed)"


def boundary(r):
    """How a P2 run's mesh meets the circles: curved (the default), straight, area-preserving (straight edges
    on enlarged circles); '' for P1."""
    for kind in ("area-preserving", "straight", "curved"):
        if kind in r["label"]:
            return kind
    return "curved" if str(r["degree"]) == "2" else ""


LINESTYLE = {"straight": "-", "area-preserving": "--", "curved": "-."}
MARKER = {"straight": "s", "area-preserving": "D", "curved": "^"}


def configs(scene, name):
    out = []
    if scene == "free":
        if name == "paper":
            out.append(cfg(1, 0.0125, 0.0125, "backward", PAPER_CG, label="paper: P1 h=dt=0.0125 backward, CG"))
        elif name == "default":
            out.append(DEFAULT)
        elif name == "paper-cholesky":
            out.append(cfg(1, 0.0125, 0.0125, "backward", label="P1 h=dt=0.0125 backward, Cholesky (the paper's discretization, Roller's solver)"))
        elif name == "grid":
            for degree in (1, 2):
                for h in (0.05, 0.025, 0.0125):
                    for div in (1, 2, 4, 8):
                        if degree == 2 and h == 0.0125 and div > 4:
                            continue
                        for cor in ("backward", "centered"):
                            out.append(cfg(degree, h, h / div, cor))
        elif name == "search":
            for h in (0.0125, 0.01):
                for dt in (0.0025, 0.002, 0.0015625, 0.00125):
                    out.append(cfg(2, h, dt, "extrapolated"))
            out += [cfg(2, 0.0125, 0.0015625, "centered"), cfg(2, 0.0125, 0.0015625, "backward"),
                    cfg(2, 0.025, 0.0015625, "extrapolated"), cfg(2, 0.025, 0.00078125, "extrapolated"),
                    cfg(1, 0.00625, 0.003125, "extrapolated"), cfg(1, 0.00625, 0.0015625, "extrapolated")]
        elif name == "curved":
            # P2 with its default curved (isoparametric) boundary, small steps: the cheapest 1 % runs
            for h, dts in ((0.05, (0.0025,)), (0.04, (0.0025,)), (0.035, (0.0025,)), (0.03, (0.0025,)),
                           (0.025, (0.003125, 0.0025, 0.00125)), (0.0125, (0.0025,))):
                for dt in dts:
                    out.append(cfg(2, h, dt, "extrapolated"))
        elif name == "geometry":
            # P2 runs with straight edges on a mesh whose boundary polygons enclose the right area (vertices on
            # circles of radius r / sqrt(sin(t)/t), t = 2 pi / N): what the straight-sided boundary costs, before
            # the curved boundary (src/mesh/geometry.c) fixed it (docs/performance.md).
            for h, dts in ((0.025, (0.003125, 0.0025, 0.00125)), (0.0125, (0.0025, 0.00125)), (0.05, (0.0025,))):
                for dt in dts:
                    out.append(cfg(2, h, dt, "extrapolated", area_preserving(h) + ["-mesh_curved", "0"], label=f"P2 h={h:g} dt={dt:g} extrapolated, area-preserving boundary"))
        else:
            raise SystemExit(f"unknown set {name} for scene free")
    else:
        if name == "paper":
            out.append(cfg(1, 0.0125, 0.0125, "backward", ["-contact_solver", "pcg"], label="paper: P1 h=dt=0.0125 backward, projected CG"))
        elif name == "default":
            out.append(DEFAULT)
        elif name == "paper-condensed":
            out.append(cfg(1, 0.0125, 0.0125, "backward", label="P1 h=dt=0.0125 backward, condensed (the paper's discretization, Roller's solver)"))
        elif name == "grid":
            for degree, hs in ((1, (0.05, 0.025, 0.0125, 0.00625)), (2, (0.05, 0.025, 0.0125))):
                for h in hs:
                    for div in (1, 2, 4):
                        if h / div < 0.003125 or (degree == 1 and h == 0.00625 and div > 2):
                            continue
                        out.append(cfg(degree, h, h / div, "backward"))
                        if div > 1:
                            out.append(cfg(degree, h, h / div, "extrapolated"))
        elif name == "reference":
            out.append(cfg(2, 0.00625, 0.0015625, "extrapolated", label="reference: P2 h=0.00625 dt=0.0015625 extrapolated"))
        elif name == "fine":
            # small steps on the coarse P2 meshes: where the time error of alpha goes below 1 %
            for h in (0.05, 0.025):
                for dt in (0.003125, 0.0015625):
                    out.append(cfg(2, h, dt, "extrapolated"))
        elif name == "check":
            # half the reference's dt on the next coarser mesh: how large the reference's own time error is
            out.append(cfg(2, 0.0125, 0.0015625, "extrapolated"))
        else:
            raise SystemExit(f"unknown set {name} for scene rolling")
    return out


def area_preserving(h, r_inner=0.25, r_outer=0.5):
    """-r_inner/-r_outer for a mesh whose boundary polygons have the area of the true circles. gmsh splits each
    of the two half circles into ceil(pi r / h) edges (checked with -mesh_view_info at h = 0.05 ... 0.01)."""
    out = []
    for name, r in (("-r_inner", r_inner), ("-r_outer", r_outer)):
        t = 2 * np.pi / (2 * np.ceil(np.pi * r / h - 1e-9))
        out += [name, f"{r / np.sqrt(np.sin(t) / t):.10f}"]
    return out


# ---------------------------------------------------------------- references
@functools.lru_cache(maxsize=None)
def _exact_module():
    from rollerref import axisym
    return axisym


def free_exact(times, n=256):
    ar = _exact_module()
    p = dict(ar.DEFAULTS)
    p["n"] = n
    return ar.reference(p, np.asarray(times), scheme="exact")


def free_dmf(times, dt, coriolis, n=64):
    ar = _exact_module()
    p = dict(ar.DEFAULTS)
    p["n"] = n
    return ar.reference(p, np.asarray(times), scheme="dmf", dt=dt, coriolis=coriolis)


def rel_max(q, qref, scale):
    return float(np.abs(q - qref).max() / scale)


def rel_rms(q, qref, scale):
    return float(np.sqrt(np.mean((q - qref) ** 2)) / scale)


def common(t, tref):
    """Indices (i, j) with t[i] == tref[j] to rounding."""
    j = np.searchsorted(tref, t - 1e-9)
    j = np.clip(j, 0, len(tref) - 1)
    ok = np.abs(tref[j] - t) < 1e-9
    return np.nonzero(ok)[0], j[ok]


# ---------------------------------------------------------------- one run
def measure(scene, c, t_end, ref):
    base = ["-options_file", os.path.join(ROOT, "jobs", "rolling.yaml")] if scene == "rolling" else []
    if c["degree"] is None:
        c = dict(c)
        c["degree"], c["h"], c["dt"], c["coriolis"] = chosen(base, t_end)
        args = base + ["-ts_max_time", t_end] + c["extra"]
    else:  # an explicit discretization: the three-level DMF unless the config names a scheme (docs/model.md section 2.1)
        scheme = [] if "-ts_scheme" in c["extra"] else ["-ts_scheme", "dmf"]
        args = base + scheme + ["-degree", c["degree"], "-mesh_h", c["h"], "-ts_dt", c["dt"], "-coriolis_velocity", c["coriolis"],
                                "-ts_max_time", t_end] + c["extra"]
    load = os.getloadavg()[0]
    res = benchlib.run(args, csv=True)
    d = res["series"]
    row = dict(label=c["label"], scene=scene, degree=c["degree"], h=c["h"], dt=c["dt"], coriolis=c["coriolis"],
               extra=" ".join(c["extra"]), t_end=t_end, steps=len(d["t"]) - 1, nproc=1, wall_s=res["wall"],
               cpu_s=res["cpu"], setup_s=benchlib.stage(res, "Roller setup"), step_s=benchlib.stage(res, "Roller step"),
               contact_s=benchlib.stage(res, "Roller contact"), diag_s=benchlib.stage(res, "Roller diagnostics"),
               maxrss_mb=res["maxrss_mb"], load1=load, date=datetime.datetime.now().isoformat(timespec="seconds"),
               command=benchlib.shell([str(a) for a in args]).replace(ROOT + "/", ""))
    if scene == "free":
        Rx, ax = free_exact(d["t"])
        sR, sa = np.abs(Rx).max(), np.abs(ax).max()
        Rx64, ax64 = free_exact(d["t"], n=64)
        # the time part: the DMF's semi-discrete reference, for the three-level runs only (the composition has none)
        Rd, ad = free_dmf(d["t"], c["dt"], c["coriolis"]) if not c["coriolis"].startswith("exact") else (Rx64 + np.nan, ax64 + np.nan)
        row.update(err_R=rel_max(d["R"], Rx, sR), err_alpha=rel_max(d["alpha"], ax, sa),
                   rms_R=rel_rms(d["R"], Rx, sR), rms_alpha=rel_rms(d["alpha"], ax, sa),
                   err_R_time=rel_max(Rd, Rx64, sR), err_alpha_time=rel_max(ad, ax64, sa),
                   err_R_space=rel_max(d["R"], Rd, sR), err_alpha_space=rel_max(d["alpha"], ad, sa))
    else:
        if ref is not None:
            row.update(rolling_errors(d, ref))
    if SERIES_DIR:
        os.makedirs(SERIES_DIR, exist_ok=True)
        with open(series_path(scene, c["label"]), "w") as f:
            cols = ["t", "R", "alpha"] + (["contact_force"] if scene == "rolling" else [])
            f.write(",".join(cols) + "\n")
            for k in range(len(d["t"])):
                f.write(",".join(f"{d[q][k]:.10g}" for q in cols) + "\n")
    return row, d


def series_path(scene, label):
    name = "".join(ch if ch.isalnum() or ch in "=._-" else "_" for ch in label)
    return os.path.join(SERIES_DIR, f"{scene}_{name}.csv")


def rescore(rows, ref):
    """rolling: recompute the errors of every row whose series is in --series-dir against the current reference."""
    for r in rows:
        path = series_path("rolling", r["label"])
        if not os.path.exists(path):
            print(f"rescore: no series for {r['label']}", file=sys.stderr)
            continue
        d = benchlib.read_csv(path)
        r.update({k: fmt(v) for k, v in rolling_errors(d, ref).items()})
    return rows


def rolling_errors(d, ref):
    """Errors of R, alpha, contact_force against the reference run: at the common output times, or, where the
    run's dt is no multiple of the reference's (the default's dt follows the scene), at the run's times with the
    reference interpolated linearly (its dt is the finest of the study). The force oscillates after every change
    of the contact set; its level: moving averages over 0.5 time units on the 0.0125 grid."""
    i, j = common(d["t"], ref["t"])
    if len(i) > len(d["t"]) // 2:
        t, run, rf = d["t"][i], {q: d[q][i] for q in ref}, {q: ref[q][j] for q in ref}
    else:
        t = d["t"][d["t"] <= ref["t"][-1] + 1e-9]
        run, rf = {q: d[q][:len(t)] for q in ref}, {q: np.interp(t, ref["t"], ref[q]) for q in ref}
    errs = {}
    for q, key in (("R", "R"), ("alpha", "alpha"), ("contact_force", "force")):
        sc = np.abs(rf[q]).max()
        errs["err_" + key] = rel_max(run[q], rf[q], sc)
        errs["rms_" + key] = rel_rms(run[q], rf[q], sc)
    grid = 0.0125 * np.arange(int(t[-1] / 0.0125 + 1e-9) + 1)
    w = 40
    if len(grid) > w:
        F, Fr = np.interp(grid, t, run["contact_force"]), np.interp(grid, t, rf["contact_force"])
        avg = lambda q: np.convolve(q, np.ones(w) / w, "valid")  # noqa: E731
        errs["err_force_avg"] = rel_max(avg(F), avg(Fr), np.abs(avg(Fr)).max())
    return errs


# ---------------------------------------------------------------- CSV, table, plot
def load_rows(path):
    if not os.path.exists(path):
        return []
    with open(path) as f:
        return list(csv.DictReader(f))


def save_rows(path, rows):
    with open(path, "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=FIELDS)
        w.writeheader()
        for r in rows:
            w.writerow({k: fmt(r.get(k, "")) for k in FIELDS})


def fmt(v):
    if isinstance(v, float):
        return f"{v:.6g}"
    return v


def num(r, k):
    try:
        return float(r[k])
    except (KeyError, ValueError, TypeError):
        return float("nan")


def table(rows, scene):
    qs = ["R", "alpha"] + (["force"] if scene == "rolling" else [])
    head = "| run | steps | wall [s] | CPU [s] | setup [s] | " + " | ".join(f"err {q}" for q in qs)
    if scene == "free":
        head += " | R: time / space | alpha: time / space"
    else:
        head += " | err force, 0.5-averaged"
    lines = [head + " |", "|" + "---|" * (head.count("|") - 0)]
    lines[1] = "|" + "---|" * (len(head.split("|")) - 2)
    for r in sorted(rows, key=lambda r: (not r["label"].startswith(("paper", "default", "reference")), num(r, "degree"), -num(r, "h"), -num(r, "dt"), r["coriolis"])):
        cells = [r["label"], r["steps"], f"{num(r, 'wall_s'):.1f}", f"{num(r, 'cpu_s'):.1f}", f"{num(r, 'setup_s'):.1f}"]
        cells += [f"{num(r, 'err_' + q):.2e}" for q in qs]
        if scene == "free":
            cells += [f"{num(r, 'err_R_time'):.1e} / {num(r, 'err_R_space'):.1e}", f"{num(r, 'err_alpha_time'):.1e} / {num(r, 'err_alpha_space'):.1e}"]
        else:
            cells += [f"{num(r, 'err_force_avg'):.2e}"]
        lines.append("| " + " | ".join(str(c) for c in cells) + " |")
    return "\n".join(lines) + "\n"


def plot(rows, scene, path, xkey="cpu_s"):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from matplotlib.lines import Line2D
    qs = [("R", "R"), ("alpha", "alpha")] + ([("force_avg", "contact force, 0.5-averaged"), ("force", "contact force")] if scene == "rolling" else [("both", "max(R, alpha)")])
    fig, axes = plt.subplots(1, len(qs), figsize=(5.6 * len(qs), 5.6), sharey=True)
    hs = sorted({num(r, "h") for r in rows if not r["label"].startswith(("paper", "default", "reference"))}, reverse=True)
    cmap = plt.get_cmap("viridis")
    hcolor = {h: cmap(i / max(1, len(hs) - 1) * 0.9) for i, h in enumerate(hs)}
    corfill = {"backward": "full", "extrapolated": "left", "centered": "none"}
    for ax, (q, qname) in zip(axes, qs):
        def err(r):
            if q == "both":
                return max(num(r, "err_R"), num(r, "err_alpha"))
            return num(r, "err_" + q)
        groups = {}
        for r in rows:
            if r["label"].startswith(("paper", "default", "reference")):
                continue
            groups.setdefault((r["degree"], num(r, "h"), r["coriolis"], boundary(r)), []).append(r)
        for (deg, h, cor, kind), rs in groups.items():
            rs = sorted(rs, key=lambda r: -num(r, "dt"))
            x = [num(r, xkey) for r in rs]
            y = [err(r) for r in rs]
            ax.loglog(x, y, ls=LINESTYLE.get(kind, ":"), lw=0.8, color=hcolor[h], alpha=0.6)
            for r, xi, yi in zip(rs, x, y):
                dth = num(r, "dt") / num(r, "h")
                ax.loglog(xi, yi, marker=MARKER.get(kind, "o"), fillstyle=corfill.get(cor, "full"), color=hcolor[h],
                          ms=8 if abs(dth - 1) < 1e-9 else 6, mec="k" if abs(dth - 1) < 1e-9 else hcolor[h], ls="")
        for r in rows:
            if r["label"].startswith("paper"):
                ax.loglog(num(r, xkey), err(r), "r*", ms=16, mec="k")
                ax.axvline(num(r, xkey), color="r", ls=":", lw=1)
            elif r["label"].startswith("default"):
                ax.loglog(num(r, xkey), err(r), "P", color="orange", ms=11, mec="k")
        ax.axhline(0.01, color="gray", ls="--", lw=1)
        if q == "both" or (scene == "rolling" and q == "alpha"):
            # the cheapest run below 1 % in R and alpha (and the averaged force)
            def ok(r):
                qq = ("R", "alpha") if scene == "free" else ("R", "alpha", "force_avg")
                return all(num(r, "err_" + k) < 0.01 for k in qq)
            cand = [r for r in rows if ok(r) and not r["label"].startswith(("paper", "default", "reference"))]
            if cand:
                r = min(cand, key=lambda r: num(r, xkey))
                ax.annotate(r["label"].replace(" extrapolated", "").replace(", ", ",\n"),
                            (num(r, xkey), err(r)), xytext=(-40, 26), textcoords="offset points", fontsize=7,
                            ha="right", arrowprops=dict(arrowstyle="-", lw=0.6))
        ax.set_xlabel("wall time of the run [s]" if xkey == "wall_s" else "CPU time of the run [s] (serial: = wall time on an idle core)")
        ax.set_title(f"max error in {qname}")
        ax.grid(True, which="both", alpha=0.3)
    axes[0].set_ylabel("max over t of |q - q_ref| / max |q_ref|")
    handles = [Line2D([], [], marker="o", ls=":", color="gray", label="P1")]
    for kind in ("curved", "straight", "area-preserving"):
        if any(boundary(r) == kind for r in rows):
            handles.append(Line2D([], [], marker=MARKER[kind], ls=LINESTYLE[kind], color="gray", label=f"P2, {kind} boundary"))
    handles += [Line2D([], [], marker="o", ls="", color=hcolor[h], label=f"h = {h:g}") for h in hs]
    handles += [Line2D([], [], marker="o", ls="", color="gray", fillstyle=corfill[c], label=f"Coriolis {c}") for c in corfill if any(r["coriolis"] == c for r in rows)]
    handles += [Line2D([], [], marker="o", ls="", color="gray", mec="k", ms=8, label="dt = h (black edge)"),
                Line2D([], [], marker="*", ls="", color="r", mec="k", ms=14, label="paper's configuration")]
    if any(r["label"].startswith("default") for r in rows):
        handles.append(Line2D([], [], marker="P", ls="", color="orange", mec="k", ms=10, label="Roller default"))
    fig.legend(handles=handles, fontsize=8, loc="lower center", ncol=min(len(handles), 7), frameon=False)
    title = {"free": "Obstacle-free scene (figure 4), 0 <= t <= 20: error against the exact reference",
             "rolling": "Rolling contact (figure 9), 0 <= t <= 10: error against the finest run (P2, h = 0.00625, dt = 0.0015625)"}[scene]
    fig.suptitle(title + "\n(2-core machine shared with other jobs: CPU time, user + system, of each serial run)")
    fig.tight_layout(rect=(0, 0.1, 1, 1))
    fig.savefig(path, dpi=110)
    plt.close(fig)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--scene", choices=["free", "rolling"], default="free")
    ap.add_argument("--set", action="append", default=[], help="paper, default, grid, search, reference")
    ap.add_argument("--only", default=None, help="run only configs whose label contains this string")
    ap.add_argument("--t-end", type=float, default=20.0)
    ap.add_argument("--out", default=None, help="output prefix (default bench/results/<scene>)")
    ap.add_argument("--ref", default=None, help="rolling: reference CSV (default bench/results/rolling_ref.csv)")
    ap.add_argument("--figure", default=None, help="also save the plot here (e.g. docs/figures/perf_free.png)")
    ap.add_argument("--plot-only", action="store_true")
    ap.add_argument("--series-dir", default=None, help="keep the series of every run in this directory")
    ap.add_argument("--rescore", action="store_true", help="rolling: recompute the errors from --series-dir against --ref")
    opt = ap.parse_args()
    global SERIES_DIR
    SERIES_DIR = opt.series_dir
    out = opt.out or os.path.join(ROOT, "bench", "results", opt.scene)
    os.makedirs(os.path.dirname(out), exist_ok=True)
    rows = load_rows(out + ".csv")
    ref = None
    refpath = opt.ref or os.path.join(ROOT, "bench", "results", "rolling_ref.csv")
    if opt.scene == "rolling" and os.path.exists(refpath):
        ref = benchlib.read_csv(refpath)
    if opt.rescore:
        if ref is None or not SERIES_DIR:
            raise SystemExit("--rescore needs the reference CSV and --series-dir")
        save_rows(out + ".csv", rescore(rows, ref))
    elif not opt.plot_only:
        todo = [c for s in (opt.set or ["paper"]) for c in configs(opt.scene, s)]
        if opt.only:
            todo = [c for c in todo if opt.only in c["label"]]
        for c in todo:
            row, series = measure(opt.scene, c, opt.t_end, ref)
            if c["label"].startswith("reference"):
                with open(refpath, "w") as f:   # keep what the error needs, every 0.0125
                    f.write("t,R,alpha,contact_force\n")
                    keep = np.nonzero(np.abs(series["t"] / 0.0125 - np.round(series["t"] / 0.0125)) < 1e-6)[0]
                    for k in keep:
                        f.write(f"{series['t'][k]:.17g},{series['R'][k]:.17g},{series['alpha'][k]:.17g},{series['contact_force'][k]:.17g}\n")
                ref = benchlib.read_csv(refpath)
            rows = [r for r in rows if r["label"] != row["label"]] + [{k: fmt(v) for k, v in row.items()}]
            save_rows(out + ".csv", rows)
            print(f"{row['label']}: wall {row['wall_s']:.2f} s cpu {row['cpu_s']:.2f} s err R {row.get('err_R', float('nan')):.3e} "
                  f"alpha {row.get('err_alpha', float('nan')):.3e}" + (f" force {row.get('err_force', float('nan')):.3e}" if opt.scene == "rolling" else "")
                  + f"  [load {row['load1']:.2f}]", flush=True)
    rows = load_rows(out + ".csv")
    with open(out + ".md", "w") as f:
        f.write(table(rows, opt.scene))
    plot(rows, opt.scene, out + ".png")
    if opt.figure:
        plot(rows, opt.scene, opt.figure)


if __name__ == "__main__":
    main()
