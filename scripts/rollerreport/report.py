"""The squeal report of an output folder (docs/squeal.md section 9.1).

The folder holds what the steps of the one-command run write (any may be missing; the report says so):
- `scene.json`: {"name", "units": "si" | "nd", "loss_factor" (or, SI scenes, "kelvin_voigt_tau" in s: the
  loss factor at the mode's frequency f is then 2 pi f tau), "friction", "creep", "pitch_si_hz" (nd scenes: the
  SI pitch the predicted mode is heard at), "seconds_per_unit" (optional; else f_nd / pitch_si_hz)};
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
    if "kelvin_voigt_tau" in scene:  # Kelvin-Voigt: the loss factor at the mode's frequency, 2 pi f tau
        eta = 2 * math.pi * abs(f) * num(scene["kelvin_voigt_tau"]) if "seconds_per_unit" not in scene and \
            scene.get("units", "nd") == "si" else eta
    si = scene.get("units", "nd") == "si"
    pitch = f if si else num(scene.get("pitch_si_hz"))
    s = num(scene.get("seconds_per_unit")) if "seconds_per_unit" in scene else (1.0 if si else f / pitch)
    return {"squeals": sigma > 0, "growth_rate": sigma, "frequency": f, "pitch_hz": pitch,
            "seconds_per_unit": s, "order": mode.get("order", ""), "wave": mode.get("wave", ""),
            "loss_factor": eta, "loss_factor_margin": 2 * sigma / w, "loss_factor_onset": eta + 2 * sigma / w}


def sweep_map(rows, png, scene_x=None):
    """The largest growth rate per swept point, drawn over the two swept options; returns (xname, yname,
    friction at onset at the scene's x or None)."""
    swept = [k for k in rows[0] if k not in FIXED]
    xname = next((k for k in swept if k != "friction"), swept[0])
    yname = "friction" if "friction" in swept else (swept[1] if len(swept) > 1 else swept[0])
    best = {}
    for r in rows:
        key = (num(r[xname]), num(r[yname]))
        g = num(r["growth_rate"])
        if num(r.get("im")) > 0 and math.isfinite(g):
            best[key] = max(best.get(key, -math.inf), g)
    pts = np.array([(x, y, g) for (x, y), g in best.items()])
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, ax = plt.subplots(figsize=(5.5, 4))
    lim = max(float(np.max(np.abs(pts[:, 2]))), 1e-300)
    sc = ax.scatter(pts[:, 0], pts[:, 1], c=pts[:, 2], cmap="coolwarm", vmin=-lim, vmax=lim, s=120, marker="s")
    fig.colorbar(sc, label="largest growth rate Re(lambda)")
    unstable = pts[:, 2] > 0
    ax.scatter(pts[unstable, 0], pts[unstable, 1], facecolors="none", edgecolors="k", s=160, marker="s")
    ax.set_xlabel(xname)
    ax.set_ylabel(yname)
    ax.set_title("squeal map (outlined: unstable)")
    fig.tight_layout()
    fig.savefig(png, dpi=100)
    plt.close(fig)
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


def write(folder, signal="contact_force"):
    """Write report.md, map.png, squeal.wav, spectrogram.png and the animation into folder; returns the
    dict of what was found and written."""
    j = lambda name: os.path.join(folder, name)  # noqa: E731
    scene = json.load(open(j("scene.json"))) if os.path.exists(j("scene.json")) else {}
    out = {"scene": scene, "files": [], "missing": []}
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
                  f"(2 sigma / omega); the mode {'stabilizes' if v['squeals'] else 'destabilizes'} at a loss factor "
                  f"of about {v['loss_factor_onset']:.3g}", ""]
    else:
        out["missing"].append("modes.csv")
    if os.path.exists(j("sweep.csv")):
        rows = read_rows(j("sweep.csv"))
        xname = next((k for k in rows[0] if k not in FIXED and k != "friction"), None)
        scene_x = num(scene.get(xname, scene.get("creep")), None)  # e.g. "sheet_speed" when that is swept
        xname, yname, onset = sweep_map(rows, j("map.png"), scene_x)
        out["files"].append("map.png")
        out["friction_onset"] = onset
        lines += ["## Map", "", f"![map](map.png)", "",
                  f"- friction at onset (scene's {xname}): {onset if onset is not None else 'none in the map'}", ""]
    else:
        out["missing"].append("sweep.csv")
    if os.path.exists(j("transient.csv")) and v is not None:
        data = {k: np.array([num(r[k]) for r in read_rows(j("transient.csv"))]) for k in ("t", signal)}
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
    if os.path.exists(j("transient.h5")):
        path, kind = zones.animate(zones.frames_from_h5(j("transient.h5")), j("zones"))
        out["files"].append(os.path.basename(path))
        lines += ["## Stick and slip", "", f"![zones]({os.path.basename(path)}) ({kind})", ""]
    else:
        out["missing"].append("transient.h5")
    if out["missing"]:
        lines += ["Missing: " + ", ".join(out["missing"]), ""]
    with open(j("report.md"), "w") as f:
        f.write("\n".join(lines))
    out["files"].append("report.md")
    with open(j("report.json"), "w") as f:
        json.dump({k: val for k, val in out.items()}, f, indent=1, default=str)
    return out
