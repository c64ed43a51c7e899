"""Time series of Roller runs: one quantity of the -monitor_csv CSV against t, several runs overlaid,
optionally with a reference curve (rollerref.axisym writes columns t,R,alpha).

    PYTHONPATH=scripts python3 -m rollerplots.series --quantity R --out docs/figures/fig3_R.png \\
        --label 'h=0.0125' run1.csv --label 'h=0.025' run2.csv [--reference ref.csv]

Each --label names the CSV that follows it; a CSV without one is labelled by its file name. The quantity is
any CSV column (R, alpha, energy, contact_force, gap_min, ...); see docs/output.md.
"""
import argparse
import csv
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

YLABELS = {
    "R": r"$R(t)$, mean radial displacement of $\Gamma_C$",
    "alpha": r"$\alpha(t)$, mean tangential displacement of $\Gamma_C$",
    "energy": r"discrete energy $E^k$",
    "contact_nodes": "active contact nodes",
    "contact_force": "total contact force",
    "gap_min": r"least gap on $\Gamma_C$",
    "theta": r"$\theta(t)$",
}
VALUED = ("--quantity", "--out", "--reference", "--reference-label", "--title", "--xlim", "--label")


def read_columns(path):
    """A CSV with a header row as a dict of float arrays (nan for empty or 'nan' cells)."""
    with open(path, newline="") as f:
        rows = list(csv.reader(f))
    if not rows:
        sys.exit(f"rollerplots.series: {path} is empty")
    head, body = rows[0], [r for r in rows[1:] if r]

    def num(v):
        try:
            return float(v)
        except ValueError:
            return np.nan

    return {name: np.array([num(r[i]) if i < len(r) else np.nan for r in body]) for i, name in enumerate(head)}


def labelled_runs(argv):
    """(label, csv) pairs in command-line order: a --label applies to the next CSV."""
    runs, pending, i = [], None, 0
    while i < len(argv):
        tok = argv[i]
        if tok == "--label":
            pending, i = argv[i + 1] if i + 1 < len(argv) else None, i + 2
        elif tok.startswith("--label="):
            pending, i = tok.split("=", 1)[1], i + 1
        elif tok == "--xlim":
            i += 3
        elif tok in VALUED:
            i += 2
        elif tok.startswith("-"):
            i += 1
        else:
            runs.append((pending if pending is not None else os.path.basename(tok), tok))
            pending, i = None, i + 1
    return runs


def main(argv):
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--quantity", required=True, help="CSV column to plot against t (R, alpha, energy, ...)")
    p.add_argument("--out", required=True, help="PNG file to write")
    p.add_argument("--label", action="append", default=[], help="label of the CSV that follows")
    p.add_argument("--reference", help="reference CSV with columns t,R,alpha (rollerref.axisym)")
    p.add_argument("--reference-label", default="reference", help="legend entry of the reference")
    p.add_argument("--title", help="figure title")
    p.add_argument("--xlim", nargs=2, type=float, metavar=("TMIN", "TMAX"), help="time window")
    p.add_argument("csv", nargs="+", help="monitor CSV files (-monitor_csv)")
    args = p.parse_intermixed_args(argv)
    runs = labelled_runs(argv)
    q = args.quantity

    fig, ax = plt.subplots(figsize=(7.5, 4.2))
    for label, path in runs:
        data = read_columns(path)
        if q not in data or "t" not in data:
            sys.exit(f"rollerplots.series: {path} has no column '{q}' (columns: {', '.join(data)})")
        ax.plot(data["t"], data[q], lw=1.2, label=label)
    if args.reference:
        ref = read_columns(args.reference)
        if q in ref and "t" in ref:
            ax.plot(ref["t"], ref[q], "k--", lw=1.0, label=args.reference_label)
        else:
            print(f"rollerplots.series: the reference {args.reference} has no column '{q}'; not drawn", file=sys.stderr)
    ax.set_xlabel("$t$")
    ax.set_ylabel(YLABELS.get(q, q))
    if args.xlim:
        ax.set_xlim(*args.xlim)
    if args.title:
        ax.set_title(args.title)
    ax.grid(True, lw=0.3, alpha=0.6)
    ax.ticklabel_format(axis="y", style="sci", scilimits=(-3, 3))
    ax.legend(fontsize="small")
    fig.tight_layout()
    os.makedirs(os.path.dirname(os.path.abspath(args.out)), exist_ok=True)
    fig.savefig(args.out, dpi=150)
    print(f"rollerplots.series: {q} of {len(runs)} run(s) -> {args.out}")


if __name__ == "__main__":
    main(sys.argv[1:])
