"""Pictures of the fields Roller writes with -output F.h5 (docs/output.md).

stress mode (default): |sigma| (stress_norm) on the deformed roller in the lab frame, x + displacement_lab,
one panel per chosen time (the nearest stored step), a common colour scale, the deformation optionally
magnified (--scale; the rigid rotation is not), and the obstacle line
y = g(t) = min(v t, depth) - r_outer (docs/model.md section 1):

    PYTHONPATH=scripts python3 -m rollerplots.fields F.h5 --times 5 10 20 --out sigma.png

contact mode: the vertex field contact_pressure along Gamma_C against the lab-frame angle of the material
point (0 at the bottom, positive counter-clockwise), one curve per chosen time; if the file has no such
field, says so and writes nothing:

    PYTHONPATH=scripts python3 -m rollerplots.fields F.h5 --mode contact --times 5 10 20 --out pressure.png

The obstacle (on/off, v, depth) and r_outer default to the run's own values stored in /parameters, else
to Roller's defaults 0.005, 0.025, 0.5; the options override both.
"""
import argparse
import math
import os
import sys

import h5py
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from matplotlib.tri import Triangulation  # noqa: E402

ROLLER_DEFAULTS = {"obstacle_speed": 0.005, "obstacle_depth": 0.025, "r_outer": 0.5}


def vertex_field(f, name):
    """The dataset of the vertex field `name`: PETSc names it /vertex_fields/<vec>_<field>; of the
    candidates <name>_* the shortest (displacement_displacement, not displacement_lab_displacement)."""
    group = f.get("vertex_fields")
    if group is None:
        return None
    if name in group:
        return group[name]
    cands = sorted((k for k in group if k.startswith(name + "_")), key=len)
    return group[cands[0]] if cands else None


def pick_steps(times, wanted):
    """Indices of the stored steps nearest to the wanted times (the last step if none are wanted)."""
    if not wanted:
        return [len(times) - 1]
    steps = []
    for t in wanted:
        k = int(np.argmin(np.abs(times - t)))
        if abs(times[k] - t) > 1e-9 * max(1.0, abs(t)):
            print(f"rollerplots.fields: t = {t:g} is not stored; nearest step t = {times[k]:g}", file=sys.stderr)
        if k in steps:
            print(f"rollerplots.fields: t = {t:g} gives the same stored step as an earlier time; skipped", file=sys.stderr)
            continue
        steps.append(k)
    return steps


def obstacle_settings(f, args):
    """(draw?, v, depth, r_outer): command line, else the run's /parameters, else Roller's defaults."""
    par = dict(f["parameters"].attrs) if "parameters" in f else {}
    value = {k: float(par.get(k, d)) for k, d in ROLLER_DEFAULTS.items()}
    for k in value:
        if getattr(args, k) is not None:
            value[k] = getattr(args, k)
    if args.no_obstacle:
        draw = False
    elif args.obstacle:
        draw = True
    else:
        draw = bool(par.get("obstacle", 1))
    return draw, value["obstacle_speed"], value["obstacle_depth"], value["r_outer"]


def lab_positions(x, xi, lab, scale):
    """Lab-frame positions R(theta)(x + scale xi): theta recovered from lab = R(theta)(x + xi) - x, so that
    a magnification applies to the deformation and not to the rigid rotation."""
    p, q = x + xi, x + lab
    theta = math.atan2(np.sum(p[:, 0] * q[:, 1] - p[:, 1] * q[:, 0]), np.sum(p[:, 0] * q[:, 0] + p[:, 1] * q[:, 1]))
    c, s = math.cos(theta), math.sin(theta)
    m = x + scale * xi
    return np.stack([c * m[:, 0] - s * m[:, 1], s * m[:, 0] + c * m[:, 1]], axis=1)


def panel_grid(n):
    cols = min(n, 3)
    return (n + cols - 1) // cols, cols


def plot_stress(f, args, times, steps):
    x = f["geometry/vertices"][:]
    cells = f["viz/topology/cells"][:]
    lab = vertex_field(f, "displacement_lab")
    xi = vertex_field(f, "displacement")
    val = vertex_field(f, args.field)
    for name, d in (("displacement_lab", lab), ("displacement", xi), (args.field, val)):
        if d is None:
            sys.exit(f"rollerplots.fields: {args.h5} has no vertex field {name}")
    draw, v, depth, r_outer = obstacle_settings(f, args)
    values = []
    for k in steps:
        a = val[k]
        values.append(np.linalg.norm(a, axis=1) if a.ndim == 2 else a)
    vmax = args.vmax if args.vmax is not None else max(float(np.max(a)) for a in values)
    vmin = args.vmin if args.vmin is not None else min(0.0, min(float(np.min(a)) for a in values))
    rows, cols = panel_grid(len(steps))
    fig, axes = plt.subplots(rows, cols, figsize=(4.0 * cols + 1.2, 4.0 * rows), squeeze=False, layout="constrained")
    for ax in axes.ravel()[len(steps):]:
        ax.set_visible(False)
    pad = 0.08 * r_outer
    for ax, k, a in zip(axes.ravel(), steps, values):
        X = x + lab[k][:, :2] if args.scale == 1.0 else lab_positions(x, xi[k][:, :2], lab[k][:, :2], args.scale)
        tri = Triangulation(X[:, 0], X[:, 1], cells)
        im = ax.tripcolor(tri, a, shading="gouraud", cmap=args.cmap, vmin=vmin, vmax=vmax)
        if args.mesh:
            ax.triplot(tri, lw=0.2, color="k", alpha=0.3)
        t = times[k]
        title = f"t = {t:g}"
        if draw:
            g = min(v * t, depth) - r_outer
            ax.axhspan(g - 2 * pad, g, color="0.85", zorder=0)
            ax.axhline(g, color="k", lw=1.2)
            title += f", g(t) = {g:.4g}"
        ax.set_title(title, fontsize="medium")
        ax.set_aspect("equal")
        lim = X[:, 0].min() - pad, X[:, 0].max() + pad
        ax.set_xlim(*lim)
        ax.set_ylim(min(X[:, 1].min(), -r_outer) - pad, X[:, 1].max() + pad)
        ax.set_xlabel("$x_1$")
        ax.set_ylabel("$x_2$")
    label = r"$|\sigma|$" if args.field == "stress_norm" else args.field
    fig.colorbar(im, ax=axes.ravel().tolist(), shrink=0.85, label=label)
    if args.scale != 1.0:
        fig.suptitle(f"deformation magnified {args.scale:g} times", fontsize="small")
    return fig


def plot_contact(f, args, times, steps):
    p = vertex_field(f, "contact_pressure")
    if p is None:
        print(f"rollerplots.fields: {args.h5} has no vertex field contact_pressure; nothing to plot")
        return None
    x = f["geometry/vertices"][:]
    lab = vertex_field(f, "displacement_lab")
    r = np.linalg.norm(x, axis=1)
    _, _, _, r_outer = obstacle_settings(f, args)
    on = np.abs(r - r.max()) <= 1e-6 * r.max()
    fig, ax = plt.subplots(figsize=(7.5, 4.2))
    for k in steps:
        X = x[on] + (lab[k][on, :2] if lab is not None else 0.0)
        phi = np.degrees(np.arctan2(X[:, 0], -X[:, 1]))  # lab angle from the bottom, counter-clockwise
        a = p[k][on]
        if a.ndim == 2:
            a = a[:, 0]
        order = np.argsort(phi)
        ax.plot(phi[order], a[order], lw=1.2, label=f"t = {times[k]:g}")
    ax.set_xlabel(r"lab angle of the point of $\Gamma_C$ from the bottom (degrees)")
    ax.set_ylabel("contact pressure")
    ax.set_xlim(-180, 180)
    ax.grid(True, lw=0.3, alpha=0.6)
    ax.legend(fontsize="small")
    fig.tight_layout()
    return fig


def main(argv):
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("h5", help="the HDF5 file of -output (or its .part of a run that did not finish)")
    p.add_argument("--out", required=True, help="PNG file to write")
    p.add_argument("--mode", choices=("stress", "contact"), default="stress")
    p.add_argument("--times", nargs="+", type=float, default=[], help="output times (nearest stored step; default: the last)")
    p.add_argument("--field", default="stress_norm", help="vertex field to colour by (a vector is shown by its length)")
    p.add_argument("--obstacle-speed", dest="obstacle_speed", type=float, help="v in g(t) (default: the run's, else 0.005)")
    p.add_argument("--obstacle-depth", dest="obstacle_depth", type=float, help="depth in g(t) (default: the run's, else 0.025)")
    p.add_argument("--r-outer", dest="r_outer", type=float, help="r_outer in g(t) (default: the run's, else 0.5)")
    p.add_argument("--obstacle", action="store_true", help="draw the obstacle even if the run had none")
    p.add_argument("--no-obstacle", action="store_true", help="do not draw the obstacle")
    p.add_argument("--scale", type=float, default=1.0, help="magnify the deformation this many times (not the rotation)")
    p.add_argument("--vmin", type=float, help="colour scale minimum (default: min(0, data))")
    p.add_argument("--vmax", type=float, help="colour scale maximum (default: the largest over the panels)")
    p.add_argument("--cmap", default="viridis")
    p.add_argument("--mesh", action="store_true", help="draw the mesh edges")
    args = p.parse_args(argv)

    with h5py.File(args.h5, "r") as f:
        if "time" not in f:
            sys.exit(f"rollerplots.fields: {args.h5} has no fields (no /time)")
        times = f["time"][:].ravel()
        nsteps = min(d.shape[0] for d in f["vertex_fields"].values()) if "vertex_fields" in f else 0
        if nsteps == 0:
            sys.exit(f"rollerplots.fields: {args.h5} has no stored step")
        times = times[:nsteps]  # a killed run may have written a time without its fields
        steps = pick_steps(times, args.times)
        fig = plot_contact(f, args, times, steps) if args.mode == "contact" else plot_stress(f, args, times, steps)
    if fig is None:
        return
    os.makedirs(os.path.dirname(os.path.abspath(args.out)), exist_ok=True)
    fig.savefig(args.out, dpi=150)
    print(f"rollerplots.fields: {args.mode} at t = {', '.join(f'{times[k]:g}' for k in steps)} -> {args.out}")


if __name__ == "__main__":
    main(sys.argv[1:])
