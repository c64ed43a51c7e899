"""The one-command squeal report (docs/squeal.md section 9.2, issue 25): `python3 -m rollerreport.run SCENE OUT` on
the printer roller (jobs/printer_roller_kelvin_voigt.yaml, SI, its own friction law) and the feeder (jobs/feed.yaml,
non-dimensional, on the coarse graded mesh of docs/squeal.md 4.2), each with a 2 x 2 map (the scene's creep and
full sliding, creep 1; the scene's friction and 0.4) on 2 ranks. Reads what the run writes and checks each file:
- commands.json: every step (CEA, map, seeded transient, report) ran and exited 0; report.md lists each command;
- report.json: the verdict is the CEA's least stable mode (largest growth rate among Im > 0 in modes.csv), squeals
  iff its growth rate > 0, the pitch its frequency in Hz (SI) or scaled by the scene's seconds per unit (nd), the
  loss-factor margin 2 sigma / omega;
- the seeded transient confirms the mode: the seed's response (the seeded run's monitor minus the unseeded run's,
  transient_base.csv) grows at the CEA's rate within 25 % (printer) / 20 % (feeder, about its stick zone with the
  two-point slip difference, docs/squeal.md 4.4.4) at its frequency within 2 %;
- sweep.csv holds the 4 cases, its case at the scene's sheet speed and friction has the CEA's largest growth rate
  (1e-6), map.png is a PNG;
- squeal.wav is readable by Python's `wave` (mono, 16 bit, 44.1 kHz), as long as the simulated span times the time
  scale (no loop); the seed's response radiated (sound.csv's p_response: the seeded run's surface orders minus the
  unseeded run's) has its loudest line within 20 % of the predicted pitch (computed here: Hann window, zero padded,
  parabolic peak) at the pitch within the span's resolution 1/T when the mode moves the surface radially (the
  feeder's order-3 wave), and none, below 0 dB SPL, when it is the torsional mode (the printer roller's);
- report.json has SPEC section 10's keys (verdict, mechanisms flutter / stick-slip / forced, spl_db, listener,
  wav_seconds, wav_source, propensity); report.html links only files of the folder;
- spectrogram.png is a PNG, the animation (vibration.gif) a GIF of several frames;
- the starts (rollerreport.divergent, on the reduced model): the scene's own start and one per divergent cell of
  sweep.csv, each classified; run to at least 4 decay times of the CEA's least stable mode; the stick-slip mechanism
  run by the scene's; the scene's start ends at the CEA's steady state (-Q/P over its last half within 5 %);
- the same command again reuses every part (journal.json) and writes the same report.json numbers."""
import csv
import json
import math
import os
import re
import struct
import subprocess
import sys
import wave

import numpy as np

from rollertest import EXE, SOURCE, Checker

c = Checker("squeal_report")
COARSE = ["-mesh_h", "0.05", "-mesh_h_contact", "0.0112", "-mesh_contact_layer", "0.0224"]
SCENES = [  # name, scene, creeps, frictions, extra roller options, growth tolerance, whether the mode is heard
    # the printer roller's least stable mode is the torsional one (order 0 standing: the surface moves tangentially,
    # which radiates nothing in the model of docs/squeal.md 9.3); the feeder's an order-3 wave, radial
    ("printer_roller", "jobs/printer_roller_kelvin_voigt.yaml", "1", "0.4", [], 0.25, False),
    ("feed", "jobs/feed.yaml", "1", "0.4", COARSE, 0.2, True),
]


def png_size(path):
    with open(path, "rb") as f:
        head = f.read(24)
    return struct.unpack(">II", head[16:24]) if head[:8] == b"\x89PNG\r\n\x1a\n" else None


def gif_frames(path):
    with open(path, "rb") as f:
        data = f.read()
    if data[:6] not in (b"GIF87a", b"GIF89a"):
        return 0
    try:
        from PIL import Image

        return Image.open(path).n_frames
    except ImportError:  # each frame has a graphic control extension
        return data.count(b"\x21\xf9\x04")


def loudest(samples, rate, band=(20.0, math.inf)):
    x = samples - samples.mean()
    m = 64 * len(x)
    spec = np.abs(np.fft.rfft(x * np.hanning(len(x)), m))
    f = np.fft.rfftfreq(m, 1.0 / rate)
    spec[(f < band[0]) | (f > band[1])] = 0
    k = int(np.argmax(spec))
    if not (0 < k < len(spec) - 1 and spec[k - 1] > 0 and spec[k + 1] > 0):  # at the band's edge: no parabola
        return f[k]
    a, b, d = np.log(spec[k - 1 : k + 2])
    return f[k] + 0.5 * (a - d) / (a - 2 * b + d) * (f[1] - f[0])


for name, scene, creeps, mus, extra, gtol, audible in SCENES:
    out = os.path.abspath(name)
    cmd = [sys.executable, "-m", "rollerreport.run", os.path.join(SOURCE, scene), out, "--roller", EXE, "--ranks", "2",
           "--creeps", creeps, "--frictions", mus, "--"] + extra
    env = dict(os.environ, PYTHONPATH=os.path.join(SOURCE, "scripts"))
    r = subprocess.run(cmd, env=env, capture_output=True, text=True)
    steps = json.load(open(os.path.join(out, "commands.json"))) if os.path.exists(os.path.join(out, "commands.json")) else []
    c.check(r.returncode == 0 and [s["step"] for s in steps] == ["cea", "map", "transient", "transient_base", "basis", "divergent_runs", "report"]
            and all(s["returncode"] == 0 for s in steps),
            f"{name}: the driver ran " + ", ".join(f"{s['step']} ({s['seconds']} s{', ' + s['error'] if s['error'] else ''})" for s in steps)
            + (f"; exit {r.returncode}: {r.stdout.strip()[-400:]} {r.stderr.strip()[-400:]}" if r.returncode else ""))
    if not os.path.exists(os.path.join(out, "report.json")):
        c.check(False, f"{name}: report.json written")
        continue
    rep = json.load(open(os.path.join(out, "report.json")))
    md = open(os.path.join(out, "report.md")).read()
    c.check(all(s["command"] in md for s in steps), f"{name}: report.md lists every step's command")

    # the verdict: the CEA's least stable mode
    with open(os.path.join(out, "modes.csv")) as f:
        modes = [m for m in csv.DictReader(f) if float(m["im"]) > 0]
    lead = max(modes, key=lambda m: float(m["growth_rate"]))
    v, sc = rep.get("cea", {}), rep["scene"]
    sigma, w = float(lead["growth_rate"]), float(lead["im"])
    f_cea = w / (2 * math.pi)
    pitch = f_cea if sc["units"] == "si" else f_cea / sc["seconds_per_unit"]
    c.check(v.get("growth_rate") == sigma and abs(v.get("frequency", 0) / f_cea - 1) < 1e-12
            and v.get("squeals") == (sigma > 0) and abs(v.get("pitch_hz", 0) / pitch - 1) < 1e-12
            and abs(v.get("loss_factor_margin", 0) - 2 * sigma / w) < 1e-12 * abs(2 * sigma / w),
            f"{name}: verdict {'squeals' if v.get('squeals') else 'does not squeal'}: mode order {lead['order']} {lead['wave']}, "
            f"growth {sigma:.5g} at {f_cea:.5g} (scene units), pitch {pitch:.1f} Hz, loss-factor margin {2 * sigma / w:+.4g}, "
            f"units {sc['units']}")
    fit = rep.get("fit", {})
    ef = fit.get("frequency", 0) / f_cea - 1
    eg = fit.get("growth_rate", 0) / sigma - 1 if sigma else math.inf
    c.check(abs(ef) < 0.02, f"{name}: transient frequency {fit.get('frequency', 0):.5g} vs CEA {f_cea:.5g}: {100 * ef:+.2f} % (2 %)")
    c.check(fit.get("response") is True and abs(eg) < gtol,
            f"{name}: the seed's response ({fit.get('column')}) grows at {fit.get('growth_rate', 0):.5g} vs CEA {sigma:.5g}: "
            f"{100 * eg:+.1f} % ({100 * gtol:.0f} %)")

    missing = [x for x in ("sweep.csv", "map.png", "squeal.wav", "spectrogram.png") if not os.path.exists(os.path.join(out, x))]
    if missing:
        c.check(False, f"{name}: written: {', '.join(missing)} missing (report.json: missing {rep.get('missing')})")
        continue

    # the map
    with open(os.path.join(out, "sweep.csv")) as f:
        rows = list(csv.DictReader(f))
    cases = {row["case"] for row in rows}
    own = [float(row["growth_rate"]) for row in rows if float(row["im"]) > 0 and float(row["sheet_speed"]) == sc["sheet_speed"]
           and float(row["friction"]) == sc["friction"]]
    g_map = max(own) if own else math.nan
    size = png_size(os.path.join(out, "map.png"))
    c.check(len(cases) == 4 and abs(g_map / sigma - 1) < 1e-6 and size is not None and min(size) > 100,
            f"{name}: sweep.csv holds {len(cases)} cases (4), at the scene's point the largest growth {g_map:.6g} (CEA {sigma:.6g}); "
            f"map.png {size}")

    # the starts (rollerreport.divergent): the scene's own start from rest and every divergent cell's of the map, on the
    # reduced model until the CEA's least stable mode has died out; the scene's ends at the CEA's steady state
    div = sorted({int(row["case"]) for row in rows if float(row["im"]) == 0 and float(row["growth_rate"]) > 0})
    with open(os.path.join(out, "divergent.csv")) as f:
        starts = list(csv.DictReader(f))
    st = json.load(open(os.path.join(out, "divergent.json")))
    decay = -max(float(m["growth_rate"]) for m in modes)
    ss = {m["kind"]: m for m in rep.get("mechanisms", [])}.get("stick-slip", {})
    mapped = sorted(int(x["map_case"]) for x in starts if x["map_case"] != "")
    c.check(starts and starts[0]["scene"] == "1" and mapped == div and all(x["status"] == "ok" for x in starts)
            and all(x["outcome"] in ("stick-slip", "growing", "irregular", "chatter", "settled") for x in starts)
            and st["t_end"] >= min(4.0 / decay, 20 * float(sc.get("ts_max_time", st["t_end"]))) and ss.get("squeals") == (starts[0]["outcome"] in ("stick-slip", "growing", "irregular")),
            f"{name}: the starts: the scene's and the map's divergent cells {div} ({mapped} run), to t = {st['t_end']:.4g} "
            f"(4 decay times of the least stable mode {4.0 / decay:.4g}): {[(x['map_case'], x['outcome']) for x in starts]}; "
            f"stick-slip {ss.get('status')}, squeals {ss.get('squeals')}")
    q_p, q_cea = float(starts[0]["friction_ratio"]), st["steady_friction_ratio"]
    c.check(abs(q_p / q_cea - 1) < 0.05, f"{name}: the scene's start ends at the CEA's steady state: -Q/P {q_p:.4f} over its "
            f"last half against {q_cea:.4f} ({100 * (q_p / q_cea - 1):+.2f} %, 5 %)")

    # the sound: the simulated span, the mode's line
    with wave.open(os.path.join(out, "squeal.wav"), "rb") as wf:
        ok = wf.getnchannels() == 1 and wf.getsampwidth() == 2 and wf.getframerate() == 44100
        rate = wf.getframerate()
        samples = np.frombuffer(wf.readframes(wf.getnframes()), dtype="<i2").astype(float)
    src = rep.get("wav_source") or {}
    span = (src.get("t1", 0) - src.get("t0", 0)) * src.get("seconds_per_unit", 0)
    snd = np.genfromtxt(os.path.join(out, "sound.csv"), delimiter=",", names=True)  # the pressure the WAV quantizes
    heard = loudest(snd["p_response"], 1.0 / (snd["t"][1] - snd["t"][0]), (0.8 * pitch, 1.2 * pitch))
    res = 1.0 / (snd["t"][-1] - snd["t"][0])  # the span's resolution: a line of 8 periods is 1/8 of its pitch wide
    info = rep.get("sound", {})
    line = (abs(heard - pitch) < res and info.get("mode_line_resolved") is True) if audible else (
        info.get("mode_line_resolved") is False and info.get("spl_mode_db", 99) < 0)
    c.check(ok and abs(len(samples) / rate - span) <= 1.5 / rate and abs(rep.get("wav_seconds", 0) - len(samples) / rate) < 1e-9
            and line,
            f"{name}: squeal.wav (mono 16 bit 44.1 kHz) {len(samples) / rate * 1e3:.2f} ms = the simulated span {span * 1e3:.2f} ms "
            f"({src.get('file')}: {src.get('column')}); the seed's response radiated (sound.csv) has its loudest line within 20 % "
            f"of the pitch at {heard:.1f} Hz, predicted {pitch:.1f} Hz: {heard - pitch:+.1f} Hz (resolution {res:.1f} Hz); "
            + (f"the mode is heard: {info.get('spl_mode_db', math.nan):.1f} dB SPL" if audible else
               f"a torsional mode is silent: no line at its pitch, {info.get('spl_mode_db', math.nan):.1f} dB SPL at most (< 0)")
            + f"; the whole sound {rep.get('spl_db', math.nan):.1f} dB SPL at 1 m")
    mech = rep.get("mechanisms", [])
    lis, prop = rep.get("listener", {}), rep.get("propensity", {})
    c.check(rep.get("verdict") in ("squeals", "does not squeal") and [m["kind"] for m in mech] == ["flutter", "stick-slip", "forced"]
            and mech[0]["status"] == "run" and mech[0]["squeals"] == (sigma > 0) and mech[1]["status"] == "run" and mech[2]["status"].startswith("not run")
            and math.isfinite(rep.get("spl_db", math.nan)) and lis.get("distance_m") == 1.0 and lis.get("width_m", 0) > 0
            and set(src) >= {"file", "column", "t0", "t1", "seconds_per_unit"} and set(prop) >= {"cases", "fraction", "by_mechanism", "ranges"},
            f"{name}: report.json: verdict {rep.get('verdict')}, mechanisms " + "; ".join(f"{m['kind']}: {m['status'][:40]}" for m in mech)
            + f", listener {lis.get('distance_m')} m, propensity {prop.get('cases')} cases")
    page = open(os.path.join(out, "report.html")).read() if os.path.exists(os.path.join(out, "report.html")) else ""
    refs = set(re.findall(r"(?:src|href)='([^']+)'", page))
    c.check("squeal.wav" in refs and all(os.path.exists(os.path.join(out, x)) for x in refs), f"{name}: report.html links {sorted(refs)}")
    size = png_size(os.path.join(out, "spectrogram.png"))
    anim = [x for x in rep["files"] if x.startswith("vibration")]
    frames = gif_frames(os.path.join(out, anim[0])) if anim and anim[0].endswith(".gif") else 0
    c.check(size is not None and min(size) > 100 and frames > 1, f"{name}: spectrogram.png {size}, animation {anim} with {frames} frames")

    # again: every part reused
    r2 = subprocess.run(cmd, env=env, capture_output=True, text=True)
    jr = json.load(open(os.path.join(out, "journal.json")))
    rep2 = json.load(open(os.path.join(out, "report.json")))
    c.check(r2.returncode == 0 and all(p.get("reused") for p in jr.values()) and rep2.get("spl_db") == rep.get("spl_db")
            and rep2.get("fit") == rep.get("fit"),
            f"{name}: the same command again reuses every part ({', '.join(f'{k} ' + ('reused' if v.get('reused') else 'RUN') for k, v in jr.items())}) "
            f"and reports the same; the first run's cost: " + ", ".join(f"{k} {v.get('cpu_seconds')} s CPU" for k, v in rep.get("cost", {}).items()))
c.close()
