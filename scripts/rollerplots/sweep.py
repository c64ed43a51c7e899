"""The pictures of a sweep (`roller -modes -sweep F.csv`, docs/squeal.md section 6): the eigenvalues against one swept
option x, the other swept options held at one value each (--where name=value; default: their first value).

    PYTHONPATH=scripts python3 -m rollerplots.sweep F.csv [--x omega] [--where young=0.1 ...] [--out fig.png]
                                [--coalesce-tol 0.01] [--growth-tol 1e-6]

Top: the frequency Im(lambda) against x; with x = omega this is the Campbell diagram: the two modes of each
circumferential order n, one standing wave at omega = 0, split into a forward (blue) and a backward (red) travelling
wave; standing waves grey, each order's branches joined and labelled n. Bottom: the growth rate Re(lambda) against
x: the stability map (with x = friction the squeal map: a mode is unstable where its growth rate is > 0).
Coalescing pairs are circled in both panels and listed: two modes adjacent in frequency whose frequencies are
within --coalesce-tol (relative) of each other where one growth rate is positive (> --growth-tol |lambda|), the
mode-coupling instability of friction-induced squeal."""
import argparse
import csv
import sys
from collections import defaultdict

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

COLOR = {"forward": "C0", "backward": "C3", "standing": "0.5"}
FIXED = ["case", "re", "im", "frequency", "growth_rate", "order", "wave", "error"]


def read(path):
    with open(path) as f:
        reader = csv.DictReader(f)
        rows = list(reader)
        params = [c for c in reader.fieldnames if c not in FIXED]
    if not rows:
        sys.exit(f"rollerplots.sweep: {path} has no rows")
    return params, rows


def select(params, rows, x, where):
    """The rows with the other swept options at their chosen values, grouped by x."""
    chosen = {}
    for p in params:
        if p == x:
            continue
        values = sorted({float(r[p]) for r in rows})
        v = where.get(p, values[0])
        near = min(values, key=lambda u: abs(u - v))
        if abs(near - v) > 1e-12 * max(1.0, abs(v)):
            sys.exit(f"rollerplots.sweep: {p} = {v} is not in the sweep; its values: {values}")
        chosen[p] = near
        if p not in where and len(values) > 1:
            print(f"rollerplots.sweep: {p} held at {near} (of {values}; --where {p}=V to choose)")
    groups = defaultdict(list)
    for r in rows:
        if all(float(r[p]) == v for p, v in chosen.items()):
            groups[float(r[x])].append(r)
    return chosen, dict(sorted(groups.items()))


def coalescences(groups, tol, growth_tol):
    """(x, row, row) of the pairs adjacent in frequency within tol whose larger growth rate is > growth_tol |lambda|."""
    found = []
    for xv, rs in groups.items():
        rs = sorted(rs, key=lambda r: float(r["im"]))
        for a, b in zip(rs, rs[1:]):
            fa, fb = float(a["im"]), float(b["im"])
            scale = max(abs(complex(float(a["re"]), fa)), abs(complex(float(b["re"]), fb)))
            if fb - fa <= tol * max(fb, 1e-300) and max(float(a["re"]), float(b["re"])) > growth_tol * scale:
                found.append((xv, a, b))
    return found


def branches(groups):
    """Each order's modes at every x sorted by frequency: branch (n, k) is the k-th lowest of order n."""
    lines = defaultdict(list)
    for xv, rs in groups.items():
        per = defaultdict(list)
        for r in rs:
            per[int(r["order"])].append(r)
        for n, modes in per.items():
            for k, r in enumerate(sorted(modes, key=lambda r: float(r["im"]))):
                lines[(n, k)].append((xv, float(r["im"]), float(r["re"])))
    return lines


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("csv")
    ap.add_argument("--x", help="the swept option on the horizontal axis (default: the first)")
    ap.add_argument("--where", action="append", default=[], metavar="NAME=VALUE", help="hold another swept option at a value")
    ap.add_argument("--out", help="the figure (default: the CSV's name with .png)")
    ap.add_argument("--coalesce-tol", type=float, default=0.01, help="relative frequency distance of a coalescing pair")
    ap.add_argument("--growth-tol", type=float, default=1e-6, help="growth rate, relative to |lambda|, that counts as positive")
    ap.add_argument("--growth-ylim", metavar="LO,HI", help="the growth panel's range (strongly damped modes can hide the growing ones)")
    a = ap.parse_args()
    params, rows = read(a.csv)
    if not params:
        sys.exit(f"rollerplots.sweep: {a.csv} has no swept option column (not a -sweep CSV?)")
    x = a.x or params[0]
    if x not in params:
        sys.exit(f"rollerplots.sweep: --x {x} is not swept in {a.csv}; swept: {', '.join(params)}")
    where = {}
    for w in a.where:
        name, _, value = w.partition("=")
        if name not in params or name == x or not value:
            sys.exit(f"rollerplots.sweep: --where {w}: allowed NAME=VALUE with NAME one of {', '.join(p for p in params if p != x)}")
        where[name] = float(value)
    chosen, groups = select(params, rows, x, where)
    out = a.out or a.csv.rsplit(".", 1)[0] + ".png"

    fig, (top, bottom) = plt.subplots(2, 1, figsize=(7.5, 8), sharex=True, gridspec_kw={"height_ratios": [2, 1]})
    for (n, k), pts in sorted(branches(groups).items()):
        xs, fs, gs = (np.array(v) for v in zip(*pts))
        top.plot(xs, fs, "-", color="0.8", lw=0.8, zorder=1)
        bottom.plot(xs, gs, "-", color="0.8", lw=0.8, zorder=1)
        if k == 0:
            top.annotate(f"n={n}", (xs[-1], fs[-1]), xytext=(4, -3), textcoords="offset points", fontsize=7)
    for wave, color in COLOR.items():
        pts = [(xv, float(r["im"]), float(r["re"])) for xv, rs in groups.items() for r in rs if r["wave"] == wave]
        if pts:
            xs, fs, gs = zip(*pts)
            top.plot(xs, fs, "o", ms=3.5, color=color, label=wave, zorder=2)
            bottom.plot(xs, gs, "o", ms=3.5, color=color, zorder=2)
    pairs = coalescences(groups, a.coalesce_tol, a.growth_tol)
    for i, (xv, r, s) in enumerate(pairs):
        for ax, key in ((top, "im"), (bottom, "re")):
            ax.plot([xv, xv], [float(r[key]), float(s[key])], "o", ms=9, mfc="none", mec="k", zorder=3, label="coalescing pair" if i == 0 and ax is top else None)
        print(f"rollerplots.sweep: coalescing pair at {x} = {xv:g}: orders {r['order']}, {s['order']}, frequencies {float(r['im']):.6g}, {float(s['im']):.6g}, growth rates {float(r['re']):.3g}, {float(s['re']):.3g}")
    bottom.axhline(0, color="k", lw=0.6)
    lam = [(float(r["re"]), abs(complex(float(r["re"]), float(r["im"])))) for rs in groups.values() for r in rs]
    if all(abs(re) <= a.growth_tol * mag for re, mag in lam):
        bottom.text(0.02, 0.9, f"all |Re(lambda)| < {a.growth_tol:g} |lambda|: neutral (conservative), Re at round-off", transform=bottom.transAxes, fontsize=8, va="top")
    held = ", ".join(f"{p} = {v:g}" for p, v in chosen.items())
    kind = {"omega": "Campbell diagram", "friction": "squeal stability map"}.get(x, "eigenvalues")
    top.set_title(f"{kind}: eigenvalues against {x}" + (f" ({held})" if held else ""), fontsize=10)
    top.set_ylabel("frequency Im(lambda)")
    if a.growth_ylim:
        bottom.set_ylim(*(float(v) for v in a.growth_ylim.split(",")))
    bottom.set_ylabel("growth rate Re(lambda)")
    bottom.set_xlabel(x)
    top.legend(fontsize=8, loc="upper left")
    fig.tight_layout()
    fig.savefig(out, dpi=130)
    print(f"rollerplots.sweep: {sum(len(v) for v in groups.values())} eigenvalues at {len(groups)} values of {x}, {len(pairs)} coalescing pairs -> {out}")


if __name__ == "__main__":
    main()
