"""The squeal report of an output folder (docs/squeal.md section 9.1).

The folder holds what the steps of the one-command run write (any may be missing; the report says so):
- `scene.json`: {"name", "units": "si" | "nd", "loss_factor" (or "kelvin_voigt_tau" in the scene's unit of time:
  the loss factor at the mode's frequency f is then 2 pi f tau), "friction", "creep", "pitch_si_hz" (nd scenes: the
  SI pitch the predicted mode is heard at), "seconds_per_unit" (optional; else f_nd / pitch_si_hz), "sheet_speed"
  and "surface_speed" (omega r_outer: the map's sheet speeds as creeps)} (rollerreport.run writes it);
- `commands.json`: the steps as rollerreport.run ran them (listed in the report);
- `modes.csv`: the CEA (`roller -modes`; columns re, im, frequency, growth_rate, order, wave);
- `sweep.csv`: the map (`roller -modes -sweep`; the swept options as columns beside growth_rate, frequency);
- `transient.csv` and `transient.h5`: the seeded transient (monitor CSV with t and contact_force; fields).

The verdict: the mode of largest growth rate sigma = Re(lambda) (frequency f = Im(lambda) / 2 pi); squeals if
sigma > 0. The margin against the rubber's damping is the loss factor the mode lacks (or has to spare),
Delta eta = 2 sigma / omega: Kelvin-Voigt damping of loss factor eta gives a mode of angular frequency omega
the decay eta omega / 2, so to first order the mode turns stable at eta_onset = eta + 2 sigma / omega. The
friction at onset is read from the map: the least swept friction at which the largest growth rate is > 0, at
the swept creep nearest the scene's.
"""
import csv
import json
import math
import os

import numpy as np

from . import sound, zones

FIXED = {"case", "re", "im", "frequency", "growth_rate", "order", "wave", "error"}


def read_rows(path):
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def num(v, default=math.nan):
    try:
        return float(v)
    except (TypeError, ValueError):
        return default


def leading_mode(rows):
    """The row of largest growth rate among modes of positive frequency (im > 0)."""
    modes = [r for r in rows if num(r.get("im")) > 0 and math.isfinite(num(r.get("growth_rate")))]
    if not modes:
        raise ValueError("no mode of positive frequency in the CEA")
    return max(modes, key=lambda r: num(r["growth_rate"]))


def verdict(mode, scene):
    """The verdict as a dict from the leading mode's row and the scene."""
    sigma, w = num(mode["growth_rate"]), num(mode["im"])
    f = w / (2 * math.pi)
    eta = num(scene.get("loss_factor"), 0.0)
    if "kelvin_voigt_tau" in scene:  # Kelvin-Voigt: the loss factor at the mode's frequency, 2 pi f tau (tau and f
        eta = 2 * math.pi * abs(f) * num(scene["kelvin_voigt_tau"])  # in the scene's units of time, SI or not)
    si = scene.get("units", "nd") == "si"
    s = num(scene.get("seconds_per_unit")) if "seconds_per_unit" in scene else (1.0 if si else f / num(scene.get("pitch_si_hz")))
    pitch = f if si else (num(scene.get("pitch_si_hz")) if "pitch_si_hz" in scene else f / s)
    return {"squeals": sigma > 0, "growth_rate": sigma, "frequency": f, "pitch_hz": pitch,
            "seconds_per_unit": s, "order": mode.get("order", ""), "wave": mode.get("wave", ""),
            "loss_factor": eta, "loss_factor_margin": 2 * sigma / w, "loss_factor_onset": eta + 2 * sigma / w}


def sweep_map(rows, png, scene_x=None, scene_y=None, title="", si=False):
    """The largest growth rate per swept point (with its mode's frequency, in Hz when si), drawn over the two swept
    options; returns (xname, yname, friction at onset at the scene's x or None)."""
    swept = [k for k in rows[0] if k not in FIXED]
    xname = next((k for k in swept if k != "friction"), swept[0])
    yname = "friction" if "friction" in swept else (swept[1] if len(swept) > 1 else swept[0])
    best = {}
    for r in rows:
        key = (num(r[xname]), num(r[yname]))
        g = num(r["growth_rate"])
        if num(r.get("im")) > 0 and math.isfinite(g) and g > best.get(key, (-math.inf,))[0]:
            best[key] = (g, num(r["im"]) / (2 * math.pi))
    pts = np.array([(x, y, g) for (x, y), (g, _) in best.items()])
    freq = {key: f for key, (_, f) in best.items()}
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    # a grid of cells, one per swept (x, y), evenly spaced whatever the values (creeps of 0.005 and 1 side by side)
    xs, ys = np.unique(pts[:, 0]), np.unique(pts[:, 1])
    grid = np.full((len(ys), len(xs)), np.nan)
    for x, y, g in pts:
        grid[np.searchsorted(ys, y), np.searchsorted(xs, x)] = g
    fig, ax = plt.subplots(figsize=(max(5.0, 1.8 + 1.1 * len(xs)), max(3.2, 1.4 + 0.7 * len(ys))))
    lim = max(float(np.nanmax(np.abs(grid))), 1e-300)
    im = ax.imshow(grid, origin="lower", cmap="coolwarm", vmin=-lim, vmax=lim, aspect="auto")
    fig.colorbar(im, label="largest growth rate")
    for iy in range(len(ys)):
        for ix in range(len(xs)):
            if np.isfinite(grid[iy, ix]):
                f = freq[(xs[ix], ys[iy])]
                ax.text(ix, iy, f"{grid[iy, ix]:.3g}\n" + (f"{f:.0f} Hz" if si else f"f {f:.3g}"), ha="center",
                        va="center", fontsize=8, fontweight="bold" if grid[iy, ix] > 0 else "normal")
    if scene_x is not None and scene_y is not None and len(xs) and len(ys):
        ax.plot(np.argmin(np.abs(xs - scene_x)), np.argmin(np.abs(ys - scene_y)), "s", ms=28, mfc="none", mec="k", mew=2)
    ax.set_xticks(range(len(xs)), [f"{x:.3g}" for x in xs])
    ax.set_yticks(range(len(ys)), [f"{y:.3g}" for y in ys])
    ax.set_xlabel(xname)
    ax.set_ylabel(yname)
    ax.set_title((title + ": " if title else "") + "the least stable mode's growth rate" + (" (1/s)" if si else "")
                 + " and frequency;\nbold: > 0, squeals; framed: the scene", fontsize=9)
    fig.tight_layout()
    fig.savefig(png, dpi=100)
    plt.close(fig)
    unstable = pts[:, 2] > 0
    onset = None
    if yname == "friction":
        xs = np.unique(pts[:, 0])
        x0 = xs[np.argmin(np.abs(xs - scene_x))] if scene_x is not None else xs[0]
        col = pts[(pts[:, 0] == x0) & unstable]
        onset = float(col[:, 1].min()) if len(col) else None
    return xname, yname, onset


def transient_fit(t, y, f_guess):
    """Growth rate and frequency of the largest line near f_guess in the second half of y(t) (matrix pencil of
    scripts/squeal_fit.py on the mean-free signal)."""
    from . import squeal_fit

    t, y = np.asarray(t, float), np.asarray(y, float)
    m = t >= 0.5 * (t[0] + t[-1])
    step = max(1, int(m.sum()) // 400)  # the pencil's SVD is cubic in the samples: at most ~400 of them
    ys = y[m][::step]
    s, a = squeal_fit.pencil(ys - ys.mean(), step * (t[1] - t[0]), p=10)
    w = 2 * math.pi * f_guess
    k = min(range(len(s)), key=lambda i: abs(abs(s[i].imag) - w))
    return {"growth_rate": float(s[k].real), "frequency": float(abs(s[k].imag) / (2 * math.pi))}


def heard_column(rows, columns=("contact_force", "friction_force")):
    """The component of the force on the sheet that the transient moves most: of the normal (contact_force) and the
    tangential (friction_force) force, the one of larger standard deviation (in force units: what excites the sheet
    and the air). A torsional mode (order 0) moves the friction force, a radial one the normal force."""
    have = [c for c in columns if c in rows[0]]
    return max(have, key=lambda c: float(np.nanstd([num(r[c]) for r in rows]))) if have else columns[0]


def write(folder, signal="auto"):
    """Write report.md, map.png, squeal.wav, spectrogram.png and the animation into folder; returns the
    dict of what was found and written. signal: the transient CSV's column heard (auto: heard_column)."""
    j = lambda name: os.path.join(folder, name)  # noqa: E731
    scene = json.load(open(j("scene.json"))) if os.path.exists(j("scene.json")) else {}
    out = {"scene": scene, "files": [], "missing": []}
    commands = json.load(open(j("commands.json"))) if os.path.exists(j("commands.json")) else []
    lines = [f"# Squeal report: {scene.get('name', os.path.basename(os.path.abspath(folder)))}", ""]
    v = None
    if os.path.exists(j("modes.csv")):
        mode = leading_mode(read_rows(j("modes.csv")))
        v = out["verdict"] = verdict(mode, scene)
        word = "SQUEALS" if v["squeals"] else "does not squeal"
        lines += ["## Verdict", "",
                  f"The roller **{word}**: the leading mode (order {v['order']}, {v['wave']} wave) has the growth rate "
                  f"{v['growth_rate']:.4g} at the frequency {v['frequency']:.5g} (scene units), heard at "
                  f"**{v['pitch_hz']:.0f} Hz**.", "",
                  f"- margin against the rubber's damping: the loss factor {v['loss_factor']:.3g} "
                  f"{'lacks' if v['squeals'] else 'has to spare'} {abs(v['loss_factor_margin']):.3g} "
                  f"(2 sigma / omega); " + (f"the mode {'stabilizes' if v['squeals'] else 'destabilizes'} at a loss "
                  f"factor of about {v['loss_factor_onset']:.3g}" if v["loss_factor_onset"] > 0 else
                  "the mode is stable without the rubber's damping too (the contact alone damps it: the loss factor "
                  f"at onset {v['loss_factor_onset']:.3g} would be negative)"), ""]
    else:
        out["missing"].append("modes.csv")
    if os.path.exists(j("sweep.csv")):
        rows = read_rows(j("sweep.csv"))
        xname = next((k for k in rows[0] if k not in FIXED and k != "friction"), None)
        if xname == "sheet_speed" and num(scene.get("surface_speed"), 0.0):  # the creep 1 - V / (omega r_outer)
            for r in rows:
                r["creep"] = repr(1.0 - num(r.pop("sheet_speed")) / num(scene["surface_speed"]))
            xname = "creep"
        scene_x = num(scene.get(xname, scene.get("creep")), None)  # e.g. "sheet_speed" when that is swept
        xname, yname, onset = sweep_map(rows, j("map.png"), scene_x, num(scene.get("friction"), None),
                                        scene.get("name", ""), scene.get("units") == "si")
        out["files"].append("map.png")
        out["friction_onset"] = onset
        lines += ["## Map", "", f"![map](map.png)", "",
                  f"- friction at onset (scene's {xname}): {onset if onset is not None else 'none in the map'}", ""]
    else:
        out["missing"].append("sweep.csv")
    if os.path.exists(j("transient.csv")) and v is not None:
        # without the monitor's row 0: the initial state, before the first contact solve (its contact force is 0)
        rows = read_rows(j("transient.csv"))[1:]
        signal = heard_column(rows) if signal == "auto" else signal
        out["signal"] = signal
        data = {k: np.array([num(r[k]) for r in rows]) for k in ("t", signal)}
        fit = out["fit"] = transient_fit(data["t"], data[signal], v["frequency"])
        samples, rate = sound.audio_signal(data["t"], data[signal], v["seconds_per_unit"])
        sound.write_wav(j("squeal.wav"), samples, rate)
        heard = out["loudest_hz"] = sound.loudest_line(*sound.read_wav(j("squeal.wav")))
        sound.spectrogram_png(j("spectrogram.png"), samples, rate, v["pitch_hz"])
        out["files"] += ["squeal.wav", "spectrogram.png"]
        lines += ["## Transient", "",
                  f"Seeded with the leading mode: growth {fit['growth_rate']:.4g} (CEA {v['growth_rate']:.4g}), "
                  f"frequency {fit['frequency']:.5g} (CEA {v['frequency']:.5g}).", "",
                  f"Sound: [squeal.wav](squeal.wav), the {signal} with time scaled by {v['seconds_per_unit']:.4g} s "
                  f"per unit; its loudest line {heard:.0f} Hz (predicted {v['pitch_hz']:.0f} Hz).", "",
                  "![spectrogram](spectrogram.png)", ""]
    else:
        out["missing"].append("transient.csv")
        failed = [c for c in commands if c.get("step") == "transient" and c.get("returncode")]
        if failed:
            lines += ["## Transient", "", f"The seeded transient **stopped with an error**: {failed[0]['error']} "
                      f"(its log: {failed[0]['log']}).", ""]
    if os.path.exists(j("transient.h5")):
        path, kind = zones.animate(zones.frames_from_h5(j("transient.h5")), j("zones"))
        out["files"].append(os.path.basename(path))
        lines += ["## Stick and slip", "", f"![zones]({os.path.basename(path)}) ({kind})", ""]
    else:
        out["missing"].append("transient.h5")
    if out["missing"]:
        lines += ["Missing: " + ", ".join(out["missing"]), ""]
    if commands:
        out["commands"] = commands
        lines += ["## Commands", "", "Each step as run (in the output folder; rollerreport.run wrote them to "
                  "commands.json):", ""]
        for c in commands:
            took = f", {c['seconds']:.0f} s" if c.get("seconds") is not None else ""
            state = f" **failed**: {c['error']}" if c.get("returncode") else ""
            lines += [f"- {c['step']}: {c['what']}{took}{state}", "", "      " + c["command"], ""]
    with open(j("report.md"), "w") as f:
        f.write("\n".join(lines))
    out["files"].append("report.md")
    with open(j("report.json"), "w") as f:
        json.dump({k: val for k, val in out.items()}, f, indent=1, default=str)
    return out
