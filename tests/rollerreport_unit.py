"""The report package scripts/rollerreport (docs/squeal.md section 9.1) on a synthetic output folder: a CEA with one
growing mode, a map over creep and friction, a transient whose contact force whirls at the CEA's frequency and a
small HDF5 file of a ring with stick and slip; no roller run. Checks the verdict, the loss-factor margin, the
friction at onset, the transient's fit, the WAV (readable by `wave`, 16 bit, 44.1 kHz, the predicted pitch its
loudest line within 2 %), and that every file is written."""
import csv
import json
import math
import os
import subprocess
import sys
import tempfile
import wave

import numpy as np

from rollertest import SOURCE, Checker

sys.path.insert(0, os.path.join(SOURCE, "scripts"))
from rollerreport import report, sound  # noqa: E402

c = Checker("rollerreport_unit")
d = tempfile.mkdtemp(prefix="rollerreport_")
f_nd, sigma, eta, pitch = 0.37, 0.012, 0.05, 1234.0
json.dump({"name": "synthetic", "units": "nd", "loss_factor": eta, "friction": 0.5, "creep": 0.02,
           "pitch_si_hz": pitch}, open(os.path.join(d, "scene.json"), "w"))
cols = ["case", "re", "im", "frequency", "growth_rate", "order", "wave"]
with open(os.path.join(d, "modes.csv"), "w", newline="") as f:
    w = csv.writer(f)
    w.writerow(cols)
    w.writerow([0, sigma, 2 * math.pi * f_nd, f_nd, sigma, 1, "backward"])
    w.writerow([0, -0.02, 2 * math.pi * 0.8, 0.8, -0.02, 2, "forward"])
    w.writerow([0, sigma, -2 * math.pi * f_nd, -f_nd, sigma, 1, "backward"])
with open(os.path.join(d, "sweep.csv"), "w", newline="") as f:
    w = csv.writer(f)
    w.writerow(cols + ["creep", "friction"])
    for creep in (0.01, 0.02, 0.04):
        for mu in (0.2, 0.3, 0.4, 0.5, 0.6):
            g = 0.06 * (mu - 0.35) - 0.1 * creep  # onset at mu = 0.35 + creep * 1.67
            w.writerow([0, g, 2 * math.pi * f_nd, f_nd, g, 1, "backward", creep, mu])
dt = 0.02
t = dt * np.arange(int(300 / dt))
force = 1.0 + 1e-3 * np.exp(sigma * t) * np.cos(2 * math.pi * f_nd * t + 0.3)
with open(os.path.join(d, "transient.csv"), "w", newline="") as f:
    w = csv.writer(f)
    w.writerow(["step", "t", "contact_force"])
    for k in range(len(t)):
        w.writerow([k, t[k], force[k]])
import h5py  # noqa: E402

n = 48
ang = 2 * math.pi * np.arange(n) / n
x = np.concatenate([0.5 * np.stack([np.cos(ang), np.sin(ang)], 1), 0.3 * np.stack([np.cos(ang), np.sin(ang)], 1)])
cells = np.array([[i, (i + 1) % n, n + i] for i in range(n)] + [[(i + 1) % n, n + (i + 1) % n, n + i] for i in range(n)])
with h5py.File(os.path.join(d, "transient.h5"), "w") as f:
    f.create_group("parameters").attrs.update({"omega": 1.0, "theta_start": 0.0, "r_outer": 0.5})
    f["geometry/vertices"] = x
    f["viz/topology/cells"] = cells
    f["time"] = np.linspace(0, 3, 6)[:, None]
    f["vertex_fields/displacement_displacement"] = np.zeros((6, 2 * n, 2))
    st = np.zeros((6, 2 * n))
    for k in range(6):
        ring = (np.arange(n) + k) % n
        st[k, ring[:3]], st[k, ring[3:6]] = 1, 2
    f["vertex_fields/contact_state_contact_state"] = st

env = dict(os.environ, PYTHONPATH=os.path.join(SOURCE, "scripts"))
r = subprocess.run([sys.executable, "-m", "rollerreport", d], env=env, capture_output=True, text=True)
c.check(r.returncode == 0, f"python3 -m rollerreport exits 0 ({r.stderr.strip()[-300:]})")
out = json.load(open(os.path.join(d, "report.json")))
v = out["verdict"]
c.check(v["squeals"] and abs(v["growth_rate"] - sigma) < 1e-12, f"verdict: squeals, growth {v['growth_rate']}")
c.check(abs(v["loss_factor_onset"] - (eta + 2 * sigma / (2 * math.pi * f_nd))) < 1e-12,
        f"loss factor at onset {v['loss_factor_onset']:.5f} = eta + 2 sigma / omega")
c.check(abs(v["seconds_per_unit"] - f_nd / pitch) < 1e-15, f"time scale {v['seconds_per_unit']:.4g} s per unit = f_nd / pitch")
c.check(abs(out["friction_onset"] - 0.4) < 1e-12, f"friction at onset at the scene's creep: {out['friction_onset']} (0.4)")
fit = out["fit"]
c.check(abs(fit["frequency"] / f_nd - 1) < 0.01 and abs(fit["growth_rate"] / sigma - 1) < 0.05,
        f"transient fit: f {fit['frequency']:.5f} (CEA {f_nd}), growth {fit['growth_rate']:.5f} (CEA {sigma})")
with wave.open(os.path.join(d, "squeal.wav"), "rb") as w:
    c.check(w.getnchannels() == 1 and w.getsampwidth() == 2 and w.getframerate() == 44100 and w.getnframes() >= 44100,
            f"WAV: {w.getnchannels()} channel, {8 * w.getsampwidth()} bit, {w.getframerate()} Hz, {w.getnframes()} frames")
heard = sound.loudest_line(*sound.read_wav(os.path.join(d, "squeal.wav")))
c.check(abs(heard / pitch - 1) < 0.02, f"loudest line of the WAV {heard:.1f} Hz, predicted {pitch} Hz (2 %)")
for name in ("report.md", "map.png", "spectrogram.png", "squeal.wav"):
    p = os.path.join(d, name)
    c.check(os.path.exists(p) and os.path.getsize(p) > 0, f"{name} written")
anim = [name for name in out["files"] if name.startswith("zones")]
c.check(len(anim) == 1 and os.path.getsize(os.path.join(d, anim[0])) > 0, f"animation written: {anim}")
c.check(out["missing"] == [], f"nothing missing: {out['missing']}")
c.close()
