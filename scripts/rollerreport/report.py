"""The squeal report of an output folder (docs/squeal.md section 9.1).

The folder holds what the steps of the one-command run write (any may be missing; the report says so):
- `scene.json`: {"name", "units": "si" | "nd", "loss_factor" (or "kelvin_voigt_tau" in the scene's unit of time:
  the loss factor at the mode's frequency f is then 2 pi f tau; or "rubber": "maxwell": the mode's own
  rubber_loss_factor column of modes.csv), "friction", "creep", "pitch_si_hz" (nd scenes: the
  SI pitch the predicted mode is heard at), "seconds_per_unit" (optional; else f_nd / pitch_si_hz), "sheet_speed"
  and "surface_speed" (omega r_outer: the map's sheet speeds as creeps)} (rollerreport.run writes it);
- `commands.json`: the steps as rollerreport.run ran them (listed in the report);
- `modes.csv`: the CEA (`roller -modes`; columns re, im, frequency, growth_rate, order, wave);
- `sweep.csv`: the map (`roller -modes -sweep`; the swept options as columns beside growth_rate, frequency);
- `transient.csv` and `transient.h5`: the seeded transient (monitor CSV with t and contact_force; fields);
- `transient_base.csv`: the same run unseeded (its monitor CSV): the fit is of the difference, the seed's response.

The verdict: the mode of largest growth rate sigma = Re(lambda) (frequency f = Im(lambda) / 2 pi); squeals if
sigma > 0. The margin against the rubber's damping is the loss factor the mode lacks (or has to spare),
Delta eta = 2 sigma / omega: Kelvin-Voigt damping of loss factor eta gives a mode of angular frequency omega
the decay eta omega / 2, so to first order the mode turns stable at eta_onset = eta + 2 sigma / omega. The
friction at onset is read from the map: the least swept friction at which the largest growth rate is > 0, at
the swept creep nearest the scene's.

A real eigenvalue (im = 0: roller writes one row per real eigenvalue, frequency 0, and one row of each complex pair,
im > 0) is a mode that does not oscillate. A positive one is a divergence: the steady sliding state leaves without a
pitch (the velocity weakening's stick-slip onset, docs/squeal.md 7.7). The verdict and the map name it apart from
the squeal, which is a growing oscillation.
"""
import csv
import json
import math
import os

import numpy as np

from . import divergent, heard, journal, lines, mechanisms, page, run_lines

FIXED = {"case", "re", "im", "frequency", "growth_rate", "order", "wave", "error"}


def _json(path):
    """A JSON file's content, None when it is missing."""
    if not os.path.exists(path):
        return None
    with open(path) as f:
        return json.load(f)


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


def is_real(row):
    """A real eigenvalue: Im lambda = 0 exactly (SLEPc's real arithmetic; src/modes/pep.c keeps every real one)."""
    return num(row.get("im")) == 0 and math.isfinite(num(row.get("growth_rate")))


def leading_real(rows):
    """The real eigenvalue of largest growth rate, or None."""
    real = [r for r in rows if is_real(r)]
    return max(real, key=lambda r: num(r["growth_rate"])) if real else None


def verdict(mode, scene, real=None):
    """The verdict as a dict from the leading mode's row, the scene and the leading real eigenvalue's row (a
    divergence when its growth rate is > 0: unstable without a pitch)."""
    sigma, w = num(mode["growth_rate"]), num(mode["im"])
    g_real = num(real["growth_rate"]) if real else None
    f = w / (2 * math.pi)
    eta = num(scene.get("loss_factor"), 0.0)
    if "kelvin_voigt_tau" in scene:  # Kelvin-Voigt: the loss factor at the mode's frequency, 2 pi f tau (tau and f
        eta = 2 * math.pi * abs(f) * num(scene["kelvin_voigt_tau"])  # in the scene's units of time, SI or not)
    elif scene.get("rubber") == "maxwell" and "rubber_loss_factor" in mode:  # the Maxwell rubber's loss factor of the
        eta = num(mode["rubber_loss_factor"])  # mode's shape at its frequency (docs/squeal.md 1.2)
    si = scene.get("units", "nd") == "si"
    s = num(scene.get("seconds_per_unit")) if "seconds_per_unit" in scene else (1.0 if si else f / num(scene.get("pitch_si_hz")))
    pitch = f if si else (num(scene.get("pitch_si_hz")) if "pitch_si_hz" in scene else f / s)
    return {"squeals": sigma > 0, "growth_rate": sigma, "frequency": f, "pitch_hz": pitch,
            "seconds_per_unit": s, "order": mode.get("order", ""), "wave": mode.get("wave", ""),
            "loss_factor": eta, "loss_factor_margin": 2 * sigma / w, "loss_factor_onset": eta + 2 * sigma / w,
            "real_growth_rate": g_real, "real_order": real.get("order", "") if real else "",
            "diverges": bool(real) and g_real > 0, "unstable": sigma > 0 or (bool(real) and g_real > 0)}


def drive_mode(rows, scene):
    """On the axle (modes.csv's hub_phi, docs/squeal.md 3.1): the drive's mode, the row of largest hub_phi, against
    the 1-DOF closed form of scene.json's "onedof" (rollerref.stickslip.linear_stability: the cross-check); None
    without the column."""
    have = [r for r in rows if math.isfinite(num(r.get("hub_phi")))]
    if not have:
        return None
    r = max(have, key=lambda x: num(x["hub_phi"]))
    d = {"row": rows.index(r), "growth_rate": num(r["growth_rate"]), "frequency": abs(num(r["im"])) / (2 * math.pi),
         "hub_phi": num(r["hub_phi"]), "axle_y": num(r.get("axle_y"))}
    lin = scene.get("onedof")
    if lin:
        d["one_dof_growth_rate"] = lin["growth_rate"]
        d["one_dof_frequency"] = lin["frequency"]
        d["ratio"] = d["growth_rate"] / lin["growth_rate"] if lin["growth_rate"] else math.nan
    return d


def drive_mode_line(dm):
    """The drive's mode against the 1-DOF closed form, one sentence."""
    line = (f"the drive's mode (modes.csv row {dm['row']}, the largest hub_phi): growth rate {dm['growth_rate']:+.5g} per unit "
            f"time at {dm['frequency']:.5g} cycles per unit time")
    if "one_dof_growth_rate" in dm:
        line += (f"; the 1-DOF closed form (rollerref.stickslip.linear_stability, the cross-check) {dm['one_dof_growth_rate']:+.5g} "
                 f"at {dm['one_dof_frequency']:.5g} ({100 * (dm['ratio'] - 1):+.2f} %)")
    return line


def stick_slip_lines(cyc, s, scene, stuck=0):
    """The stick-slip run's section of report.md (stuck: the CEA's steady state's stuck nodes)."""
    word = ("a sustained stick-slip limit cycle" if cyc["stick_slip"] else "a sustained oscillation without stick"
            if cyc["sustained"] else "no sustained cycle")
    md = ["## Stick-slip: the start from rest", "",
          f"stickslip.csv (the scene from rest on the axle, t = {cyc['t0']:.4g} to {cyc['t1']:.4g}), {cyc['column']} "
          f"after the motor's ramp (t >= {cyc['t_min']:.4g}): **{word}**: {cyc['why']}."]
    if math.isfinite(cyc["frequency"]):
        md += ["", f"Its pitch {cyc['frequency']:.5g} per unit time, heard at **{cyc['frequency'] / s:.2f} Hz** "
               f"({s:.4g} s per unit: {scene.get('time_scale_note', 'the scene is SI' if scene.get('units') == 'si' else 'the report time scale')})."]
    lin = scene.get("onedof")
    if lin:
        md += ["", f"The 1-DOF closed form of the scene's drive (rollerref; the CEA's cross-check): steady sliding {'stable' if lin['stable'] else 'unstable'} (growth rate {lin['growth_rate']:+.4g} "
               f"per unit time, {lin['frequency']:.4g} cycles per unit time); its start from rest: {lin.get('start_from_rest')}."
               + (f" It slides whole; the CEA's steady state rolls with {stuck} nodes stuck: the sliding closed form is not this "
                  "scene's." if stuck else "")]
    return md + [""]


def steady_stick_nodes(folder):
    """The number of stuck nodes of the CEA's steady state (steady.csv, state 1), 0 without it."""
    path = os.path.join(folder, "steady.csv")
    if not os.path.exists(path):
        return 0
    return sum(1 for r in read_rows(path) if str(r.get("state", "")).strip() in ("1", "1.0"))


def propensity_lines(prop, folder):
    """The propensity's section of report.md."""
    md = ["## Propensity", ""]
    if prop.get("status") != "run":
        return md + [prop.get("status", ""), ""]
    lo, hi = prop["confidence_95"]
    md += [f"{prop['cases']} cases (Latin hypercube, seed {prop['sampling']['seed']}, propensity.csv) over the spread "
           + ", ".join(f"{k} {a:g}-{b:g}" for k, (a, b) in prop["ranges"].items()) + f": **{100 * prop['fraction']:.1f} % "
           f"squeak** (95 % interval {100 * lo:.1f}-{100 * hi:.1f} %, Wilson); by class "
           + ", ".join(f"{k} {100 * x:.1f} %" for k, x in prop["by_class"].items()) + f". Classified by {prop['classifier']}.",
           "", "Ranked by the rank correlation with squeaking: " + ", ".join(
               f"{e['parameter']} {e['spearman']:+.2f}" for e in prop["ranking"]) + "."]
    agree, one = prop.get("agreement"), prop.get("onedof_agreement")
    if agree:
        md += ["", f"The CEA against the start from rest, case by case ({agree['cases']} cases that ran): unstable and "
               f"oscillating {agree['unstable_and_oscillating']}, unstable but settled {agree['unstable_and_settled']}, stable "
               f"but stick-slipping (bistable: only the transient sees them) {agree['stable_and_stick_slip']}."]
    if one:
        md += ["", f"The 1-DOF cross-check gives the same stick-slip verdict as the finite elements in "
               f"{one['same_stick_slip_verdict']} of {one['cases']} cases (propensity.csv, column onedof)."]
    if prop.get("validity"):
        md += ["", f"> Validity: {prop['validity']}."]
    if os.path.exists(os.path.join(folder, "propensity.png")):
        md += ["", "![propensity](propensity.png)"]
    return md + [""]


def sweep_map(rows, png, scene_x=None, scene_y=None, title="", si=False):
    """The largest growth rate per swept point (with its mode's frequency, in Hz when si; a real positive eigenvalue,
    a divergence, in place of the oscillating modes and marked "real"), drawn over the two swept options; returns
    (xname, yname, the friction at the onset of squeal at the scene's x or None, [(x, y, growth) of every point with
    a real positive eigenvalue])."""
    swept = [k for k in rows[0] if k not in FIXED]
    xname = next((k for k in swept if k != "friction"), swept[0])
    yname = "friction" if "friction" in swept else (swept[1] if len(swept) > 1 else swept[0])
    best, real = {}, {}
    for r in rows:
        key = (num(r[xname]), num(r[yname]))
        g = num(r["growth_rate"])
        if num(r.get("im")) > 0 and math.isfinite(g) and g > best.get(key, (-math.inf,))[0]:
            best[key] = (g, num(r["im"]) / (2 * math.pi))
        elif is_real(r) and g > real.get(key, -math.inf):
            real[key] = g
    divergent = sorted((x, y, g) for (x, y), g in real.items() if g > 0)
    pts = np.array([(x, y, g) for (x, y), (g, _) in best.items()])
    freq = {key: f for key, (_, f) in best.items()}
    cell = {key: max(g, real.get(key, -math.inf)) for key, (g, _) in best.items()}
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    # a grid of cells, one per swept (x, y), evenly spaced whatever the values (creeps of 0.005 and 1 side by side)
    xs, ys = np.unique(pts[:, 0]), np.unique(pts[:, 1])
    grid = np.full((len(ys), len(xs)), np.nan)
    for x, y, g in pts:
        grid[np.searchsorted(ys, y), np.searchsorted(xs, x)] = cell[(x, y)]
    fig, ax = plt.subplots(figsize=(max(5.0, 1.8 + 1.1 * len(xs)), max(3.2, 1.4 + 0.7 * len(ys))))
    lim = max(float(np.nanmax(np.abs(pts[:, 2]))), 1e-300)  # the oscillating modes' scale: a divergence saturates
    im = ax.imshow(grid, origin="lower", cmap="coolwarm", vmin=-lim, vmax=lim, aspect="auto")
    fig.colorbar(im, label="largest growth rate")
    for iy in range(len(ys)):
        for ix in range(len(xs)):
            if np.isfinite(grid[iy, ix]):
                f = freq[(xs[ix], ys[iy])]
                diverges = real.get((xs[ix], ys[iy]), -math.inf) > 0
                pitch = "real: no pitch" if diverges else (f"{f:.0f} Hz" if si else f"f {f:.3g}")
                ax.text(ix, iy, f"{grid[iy, ix]:.3g}\n" + pitch, ha="center", va="center", fontsize=8,
                        fontweight="bold" if grid[iy, ix] > 0 else "normal")
    if scene_x is not None and scene_y is not None and len(xs) and len(ys):
        ax.plot(np.argmin(np.abs(xs - scene_x)), np.argmin(np.abs(ys - scene_y)), "s", ms=28, mfc="none", mec="k", mew=2)
    ax.set_xticks(range(len(xs)), [f"{x:.3g}" for x in xs])
    ax.set_yticks(range(len(ys)), [f"{y:.3g}" for y in ys])
    ax.set_xlabel(xname)
    ax.set_ylabel(yname)
    ax.set_title((title + ": " if title else "") + "the least stable mode's growth rate" + (" (1/s)" if si else "")
                 + " and frequency;\nbold: > 0, squeals (real: diverges, stick-slip); framed: the scene", fontsize=9)
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
    return xname, yname, onset, divergent


def transient_fit(t, y, f_guess, start=None):
    """Growth rate and frequency of the line nearest f_guess in y(t) from t = start on (default: the second half)
    (matrix pencil of scripts/rollerreport/squeal_fit.py, 10 exponentials, on the mean-free signal)."""
    from . import squeal_fit

    t, y = np.asarray(t, float), np.asarray(y, float)
    m = t >= (0.5 * (t[0] + t[-1]) if start is None else start)
    step = max(1, int(m.sum()) // 400)  # the pencil's SVD is cubic in the samples: at most ~400 of them
    ys = y[m][::step]
    s, a = squeal_fit.pencil(ys - ys.mean(), step * (t[1] - t[0]), p=10)
    w = 2 * math.pi * f_guess
    k = min(range(len(s)), key=lambda i: abs(abs(s[i].imag) - w))
    return {"growth_rate": float(s[k].real), "frequency": float(abs(s[k].imag) / (2 * math.pi))}


def verdict_lines(v):
    """The report's verdict in Markdown."""
    word = "SQUEALS" if v["squeals"] else ("does not squeal, but its steady state DIVERGES" if v["diverges"] else
                                           "does not squeal")
    md = ["## Flutter: the CEA", "",
          f"The CEA: the roller **{word}**: the leading mode (order {v['order']}, {v['wave']} wave) has the growth rate "
          f"{v['growth_rate']:.4g} at the frequency {v['frequency']:.5g} (scene units), heard at "
          f"**{v['pitch_hz']:.0f} Hz**.", "",
          f"- margin against the rubber's damping: the loss factor {v['loss_factor']:.3g} "
          f"{'lacks' if v['squeals'] else 'has to spare'} {abs(v['loss_factor_margin']):.3g} "
          f"(2 sigma / omega); " + (f"the mode {'stabilizes' if v['squeals'] else 'destabilizes'} at a loss "
          f"factor of about {v['loss_factor_onset']:.3g}" if v["loss_factor_onset"] > 0 else
          "the mode is stable without the rubber's damping too (the contact alone damps it: the loss factor "
          f"at onset {v['loss_factor_onset']:.3g} would be negative)")]
    if v.get("drive_mode"):
        md += ["- on the axle, " + drive_mode_line(v["drive_mode"])]
    if v["diverges"]:
        md += [f"- **unstable without a pitch**: a real eigenvalue {v['real_growth_rate']:+.4g} (order {v['real_order']}, "
               "no frequency): a divergence, not a tone. The steady sliding state does not persist (with velocity "
               "weakening: stick-slip sets in); no pitch is predicted for it, and the modes above describe a state "
               "that does not last"]
    return md + [""]


def seed_response(j, cols):
    """(the seeded run's columns minus the unseeded run's, None) with transient_base.csv at the same times, else
    (None, why it is not used)."""
    if not os.path.exists(j("transient_base.csv")):
        return None, "transient_base.csv missing"
    rows = read_rows(j("transient_base.csv"))[1:]
    base = {k: np.array([num(r[k]) for r in rows]) for k in cols if rows and k in rows[0]}
    t = cols["t"]
    if "t" not in base or len(base["t"]) != len(t) or np.max(np.abs(base["t"] - t)) > 1e-9 * max(1.0, abs(t[-1])):
        return None, "transient_base.csv's times differ from transient.csv's"
    return {k: cols[k] - base[k] for k in cols if k != "t" and k in base}, None


def fit_lines(j, v, out):
    """The seeded transient's fit (the seed's response when transient_base.csv is there); returns the report's
    lines and sets out["fit"], out["mesh_passing"]."""
    rows = read_rows(j("transient.csv"))[1:]  # without row 0: the state before the first contact solve (force 0)
    cols = {k: np.array([num(r[k]) for r in rows]) for k in rows[0] if k == "t" or k in lines.CARRIERS}
    t, f0 = cols["t"], v["frequency"]
    response, unused = seed_response(j, cols)
    f_m = out["mesh_passing"] = lines.mesh_passing(j("transient.h5"))
    if response is not None:  # the seed's response: every line the start excites in both runs cancels
        w = t >= t[0] + 1.0 / f0  # from one period on: the seed's own start (its static part) is left out
        column, y = lines.carrier(t[w], {k: y[w] for k, y in response.items() if k in lines.CARRIERS}, f0, None)
        fit = out["fit"] = dict(transient_fit(t[w], y, f0, start=t[w][0]), column=column, response=True)
    else:
        clean = {k: lines.notch(t, y, f_m, keep=f0) for k, y in cols.items() if k != "t"}
        column, y = lines.carrier(t, clean, f0, f_m)
        fit = out["fit"] = dict(transient_fit(t, y, f0), column=column, response=False)
    s = v["seconds_per_unit"]
    how = ("the seed's response (the seeded run's column minus the unseeded run's, transient_base.csv) from one period "
           "on" if fit["response"] else f"the seeded run's second half (no unseeded run to subtract: {unused}, so every "
           "line the start excites is fitted too)")
    md = ["## Flutter: the seeded transient", "",
          f"Seeded with the leading mode, fitted on the {column}, {how}: growth {fit['growth_rate']:.4g} (CEA "
          f"{v['growth_rate']:.4g}), frequency {fit['frequency']:.5g} (CEA {f0:.5g}).", ""]
    if f_m:
        heard_at = f"{f_m / s:.1f} Hz" if s == 1 else f"{f_m:.5g} per unit of time, {f_m / s:.1f} Hz on the audio scale"
        md += [f"The mesh-passing lines (the Gamma_C vertices cross the contact patch at {heard_at}; that line and its "
               "harmonics are a discretization artefact, docs/squeal.md 7.7) are removed before the fit and the "
               "sound.", ""]
    return md


SOURCES = os.path.dirname(os.path.abspath(__file__))
PARTS = ("sound", "animation")  # the report's own parts that cost (journalled); the rest is always written


def _source_files(*names):
    return [os.path.join(SOURCES, n) for n in names]


def sound_part(folder, scene, v, out, jr):
    """squeal.wav, spectrogram.png and the levels (rollerreport.heard), journalled: reused when its inputs are the
    same. Returns the sound's dict (without the series)."""
    j = lambda name: os.path.join(folder, name)  # noqa: E731
    files = [j(f) for f in ("transient.csv", "surface.csv", "transient_base.csv", "surface_base.csv", "transient.h5",
                            "scene.json")] + _source_files(
        "heard.py", "radiation.py", "sound.py", "lines.py")
    digest = journal.inputs_hash({"part": "sound", "frequency": v["frequency"], "pitch": v["pitch_hz"]}, files)
    result = {}

    def run():
        r = heard.write(folder, scene, v, out.get("mesh_passing"))
        r.pop("series")
        result.update(r)
        return True, {"result": r}

    entry = jr.run("sound", digest, ["squeal.wav", "sound.csv", "spectrogram.png"], run, what="the sound at the listener (docs/squeal.md 9.3)")
    return entry.get("result", result)


def animation_part(folder, scene, s, snd, jr, source="transient.h5"):
    """The animation (rollerreport.animation), journalled: of the seeded transient (transient.h5 less
    transient_base.h5), or on the axle of the heard run's last periods (stickslip.h5: animation.load_window), on the
    sound's time axis."""
    from . import animation, sound

    j = lambda name: os.path.join(folder, name)  # noqa: E731
    files = [j(f) for f in (source, "transient_base.h5", "squeal.wav", "scene.json")] + _source_files("animation.py")
    digest = journal.inputs_hash({"part": "animation", "source": source}, files)

    def run():
        series = None
        if snd and os.path.exists(j("squeal.wav")):
            samples, rate = sound.read_wav(j("squeal.wav"))
            series = (np.arange(len(samples)) / rate, samples * snd["wav_reference"]["full_scale_peak_pa"] * 32768 / 32767)
        if source == "transient.h5":
            data, origin = animation.load(j("transient.h5"), j("transient_base.h5")), None
        else:  # the sound's first sample is the heard run's first row after the initial state
            data, origin = animation.load_window(j(source)), ((snd or {}).get("wav_source") or {}).get("t0")
        r = animation.write(data, j("vibration"), s, series, title=scene.get("name", ""), t_origin=origin)
        r["files"] = [os.path.basename(f) for f in r["files"]]
        return True, {"result": r}

    entry = jr.run("animation", digest, ["vibration.gif", "vibration.mp4"], run,
                   what="the roller vibrating, its stick and slip zones (docs/squeal.md 9.1)")
    return entry.get("result")


def cycle_sound_part(folder, scene, s, pitch_hz, jr):
    """squeal.wav, sound.csv and spectrogram.png of the stick-slip run (rollerreport.heard.write_cycle: its whole
    simulated span, the surface and the friction force's dipole at the listener), journalled like the sound part."""
    from . import heard

    j = lambda name: os.path.join(folder, name)  # noqa: E731
    files = [j(f) for f in ("stickslip.csv", "stickslip_surface.csv", "scene.json")] + _source_files(
        "heard.py", "radiation.py", "sound.py", "cycle.py")
    digest = journal.inputs_hash({"part": "sound", "source": "stick-slip", "s": s, "pitch": pitch_hz}, files)

    def run():
        return True, {"result": heard.write_cycle(folder, scene, s, pitch_hz)}

    entry = jr.run("sound", digest, ["squeal.wav", "sound.csv", "spectrogram.png"], run,
                   what="the stick-slip cycle's sound at the listener (docs/squeal.md 9.4)")
    return entry.get("result")


def forced_level(folder, scene, s, f):
    """The level (dB SPL, loudest 125 ms) at the listener of the forced run's sound within 20 % of the ripple's
    frequency f (per unit time) (rollerreport.heard.pressure of forced.csv and forced_surface.csv), or None."""
    from . import heard

    monitor, surface = (scene.get("ripple") or {}).get("files") or ["forced.csv", "forced_surface.csv"]
    if not os.path.exists(os.path.join(folder, surface)):
        return None
    pr = heard.pressure(folder, scene, s, monitor, surface)
    return {"spl_line_db": heard.line_level(pr["t"], pr["p"], f / s), "spl_db": radiation_level(pr)}


def radiation_level(pr):
    from . import radiation

    return radiation.level_db(pr["p"], pr["t"])[1]


def time_scale(scene, v):
    """Seconds of audio per unit of the scene's time: the CEA's (v) when it ran, else scene.json's
    "seconds_per_unit" (a non-dimensional scene; rollerreport.run --seconds-per-unit), else 1 (SI)."""
    if v is not None:
        return v["seconds_per_unit"]
    return num(scene.get("seconds_per_unit"), 1.0) if scene.get("units") != "si" else 1.0


def recorded(jr, name, keys=()):
    """The result an earlier run recorded for part `name` (journal.json), if it finished, its outputs are there and it
    has the keys this report reads (an older report's result may not)."""
    p = jr.parts.get(name) or {}
    r = p.get("result") or {}
    ok = p.get("status") == "ok" and all(os.path.exists(os.path.join(jr.folder, o)) for o in p.get("outputs", []))
    return r if ok and all(k in r for k in keys) else None


def write(folder, parts=PARTS):
    """Write report.md, report.json, report.html, map.png and, of `parts`, the sound (squeal.wav, spectrogram.png)
    and the animation (vibration.gif) into folder; returns the report's dict (report.json's content)."""
    j = lambda name: os.path.join(folder, name)  # noqa: E731
    scene = json.load(open(j("scene.json"))) if os.path.exists(j("scene.json")) else {}
    out = {"scene": scene, "files": [], "missing": []}
    jr = journal.Journal(folder)
    commands = json.load(open(j("commands.json"))) if os.path.exists(j("commands.json")) else []
    md = [f"# Squeak report: {scene.get('name', os.path.basename(os.path.abspath(folder)))}", ""]
    body = []
    v = None
    if os.path.exists(j("modes.csv")):
        rows = read_rows(j("modes.csv"))
        v = out["cea"] = verdict(leading_mode(rows), scene, leading_real(rows))
        if scene.get("axle"):
            v["drive_mode"] = drive_mode(rows, scene)
        body += verdict_lines(v)
    else:
        out["missing"].append("modes.csv")
        refused = [c for c in commands if c.get("step") == "cea" and c.get("returncode")]
        if refused:
            # roller's own reason, without PETSc's generic line before it
            out["cea_error"] = refused[0]["error"].replace("No support for this operation for this object type: ", "")
            body += ["## Flutter: the CEA", "", f"The CEA **did not run**: roller -modes stopped with: {refused[0]['error']} "
                     f"(its log: {refused[0]['log']}).", ""]
    if os.path.exists(j("sweep.csv")):
        rows = read_rows(j("sweep.csv"))
        xname = next((k for k in rows[0] if k not in FIXED and k != "friction"), None)
        if xname == "sheet_speed" and num(scene.get("surface_speed"), 0.0):  # the creep 1 - V / (omega r_outer)
            for r in rows:
                r["creep"] = repr(1.0 - num(r.pop("sheet_speed")) / num(scene["surface_speed"]))
            xname = "creep"
        scene_x = num(scene.get(xname, scene.get("creep")), None)  # e.g. "sheet_speed" when that is swept
        xname, yname, onset, diverging = sweep_map(rows, j("map.png"), scene_x, num(scene.get("friction"), None),
                                                   scene.get("name", ""), scene.get("units") == "si")
        out["files"].append("map.png")
        out["friction_onset"] = onset
        out["divergent"] = [{xname: x, yname: y, "growth_rate": g} for x, y, g in diverging]
        body += ["## Map", "", "![map](map.png)", "",
                 f"- friction at onset of squeal (scene's {xname}): {onset if onset is not None else 'none in the map'}"]
        body += [f"- **diverges** (a real positive eigenvalue: unstable without a pitch, stick-slip) at {xname} {x:.4g}, "
                 f"{yname} {y:.4g}: {g:+.4g}" for x, y, g in diverging] + [""]
    else:
        out["missing"].append("sweep.csv")
    snd = None
    s_unit = time_scale(scene, v)
    cyc = mechanisms.stick_slip_cycle(folder, scene)
    if cyc is not None:
        out["stick_slip_cycle"] = {k: x for k, x in cyc.items() if k != "crossings"}
    heard_cycle = cyc is not None and os.path.exists(j("stickslip_surface.csv")) and (
        cyc["stick_slip"] or not os.path.exists(j("transient.csv")))
    if heard_cycle and math.isfinite(cyc["frequency"]):  # the squeak the roller makes by itself: its sound is the WAV
        if "sound" in parts:
            snd = out["sound"] = cycle_sound_part(folder, scene, s_unit, cyc["frequency"] / s_unit, jr)
        else:
            snd = out["sound"] = recorded(jr, "sound", ("wav_pitch_hz", "wav_source"))
        if snd:
            out["files"] += ["squeal.wav", "sound.csv", "spectrogram.png"]
    heard_run = False
    if not (heard_cycle and math.isfinite(cyc["frequency"])) and cyc is not None and os.path.exists(j("stickslip_surface.csv")) and not os.path.exists(j("transient.csv")):
        # no stick-slip cycle: the WAV is the scene's own run from its start (the bounce, the ripple's line, a decay
        # decaying), at its level; the line looked at: the ripple's, else the CEA's least stable mode's
        rip = (scene.get("ripple") or {}).get("frequency")
        f_line = float(rip) if rip else (float(v["frequency"]) if v and v.get("frequency") else None)
        if f_line:
            snd = out["sound"] = (cycle_sound_part(folder, scene, s_unit, f_line / s_unit, jr) if "sound" in parts
                                  else recorded(jr, "sound", ("wav_pitch_hz", "wav_source")))
            heard_run, heard_cycle = bool(snd), heard_cycle and not snd
            if snd:
                out["files"] += ["squeal.wav", "sound.csv", "spectrogram.png"]
    if os.path.exists(j("transient.csv")) and v is not None and not (heard_cycle and snd):
        body += fit_lines(j, v, out)
        if "sound" in parts:
            snd = out["sound"] = sound_part(folder, scene, v, out, jr)
        else:  # not asked for: what the journal holds of an earlier run, if its files are there
            snd = out["sound"] = recorded(jr, "sound", ("spl_mode_db", "mode_line_resolved", "wav_reference", "wav_source"))
        if snd:
            out["files"] += ["squeal.wav", "sound.csv", "spectrogram.png"]
    else:
        out["missing"].append("transient.csv")
        failed = [c for c in commands if c.get("step") == "transient" and c.get("returncode")]
        if failed:
            body += ["## Flutter: the seeded transient", "", f"The seeded transient **stopped with an error**: "
                     f"{failed[0]['error']} (its log: {failed[0]['log']}).", ""]
    anim = None
    if os.path.exists(j("transient.h5")) and v is not None:
        anim = animation_part(folder, scene, s_unit, snd, jr) if "animation" in parts else recorded(jr, "animation", ("files", "reference"))
    elif os.path.exists(j("stickslip.h5")) and snd and (snd.get("wav_source") or {}).get("file") == "stickslip.csv":
        anim = (animation_part(folder, scene, s_unit, snd, jr, "stickslip.h5") if "animation" in parts
                else recorded(jr, "animation", ("files", "reference")))
    if anim:
        out["animation"] = anim
        out["files"] += anim["files"]
        body += ["## The vibration", "", f"![the roller vibrating]({anim['files'][0]})", "",
                 f"{anim['reference']}, magnified {anim['magnification']:.3g} times; {anim['frames']} frames, coloured "
                 "by the vibration's speed; the stick (blue) and slip (red) vertices of the patch; under it the sound "
                 "at the listener with the frame's time.", ""]
    elif not os.path.exists(j("transient.h5")):
        out["missing"].append("transient.h5")
    starts = divergent.read(folder)
    if starts:
        out["starts"] = {k: x for k, x in starts.items() if k != "rows"}
        out["files"].append("divergent.csv")
        body += ["## The starts: the scene's and the divergent cells'", ""] + [f"- {x}" for x in divergent.lines(starts, scene)] + [""]
    # the mechanisms and the verdict (SPEC section 10)
    forced_r = mechanisms.forced_response(folder, scene)
    stuck = steady_stick_nodes(folder)  # the CEA's steady state rolling with a stick zone: the 1-DOF's sliding is not it
    ctx = dict(folder=folder, scene=scene, verdict=v, fit=out.get("fit"), sound=snd if not (heard_cycle or heard_run) else None,
               divergent=out.get("divergent", []), seconds_per_unit=s_unit, stick_slip_cycle=cyc, steady_stuck=stuck,
               stick_slip_sound=snd if heard_cycle else None, onedof=scene.get("onedof"), forced_response=forced_r,
               forced_sound=forced_level(folder, scene, s_unit, forced_r["frequency"]) if forced_r else None,
               ripple_sweep=_json(j("ripple_sweep.json")), disturbances=_json(j("disturbances.json")), starts=starts)
    if "friction_onset" in out:
        ctx["friction_onset"] = out["friction_onset"]
    if "cea_error" in out:
        ctx["cea_error"] = out["cea_error"]
        cycle_f = [cyc["frequency"]] if cyc and cyc.get("sustained") else []  # a limit cycle's lines are stick-slip's
        ctx["run_lines"] = run_lines.read(folder, scene, s=s_unit, also=cycle_f) if scene.get("axle") else None
    out["mechanisms"] = mechanisms.evaluate(ctx)
    out["verdict"], out["verdict_complete"] = mechanisms.verdict_word(out["mechanisms"])
    out["spl_db"] = snd["spl_db"] if snd else None
    out["listener"] = snd["listener"] if snd else heard.listener(scene)
    out["wav_seconds"] = snd["wav_seconds"] if snd else 0.0
    out["wav_source"] = snd["wav_source"] if snd else None
    out["propensity"] = mechanisms.propensity(folder)
    if out["propensity"].get("status") == "run" and stuck and "agreement" not in out["propensity"]:  # the 1-DOF's cases
        out["propensity"]["validity"] = (
            f"the 1-DOF models the roller sliding on the sheet; this scene's steady state rolls with {stuck} contact "
            "nodes stuck (steady.csv), whose tangential stiffness and lack of slip the 1-DOF leaves out: its cases are "
            "classified as if the patch slid whole (the finite elements' own classification is not built)")
    by = [m["kind"] for m in out["mechanisms"] if m["status"] == "run" and m["squeals"]]
    out["squeals_by"] = by
    md += ["## Verdict", "", f"The roller **{out['verdict']}**" + (f" by {' and '.join(by)}" if by else "") + ("" if out["verdict_complete"] else
           " (from the mechanisms that ran: " + ", ".join(m["kind"] for m in out["mechanisms"] if m["status"] == "run")
           + "; not run: " + "; ".join(f"{m['kind']} ({m['status'][9:]})" for m in out["mechanisms"] if m["status"] != "run")
           + ")") + ".", ""]
    md += ["| mechanism | status | squeals | frequency (Hz) | growth (1/s) | level (dB SPL) |", "|---|---|---|---|---|---|"]
    for m in out["mechanisms"]:
        f = lambda x, spec: "-" if x is None else format(x, spec)  # noqa: E731
        md.append(f"| {m['kind']} | {m['status']} | {dict([(True, 'yes'), (False, 'no')]).get(m['squeals'], '-')} | "
                  f"{f(m['frequency_hz'], '.1f')} | {f(m['growth_rate_per_s'], '.4g')} | {f(m['spl_db'], '.1f')} |")
    md += [""] + body
    md += [x for m in out["mechanisms"] if m.get("method") for x in (
        f"## Flutter read from {m['method']}", "", *(f"- {e}" for e in m["evidence"][:2]), "")]
    if cyc is not None:
        md += stick_slip_lines(cyc, s_unit, scene, stuck)
    if snd:
        lis, src = snd["listener"], snd["wav_source"]
        pitch = v["pitch_hz"] if v is not None and not heard_cycle else snd["mode_line_hz"]
        md += ["## The sound", "", f"[squeal.wav](squeal.wav): the pressure at {lis['distance_m']:g} m from a "
               f"{lis['width_m'] * 1e3:g} mm wide roller ({lis['angle_deg']:g} degrees; {lis['model']}), radiated by "
               + (f"the friction force ({src['column']}) of {src['file']} and the surface of {src['surface_file']}" if
                  src.get("surface_file") else f"{src['column']} of {src['file']}") + ": "
               f"**{snd['spl_db']:.1f} dB SPL** (loudest 125 ms; Leq {snd['spl_leq_db']:.1f}), "
               f"{snd['spl_dba']:.1f} dB(A); loudest line {snd['loudest_hz']:.1f} Hz; the {'cycle' if heard_cycle else 'mode'}'s line (predicted {pitch:.1f} Hz, "
               f"within 20 %) {snd['spl_mode_db']:.1f} dB SPL, {snd['spl_mode_dba']:.1f} dB(A)" + ("" if snd.get("mode_line_resolved", True)
               else f" (an upper bound: no line at the pitch, the band's loudest at {snd['mode_line_hz']:.1f} Hz)") + ". "
               f"{snd['wav_seconds'] * 1e3:.1f} ms: the simulated span {src['t0']:.4g} to {src['t1']:.4g} times "
               f"{src['seconds_per_unit']:.4g} s per unit; full scale is a sine of {snd['wav_reference']['full_scale_db_spl']:g} dB SPL.", ""]
        md += [f"> {x}" for x in (snd["notice"], snd["level_note"]) if x] + ["", "![spectrogram](spectrogram.png)", ""]
    if os.path.exists(j("ripple_sweep.png")):
        md += ["## The drive's ripple swept", "", "The forced response against the ripple's frequency (ripple_sweep.csv; the "
               "forced mechanism's evidence above):", "", "![the ripple swept](ripple_sweep.png)", ""]
    if os.path.exists(j("disturbances.png")):
        md += ["## Kicks about the steady state", "", "The hub kicked against the motor by a growing fraction of its rate, "
               "from the steady state approached while sliding (disturbances.csv; the stick-slip mechanism's evidence above):",
               "", "![kicks of growing size](disturbances.png)", ""]
    md += propensity_lines(out["propensity"], folder)
    out["cost"] = jr.parts
    if jr.parts:
        md += ["## Cost", ""] + jr.cost_lines() + [""]
    if out["missing"]:
        md += ["Missing: " + ", ".join(out["missing"]), ""]
    if commands:
        out["commands"] = commands
        md += ["## Commands", "", "Each step as run (in the output folder; rollerreport.run wrote them to "
               "commands.json):", ""]
        for c in commands:
            took = f", {c['seconds']:.0f} s" if c.get("seconds") is not None else ""
            state = f" **failed**: {c['error']}" if c.get("returncode") else ""
            md += [f"- {c['step']}: {c['what']}{took}{state}", "", "      " + c["command"], ""]
    md += ["The page: [report.html](report.html).", ""]
    with open(j("report.md"), "w") as f:
        f.write("\n".join(md))
    out["files"] += ["report.md", "report.json", page.write(folder, out)]
    with open(j("report.json"), "w") as f:
        json.dump(out, f, indent=1, default=str)
    return out
