"""What a listener hears (docs/squeal.md 9.3): the transient's surface motion radiated to the listener
(rollerreport.radiation), written as squeal.wav of the simulated span at a stated level (rollerreport.sound) and at
full precision as sound.csv (t in s of audio, p and the A-weighted p_a in Pa: the 16-bit WAV's step is 3.7 dB SPL
at its 94 dB full scale; p_response: the seed's response radiated, the seeded run's orders minus the unseeded
run's, when transient_base.csv is there), its levels in dB SPL and dB(A) (the mode's line: p_response within 20 %
of the pitch), its spectrogram.

The surface's orders come from what the folder holds:
- transient.csv's R (the mean radial displacement of Gamma_C): order 0, the breathing of the roller, always;
- surface.csv (`roller -monitor_surface_csv`, when the roller has it): the lab-frame orders n >= 1 of the radial
  displacement of Gamma_C, columns ur<n>c, ur<n>s;
With `-axle` the displacement is the body's whole motion in the motor's frame, the hub's translation included (the
nodes of Gamma_D move with the hub: docs/model.md section 10): the surface's orders already carry the hub's bounce.
Tangential motion (alpha, the torsional mode; the sheet's in-plane speed) has no normal velocity and is silent in
this model. The mesh's lines (rollerreport.lines) are removed from each series first.
"""
import csv
import math
import os

import numpy as np

from . import lines, radiation, sound

DEFAULT_WIDTH = 0.030  # m: the printer roller's (docs/squeal.md 7.1: a 30 mm wide roller)


def listener(scene):
    """The listener: distance (m), the roller's width (m), the direction (degrees; 90 above the roller) from
    scene.json's "listener", else the defaults (1 m: ISO 7779 / ECMA-74's bystander; 30 mm)."""
    given = scene.get("listener") or {}
    return {"distance_m": float(given.get("distance_m", radiation.DEFAULT_LISTENER["distance_m"])),
            "width_m": float(given.get("width_m", DEFAULT_WIDTH)),
            "angle_deg": float(given.get("angle_deg", radiation.DEFAULT_LISTENER["angle_deg"])),
            "air": {"density_kg_m3": radiation.RHO_AIR, "sound_speed_m_s": radiation.C_AIR},
            "model": "2-D exact cylinder radiation per circumferential order x the finite-width factor of a line of "
                     "monopoles, free field (docs/squeal.md 9.3)"}


def _columns(path, names):
    with open(path, newline="") as f:
        rows = list(csv.DictReader(f))[1:]  # row 0: the state before the first contact solve
    have = [n for n in names if rows and n in rows[0]]
    return {n: np.array([float(r[n]) for r in rows]) for n in ["t"] + have}


def surface_orders(folder, f_m=None, keep=None, base=False, files=None):
    """(t, {n: (cos part, sin part)} in scene length units, source {file, columns}) from the folder's files (base: the
    unseeded run's, transient_base.csv and surface_base.csv; files: another run's (monitor CSV, surface CSV), e.g. the
    stick-slip run's stickslip.csv and stickslip_surface.csv)."""
    j = lambda name: os.path.join(folder, name)  # noqa: E731
    tcsv, scsv = files or (("transient_base.csv", "surface_base.csv") if base else ("transient.csv", "surface.csv"))
    cols = _columns(j(tcsv), ["R"])
    t = cols["t"]
    clean = lambda y: lines.notch(t, y, f_m, keep=keep)  # noqa: E731  (mean-free, the mesh's lines removed)
    orders = {0: (clean(cols["R"]), None)}
    source = {"file": tcsv, "columns": ["R"]}
    if os.path.exists(j(scsv)):
        with open(j(scsv), newline="") as f:
            head = next(csv.reader(f))
        names = [h for h in head if h.startswith("ur") and h[-1] in "cs"]
        surf = _columns(j(scsv), names)
        if len(surf["t"]) == len(t) and np.allclose(surf["t"], t):
            for n in sorted({int(h[2:-1]) for h in names}):
                orders[n] = (clean(surf.get(f"ur{n}c", np.zeros_like(t))), clean(surf.get(f"ur{n}s", np.zeros_like(t))))
            source = {"file": scsv, "columns": ["ur0"] + names}
    return t, orders, source


def response(folder, t, orders, f_m=None, keep=None):
    """The seed's response: the seeded run's orders minus the unseeded run's (transient_base.csv, surface_base.csv:
    the same times and the same orders), or None."""
    if not os.path.exists(os.path.join(folder, "transient_base.csv")):
        return None
    tb, ob, _ = surface_orders(folder, f_m, keep, base=True)
    if len(tb) != len(t) or not np.allclose(tb, t) or set(ob) != set(orders):
        return None
    sub = lambda a, b: None if a is None else a - b  # noqa: E731
    return {n: (orders[n][0] - ob[n][0], sub(orders[n][1], ob[n][1])) for n in orders}


def uniform(t, orders):
    """The series on a uniform grid of the mean step (the monitor's rows are uniform at a fixed -ts_dt)."""
    dt = (t[-1] - t[0]) / (len(t) - 1)
    tu = t[0] + dt * np.arange(len(t))
    if np.allclose(tu, t, rtol=0, atol=1e-6 * dt):
        return t, orders
    f = lambda y: None if y is None else np.interp(tu, t, y)  # noqa: E731
    return tu, {n: (f(c), f(s)) for n, (c, s) in orders.items()}


def write(folder, scene, v, f_m=None, seeded=True, files=None, note=None):
    """squeal.wav, spectrogram.png and the levels; returns the sound's dict for report.json. v: {seconds_per_unit,
    frequency (per unit time), pitch_hz}; files: the (monitor CSV, surface CSV) radiated (default the seeded
    transient's, with the seed's response from the unseeded run's); note: the level's note (default the seed's)."""
    import h5py

    j = lambda name: os.path.join(folder, name)  # noqa: E731
    s = float(v["seconds_per_unit"])
    L = float(scene.get("metres_per_unit", 1.0 if scene.get("units") == "si" else math.nan))
    r_outer = scene.get("r_outer")
    if r_outer is None and os.path.exists(j("transient.h5")):
        with h5py.File(j("transient.h5"), "r") as f:
            r_outer = float(np.ravel(f["parameters"].attrs["r_outer"])[0])
    lis = listener(scene)
    t, orders, source = surface_orders(folder, f_m, keep=v["frequency"], files=files)
    seed = None if files else response(folder, t, orders, f_m, keep=v["frequency"])
    t, orders = uniform(t, orders)
    ts = (t - t[0]) * s
    metres = lambda o: {n: (c * L, None if sn is None else sn * L) for n, (c, sn) in o.items()}  # noqa: E731
    p = radiation.radiate(ts, metres(orders), float(r_outer) * L, lis["distance_m"], lis["width_m"], lis["angle_deg"])
    # the mode's own sound: the seed's response radiated (else the seeded run's), within 20 % of the pitch
    pr = radiation.radiate(ts, metres(uniform(t, seed)[1]), float(r_outer) * L, lis["distance_m"], lis["width_m"],
                           lis["angle_deg"]) if seed is not None else p
    wav = sound.write_pressure_wav(j("squeal.wav"), ts, p)
    leq, lmax = radiation.level_db(p, ts)
    pa = radiation.a_weighted(ts, p)
    leq_a, lmax_a = radiation.level_db(pa, ts)
    with open(j("sound.csv"), "w", newline="") as f:  # the pressure at full precision (the WAV is 16 bit)
        w = csv.writer(f)
        w.writerow(["t", "p", "p_a", "p_response"])
        w.writerows(zip(ts.tolist(), p.tolist(), pa.tolist(), pr.tolist()))
    pm = radiation.band(ts, pr, 0.8 * v["pitch_hz"], 1.2 * v["pitch_hz"])  # the mode's line: within 20 % of its pitch
    mode_db = radiation.level_db(pm, ts)[1]
    rate_p = 1.0 / (ts[1] - ts[0])
    at = sound.loudest_line(pr, rate_p, fmin=0.8 * v["pitch_hz"], pad=64, fmax=1.2 * v["pitch_hz"])
    # the band's loudest line is the mode's: within the span's resolution 1/T of the pitch, and not the band's edge
    # (a short span's lines are 1/T wide, and the radiation's rise with frequency tilts them up)
    res = 1.0 / (ts[-1] - ts[0])
    resolved = abs(at - v["pitch_hz"]) < res and 0.8 * v["pitch_hz"] + 0.5 * res < at < 1.2 * v["pitch_hz"] - 0.5 * res
    mode_dba = mode_db + float(radiation.a_weighting_db(v["pitch_hz"]))
    samples, rate = sound.read_wav(j("squeal.wav"))
    loud = sound.loudest_line(samples, rate, pad=8) if np.any(samples) else math.nan
    sound.spectrogram_png(j("spectrogram.png"), wav["samples"], rate, v["pitch_hz"],
                          f"The sound at {lis['distance_m']:g} m ({lis['width_m'] * 1e3:g} mm wide roller): "
                          f"Lmax {lmax:.1f} dB, {lmax_a:.1f} dB(A)")
    note = note if note is not None else ("the seeded transient's level is that of its seed (-ic_amplitude, 2 % of the depth by default): what a "
            "disturbance of that size in the mode sounds like, not a level the roller reaches by itself" if seeded else "")
    return {"spl_db": lmax, "spl_leq_db": leq, "spl_dba": lmax_a, "spl_leq_dba": leq_a, "loudest_hz": loud,
            "spl_mode_db": mode_db, "spl_mode_dba": mode_dba, "mode_band_hz": [0.8 * v["pitch_hz"], 1.2 * v["pitch_hz"]],
            "mode_line_hz": at, "mode_line_resolved": bool(resolved),
            "mode_source": "the seed's response (the seeded run minus the unseeded run)" if seed is not None else "the seeded run",
            "wav_seconds": wav["seconds"], "notice": wav["notice"], "level_note": note,
            "wav_reference": {"full_scale_db_spl": wav["full_scale_db"], "full_scale_peak_pa": wav["full_scale_pa"],
                              "peak_pa": wav["peak_pa"], "rate": rate},
            "wav_source": {"file": source["file"], "column": ",".join(source["columns"]), "t0": float(t[0]),
                           "t1": float(t[-1]), "seconds_per_unit": s, "metres_per_unit": L},
            "listener": lis, "orders": sorted(orders), "series": (ts, p)}


def force_scale(scene):
    """Newtons per metre of width per unit of the scene's force per unit width: 1 in SI scenes; a non-dimensional
    scene heard at the reference rubber (rollerreport.run: the printer roller's density and the time and length
    scales' speed, stress = rho (L/s)^2) has scene.json's "newtons_per_metre_per_unit"."""
    if scene.get("units") == "si":
        return 1.0
    return float(scene.get("newtons_per_metre_per_unit", math.nan))


def pressure(folder, scene, s, monitor, surface, column="friction_force", keep=None):
    """The pressure at the listener of a run on the axle (the stick-slip or the forced run: its monitor CSV and its
    -monitor_surface_csv): the surface's orders radiated (rollerreport.radiation.radiate) plus the friction force on
    the sheet (`column`, per unit width, times the roller's width) as a compact force dipole
    (radiation.force_dipole); both without the components above a quarter of the step's rate, 1/(4 dt) (fewer than 4
    steps a period: the trapezoidal rule's undamped step-to-step ringing of the contact, an artefact), and without the
    mesh-passing lines (rollerreport.lines: the vertices of mesh.h5 crossing the patch, a discretization artefact;
    `keep`, per unit time, is never removed). Returns {t (s of audio from 0), p, p_surface, p_force, cutoff_hz,
    mesh_passing, t0, t1, source}."""
    lis = listener(scene)
    L = float(scene.get("metres_per_unit", 1.0 if scene.get("units") == "si" else math.nan))
    f_m = lines.mesh_passing(os.path.join(folder, "mesh.h5")) if os.path.exists(os.path.join(folder, "mesh.h5")) else None
    t, orders, source = surface_orders(folder, f_m, keep, files=(monitor, surface))
    cols = _columns(os.path.join(folder, monitor), [column])
    t, orders = uniform(t, orders)
    force = np.interp(t, cols["t"], cols[column]) if column in cols else np.zeros_like(t)
    force = lines.notch(t, force, f_m, keep=keep) if f_m else force
    ts = (t - t[0]) * s
    metres = {n: (c * L, None if sn is None else sn * L) for n, (c, sn) in orders.items()}
    cut = 1.0 / (4 * (ts[1] - ts[0]))
    p_s = radiation.band(ts, radiation.radiate(ts, metres, float(scene["r_outer"]) * L, lis["distance_m"], lis["width_m"],
                                               lis["angle_deg"]), 0.0, cut)
    p_f = radiation.band(ts, radiation.force_dipole(ts, force * force_scale(scene) * lis["width_m"], lis["distance_m"],
                                                    lis["angle_deg"]), 0.0, cut)
    return {"t": ts, "p": p_s + p_f, "p_surface": p_s, "p_force": p_f, "cutoff_hz": cut, "mesh_passing": f_m, "t0": float(t[0]),
            "t1": float(t[-1]), "source": source, "column": column}


def line_level(ts, p, f_hz, band=0.2):
    """The loudest 125 ms level (dB SPL) of p within `band` of f_hz."""
    return radiation.level_db(radiation.band(ts, p, (1 - band) * f_hz, (1 + band) * f_hz), ts)[1]


def write_cycle(folder, scene, s, pitch_hz, monitor="stickslip.csv", surface="stickslip_surface.csv",
                column="friction_force", full_scale_db=None):
    """squeal.wav, sound.csv and spectrogram.png of a run on the axle (rollerreport.heard.pressure: the surface and the
    friction force's dipole at the listener) over its whole simulated span at the stated level (rollerreport.sound);
    returns the sound's dict for report.json (the keys of `write`'s) with the WAV's own pitch (rollerreport.cycle's
    autocorrelation over its last two thirds)."""
    from . import cycle

    j = lambda name: os.path.join(folder, name)  # noqa: E731
    lis = listener(scene)
    pr = pressure(folder, scene, s, monitor, surface, column, keep=pitch_hz * s)
    ts, p = pr["t"], pr["p"]
    lis["model"] += ("; plus the friction force on the sheet as a compact force dipole, cos(angle from the sheet) / "
                     "(4 pi c d) dF/dt (docs/squeal.md 9.4)")
    db = float(full_scale_db if full_scale_db is not None else scene.get("wav_full_scale_db", sound.FULL_SCALE_DB))
    wav = sound.write_pressure_wav(j("squeal.wav"), ts, p, full_scale_db=db)
    leq, lmax = radiation.level_db(p, ts)
    pa = radiation.a_weighted(ts, p)
    leq_a, lmax_a = radiation.level_db(pa, ts)
    with open(j("sound.csv"), "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["t", "p", "p_a", "p_surface", "p_force"])
        w.writerows(zip(ts.tolist(), p.tolist(), pa.tolist(), pr["p_surface"].tolist(), pr["p_force"].tolist()))
    samples, rate = sound.read_wav(j("squeal.wav"))
    k = len(samples) // 3
    wav_pitch = cycle.fundamental(samples[k:], rate, fmin=max(1.0, 0.25 * pitch_hz), fmax=min(0.5 * rate, 4 * pitch_hz))
    loud = sound.loudest_line(samples, rate, pad=8, fmin=1.0) if np.any(samples) else math.nan
    line_db = line_level(ts, p, pitch_hz)
    sound.spectrogram_png(j("spectrogram.png"), wav["samples"], rate, pitch_hz,
                          f"The sound at {lis['distance_m']:g} m ({lis['width_m'] * 1e3:g} mm wide roller, "
                          f"{lis['angle_deg']:g} deg): Lmax {lmax:.1f} dB, {lmax_a:.1f} dB(A)",
                          fmax=min(pr["cutoff_hz"], 40 * pitch_hz),  # the cycle's harmonics, resolved to a quarter pitch
                          nfft=min(2 ** int(math.ceil(math.log2(4 * rate / pitch_hz))), 2 ** int(math.log2(max(len(samples) // 4, 64)))))
    levels = {"surface": radiation.level_db(pr["p_surface"], ts)[1], "force": radiation.level_db(pr["p_force"], ts)[1]}
    note = (f"the run's own level (no seed): the surface radiates {levels['surface']:.1f} dB SPL, the friction force's "
            f"dipole {levels['force']:.1f} dB SPL (cos of the listener's angle from the sheet, "
            f"{math.cos(math.radians(lis['angle_deg'])):.3f}: none above the roller); components above "
            f"{pr['cutoff_hz']:.0f} Hz (a quarter of the step's rate) removed"
            + (f", and the mesh-passing lines k x {pr['mesh_passing'] / s:.1f} Hz (a discretization artefact)" if pr["mesh_passing"] else ""))
    return {"spl_db": lmax, "spl_leq_db": leq, "spl_dba": lmax_a, "spl_leq_dba": leq_a, "loudest_hz": loud,
            "spl_mode_db": line_db, "spl_mode_dba": line_db + float(radiation.a_weighting_db(pitch_hz)),
            "mode_band_hz": [0.8 * pitch_hz, 1.2 * pitch_hz], "mode_line_hz": pitch_hz, "mode_line_resolved": True,
            "mode_source": f"{monitor} ({column}) and {surface}", "wav_pitch_hz": wav_pitch, "levels_db": levels,
            "cutoff_hz": pr["cutoff_hz"], "wav_seconds": wav["seconds"], "notice": wav["notice"], "level_note": note,
            "wav_reference": {"full_scale_db_spl": wav["full_scale_db"], "full_scale_peak_pa": wav["full_scale_pa"],
                              "peak_pa": wav["peak_pa"], "rate": rate},
            "wav_source": {"file": monitor, "column": column, "surface_file": surface,
                           "surface_columns": pr["source"]["columns"], "t0": pr["t0"], "t1": pr["t1"],
                           "seconds_per_unit": s, "metres_per_unit": scene.get("metres_per_unit"),
                           "newtons_per_metre_per_unit": force_scale(scene)},
            "listener": lis, "orders": sorted(pr["source"]["columns"])}
