"""The one-command squeal report (docs/squeal.md section 9.2, issue 25): `python3 -m rollerreport.run SCENE OUT` on
the printer roller (jobs/printer_roller.yaml, SI, its own friction law) and the feeder (jobs/feed.yaml,
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
- squeal.wav is readable by Python's `wave` (mono, 16 bit, 44.1 kHz, >= 1 s) and the loudest line of its spectrum
  (computed here: Hann window, zero padded, parabolic peak) is the predicted pitch within 2 %;
- spectrogram.png is a PNG, the animation a GIF of several frames."""
import csv
import json
import math
import os
import struct
import subprocess
import sys
import wave

import numpy as np

from rollertest import EXE, SOURCE, Checker

c = Checker("squeal_report")
COARSE = ["-mesh_h", "0.05", "-mesh_h_contact", "0.0112", "-mesh_contact_layer", "0.0224"]
SCENES = [  # name, scene, creeps, frictions, extra roller options, growth tolerance
    ("printer_roller", "jobs/printer_roller.yaml", "1", "0.4", [], 0.25),
    ("feed", "jobs/feed.yaml", "1", "0.4", COARSE, 0.2),
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


def loudest(samples, rate):
    x = samples - samples.mean()
    m = 8 * len(x)
    spec = np.abs(np.fft.rfft(x * np.hanning(len(x)), m))
    f = np.fft.rfftfreq(m, 1.0 / rate)
    spec[f < 20] = 0
    k = int(np.argmax(spec))
    a, b, d = np.log(spec[k - 1 : k + 2])
    return f[k] + 0.5 * (a - d) / (a - 2 * b + d) * (f[1] - f[0])


for name, scene, creeps, mus, extra, gtol in SCENES:
    out = os.path.abspath(name)
    cmd = [sys.executable, "-m", "rollerreport.run", os.path.join(SOURCE, scene), out, "--roller", EXE, "--ranks", "2",
           "--creeps", creeps, "--frictions", mus, "--"] + extra
    env = dict(os.environ, PYTHONPATH=os.path.join(SOURCE, "scripts"))
    r = subprocess.run(cmd, env=env, capture_output=True, text=True)
    steps = json.load(open(os.path.join(out, "commands.json"))) if os.path.exists(os.path.join(out, "commands.json")) else []
    c.check(r.returncode == 0 and [s["step"] for s in steps] == ["cea", "map", "transient", "transient_base", "report"]
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
    v, sc = rep.get("verdict", {}), rep["scene"]
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

    # the sound
    with wave.open(os.path.join(out, "squeal.wav"), "rb") as wf:
        ok = wf.getnchannels() == 1 and wf.getsampwidth() == 2 and wf.getframerate() == 44100 and wf.getnframes() >= 44100
        rate = wf.getframerate()
        samples = np.frombuffer(wf.readframes(wf.getnframes()), dtype="<i2").astype(float)
    heard = loudest(samples, rate)
    c.check(ok and abs(heard / pitch - 1) < 0.02,
            f"{name}: squeal.wav (mono 16 bit 44.1 kHz, {len(samples) / rate:.2f} s, the {rep.get('signal')}): loudest line "
            f"{heard:.1f} Hz, predicted {pitch:.1f} Hz: {100 * (heard / pitch - 1):+.2f} % (2 %)")
    size = png_size(os.path.join(out, "spectrogram.png"))
    anim = [x for x in rep["files"] if x.startswith("zones")]
    frames = gif_frames(os.path.join(out, anim[0])) if anim and anim[0].endswith(".gif") else 0
    c.check(size is not None and min(size) > 100 and frames > 1, f"{name}: spectrogram.png {size}, animation {anim} with {frames} frames")
c.close()
