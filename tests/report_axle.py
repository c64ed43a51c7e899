"""The squeak report end to end on a scene built to squeak by stick-slip from the start while its linearization is
stable (jobs/axle_bistable.yaml; docs/validation.md 10.5, docs/squeal.md 9.4): `python3 -m rollerreport.run` with the
listener at 45 degrees from the sheet, the motor's ripple for the forced run (a start sliding) and 64 propensity
cases, then every file is read:
- report.json: verdict "squeals", by stick-slip (report.md says so); stick-slip run and squeaking; flutter run by the
  CEA (roller -modes on the scene, -axle: docs/squeal.md 3.1), not squeaking: steady sliding stable (every eigenvalue,
  real ones too, Re < 0), the drive's mode (the largest hub_phi) within 5 % of the 1-DOF closed form -0.007939
  (docs/validation.md 10.5; tests/axle_modes_onset.py: -0.0080459), which the report states beside it;
- stickslip.csv read here: the period of hub_rate - omega over its last four upward crossings (as
  tests/axle_stickslip.py measures it), the patch stuck in each of those periods; the report's pitch within 0.5 % of
  it and within 1 % of docs/validation.md's 19.536, its amplitude within 2 % of 0.007621;
- squeal.wav: mono 16-bit 44.1 kHz, at least 0.5 s, as long as the simulated span of wav_source times its time scale
  (1.5 samples), its pitch (the autocorrelation of its last two thirds, measured here) within 2 % of the limit cycle's,
  sustained (the RMS of its last two spans of four periods within 10 %), full scale the stated 94 dB SPL;
- forced: the hub's response at the ripple within 10 % of rollerref.forced's closed form, its level finite; the ripple
  swept (24 frequencies of the band and the CEA's modes): its case at the scene's ripple within 2 % of the forced
  run's line, its peak at the CEA's drive mode;
- kicks about the steady state (disturbances.csv: the approach sliding, then the hub kicked against the motor by 0.1 to
  150 % of its rate, the reduced model): the approach settles, the kicks up to some size settle and all larger reach a
  stick-slip cycle (the basin's edge), which coexists with the settled steady state; rollerref's 1-DOF threshold
  (basin.kick_threshold, 82.6 % of the motor's rate) between the largest kick that settles and the smallest that does
  not; the page shows disturbances.png;
- propensity: 64 cases in propensity.csv, the fraction inside its interval; each case by the finite elements (its CEA
  and its start from rest on the reduced model, on the coarser mesh -mesh_h 0.2 -mesh_h_contact 0.008 with its own
  basis): every run finished, no unstable CEA whose start settles, the 1-DOF's stick-slip verdict the same in at least
  85 % of the cases;
- the vibration seen: vibration.gif of the heard run's last three periods of the drive's mode (stickslip.h5, -output
  -output_start), on the page;
- report.html plays squeal.wav; a second run reuses every part (journal.json).
The CEA with --nev 8 (the drive's mode and the rubber's lowest, as tests/axle_modes_onset.py: about a CPU minute;
the report's default 40 takes over 10 CPU minutes on this scene).
long: the CEA (8 eigenvalues of about 40k unknowns), two finite-element runs of about 4100 steps (about 1.5 CPU minutes
each), the propensity's 64 CEAs (about 20 CPU minutes) and the reduced maps (the ripple, the kicks, the propensity's
starts: a few CPU minutes): about 30 CPU minutes."""
import csv
import json
import math
import os
import subprocess
import sys
import wave

import numpy as np

from rollertest import EXE, SOURCE, Checker

c = Checker("report_axle")
out = os.path.abspath("report_axle")
scene = os.path.join(SOURCE, "jobs", "axle_bistable.yaml")
cmd = [sys.executable, "-m", "rollerreport.run", scene, out, "--angle", "45", "--ripple", "0.001,0.03", "--forced-options",
       "-theta_start 0 -drive_ramp 0 -nip_ramp 60", "--nev", "8", "--ranks", "2", "--propensity-options", "-mesh_h 0.2 -mesh_h_contact 0.008",
       "--roller", os.path.abspath(EXE)]
r = subprocess.run(cmd, capture_output=True, text=True)
c.check(r.returncode == 0 and os.path.exists(os.path.join(out, "report.json")), f"rollerreport.run exits 0 ({r.stderr.strip()[-400:]})")
rep = json.load(open(os.path.join(out, "report.json")))
sc = json.load(open(os.path.join(out, "scene.json")))
mech = {m["kind"]: m for m in rep["mechanisms"]}
ss, fl, fo = mech["stick-slip"], mech["flutter"], mech["forced"]
md = open(os.path.join(out, "report.md")).read()
c.check(rep["verdict"] == "squeals" and rep["squeals_by"] == ["stick-slip"] and "**squeals** by stick-slip" in md
        and ss["status"] == "run" and ss["squeals"] is True and rep["verdict_complete"],
        f"verdict {rep['verdict']} by {rep['squeals_by']} (complete: {rep['verdict_complete']}): stick-slip {ss['status']}, squeals {ss['squeals']}; "
        f"flutter {fl['status']}, squeals {fl['squeals']}")

# the CEA on the axle: steady sliding stable, the drive's mode against the closed form (read here from modes.csv)
with open(os.path.join(out, "modes.csv"), newline="") as f:
    modes = list(csv.DictReader(f))
cea = rep.get("cea") or {}
dm = cea.get("drive_mode") or {}
drive = max(modes, key=lambda m: float(m["hub_phi"]))
worst = max(float(m["re"]) for m in modes)
CLOSED = -0.007939  # docs/validation.md 10.5
c.check(fl["status"] == "run" and fl["squeals"] is False and not cea.get("unstable", True) and worst < 0
        and abs(sc["onedof"]["growth_rate"] / CLOSED - 1) < 1e-3 and dm.get("row") == modes.index(drive)
        and abs(float(drive["re"]) / CLOSED - 1) < 0.05 and abs(dm["growth_rate"] - float(drive["growth_rate"])) < 1e-12
        and abs(dm["one_dof_growth_rate"] - sc["onedof"]["growth_rate"]) < 1e-12 and any("1-DOF closed form" in e for e in fl["evidence"])
        and math.isfinite(fl["growth_rate_per_s"]) and math.isfinite(fl["loss_factor_margin"]),
        f"the CEA ({len(modes)} eigenvalues): steady sliding stable (the largest Re {worst:+.6g}; the least stable oscillating mode "
        f"{cea.get('growth_rate', math.nan):+.6g} at {cea.get('frequency', math.nan):.5g}, loss-factor margin {cea.get('loss_factor_margin', math.nan):+.3g}); "
        f"the drive's mode (row {modes.index(drive)}, hub_phi {float(drive['hub_phi']):.4g}) {float(drive['re']):+.7f} + {float(drive['im']):.5f} i against the "
        f"closed form {CLOSED} ({100 * (float(drive['re']) / CLOSED - 1):+.2f} %; tests/axle_modes_onset.py: -0.0080459)")

# the limit cycle read here from the run's own CSV
with open(os.path.join(out, "stickslip.csv"), newline="") as f:
    rows = list(csv.DictReader(f))[1:]
t = np.array([float(x["t"]) for x in rows])
w = np.array([float(x["hub_rate"]) for x in rows]) - float(sc["surface_speed"]) / float(sc["r_outer"])
stick = np.array([float(x["stick_nodes"]) for x in rows])
i = np.nonzero((w[:-1] < 0) & (w[1:] >= 0) & (t[:-1] > sc["drive_started"]))[0]
tc = (t[i] - w[i] * (t[i + 1] - t[i]) / (w[i + 1] - w[i]))[-5:]
per = float(np.mean(np.diff(tc)))
sticks = [int(stick[(t >= a) & (t < b)].max()) for a, b in zip(tc[:-1], tc[1:])]
s = sc["seconds_per_unit"]
c.check(len(tc) == 5 and min(sticks) > 0 and abs(ss["period"] / per - 1) < 0.005 and abs(per / 19.536 - 1) < 0.01
        and abs(ss["limit_cycle_amplitude"] / 0.007621 - 1) < 0.02,
        f"the cycle: period {per:.4f} here, {ss['period']:.4f} in the report (docs/validation.md 10.5: 19.536), amplitude "
        f"{ss['limit_cycle_amplitude']:.6f} (0.007621), stuck in the last four periods {sticks}; heard at {ss['frequency_hz']:.3f} Hz")

# squeal.wav
src = rep["wav_source"]
with wave.open(os.path.join(out, "squeal.wav"), "rb") as f:
    ok = f.getnchannels() == 1 and f.getsampwidth() == 2 and f.getframerate() == 44100
    rate, n = f.getframerate(), f.getnframes()
    x = np.frombuffer(f.readframes(n), "<i2").astype(float)
span = (src["t1"] - src["t0"]) * src["seconds_per_unit"]
k = len(x) // 3
y = x[k:] - x[k:].mean()
spec = np.fft.rfft(y, 2 * len(y))
ac = np.fft.irfft(spec * np.conj(spec))[:len(y)] / (len(y) - np.arange(len(y)))
# the pitch: the first maximum of the autocorrelation above half its zero lag, after its first zero (the cycle
# alternates slightly, as in docs/validation.md 10.5: two periods correlate a hair better than one)
z = int(np.argmax(ac < 0))
lag = z + next(i for i in range(len(ac) - z - 2) if ac[z + i + 1] > 0.5 * ac[0] and ac[z + i + 1] >= ac[z + i] and ac[z + i + 1] >= ac[z + i + 2]) + 1
a, b, cc = ac[lag - 1: lag + 2]
pitch = rate / (lag + 0.5 * (a - cc) / (a - 2 * b + cc))
four = int(round(4 * rate / ss["frequency_hz"]))  # four periods of the cycle
rms = [math.sqrt(np.mean(x[m:m + four] ** 2)) for m in (len(x) - 2 * four, len(x) - four)]
c.check(ok and n / rate >= 0.5 and abs(n / rate - span) <= 1.5 / rate and src["file"] == "stickslip.csv"
        and os.path.exists(os.path.join(out, src["file"])) and rep["wav_seconds"] == n / rate,
        f"squeal.wav: {n / rate:.4f} s, the span {src['t0']:.4g}..{src['t1']:.5g} of {src['file']} x {src['seconds_per_unit']:.5g} s = {span:.4f} s")
c.check(abs(pitch / ss["frequency_hz"] - 1) < 0.02 and abs(pitch * per * s - 1) < 0.02,
        f"squeal.wav's pitch {pitch:.3f} Hz against the cycle's {ss['frequency_hz']:.3f} Hz ({100 * (pitch / ss['frequency_hz'] - 1):+.3f} %)")
c.check(abs(rms[1] / rms[0] - 1) < 0.10 and rep["sound"]["wav_reference"]["full_scale_db_spl"] == 94.0 and math.isfinite(rep["spl_db"]),
        f"sustained: the RMS of the last two spans of four periods {rms[0]:.1f}, {rms[1]:.1f}; {rep['spl_db']:.1f} dB SPL at 1 m, 45 degrees; full scale 94 dB SPL")

# forced, propensity, the page, the reuse
ref = sc["ripple"]["one_dof"]["rate_amplitude"]
c.check(fo["status"] == "run" and abs(fo["response_rate_amplitude"] / ref - 1) < 0.10 and fo["spl_db"] is not None and math.isfinite(fo["spl_db"]),
        f"forced: the hub rate at the ripple {fo['response_rate_amplitude']:.6g} against the 1-DOF closed form {ref:.6g} "
        f"({100 * (fo['response_rate_amplitude'] / ref - 1):+.2f} %), its line {fo['spl_db']:.1f} dB SPL")
# the ripple swept (ripple_sweep.csv, the reduced model): its case at the scene's ripple is the forced run's line (the
# same frequency, a longer run), and the response peaks at the drive's mode of the CEA (largest hub_phi)
sw = json.load(open(os.path.join(out, "ripple_sweep.json")))
with open(os.path.join(out, "modes.csv"), newline="") as f:
    drive_hz = float(max(csv.DictReader(f), key=lambda m: float(m["hub_phi"]))["im"]) / (2 * math.pi) / sc["seconds_per_unit"]
at = sw["scene_ripple"]
c.check(sw["failed"] == 0 and sw["cases"] >= 24 and abs(at["frequency_hz"] * sc["seconds_per_unit"] / 0.03 - 1) < 1e-9
        and abs(at["rate_amplitude"] / fo["response_rate_amplitude"] - 1) < 0.02 and abs(sw["peak"]["frequency_hz"] / drive_hz - 1) < 1e-9,
        f"ripple swept over {sw['cases']} frequencies: at the scene's {at['frequency_hz']:.4g} Hz {at['rate_amplitude']:.6g} against the "
        f"forced run's {fo['response_rate_amplitude']:.6g} ({100 * (at['rate_amplitude'] / fo['response_rate_amplitude'] - 1):+.2f} %); "
        f"the peak at {sw['peak']['frequency_hz']:.4g} Hz, the CEA's drive mode {drive_hz:.4g} Hz")
# kicks of growing size about the steady state (disturbances.csv): the basin's edge against the 1-DOF's
kd = json.load(open(os.path.join(out, "disturbances.json")))
with open(os.path.join(out, "disturbances.csv"), newline="") as f:
    kicks = [(float(r["kick_rate_fraction"]), r["outcome"]) for r in csv.DictReader(f)][1:]
sk, one = kd.get("smallest_kick") or {}, kd.get("onedof") or {}
edge = sk.get("kick_rate_fraction", math.inf)
c.check(kd["failed"] == 0 and kd["steady"] == "settled" and kd["coexists"] and all((o == "stick-slip") == (x >= edge) for x, o in kicks)
        and all(o in ("settled", "stick-slip") for x, o in kicks) and kd["largest_settled"] <= one.get("threshold", -1) <= edge
        and (ss.get("disturbances") or {}).get("coexists") and any("coexists" in e for e in ss["evidence"]),
        f"kicks about the steady state: the approach {kd['steady']}; {kicks}; the cycle from {edge} of the motor's rate, "
        f"{kd['largest_settled']} settles; the 1-DOF's threshold {one.get('threshold')}")
prop = rep["propensity"]
with open(os.path.join(out, "propensity.csv"), newline="") as f:
    cases = list(csv.DictReader(f))
c.check(prop["cases"] >= 64 and len(cases) == prop["cases"] and prop["confidence_95"][0] <= prop["fraction"] <= prop["confidence_95"][1]
        and abs(prop["fraction"] - sum(int(r["squeaks"]) for r in cases) / len(cases)) < 1e-12,
        f"propensity: {prop['cases']} cases, {100 * prop['fraction']:.1f} % squeak (95 %: {prop['confidence_95']})")
# each case by the finite elements: its CEA and its reduced start from rest (the propensity's coarse mesh, its own basis),
# the 1-DOF beside it. On this scene the 1-DOF is the finite elements' torsion (docs/validation.md 10.5: the cycle's
# period within 2.2 %), so their stick-slip verdicts agree but near the basin's edge; an unstable CEA grows in its run.
agree, one = prop.get("agreement") or {}, prop.get("onedof_agreement") or {}
ran = [r for r in cases if r["transient"] != "failed"]
c.check(prop.get("model", "").startswith("finite elements") and len(ran) == len(cases) and all(r["cea"] in ("stable", "flutter", "divergence") for r in cases)
        and agree.get("unstable_and_settled") == 0 and one.get("same_stick_slip_verdict", 0) >= 0.85 * len(cases),
        f"propensity by the finite elements: {len(ran)} of {len(cases)} runs, CEA classes {sorted(set(r['cea'] for r in cases))}; "
        f"CEA against the start {agree}; the 1-DOF's stick-slip verdict the same in {one.get('same_stick_slip_verdict')} of {len(cases)} (>= 85 %); "
        f"classes {prop['by_class']}")
page = open(os.path.join(out, "report.html")).read()
c.check("src='squeal.wav'" in page and "propensity.png" in page and "disturbances.png" in page,
        "report.html plays squeal.wav and shows the propensity and the kicks")
anim = rep.get("animation") or {}
c.check("vibration.gif" in anim.get("files", []) and os.path.getsize(os.path.join(out, "vibration.gif")) > 0 and "vibration.gif" in page
        and "heard run" in anim.get("reference", "") and anim.get("frames", 0) >= 100,
        f"the vibration seen: {anim.get('files')}, {anim.get('frames')} frames, {anim.get('reference')}")
r2 = subprocess.run(cmd, capture_output=True, text=True)
again = json.load(open(os.path.join(out, "report.json")))
jr = json.load(open(os.path.join(out, "journal.json")))
c.check(r2.returncode == 0 and all(p.get("reused") for name, p in jr.get("parts", jr).items() if name in ("cea", "basis", "stickslip", "forced", "disturbances_runs", "disturbances", "propensity_basis", "propensity_runs", "propensity_cea", "propensity", "sound"))
        and again["mechanisms"][1]["period"] == ss["period"],
        "the same command again reuses every part: " + ", ".join(f"{k} {'reused' if p.get('reused') else 'REDONE'}" for k, p in jr.get("parts", jr).items()))
c.close()
