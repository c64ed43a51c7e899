"""Amplitude spectra of Roller's CSV columns, with the contact's element-passing frequency marked (the
cogging of the contact force, docs/contact.md "Cogging: the force spectrum"). The functions are in
rollerreport.spectrum.

    PYTHONPATH=scripts python3 -m rollerplots.spectrum run.csv [more.csv ...] [--columns contact_force alpha]
        [--tmin 10 --tmax 20] [--omega W] [--h H | --n-boundary N] [--r-outer 0.5]
        [-o spectrum.png] [--table] [--json summary.json]

Window: --tmin <= t <= --tmax, default the second half of the run. Amplitudes are those of sinusoids
(2|FFT|/N of the Hann-windowed signal with the window's gain divided out, the mean removed), plotted and
tabulated relative to the column's mean in the window. The element-passing frequency is

    f_e = omega r_C / h        (cycles per unit time; a period h / (omega r_C))

with h the arc length of a Gamma_C edge: --h (alias --mesh-h) gives it, or --n-boundary N (the number of
Gamma_C vertices: h = 2 pi r_C / N, f_e = N omega / (2 pi)); gmsh rounds -mesh_h to a whole number of edges.
omega defaults to the slope of the CSV's theta column. For P2 the Lagrange nodes on Gamma_C are h/2
apart, so 2 f_e is marked and tabulated too.

--table prints, per CSV and column: mean, std/mean, largest |deviation|/mean, the lines at f_e and 2 f_e
(amplitude / mean, the frequency where the line's peak was found within one resolution bin of the
nominal one, and its ratio to the median level of the spectrum within 20 bins around it, "bg": about 1-3
means no line stands out of the broadband floor), the strongest line (f, amplitude / mean); and, if the CSV has contact_nodes, how often the
number of contact nodes changes and how often it reverses within --flicker-steps steps and in successive
steps (flicker; rolling alone changes it about 2 (P1) or 4 (P2) times f_e per unit time, nodes entering
and leaving the contact zone).
"""
import argparse
import json
import math
import os
import sys

from rollerreport import spectrum as sp


def parse(argv):
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("csv", nargs="+", help="Roller monitor CSV file(s) (-monitor_csv)")
    p.add_argument("--columns", nargs="+", default=["contact_force", "alpha"],
                   help="CSV columns to analyse (default: contact_force alpha); any column of the CSV")
    p.add_argument("--tmin", type=float, help="window start (default: half the run's end time)")
    p.add_argument("--tmax", type=float, help="window end (default: the last row)")
    p.add_argument("--omega", type=float, help="rotation rate (default: the slope of the theta column)")
    p.add_argument("--h", "--mesh-h", dest="h", type=float, help="edge length on Gamma_C (for f_e)")
    p.add_argument("--n-boundary", type=int, help="number of Gamma_C vertices (h = 2 pi r_C / N; instead of --h)")
    p.add_argument("--r-outer", type=float, default=0.5, help="r_C (default 0.5, Roller's -r_outer default)")
    p.add_argument("--band", type=float, help="search half-width around f_e (default one bin, 1/(tmax - tmin))")
    p.add_argument("--detrend", choices=("mean", "linear"), default="mean", help="what is removed before the FFT")
    p.add_argument("--fmax", type=float, help="upper limit of the plotted frequency axis (default: 3 f_e or Nyquist)")
    p.add_argument("--label", action="append", default=[], help="legend label of each CSV, in order")
    p.add_argument("--flicker-steps", type=int, default=3, help="reversals of contact_nodes within this many steps")
    p.add_argument("--title", help="figure title")
    p.add_argument("-o", "--out", help="PNG to write")
    p.add_argument("--table", action="store_true", help="print the summary numbers")
    p.add_argument("--json", help="write the summary numbers to this JSON file")
    a = p.parse_args(argv)
    if a.h is not None and a.n_boundary is not None:
        p.error("give --h or --n-boundary, not both")
    if a.h is not None and a.h <= 0 or a.n_boundary is not None and a.n_boundary <= 0:
        p.error("--h and --n-boundary must be positive")
    if not (a.out or a.table or a.json):
        a.table = True
    return a


def analyse(args):
    runs = []
    for i, path in enumerate(args.csv):
        try:
            data = sp.read_csv(path)
            t_all = sp.column(data, "t", path)
            cols = {c: sp.column(data, c, path) for c in args.columns}
        except (OSError, ValueError) as e:
            sys.exit(f"rollerplots.spectrum: {e}")
        omega = args.omega
        if omega is None and "theta" in data:
            omega = sp.omega_from_theta(t_all, data["theta"])
        h = args.h
        if args.n_boundary:
            h = 2 * math.pi * args.r_outer / args.n_boundary
        f_e = sp.element_passing_frequency(omega, h, args.r_outer) if omega and h else None
        run = {"csv": path, "label": args.label[i] if i < len(args.label) else os.path.basename(path),
               "omega": omega, "h": h, "r_outer": args.r_outer, "f_e": f_e, "columns": {}, "series": {}}
        for c, y in cols.items():
            try:
                t, yw = sp.window(t_all, y, args.tmin, args.tmax)
                t, yw, resampled = sp.uniform_series(t, yw)
                s = sp.summary(t, yw, f_e, args.band, args.detrend)
            except ValueError as e:
                sys.exit(f"rollerplots.spectrum: {path}, column {c}: {e}")
            s["resampled"] = resampled
            run["columns"][c] = s
            run["series"][c] = (t, yw)
        if "contact_nodes" in data:
            t, n = sp.window(t_all, data["contact_nodes"], args.tmin, args.tmax)
            fl = sp.flicker(n, args.flicker_steps)
            fl.update(min=int(n.min()), max=int(n.max()), mean=float(n.mean()), steps=int(len(n) - 1))
            run["contact_nodes"] = fl
        runs.append(run)
    return runs


def fmt(x, spec=".3g"):
    return "-" if x is None or (isinstance(x, float) and math.isnan(x)) else format(x, spec)


def harm(f, f_e):
    """' (= 3.00 f_e)' when f is within 2 % of a multiple of f_e."""
    if not f_e or f < 0.5 * f_e:
        return ""
    k = round(f / f_e)
    return f" (= {f / f_e:.2f} f_e)" if abs(f / f_e - k) < 0.02 * k else ""


def print_table(runs):
    print("| run | column | window | mean | std/mean | max dev/mean | f_e | line at f_e / mean | line at 2 f_e / mean "
          "| strongest line: f, amp/mean |")
    print("|---|---|---|---|---|---|---|---|---|---|")
    for r in runs:
        for c, s in r["columns"].items():
            fe, fe2 = (f"{fmt(s[k + '_rel'])} (at {fmt(s[k + '_f'], '.4g')}, {s[k + '_over_background']:.1f} x bg)"
                       if k in s else "-" for k in ("fe", "2fe"))
            print(f"| {r['label']} | {c} | {s['tmin']:g}..{s['tmax']:g} | {s['mean']:.6g} | {fmt(s['std_rel'])} | "
                  f"{fmt(s['maxdev_rel'])} | {fmt(r['f_e'], '.4g')} | {fe} | {fe2} | "
                  f"{s['strongest_f']:.4g}{harm(s['strongest_f'], r['f_e'])}, {fmt(s['strongest_rel'])} |")
    for r in runs:
        if "contact_nodes" in r:
            n = r["contact_nodes"]
            print(f"{r['label']}: contact_nodes {n['min']}..{n['max']} (mean {n['mean']:.2f}) over {n['steps']} steps: "
                  f"changes in {n['changes']} steps, {n['reversals']} reversals within {n['within']} steps "
                  f"({n['immediate']} in successive steps), "
                  f"largest jump {n['max_jump']}")
    for r in runs:
        notes = []
        if r["omega"] is None:
            notes.append("no omega (no theta column, no --omega)")
        if r["h"] is None:
            notes.append("no --h / --n-boundary: f_e not marked")
        if any(s["resampled"] for s in r["columns"].values()):
            notes.append("non-uniform t resampled")
        if notes:
            print(f"{r['label']}: " + "; ".join(notes))


def plot(runs, args):
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    cols = args.columns
    fig, axes = plt.subplots(len(cols), 2, figsize=(12, 3.4 * len(cols)), squeeze=False,
                             gridspec_kw={"width_ratios": [1, 1.4]})
    f_es = [r["f_e"] for r in runs if r["f_e"]]
    for i, c in enumerate(cols):
        ax_t, ax_f = axes[i]
        fmax = args.fmax
        for r in runs:
            t, y = r["series"][c]
            s = r["columns"][c]
            line, = ax_t.plot(t, y, lw=0.7, label=r["label"])
            f, a = sp.spectrum(t, y, detrend=args.detrend)
            if fmax is None:
                fmax = min(4.2 * max(f_es), f[-1]) if f_es else f[-1]
            m = abs(s["mean"]) or 1.0
            sel = (f > 0) & (f <= fmax)
            ax_f.semilogy(f[sel], a[sel] / m, lw=0.8, color=line.get_color(), label=r["label"])
            if "fe" in s:
                ax_f.plot([s["fe_f"]], [s["fe_rel"]], "o", ms=5, mfc="none", color=line.get_color())
        for k, f_e in enumerate(sorted(set(f_es))):
            for j in range(1, int(fmax / f_e) + 1):
                ax_f.axvline(j * f_e, color="k", ls="--" if j == 1 else ":", lw=0.8,
                             label=(r"$f_e = \omega r_C / h$" if j == 1 else r"$2 f_e, 3 f_e, \ldots$" if j == 2 else None)
                             if k == 0 else None)
        ax_t.set_xlabel("$t$")
        ax_t.set_ylabel(c)
        ax_t.grid(True, lw=0.3, alpha=0.6)
        ax_f.set_xlabel("frequency (cycles per unit time)")
        ax_f.set_ylabel(f"amplitude / mean of {c}")
        ax_f.set_xlim(0, fmax)
        ax_f.grid(True, which="both", lw=0.3, alpha=0.5)
        ax_f.legend(fontsize="small", loc="best", framealpha=0.9)
        if len(runs) > 1:
            ax_t.legend(fontsize="small")
    r0 = runs[0]
    s0 = next(iter(r0["columns"].values()))
    title = args.title or (f"{r0['label']}: window {s0['tmin']:g} <= t <= {s0['tmax']:g}"
                           + (f", omega = {r0['omega']:.4g}, h = {r0['h']:.4g}, r_C = {r0['r_outer']:g}, "
                              f"f_e = {r0['f_e']:.4g}" if r0["f_e"] else ""))
    fig.suptitle(title, fontsize="medium")
    fig.tight_layout()
    os.makedirs(os.path.dirname(os.path.abspath(args.out)), exist_ok=True)
    fig.savefig(args.out, dpi=130)
    print(f"rollerplots.spectrum: {', '.join(cols)} of {len(runs)} run(s) -> {args.out}")


def main(argv):
    args = parse(argv)
    runs = analyse(args)
    if args.table:
        print_table(runs)
    if args.json:
        out = [{k: v for k, v in r.items() if k != "series"} for r in runs]
        with open(args.json, "w") as f:
            json.dump(out, f, indent=1)
    if args.out:
        plot(runs, args)


if __name__ == "__main__":
    main(sys.argv[1:])
