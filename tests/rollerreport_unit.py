"""The report package scripts/rollerreport (docs/squeal.md section 9) on synthetic folders (tests/rollerreport_data.py),
no roller run:
- the radiation model (rollerreport.radiation) against the closed forms: the pulsating cylinder's radiation
  resistance rho c pi ka / 2 (ka << 1) and rho c (ka >> 1) (Morse & Ingard 7.3), the exact resistance
  2 rho c / (pi ka |H_n'(ka)|^2) against the power through a far circle, the oscillating cylinder's added mass
  rho pi a^2 and resistance rho c pi^2 a (ka)^3 / 2 (Junger & Feit 10); the finite width: the infinite width's 2-D
  field, and a short roller's point monopole (volume velocity 2 pi a W V) and point dipole (force
  2 rho pi a^2 W dU/dt); a sinusoid through radiate() at the transfer function's amplitude; IEC 61672's A-weighting;
- the report: the CEA's verdict, the loss-factor margin, the friction at onset, the transient's fit beside the
  mesh-passing square wave, the divergence of a real eigenvalue; report.json's keys of SPEC section 10 (verdict,
  mechanisms flutter / stick-slip / forced, those not computable "not run" with what they need, spl_db, listener,
  wav_seconds, wav_source, propensity);
- squeal.wav: its length the simulated span times the time scale (no loop), its loudest line the pitch, its
  envelope the transient's (a growing mode grows, a decaying one decays, at the mode's rate per second), its level
  fixed by the stated reference (a roller 10 times quieter: 20 dB lower in spl_db and a 10 times smaller WAV), the
  notice when it is shorter than 0.5 s;
- the journal: a second report reuses the sound and the animation, a changed transient redoes them;
- the seed's response fitted through transient_base.csv; a limit cycle recognized as sustained."""
import json
import math
import os
import shutil
import subprocess
import sys
import wave

import numpy as np
from scipy.special import h1vp, hankel1

import rollerreport_data as D
from rollertest import SOURCE, Checker, scratch
from rollerreport import lines, mechanisms, radiation, report, run, sound  # noqa: E402

c = Checker("rollerreport_unit")
rho, cs = radiation.RHO_AIR, radiation.C_AIR

# ---- the radiation model against the closed forms
ka = 1e-3
z0, z1 = complex(radiation.impedance(0, ka)), complex(radiation.impedance(1, ka))
c.check(abs(z0.real / (math.pi * ka / 2) - 1) < 1e-3, f"pulsating cylinder, ka = 1e-3: resistance {z0.real:.6e} rho c = pi ka / 2 ({math.pi * ka / 2:.6e})")
c.check(abs(complex(radiation.impedance(0, 200.0)) - 1) < 0.01, f"pulsating cylinder, ka = 200: z = {complex(radiation.impedance(0, 200.0)):.4f} rho c -> rho c")
a = 0.0125
for f in (20.0, 100.0):  # ka 0.005, 0.023: the closed forms' error is O((ka)^2 ln ka)
    k = 2 * math.pi * f / cs
    Z = math.pi * a * rho * cs * complex(radiation.impedance(1, k * a))  # force per unit length over U
    mass, res = -Z.imag / (2 * math.pi * f), Z.real
    c.check(abs(mass / (rho * math.pi * a * a) - 1) < 0.003 and abs(res / (rho * cs * math.pi**2 * a * (k * a) ** 3 / 2) - 1) < 0.003,
            f"oscillating cylinder at {f:g} Hz (ka {k * a:.3f}): added mass {mass:.4e} kg/m (rho pi a^2 = {rho * math.pi * a * a:.4e}), "
            f"resistance {res:.4e} (rho c pi^2 a (ka)^3 / 2 = {rho * cs * math.pi**2 * a * (k * a) ** 3 / 2:.4e})")
worst = bc = 0.0
for n in range(4):
    for kav in (0.1, 1.0, 10.0):
        exact = 2 / (math.pi * kav * abs(h1vp(n, kav)) ** 2)
        k = kav / a
        w = k * cs

        def pv(r):  # the pressure and the radial velocity (1/(i w rho)) dp/dr by central differences, per unit V
            h = 1e-6 * r
            p = lambda x: complex(radiation.pressure_2d(n, np.array([k]), a, x)[0])  # noqa: E731
            return p(r), (p(r + h) - p(r - h)) / (2 * h) / (1j * w * rho)

        bc = max(bc, abs(pv(a)[1] - 1))  # the surface moves at V = 1
        p, vr = pv(300 * a)  # the power through a far circle, the angular mean of |e^{in phi}|^2 = 1 (n = 0) or 1/2
        share = 1.0 if n == 0 else 0.5
        far = 0.5 * (p * vr.conjugate()).real * 2 * math.pi * 300 * a * share
        surface = 0.5 * rho * cs * complex(radiation.impedance(n, kav)).real * 2 * math.pi * a * share
        worst = max(worst, abs(far / surface - 1), abs(complex(radiation.impedance(n, kav)).real / exact - 1))
c.check(worst < 1e-5 and bc < 1e-6, f"orders 0-3, ka 0.1-10: the field moves the surface at V (finite differences, {bc:.1e}); "
        f"Re z = 2 / (pi ka |H_n'|^2) and the power through r = 300 a is the surface's (worst {worst:.1e})")
d_l, W = 1.0, 0.03
k = 2 * math.pi * 200.0 / cs
c.check(abs(complex(radiation.width_factor(np.array([k]), d_l, 2000.0)[0]) - 1) < 2e-3,
        f"width 2 km: the 2-D field (factor {complex(radiation.width_factor(np.array([k]), d_l, 2000.0)[0]):.4f})")
p = complex(radiation.transfer(0, np.array([k]), a, d_l, W)[0])
mono = 2 * math.pi * 200.0 * rho * (2 * math.pi * a * W) / (4 * math.pi * d_l)
c.check(abs(abs(p) / mono - 1) < 0.01, f"a 30 mm roller breathing at 200 Hz: {abs(p):.5f} Pa per m/s at 1 m, the point monopole "
        f"omega rho Q / (4 pi d) {mono:.5f} (1 %)")
k = 2 * math.pi * 500.0 / cs
p = abs(complex(radiation.transfer(1, np.array([k]), a, d_l, W)[0]))  # V_{+1} = V_{-1} = U/2: the cos part U
dip = k * 2 * math.pi * 500.0 * (2 * rho * math.pi * a * a * W) / (4 * math.pi * d_l)
c.check(abs(p / dip - 1) < 0.02, f"a 30 mm roller translating at 500 Hz: {p:.5f} Pa per m/s at 1 m, the point dipole "
        f"k omega (2 rho pi a^2 W) / (4 pi d) {dip:.5f} (2 %)")
fs, f0, amp = 200e3, 1000.0, 1e-6
ts = np.arange(int(0.1 * fs)) / fs
pt = radiation.radiate(ts, {0: (amp * np.cos(2 * math.pi * f0 * ts), None)}, a, d_l, W)
mid = (ts > 0.03) & (ts < 0.07)
want = abs(complex(radiation.transfer(0, np.array([2 * math.pi * f0 / cs]), a, d_l, W)[0])) * 2 * math.pi * f0 * amp
c.check(abs(np.max(np.abs(pt[mid])) / want - 1) < 0.005, f"radiate(): 1 um breathing at 1 kHz: {np.max(np.abs(pt[mid])):.5e} Pa "
        f"peak (|T| omega A = {want:.5e}, 0.5 %)")
aw = radiation.a_weighting_db([10**1.5, 100.0, 1000.0, 10000.0])  # the exact frequencies of the nominal 31.5 Hz ...
c.check(np.allclose(aw, [-39.4, -19.1, 0.0, -2.5], atol=0.06), f"A-weighting at 31.6, 100, 1k, 10k Hz: {np.round(aw, 2)} (IEC 61672: -39.4, -19.1, 0, -2.5)")

# ---- a squealing synthetic roller
d = scratch("rollerreport_")
t = D.make(d)
r = subprocess.run([sys.executable, "-m", "rollerreport", d], capture_output=True, text=True)
c.check(r.returncode == 0, f"python3 -m rollerreport exits 0 ({r.stderr.strip()[-400:]})")
out = json.load(open(os.path.join(d, "report.json")))
v = out["cea"]
c.check(v["squeals"] and abs(v["growth_rate"] - D.SIGMA) < 1e-12, f"the CEA: squeals, growth {v['growth_rate']}")
c.check(abs(v["loss_factor_onset"] - (D.ETA + 2 * D.SIGMA / (2 * math.pi * D.F_ND))) < 1e-12,
        f"loss factor at onset {v['loss_factor_onset']:.5f} = eta + 2 sigma / omega")
s = v["seconds_per_unit"]
c.check(abs(s - D.F_ND / D.PITCH) < 1e-15, f"time scale {s:.4g} s per unit = f_nd / pitch")
c.check(abs(out["friction_onset"] - 0.4) < 1e-12, f"friction at onset at the scene's creep: {out['friction_onset']} (0.4)")
fit = out["fit"]
c.check(abs(fit["frequency"] / D.F_ND - 1) < 0.01 and abs(fit["growth_rate"] / D.SIGMA - 1) < 0.05,
        f"transient fit on the {fit['column']}: f {fit['frequency']:.5f} (CEA {D.F_ND}), growth {fit['growth_rate']:.5f} (CEA {D.SIGMA})")
heard_mesh = f"{D.F_MESH * D.PITCH / D.F_ND:.1f} Hz"
c.check(abs(out["mesh_passing"] / D.F_MESH - 1) < 1e-12 and heard_mesh in open(os.path.join(d, "report.md")).read(),
        f"the mesh-passing frequency {out['mesh_passing']:.4f} (omega N / 2 pi = {D.F_MESH:.4f}) named in report.md at {heard_mesh}")
c.check(not v["diverges"] and v["real_growth_rate"] is None and out["divergent"] == [], "no real eigenvalue: no divergence")
kinds = [m["kind"] for m in out["mechanisms"]]
fl = out["mechanisms"][0]
later = out["mechanisms"][1:]
c.check(out["verdict"] == "squeals" and kinds == ["flutter", "stick-slip", "forced"] and fl["status"] == "run" and fl["squeals"]
        and abs(fl["frequency_hz"] - D.PITCH) < 1e-9 and abs(fl["growth_rate_per_s"] - D.SIGMA / s) < 1e-9 * D.SIGMA / s
        and fl["spl_db"] == out["sound"]["spl_mode_db"] and abs(fl["spl_db"] - out["spl_db"]) < 0.5 and fl["evidence"]
        and out["sound"]["mode_line_resolved"] and abs(out["sound"]["mode_line_hz"] / D.PITCH - 1) < 0.005,
        f"report.json: verdict {out['verdict']}, mechanisms {kinds}; flutter squeals at {fl['frequency_hz']:.1f} Hz, "
        f"{fl['growth_rate_per_s']:.2f} /s, {fl['spl_db']:.1f} dB")
c.check(all(m["status"].startswith("not run: ") and m["squeals"] is None and m["frequency_hz"] is None and "rollerreport.run" in m["status"]
            for m in later) and out["verdict_complete"] is False,
        "stick-slip and forced: 'not run' with what they need (" + "; ".join(m["status"] for m in later) + ")")
src, lis, prop = out["wav_source"], out["listener"], out["propensity"]
c.check(set(src) >= {"file", "column", "t0", "t1", "seconds_per_unit"} and src["file"] == "transient.csv" and src["column"] == "R"
        and lis["distance_m"] == 1.0 and lis["width_m"] == 0.03 and set(prop) >= {"cases", "fraction", "by_mechanism", "ranges"}
        and prop["cases"] == 0 and prop["status"].startswith("not run") and math.isfinite(out["spl_db"]),
        f"report.json: spl_db {out['spl_db']:.1f}, listener {lis['distance_m']} m / {lis['width_m']} m, wav_source {src}, propensity {prop['cases']} cases ({prop['status'][:40]}...)")

span = (t[-1] - t[1]) * s  # row 0 left out
with wave.open(os.path.join(d, "squeal.wav"), "rb") as w:
    frames, rate = w.getnframes(), w.getframerate()
    c.check(w.getnchannels() == 1 and w.getsampwidth() == 2 and rate == 44100 and abs(frames / rate - span) <= 1.5 / rate
            and abs(out["wav_seconds"] - span) <= 1.5 / rate,
            f"WAV: mono 16 bit 44.1 kHz, {frames} frames = {frames / rate * 1e3:.2f} ms, the simulated span x the time scale "
            f"{span * 1e3:.2f} ms (no loop); wav_seconds {out['wav_seconds'] * 1e3:.2f} ms")
samples, rate = sound.read_wav(os.path.join(d, "squeal.wav"))
heard = sound.loudest_line(samples, rate, pad=8)
grow = sound.envelope_rate(samples[int(0.1 * len(samples)) : int(0.9 * len(samples))], rate, D.PITCH)
c.check(abs(heard / D.PITCH - 1) < 0.01 and abs(grow / (D.SIGMA / s) - 1) < 0.05,
        f"the WAV's loudest line {heard:.1f} Hz (pitch {D.PITCH}, 1 %), its envelope grows at {grow:.2f} /s (the mode's {D.SIGMA / s:.2f} /s, 5 %)")
snd = out["sound"]
pc = np.genfromtxt(os.path.join(d, "sound.csv"), delimiter=",", names=True)
lsb = snd["wav_reference"]["full_scale_peak_pa"] / 32767
res = np.interp(np.arange(len(samples)) / rate, pc["t"], pc["p"]) - samples * 32768 / 32767 * snd["wav_reference"]["full_scale_peak_pa"]
c.check(len(pc["t"]) == len(t) - 1 and np.max(np.abs(res)) <= 0.5 * lsb * 1.001,
        f"sound.csv holds the pressure the WAV quantizes: {len(pc['t'])} rows, the WAV within half a step ({np.max(np.abs(res)) / lsb:.3f} of {lsb:.3g} Pa)")
c.check(snd["notice"] and "not looped" in snd["notice"] and "0.5 s" in open(os.path.join(d, "report.md")).read(),
        f"a {out['wav_seconds'] * 1e3:.0f} ms WAV: the notice in report.json and report.md ({snd['notice'][:60]}...)")
for name in ("report.md", "report.html", "map.png", "spectrogram.png", "squeal.wav", "vibration.gif"):
    p = os.path.join(d, name)
    c.check(os.path.exists(p) and os.path.getsize(p) > 0, f"{name} written")
jr = json.load(open(os.path.join(d, "journal.json")))
c.check(all(jr[p]["status"] == "ok" and not jr[p]["reused"] and jr[p]["cpu_seconds"] > 0 and jr[p]["wall_seconds"] > 0 for p in ("sound", "animation")),
        "journal.json: sound and animation ran, their CPU " + ", ".join(f"{p} {jr[p]['cpu_seconds']} s" for p in ("sound", "animation")))

# the journal: the same folder again reuses both; a changed transient redoes the sound
mtime = os.path.getmtime(os.path.join(d, "squeal.wav"))
r2 = subprocess.run([sys.executable, "-m", "rollerreport", d], capture_output=True, text=True)
jr = json.load(open(os.path.join(d, "journal.json")))
c.check(r2.returncode == 0 and jr["sound"]["reused"] and jr["animation"]["reused"] and os.path.getmtime(os.path.join(d, "squeal.wav")) == mtime
        and json.load(open(os.path.join(d, "report.json")))["spl_db"] == out["spl_db"],
        "a second report reuses the sound and the animation (journal.json: reused; squeal.wav untouched; the same spl_db)")

# a quiet roller sounds quiet: the same transient 10 times smaller, the same reference
dq = scratch("rollerreport_quiet_")
D.make(dq, r_amp=1e-5)
rq = subprocess.run([sys.executable, "-m", "rollerreport", dq, "--parts", "sound"], capture_output=True, text=True)
oq = json.load(open(os.path.join(dq, "report.json"))) if rq.returncode == 0 else {"spl_db": math.nan, "sound": {}}
sq, _ = sound.read_wav(os.path.join(dq, "squeal.wav")) if rq.returncode == 0 else (np.zeros(1), 0)
ratio = np.max(np.abs(sq)) / np.max(np.abs(samples)) * 10 ** ((oq["sound"].get("wav_reference", {}).get("full_scale_db_spl", 0)
                                                                  - snd["wav_reference"]["full_scale_db_spl"]) / 20)
c.check(abs(out["spl_db"] - oq["spl_db"] - 20) < 0.05 and abs(ratio - 0.1) < 0.002,
        f"10 times smaller: {oq['spl_db']:.2f} dB SPL against {out['spl_db']:.2f} (20 dB less), its WAV's peak {ratio:.4f} of the "
        f"loud one's at the same reference (full scale {oq['sound'].get('wav_reference', {}).get('full_scale_db_spl')} and "
        f"{snd['wav_reference']['full_scale_db_spl']} dB SPL)")
# a decaying mode decays in the WAV; a changed transient.csv redoes the sound part
D.make(dq, sigma=-0.01, r_amp=1e-5)
rq = subprocess.run([sys.executable, "-m", "rollerreport", dq, "--parts", "sound"], capture_output=True, text=True)
jq = json.load(open(os.path.join(dq, "journal.json")))
sq, rate = sound.read_wav(os.path.join(dq, "squeal.wav"))
decay = sound.envelope_rate(sq[int(0.1 * len(sq)) : int(0.9 * len(sq))], rate, D.PITCH)
c.check(rq.returncode == 0 and not jq["sound"]["reused"] and abs(decay / (-0.01 / s) - 1) < 0.05,
        f"a decaying mode (-0.01 per unit): the sound redone (transient.csv changed), its WAV decays at {decay:.2f} /s ({-0.01 / s:.2f}, 5 %)")

# the jam (docs/squeal.md 7.7): a torsional mode in alpha beside the mesh's square wave in the contact force
tj = np.arange(800) * 2.387e-5
jam = {"t": tj, "alpha": -5.17e-5 + 1.3e-6 * np.exp(-27.7 * tj) * np.cos(2 * math.pi * 418.9 * tj),
       "contact_force": 104.5 + 0.06 * np.sign(np.sin(2 * math.pi * 1587.9 * tj)) + 1e-3 * np.cos(2 * math.pi * 418.9 * tj)}
column, y = lines.carrier(tj, jam, 418.9, 1587.9)
fj = report.transient_fit(tj, y, 418.9)
c.check(column == "alpha" and abs(fj["frequency"] / 418.9 - 1) < 0.01 and abs(fj["growth_rate"] / -27.7 - 1) < 0.05,
        f"the jam: fitted on the {column} (alpha): {fj['frequency']:.2f} Hz (418.9), {fj['growth_rate']:.2f} /s (-27.7)")

# the seed's response (docs/squeal.md 4.4.4): a decaying mode beside the start's line and noise, both in the unseeded run
d3 = scratch("rollerreport_base_")
for name in ("scene.json", "sweep.csv", "transient.h5"):
    shutil.copy(os.path.join(d, name), d3)
f3, s3 = 0.177, -0.0205
D.write_csv(os.path.join(d3, "modes.csv"), D.COLS, [[0, s3, 2 * math.pi * f3, f3, s3, 3, "backward"],
                                                    [0, -0.03, 2 * math.pi * 0.23, 0.23, -0.03, 1, "forward"]])
start = 2e-3 * np.cos(2 * math.pi * 0.1965 * t) + 5e-4 * np.random.default_rng(1).standard_normal(len(t))
seeded = 1e-3 * np.exp(s3 * t) * np.cos(2 * math.pi * f3 * t + 0.3)
for name, y in (("transient.csv", start + seeded), ("transient_base.csv", start)):
    D.write_csv(os.path.join(d3, name), ["step", "t", "contact_force", "R"], [[k, t[k], 1.0 + 0.1 * y[k], 0.01 * y[k]] for k in range(len(t))])
r3 = subprocess.run([sys.executable, "-m", "rollerreport", d3, "--parts", ""], capture_output=True, text=True)
fit3 = json.load(open(os.path.join(d3, "report.json"))).get("fit", {}) if r3.returncode == 0 else {}
alone = report.transient_fit(t, start + seeded, f3)
c.check(fit3.get("response") is True and abs(fit3["frequency"] / f3 - 1) < 0.01 and abs(fit3["growth_rate"] / s3 - 1) < 0.05
        and "transient_base.csv" in open(os.path.join(d3, "report.md")).read() and abs(alone["frequency"] / f3 - 1) > 0.05,
        f"the seed's response fitted: {fit3.get('frequency', 0):.4f} ({f3}), {fit3.get('growth_rate', 0):.5f} ({s3}) on the "
        f"{fit3.get('column')}; the seeded run alone gives {alone['frequency']:.4f} (the start's line)")

# a real positive eigenvalue: a divergence, unstable without a pitch, evidence for stick-slip (not run)
dr = scratch("rollerreport_real_")
json.dump({"name": "worn", "units": "si", "kelvin_voigt_tau": 4e-6, "friction": 1.2, "creep": 0.01}, open(os.path.join(dr, "scene.json"), "w"))
D.write_csv(os.path.join(dr, "modes.csv"), D.COLS[1:], [[-51.6, 0, 0, -51.6, 0, "standing"], [11683.0, 0, 0, 11683.0, 6, "standing"],
                                                       [-21.9, 2 * math.pi * 490.7, 490.7, -21.9, 0, "standing"]])
rows = []
for case, (mu, speed) in enumerate([(0.8, 0.2356), (1.2, 0.2356), (0.8, 0.0), (1.2, 0.0)]):
    rows.append([case, mu, speed, -21.9, 2 * math.pi * 490.7, 490.7, -21.9, 0, "standing"])
    rows.append([case, mu, speed, 11683.0 if case == 0 else -51.6, 0, 0, 11683.0 if case == 0 else -51.6, 6, "standing"])
D.write_csv(os.path.join(dr, "sweep.csv"), ["case", "friction", "sheet_speed"] + D.COLS[1:], rows)
r = subprocess.run([sys.executable, "-m", "rollerreport", dr], capture_output=True, text=True)
out = json.load(open(os.path.join(dr, "report.json"))) if r.returncode == 0 else {}
v, md = out.get("cea", {}), open(os.path.join(dr, "report.md")).read() if r.returncode == 0 else ""
c.check(r.returncode == 0 and not v["squeals"] and v["diverges"] and v["unstable"] and v["real_growth_rate"] == 11683.0
        and abs(v["frequency"] - 490.7) < 1e-9 and "unstable without a pitch" in md,
        f"a real eigenvalue +11683: diverges {v.get('diverges')}, squeals {v.get('squeals')} ({r.stderr.strip()[-300:]})")
div = out.get("divergent", [])
ss = out.get("mechanisms", [{}, {}])[1]
c.check(len(div) == 1 and div[0]["friction"] == 0.8 and div[0]["sheet_speed"] == 0.2356 and out.get("friction_onset") is None
        and "**diverges**" in md and ss.get("status", "").startswith("not run") and any("divergence" in e for e in ss.get("evidence", [])),
        f"the map: a divergence at {div} only, no friction at onset; stick-slip not run, the divergence its evidence")

# a limit cycle is sustained, a decaying oscillation is not (mechanisms.limit_cycle on a stick-slip saw-tooth)
tl = np.arange(20000) * 1e-5
saw = 0.3 * ((tl * 310.0) % 1.0 - 0.5)
cyc = mechanisms.limit_cycle(tl, saw)
dec = mechanisms.limit_cycle(tl, np.exp(-40 * tl) * np.cos(2 * math.pi * 310.0 * tl))
c.check(abs(cyc["frequency"] / 310.0 - 1) < 0.01 and abs(cyc["growth_rate"]) < 1.0 and abs(cyc["amplitude"] - 0.15) < 0.01
        and dec["growth_rate"] < -30, f"limit cycle: a 310 Hz saw-tooth at {cyc['frequency']:.1f} Hz, amplitude {cyc['amplitude']:.3f}, "
        f"envelope {cyc['growth_rate']:+.2f} /s; a decaying tone {dec['growth_rate']:+.1f} /s")

# the driver's scene: units, creep, the map's grid, the time and length scales of a non-dimensional scene
yml = os.path.join(d, "scene.yaml")
with open(yml, "w") as f:
    f.write("young: 2.0e6\nr_outer: 0.0125\nr_inner: 0.005\nomega: 19.04\nsheet_speed: 0.2356\nfriction: 0.8\n"
            "friction_static: 1.0\nfriction_decay: 0.01\nviscosity: 8.0e-6\n")
opts = run.scene_options(yml, ["-friction", "0.7", "-obstacle"])
sc = run.scene_json("s", opts, run.detect_units(opts), {"distance_m": 2.0, "width_m": 0.02, "angle_deg": 45.0})
c.check(sc["units"] == "si" and sc["friction"] == 0.7 and opts["obstacle"] == "true" and abs(sc["creep"] - (1 - 0.2356 / (19.04 * 0.0125))) < 1e-15
        and sc["kelvin_voigt_tau"] == 8e-6 and sc["metres_per_unit"] == 1.0 and sc["listener"]["distance_m"] == 2.0,
        f"scene.json of an SI scene with -friction 0.7: units {sc['units']}, creep {sc['creep']:.6f}, listener {sc['listener']}")
# a Maxwell rubber's scene: the loss factor is each mode's own (modes.csv's rubber_loss_factor), not 2 pi f tau
with open(yml, "a") as f:
    f.write("rubber: maxwell\nrubber_loss_factor: 0.1\nrubber_band: 100,5000\n")
mx = run.scene_json("m", run.scene_options(yml, ["-viscosity", "0"]), "si")
row = {"re": "-40.0", "im": "3200.0", "growth_rate": "-40.0", "order": "0", "wave": "standing", "rubber_loss_factor": "0.0987"}
v = report.verdict(row, mx)
c.check(mx.get("rubber") == "maxwell" and "kelvin_voigt_tau" not in mx and mx["loss_factor"] == 0.1 and v["loss_factor"] == 0.0987
        and abs(v["loss_factor_margin"] + 0.025) < 1e-15,
        f"scene.json of a Maxwell rubber: {mx.get('rubber')}, loss factor {mx.get('loss_factor')}; the verdict takes the mode's {v['loss_factor']}, margin {v['loss_factor_margin']}")
creeps, speeds, mus = run.map_grid(sc)
c.check(sc["creep"] in creeps and 1.0 in creeps and speeds[creeps.index(sc["creep"])] == 0.2356 and speeds[-1] == 0.0
        and mus == [0.35, 0.7, 1.0], f"the default map: creeps {[round(x, 5) for x in creeps]}, frictions {mus}")
opts = run.scene_options(os.path.join(SOURCE, "jobs", "feed.yaml"), [])
sc = run.scene_json("feed", opts, run.detect_units(opts))
c_nd = math.sqrt(0.1 / (2 * 1.49) / 1.0)
c.check(sc["units"] == "nd" and abs(sc["seconds_per_unit"] - 0.0125 / 0.5 * c_nd / 23.6) < 1e-15 and abs(sc["creep"] - 0.01) < 1e-12
        and abs(sc["metres_per_unit"] - 0.025) < 1e-15,
        f"feed.yaml: units {sc['units']}, {sc['seconds_per_unit']:.4g} s and {sc['metres_per_unit']:.4g} m per unit (the printer roller's size and rubber)")
c.close()
