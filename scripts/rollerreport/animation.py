"""The vibration, seen: the roller deforming in the lab frame, its vibration magnified and coloured by its speed, the
stick and slip zones along the contact patch, and the sound at the listener with the frame's time marked (the
sound's time axis, t_audio = seconds_per_unit t), from a transient's HDF5 fields (docs/output.md).

The vibration is the seeded run's displacement minus the unseeded run's (transient_base.h5, the same times and
vertices: the seed's response, as the fit uses) when that file is there, else the displacement less its value at
the first stored step; it is magnified so that its largest excursion is MAGNIFIED_TO of r_outer, the steady
deformation (the patch) drawn at its true size. The states are the vertices' (0 off, 1 stick, 2 slip). Written as
a GIF (matplotlib's PillowWriter), and also as an MP4 when ffmpeg is on the PATH.

On the axle (`load_window`: the heard run's fields over its last periods, `roller -output F.h5 -output_start T`) there is
no unseeded twin: the steady rolling state is steady in the lab, so it is the lab deformation R(theta) xi's mean over the
window at fixed lab points (Eulerian: each frame's interpolated from its rotated mesh onto the reference vertices,
averaged), and the vibration is each frame's lab deformation less that mean at the frame's own vertex places;
the frame's angle theta (the motor's, with the hub's own motion in the displacement) is the rotation that takes x + xi
to x + displacement_lab, fitted over the vertices.
"""
import math
import shutil

import numpy as np

MAGNIFIED_TO = 0.06
STATE_COLOURS = {1: "tab:blue", 2: "tab:red"}
STATE_NAMES = {1: "stick", 2: "slip"}


def load(h5, base_h5=None, frames=120):
    """The frames' data: {t, x (vertices), cells, omega, theta_start, r_outer, xi [k, n, 2] steady part, dxi [k, n, 2]
    the vibration, speed [k, n] its speed, state [k, n] or None, reference: how the vibration was taken}."""
    import h5py

    with h5py.File(h5, "r") as f:
        par = dict(f["parameters"].attrs) if "parameters" in f else {}
        g = f["vertex_fields"]
        xi = g["displacement_displacement"][:][:, :, :2]
        vel = g["velocity_displacement"][:][:, :, :2] if "velocity_displacement" in g else None
        cs = next((g[k][:] for k in g if k.startswith("contact_state")), None)
        out = {"t": f["time"][:].ravel()[: len(xi)], "x": f["geometry/vertices"][:][:, :2], "cells": f["viz/topology/cells"][:],
               "omega": float(np.ravel(par.get("omega", 0.0))[0]), "theta_start": float(np.ravel(par.get("theta_start", 0.0))[0]),
               "r_outer": float(np.ravel(par.get("r_outer", 0.0))[0])}
    base = None
    if base_h5:
        try:
            with h5py.File(base_h5, "r") as f:
                bt = f["time"][:].ravel()
                g = f["vertex_fields"]
                if len(bt) >= len(out["t"]) and np.allclose(bt[: len(out["t"])], out["t"], rtol=0, atol=1e-9 * max(1.0, abs(out["t"][-1]))):
                    base = (g["displacement_displacement"][: len(xi)][:, :, :2],
                            g["velocity_displacement"][: len(xi)][:, :, :2] if "velocity_displacement" in g else None)
        except (OSError, KeyError):
            base = None
    if base is not None:
        steady, dxi = base[0], xi - base[0]
        dv = vel - base[1] if vel is not None and base[1] is not None else None
        out["reference"] = "the seeded run minus the unseeded run (transient_base.h5): the seed's response"
    else:
        steady, dxi = np.repeat(xi[:1], len(xi), axis=0), xi - xi[:1]
        dv = vel
        out["reference"] = "the displacement less its first stored step (no transient_base.h5)"
    if dv is None:  # from the displacement's differences
        dt = np.gradient(out["t"]) if len(out["t"]) > 1 else np.ones(1)
        dv = np.gradient(dxi, axis=0) / dt[:, None, None] if len(xi) > 1 else np.zeros_like(dxi)
    keep = np.unique(np.linspace(0, len(xi) - 1, min(frames, len(xi))).round().astype(int))
    out.update(t=out["t"][keep], xi=steady[keep], dxi=dxi[keep], speed=np.hypot(dv[keep, :, 0], dv[keep, :, 1]),
               state=cs[keep] if cs is not None else None)
    return out


def _interpolator(x, cells, values):
    """values on the vertices x of the triangles cells as a function of points at ([m, 2]), linear; a point outside the
    mesh (the polygonal boundary turned) takes its nearest vertex's value. Built once, evaluated at many point sets."""
    from matplotlib.tri import LinearTriInterpolator, Triangulation

    tri = Triangulation(x[:, 0], x[:, 1], cells)
    parts = [LinearTriInterpolator(tri, values[:, c]) for c in range(values.shape[1])]

    def at_points(at):
        out = np.stack([np.ma.filled(f(at[:, 0], at[:, 1]), np.nan) for f in parts], axis=1)
        for i in np.where(np.isnan(out).any(axis=1))[0]:
            out[i] = values[np.argmin(np.hypot(x[:, 0] - at[i, 0], x[:, 1] - at[i, 1]))]
        return out

    return at_points


def load_window(h5, frames=160):
    """The frames of a run's fields over a window (the axle's heard run, module docstring): the same keys as load, with
    theta [k] the frame's angle, xi the steady lab state and dxi the vibration turned back into the frame (so that
    R(theta) (x + xi + m dxi) is the lab picture magnified m times)."""
    import h5py

    with h5py.File(h5, "r") as f:
        par = dict(f["parameters"].attrs) if "parameters" in f else {}
        g = f["vertex_fields"]
        n = len(f["time"][:].ravel())
        keep = np.unique(np.linspace(0, n - 1, min(frames, n)).round().astype(int))
        xi = g["displacement_displacement"][:][keep][:, :, :2]
        lab = g["displacement_lab_displacement"][:][keep][:, :, :2]
        cs = next((g[k][:][keep] for k in g if k.startswith("contact_state")), None)
        t = f["time"][:].ravel()[keep]
        x, cells = f["geometry/vertices"][:][:, :2], f["viz/topology/cells"][:]
    a, b = x[None] + xi, x[None] + lab
    theta = np.arctan2(np.sum(a[..., 0] * b[..., 1] - a[..., 1] * b[..., 0], axis=1), np.sum(a[..., 0] * b[..., 0] + a[..., 1] * b[..., 1], axis=1))
    placed = [_rotate(x, th) for th in theta]  # each frame's vertices in the lab, undeformed
    lab = np.array([_rotate(u, th) for u, th in zip(xi, theta)])  # the deformation in the lab: R(theta) xi (no rigid turn)
    steady = np.mean([_interpolator(p, cells, u)(x) for p, u in zip(placed, lab)], axis=0)  # at the fixed lab points x
    at = _interpolator(x, cells, steady)  # one interpolant of the steady state, at each frame's vertices
    here = np.array([at(p) for p in placed])
    vib = lab - here
    dt = np.gradient(t) if len(t) > 1 else np.ones(1)
    dv = np.gradient(vib, axis=0) / dt[:, None, None] if len(t) > 1 else np.zeros_like(vib)
    back = lambda v, th: _rotate(v, -th)  # noqa: E731  lab vectors into the frame
    return {"t": t, "x": x, "cells": cells, "omega": float(np.ravel(par.get("omega", 0.0))[0]), "theta_start": 0.0,
            "r_outer": float(np.ravel(par.get("r_outer", 0.0))[0]), "theta": theta,
            "xi": np.array([back(u, th) for u, th in zip(here, theta)]), "dxi": np.array([back(u, th) for u, th in zip(vib, theta)]),
            "speed": np.hypot(dv[..., 0], dv[..., 1]), "state": cs,
            "reference": "the heard run's lab deformation less its mean over the window at fixed lab points (the steady "
                         f"rolling state), over its last {t[-1] - t[0]:.4g} units of time"}


def _angle(data, k):
    return float(data["theta"][k]) if "theta" in data else data["omega"] * max(float(data["t"][k]) - data["theta_start"], 0.0)


def _rotate(p, th):
    c, s = math.cos(th), math.sin(th)
    return np.stack([c * p[:, 0] - s * p[:, 1], s * p[:, 0] + c * p[:, 1]], axis=1)


def write(data, stem, seconds_per_unit=1.0, sound=None, fps=10, title="", t_origin=None):
    """The animation at stem.gif (and stem.mp4 with ffmpeg). sound: (t_audio in s, pressure in Pa) at the listener,
    drawn under the roller over the frames' span with the frame's time marked; t_origin: the simulated time of the
    sound's first sample (default the first frame's). Returns {files, frames, magnification, reference}."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from matplotlib import animation
    from matplotlib.tri import Triangulation

    x, cells, r = data["x"], data["cells"], data["r_outer"] or float(np.max(np.hypot(data["x"][:, 0], data["x"][:, 1])))
    top = float(np.max(np.hypot(data["dxi"][..., 0], data["dxi"][..., 1])))
    mag = MAGNIFIED_TO * r / top if top > 0 else 1.0
    vmax = float(np.percentile(data["speed"], 99.5)) or float(np.max(data["speed"])) or 1.0  # a spike does not set it
    contact = data["state"] is not None and np.any(data["state"] > 0)
    fig = plt.figure(figsize=(9, 6.2))
    grid = fig.add_gridspec(2, 2, height_ratios=(3, 1.1), width_ratios=(1, 1))
    ax, az, ap = fig.add_subplot(grid[0, 0]), fig.add_subplot(grid[0, 1]), fig.add_subplot(grid[1, :])
    t_audio = (data["t"] - (data["t"][0] if t_origin is None else t_origin)) * seconds_per_unit
    if sound is not None:
        ts, p = np.asarray(sound[0]), np.asarray(sound[1])
        span = (ts >= t_audio[0] - 0.02 * np.ptp(t_audio)) & (ts <= t_audio[-1] + 0.02 * np.ptp(t_audio))
        ap.plot(ts[span] * 1e3, p[span], lw=0.6, color="0.3")
        ap.set_ylabel("p at the listener (Pa)", fontsize=8)
    ap.set_xlabel("time (ms of the sound: simulated time x seconds per unit)", fontsize=8)
    cursor = ap.axvline(t_audio[0] * 1e3, color="C3", lw=1.2)
    if len(t_audio) > 1:  # the frames' span (the sound may be longer: on the axle the frames are its last periods)
        ap.set_xlim(t_audio[0] * 1e3, t_audio[-1] * 1e3)
    if contact:  # the window around every frame's contact vertices, in the lab
        pts = [_rotate(x[st > 0], _angle(data, k)) for k, st in enumerate(data["state"]) if np.any(st > 0)]
        pts = np.concatenate(pts)
        w = max(float(np.ptp(pts[:, 0])), 1e-3 * r)
        box = (float(pts[:, 0].min()) - 0.6 * w, float(pts[:, 0].max()) + 0.6 * w, float(pts[:, 1].min()) - 0.15 * w, float(pts[:, 1].min()) + 0.85 * w)
    colourbar = [None]

    def draw(k):
        th = _angle(data, k)
        p = _rotate(x + data["xi"][k] + mag * data["dxi"][k], th)
        tri = Triangulation(p[:, 0], p[:, 1], cells)
        for a in (ax, az):
            a.clear()
            a.set_aspect("equal")
            a.set_axis_off()
        im = ax.tripcolor(tri, data["speed"][k], shading="gouraud", cmap="viridis", vmin=0, vmax=vmax)
        if colourbar[0] is None:
            colourbar[0] = fig.colorbar(im, ax=ax, fraction=0.04, label="vibration speed (scene units)")
        ax.axhline(-r * 1.0, color="k", lw=1)
        ax.set_xlim(-1.1 * r, 1.1 * r)
        ax.set_ylim(-1.1 * r, 1.1 * r)
        ax.set_title(f"vibration x {mag:.3g}; t = {t_audio[k] * 1e3:.3f} ms of sound", fontsize=8)
        if contact:
            near = np.all((p[cells, 0] > box[0] - (box[1] - box[0])) & (p[cells, 0] < box[1] + (box[1] - box[0])) & (p[cells, 1] < box[3] + (box[3] - box[2])), axis=1)
            if near.any():
                az.tripcolor(Triangulation(p[:, 0], p[:, 1], cells[near]), data["speed"][k], shading="gouraud", cmap="viridis", vmin=0, vmax=vmax, alpha=0.6)
            st = data["state"][k]
            for v, col in STATE_COLOURS.items():
                on = st == v
                if on.any():
                    az.plot(p[on, 0], p[on, 1], "o", ms=4, color=col, label=f"{STATE_NAMES[v]} ({int(on.sum())})")
            if np.any(st > 0):
                az.axhline(float(p[st > 0, 1].min()), color="k", lw=1.5)
                az.legend(loc="upper right", fontsize=7)
            az.set_xlim(box[0], box[1])
            az.set_ylim(box[2], box[3])
            az.set_title("the contact patch: stick (blue) and slip (red) vertices", fontsize=8)
        cursor.set_xdata([t_audio[k] * 1e3] * 2)
        return []

    if title:
        fig.suptitle(title, fontsize=9)
    anim = animation.FuncAnimation(fig, draw, frames=len(data["t"]))
    files = [f"{stem}.gif"]
    anim.save(files[0], writer=animation.PillowWriter(fps=fps))
    if shutil.which("ffmpeg"):
        try:
            anim.save(f"{stem}.mp4", writer=animation.FFMpegWriter(fps=fps, codec="libx264", extra_args=["-pix_fmt", "yuv420p"]))
            files.append(f"{stem}.mp4")
        except (OSError, RuntimeError, ValueError):
            pass
    plt.close(fig)
    return {"files": files, "frames": len(data["t"]), "magnification": mag, "reference": data["reference"], "fps": fps}
