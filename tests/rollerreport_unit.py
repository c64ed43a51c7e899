"""The report package scripts/rollerreport (docs/squeal.md section 9.1) on a synthetic output folder: a CEA with one
growing mode, a map over creep and friction, a transient whose contact force whirls at the CEA's frequency and a
small HDF5 file of a ring with stick and slip; no roller run. Checks the verdict, the loss-factor margin, the
friction at onset, the transient's fit, the WAV (readable by `wave`, 16 bit, 44.1 kHz, the predicted pitch its
loudest line within 2 %), and that every file is written. The contact force also carries the mesh-passing line
omega N / (2 pi) of the ring's N outer vertices, a square wave 1 to 30 times the mode's amplitude (the printer roller's jam,
docs/squeal.md 7.7): the fit and the WAV must not take it for the mode. A second folder's CEA has a real positive
eigenvalue (the worn roller's divergence): the verdict and the map must name it, unstable without a pitch. A third
folder's decaying mode is hidden in the seeded run by the start's line and noise, which the unseeded run
(transient_base.csv) has too: the report fits the seed's response, the difference."""
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
n, omega = 48, 0.1  # the ring's vertices on its outer circle pass the patch at omega n / (2 pi) (2.06 f_nd)
f_mesh = omega * n / (2 * math.pi)
force = 1.0 + 1e-3 * np.exp(sigma * t) * np.cos(2 * math.pi * f_nd * t + 0.3) + 0.03 * np.sign(np.sin(2 * math.pi * f_mesh * t))
with open(os.path.join(d, "transient.csv"), "w", newline="") as f:
    w = csv.writer(f)
    w.writerow(["step", "t", "contact_force"])
    for k in range(len(t)):
        w.writerow([k, t[k], force[k]])
import h5py  # noqa: E402

ang = 2 * math.pi * np.arange(n) / n
x = np.concatenate([0.5 * np.stack([np.cos(ang), np.sin(ang)], 1), 0.3 * np.stack([np.cos(ang), np.sin(ang)], 1)])
cells = np.array([[i, (i + 1) % n, n + i] for i in range(n)] + [[(i + 1) % n, n + (i + 1) % n, n + i] for i in range(n)])
with h5py.File(os.path.join(d, "transient.h5"), "w") as f:
    f.create_group("parameters").attrs.update({"omega": omega, "theta_start": 0.0, "r_outer": 0.5})
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
heard_mesh = f"{f_mesh * pitch / f_nd:.1f} Hz"  # on the audio scale: f / (seconds per unit)
c.check(abs(out["mesh_passing"] / f_mesh - 1) < 1e-12 and heard_mesh in open(os.path.join(d, "report.md")).read(),
        f"the mesh-passing frequency {out['mesh_passing']:.4f} (omega N / 2 pi = {f_mesh:.4f}) named in report.md at {heard_mesh}")
c.check(not v["diverges"] and v["real_growth_rate"] is None and out["divergent"] == [],
        "no real eigenvalue: no divergence in the verdict or the map")

# the jam (docs/squeal.md 7.7): a torsional mode decaying at 27.7 /s in alpha (the mean tangential displacement), the
# contact force only the mesh's square wave at 1588 Hz and a trace of the mode: the fit takes alpha and finds the mode
from rollerreport import lines  # noqa: E402

tj = np.arange(800) * 2.387e-5
jam = {"t": tj, "alpha": -5.17e-5 + 1.3e-6 * np.exp(-27.7 * tj) * np.cos(2 * math.pi * 418.9 * tj),
       "contact_force": 104.5 + 0.06 * np.sign(np.sin(2 * math.pi * 1587.9 * tj)) + 1e-3 * np.cos(2 * math.pi * 418.9 * tj)}
column, y = lines.carrier(tj, jam, 418.9, 1587.9)
fj = report.transient_fit(tj, y, 418.9)
c.check(column == "alpha" and abs(fj["frequency"] / 418.9 - 1) < 0.01 and abs(fj["growth_rate"] / -27.7 - 1) < 0.05,
        f"the jam: fitted on the {column} (alpha): {fj['frequency']:.2f} Hz (418.9), {fj['growth_rate']:.2f} /s (-27.7)")

# the seed's response (docs/squeal.md 4.4.4): as on the feeder, the leading mode decays (order 3, -0.0205 at 0.177)
# and the start excites a steady line beside it (0.1965, twice the seed) and noise, the same in the unseeded run
# (transient_base.csv): the seeded run alone is fitted to the start's line; the difference gives the mode
import shutil  # noqa: E402

d3 = tempfile.mkdtemp(prefix="rollerreport_base_")
for name in ("scene.json", "sweep.csv", "transient.h5"):
    shutil.copy(os.path.join(d, name), d3)
f3, s3 = 0.177, -0.0205
with open(os.path.join(d3, "modes.csv"), "w", newline="") as f:
    w = csv.writer(f)
    w.writerow(cols)
    w.writerow([0, s3, 2 * math.pi * f3, f3, s3, 3, "backward"])
    w.writerow([0, -0.03, 2 * math.pi * 0.23, 0.23, -0.03, 1, "forward"])
start = 2e-3 * np.cos(2 * math.pi * 0.1965 * t) + 5e-4 * np.random.default_rng(1).standard_normal(len(t))
seeded = 1e-3 * np.exp(s3 * t) * np.cos(2 * math.pi * f3 * t + 0.3)
for name, y in (("transient.csv", start + seeded), ("transient_base.csv", start)):
    with open(os.path.join(d3, name), "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["step", "t", "contact_force", "R"])
        for k in range(len(t)):
            w.writerow([k, t[k], 1.0 + 0.1 * y[k], 0.01 * y[k]])
r3 = subprocess.run([sys.executable, "-m", "rollerreport", d3], env=env, capture_output=True, text=True)
fit3 = json.load(open(os.path.join(d3, "report.json"))).get("fit", {}) if r3.returncode == 0 else {}
alone = report.transient_fit(t, start + seeded, f3)
c.check(fit3.get("response") is True and abs(fit3["frequency"] / f3 - 1) < 0.01 and abs(fit3["growth_rate"] / s3 - 1) < 0.05
        and "transient_base.csv" in open(os.path.join(d3, "report.md")).read() and abs(alone["frequency"] / f3 - 1) > 0.05,
        f"the seed's response (seeded minus transient_base.csv) fitted: {fit3.get('frequency', 0):.4f} ({f3}), "
        f"{fit3.get('growth_rate', 0):.5f} ({s3}) on the {fit3.get('column')}; the seeded run alone gives "
        f"{alone['frequency']:.4f}, {alone['growth_rate']:.5f} (the start's line)")

# a real positive eigenvalue (im = 0, frequency 0: roller's one row per real eigenvalue): a divergence, unstable
# without a pitch, beside a decaying oscillating mode; in the map at one point
dr = tempfile.mkdtemp(prefix="rollerreport_real_")
json.dump({"name": "worn", "units": "si", "kelvin_voigt_tau": 4e-6, "friction": 1.2, "creep": 0.01},
          open(os.path.join(dr, "scene.json"), "w"))
with open(os.path.join(dr, "modes.csv"), "w", newline="") as f:
    w = csv.writer(f)
    w.writerow(cols[1:])
    w.writerow([-51.6, 0, 0, -51.6, 0, "standing"])
    w.writerow([11683.0, 0, 0, 11683.0, 6, "standing"])
    w.writerow([-21.9, 2 * math.pi * 490.7, 490.7, -21.9, 0, "standing"])
with open(os.path.join(dr, "sweep.csv"), "w", newline="") as f:
    w = csv.writer(f)
    w.writerow(["case", "friction", "sheet_speed"] + cols[1:])
    for case, (mu, speed) in enumerate([(0.8, 0.2356), (1.2, 0.2356), (0.8, 0.0), (1.2, 0.0)]):
        w.writerow([case, mu, speed, -21.9, 2 * math.pi * 490.7, 490.7, -21.9, 0, "standing"])
        w.writerow([case, mu, speed, 11683.0 if case == 0 else -51.6, 0, 0, 11683.0 if case == 0 else -51.6, 6, "standing"])
r = subprocess.run([sys.executable, "-m", "rollerreport", dr], env=env, capture_output=True, text=True)
out = json.load(open(os.path.join(dr, "report.json"))) if r.returncode == 0 else {}
v, md = out.get("verdict", {}), open(os.path.join(dr, "report.md")).read() if r.returncode == 0 else ""
c.check(r.returncode == 0 and not v["squeals"] and v["diverges"] and v["unstable"] and v["real_growth_rate"] == 11683.0
        and abs(v["frequency"] - 490.7) < 1e-9 and "unstable without a pitch" in md,
        f"a real eigenvalue +11683: verdict diverges {v.get('diverges')}, squeals {v.get('squeals')}, the pitch still the "
        f"oscillating mode's {v.get('pitch_hz', 0):.1f} Hz; report.md says 'unstable without a pitch' ({r.stderr.strip()[-300:]})")
div = out.get("divergent", [])
c.check(len(div) == 1 and div[0]["friction"] == 0.8 and div[0]["sheet_speed"] == 0.2356 and div[0]["growth_rate"] == 11683.0
        and out.get("friction_onset") is None and "**diverges**" in md,
        f"the map: a divergence at {div} only, no friction at onset of squeal ({out.get('friction_onset')})")

# the loop of a short transient keeps its own line: 16 ms of a tone at 489 Hz (8 periods, decaying as the printer
# roller's order-0 mode) heard at 489 Hz, not at the nearest multiple of 1 / (loop length) (about 120 Hz apart)
tt = np.arange(801) * 2.046e-5
samples, rate = sound.audio_signal(tt, 104.5 + 0.3 * np.exp(-36 * tt) * np.cos(2 * math.pi * 489.0 * tt + 0.4))
heard = sound.loudest_line(samples, rate)
c.check(len(samples) >= rate and abs(heard / 489.0 - 1) < 0.005, f"a 16 ms tone at 489 Hz looped to {len(samples) / rate:.2f} s: loudest line {heard:.2f} Hz (0.5 %)")

# the driver's scene: units, creep, the map's grid, the audio time scale of a non-dimensional scene
from rollerreport import run  # noqa: E402

yml = os.path.join(d, "scene.yaml")
with open(yml, "w") as f:
    f.write("young: 2.0e6\nr_outer: 0.0125\nr_inner: 0.005\nomega: 19.04\nsheet_speed: 0.2356\nfriction: 0.8\n"
            "friction_static: 1.0\nfriction_decay: 0.01\nviscosity: 8.0e-6\n")
opts = run.scene_options(yml, ["-friction", "0.7", "-obstacle"])
sc = run.scene_json("s", opts, run.detect_units(opts))
c.check(sc["units"] == "si" and sc["friction"] == 0.7 and opts["obstacle"] == "true" and abs(sc["creep"] - (1 - 0.2356 / (19.04 * 0.0125))) < 1e-15
        and sc["kelvin_voigt_tau"] == 8e-6, f"scene.json of an SI scene with -friction 0.7 given: units {sc['units']}, creep {sc['creep']:.6f}, friction {sc['friction']}")
creeps, speeds, mus = run.map_grid(sc)
c.check(sc["creep"] in creeps and 1.0 in creeps and speeds[creeps.index(sc["creep"])] == 0.2356 and speeds[-1] == 0.0
        and mus == [0.35, 0.7, 1.0], f"the default map: creeps {[round(x, 5) for x in creeps]}, frictions {mus} (the static coefficient the largest)")
opts = run.scene_options(os.path.join(SOURCE, "jobs", "feed.yaml"), [])
sc = run.scene_json("feed", opts, run.detect_units(opts))
c_nd = math.sqrt(0.1 / (2 * 1.49) / 1.0)
c.check(sc["units"] == "nd" and abs(sc["seconds_per_unit"] - 0.0125 / 0.5 * c_nd / 23.6) < 1e-15 and abs(sc["creep"] - 0.01) < 1e-12,
        f"feed.yaml: units {sc['units']}, creep {sc['creep']:.6f}, {sc['seconds_per_unit']:.4g} s per unit (the printer roller's size and rubber)")
c.close()
