"""The rolling roller with its stick and slip zones coloured (docs/output.md: /vertex_fields/contact_state_*,
0 off the sheet, 1 stick, 2 slip), drawn in the lab frame from a transient's HDF5 output.

The animation is a GIF (matplotlib's PillowWriter) when Pillow is importable, an MP4 when ffmpeg is on the PATH,
else a PNG strip of up to `frames` panels; animate() returns the path written and says which.
"""
import importlib.util
import math
import shutil

import numpy as np

STATE_COLOURS = {0: "0.75", 1: "tab:blue", 2: "tab:red"}
STATE_NAMES = {0: "off", 1: "stick", 2: "slip"}


def frames_from_h5(path, frames=12, scale=1.0):
    """[(t, lab positions of the vertices, cells, state per vertex or None)] for up to `frames` stored steps
    spread over the run. The lab positions rotate the deformed mesh by omega (t - theta_start)."""
    import h5py

    out = []
    with h5py.File(path, "r") as f:
        par = dict(f["parameters"].attrs) if "parameters" in f else {}
        omega = float(par.get("omega", 0.0))
        t0 = float(par.get("theta_start", 0.0))
        x = f["geometry/vertices"][:][:, :2]
        cells = f["viz/topology/cells"][:]
        times = f["time"][:].ravel()
        g = f["vertex_fields"]
        xi = g.get("displacement_displacement")
        cs = next((g[k] for k in g if k.startswith("contact_state")), None)
        n = min(len(times), xi.shape[0] if xi is not None else len(times))
        for k in np.unique(np.linspace(0, n - 1, min(frames, n)).round().astype(int)):
            th = omega * max(float(times[k]) - t0, 0.0)
            m = x + (scale * xi[k][:, :2] if xi is not None else 0.0)
            c, s = math.cos(th), math.sin(th)
            p = np.stack([c * m[:, 0] - s * m[:, 1], s * m[:, 0] + c * m[:, 1]], axis=1)
            state = np.asarray(cs[k]).ravel() if cs is not None else None
            out.append((float(times[k]), p, cells, state))
    return out


def _draw(ax, frame, lim):
    t, p, cells, state = frame
    ax.clear()
    ax.triplot(p[:, 0], p[:, 1], cells, color="0.6", lw=0.3)
    if state is not None:
        for v, col in STATE_COLOURS.items():
            on = state == v
            if v and on.any():
                ax.plot(p[on, 0], p[on, 1], "o", ms=3, color=col, label=STATE_NAMES[v])
    ax.axhline(-lim * 0.98, color="k", lw=1)
    ax.set_xlim(-lim, lim)
    ax.set_ylim(-lim, lim)
    ax.set_aspect("equal")
    ax.set_axis_off()
    ax.set_title(f"t = {t:.4g}", fontsize=8)


def patch_box(frames):
    """(x0, x1, y0, y1): a window around every frame's contact vertices (state 1 or 2), or None without contact."""
    pts = [fr[1][fr[3] > 0] for fr in frames if fr[3] is not None and np.any(fr[3] > 0)]
    if not pts:
        return None
    p = np.concatenate(pts)
    x0, x1, y0 = float(p[:, 0].min()), float(p[:, 0].max()), float(p[:, 1].min())
    w = max(x1 - x0, 1e-12)
    return x0 - 0.6 * w, x1 + 0.6 * w, y0 - 0.15 * w, y0 + 0.85 * w


def _draw_zoom(ax, frame, box):
    """The contact patch enlarged: the mesh near it and its stick (blue) and slip (red) vertices on the sheet."""
    t, p, cells, state = frame
    ax.clear()
    x0, x1, y0, y1 = box
    near = np.all((p[cells, 0] > x0 - (x1 - x0)) & (p[cells, 0] < x1 + (x1 - x0)) & (p[cells, 1] < y1 + (y1 - y0)), axis=1)
    if near.any():
        ax.triplot(p[:, 0], p[:, 1], cells[near], color="0.6", lw=0.4)
    for v, col in STATE_COLOURS.items():
        on = state == v
        if v and on.any():
            ax.plot(p[on, 0], p[on, 1], "o", ms=5, color=col, label=f"{STATE_NAMES[v]} ({int(on.sum())})")
    sheet = float(p[state > 0, 1].min()) if np.any(state > 0) else y0
    ax.axhline(sheet, color="k", lw=1.5)
    ax.set_xlim(x0, x1)
    ax.set_ylim(y0, y1)
    ax.set_aspect("equal")
    ax.set_axis_off()
    if np.any(state > 0):
        ax.legend(loc="upper right", fontsize=7)
    ax.set_title("the contact patch (vertices)", fontsize=8)


def animate(frames, stem, fps=6):
    """The animation of frames at stem.gif (Pillow), stem.mp4 (ffmpeg) or stem_strip.png; returns (path, kind)."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    lim = 1.05 * max(float(np.max(np.abs(fr[1]))) for fr in frames)
    have_pil = importlib.util.find_spec("PIL") is not None
    if have_pil or shutil.which("ffmpeg"):
        from matplotlib import animation

        box = patch_box(frames)
        if box is None:
            fig, ax = plt.subplots(figsize=(4, 4))
            draw = lambda i: _draw(ax, frames[i], lim)  # noqa: E731
        else:  # the whole roller and its contact patch enlarged (a printer roller's patch is 6 % of its diameter)
            fig, (ax, az) = plt.subplots(1, 2, figsize=(8, 4))
            draw = lambda i: (_draw(ax, frames[i], lim), _draw_zoom(az, frames[i], box))  # noqa: E731
        anim = animation.FuncAnimation(fig, draw, frames=len(frames))
        if have_pil:
            path, writer, kind = f"{stem}.gif", animation.PillowWriter(fps=fps), "gif"
        else:
            path, writer, kind = f"{stem}.mp4", animation.FFMpegWriter(fps=fps), "mp4"
        anim.save(path, writer=writer)
        plt.close(fig)
        return path, kind
    cols = min(len(frames), 4)
    rows = (len(frames) + cols - 1) // cols
    fig, axes = plt.subplots(rows, cols, figsize=(2.5 * cols, 2.5 * rows), squeeze=False)
    for ax in axes.ravel():
        ax.set_axis_off()
    for ax, fr in zip(axes.ravel(), frames):
        _draw(ax, fr, lim)
    handles = [plt.Line2D([], [], marker="o", ls="", color=STATE_COLOURS[v], label=STATE_NAMES[v]) for v in (1, 2)]
    fig.legend(handles=handles, loc="lower center", ncol=2)
    fig.suptitle("stick (blue) and slip (red) at the contact, lab frame (no Pillow, no ffmpeg: a PNG strip)")
    fig.tight_layout(rect=(0, 0.05, 1, 0.95))
    path = f"{stem}_strip.png"
    fig.savefig(path, dpi=90)
    plt.close(fig)
    return path, "png strip"
