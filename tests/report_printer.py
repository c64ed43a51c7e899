"""The squeak report on the printer's own scenes (issue 38; docs/squeal.md 7.10): `python3 -m rollerreport.run` on
jobs/printer_roller.yaml (the feed on the real axle, the Maxwell EPDM, the stepper's ripple) and jobs/printer_pick.yaml
(the pick from rest, the sheet with its own mass), with the report's defaults, then every file is read:
- report.json has SPEC section 10's keys: verdict, mechanisms of the kinds flutter, stick-slip and forced, spl_db (a
  finite level), wav_seconds, propensity with at least 64 cases (propensity.csv as many rows), wav_source;
- squeal.wav: mono 16-bit 44.1 kHz, at least 0.5 s, as long as the simulated span of wav_source times its time scale
  (1.5 samples); the pressure at the listener (sound.csv) at the stated full scale (every sample within one 16-bit
  code); its envelope the run's: the bounce decaying in it as in the run's contact_force (the band 150-270 Hz in 20 ms
  windows over 12-60 ms: the decay rates within 15 %), the ripple's line sustained in it and in friction_force (the
  band 800-950 Hz over the last two 0.1 s within 10 %);
- stick-slip: run; it squeaks only if the patch lets go whole in the run (stick_nodes 0 after the nip) and sticks again;
- forced: run at the ripple's 873 Hz; the hub rate's line within 5 % of rollerref.forced.two_dof (hub and tyre, the
  tyre free, the rubber's torsion at the Maxwell EPDM's storage modulus at 873 Hz, read from the CEA's branches);
- flutter: on printer_roller.yaml run by the CEA on the axle (roller -modes with -axle and -rubber maxwell), squeaking
  only with an eigenvalue of positive real part; its bounce (the largest axle_y) within 1.5 % in frequency and 10 % in
  decay of the same run's contact_force (a damped sine fitted over 12-30 ms; the frozen branches' error, docs/squeal.md
  3.1), and the same run read for a growing line as without a CEA (rollerreport.run_lines) agrees with it (a line grows
  iff an oscillating eigenvalue has Re > 0); on printer_pick.yaml, whose CEA roller refuses (-sheet_mass), run by that
  reading of its own run, roller's reason first in its evidence;
- the ripple swept over the band and the CEA's modes: its case at 873 Hz within 5 % of the 0.51 s run's line;
- kicks about the steady state (disturbances.csv, 15 kicks against the motor of 0.1-150 % of its rate, the reduced
  model): every run finished and read, the stick-slip mechanism's evidence says what they found; the kicked runs that
  settle end within 2 % of the motor's rate of the undisturbed one;
- the vibration seen: vibration.gif of the heard run's last three periods of the drive's mode (stickslip.h5);
- the propensity's 64 cases by the finite elements (on the coarse mesh -mesh_h 0.0012 -mesh_h_contact 3e-4, its own
  basis): every case's reduced start classified, every case's CEA on printer_roller.yaml, none on printer_pick.yaml;
- report.html loads squeal.wav with its duration and every image in headless Chromium.
long: per scene a CEA of 115k unknowns (printer_roller only, about 4 CPU minutes), the reduced model's basis and its
runs of 0.51 s (90,600 steps, about 2 CPU minutes each), the propensity's 64 reduced starts and (printer_roller) 64
CEAs on the coarse mesh; the two scenes at a time."""
import csv
import json
import math
import os
import shutil
import subprocess
import sys
import wave
from concurrent.futures import ThreadPoolExecutor

import numpy as np

from rollertest import EXE, SOURCE, Checker, chromium_probe, fit_maxwell_decay, maxwell_branches, maxwell_modulus

sys.path.insert(0, os.path.join(SOURCE, "scripts"))
from rollerref import forced as ref_forced  # noqa: E402
from rollerreport import run_lines  # noqa: E402

c = Checker("report_printer")
RIPPLE = 873.0
PROPENSITY_MESH = "-mesh_h 0.0012 -mesh_h_contact 3e-4"  # the propensity's cases on the coarse printer mesh (its own basis)


def column(path, names):
    with open(path, newline="") as f:
        rows = list(csv.DictReader(f))[1:]
    return {n: np.array([float(r[n]) for r in rows]) for n in names}


def band_rms(t, y, lo, hi, windows):
    """The RMS of y's band lo..hi (FFT mask over the whole series, uniform t) in each window [a, b)."""
    Y = np.fft.rfft(y - y.mean())
    f = np.fft.rfftfreq(len(y), t[1] - t[0])
    yb = np.fft.irfft(Y * ((f >= lo) & (f <= hi)), len(y))
    return np.array([math.sqrt(np.mean(yb[(t >= a) & (t < b)] ** 2)) for a, b in windows])


def decay(windows, rms):
    mids = np.array([0.5 * (a + b) for a, b in windows])
    return float(np.polyfit(mids, np.log(rms), 1)[0])


def wav(path):
    with wave.open(path, "rb") as f:
        ok = f.getnchannels() == 1 and f.getsampwidth() == 2 and f.getframerate() == 44100
        rate, n = f.getframerate(), f.getnframes()
        x = np.frombuffer(f.readframes(n), "<i2").astype(float)
    return ok, rate, x


def branch_modulus(out):
    """G'(873 Hz)/mu of the scene's Maxwell branches (the CEA's modes.h5, else a free roller's eigenproblem's)."""
    h5 = os.path.join(out, "modes.h5")
    if not os.path.exists(h5):
        h5 = os.path.join(out, "branches.h5")
        subprocess.run([EXE, "-options_file", os.path.join(SOURCE, "jobs", "printer_pick.yaml"), "-obstacle", "false", "-axle", "false", "-sheet_mass", "0", "-sheet_resistance", "0", "-mesh_h", "0.003",
                        "-mesh_h_contact", "0", "-modes", "-modes_nev", "2", "-modes_output", h5, "-quiet"], check=True, capture_output=True)
    tau, g = maxwell_branches(h5)
    return maxwell_modulus(2j * math.pi * RIPPLE, tau, g).real


def report(name):
    # the feed's 64 CEAs on two ranks (the pick has none: it ends first)
    ranks = "2" if name == "printer_roller" else "1"
    return subprocess.run([sys.executable, "-m", "rollerreport.run", os.path.join(SOURCE, "jobs", f"{name}.yaml"), os.path.abspath(name),
                           "--propensity-options", PROPENSITY_MESH, "--ranks", ranks, "--ripple-sweep", "8", "--roller", os.path.abspath(EXE)],
                          capture_output=True, text=True)


browser = shutil.which("chromium") or shutil.which("chromium-browser")
with ThreadPoolExecutor(2) as pool:  # the two scenes at a time
    runs = dict(zip(("printer_roller", "printer_pick"), pool.map(report, ("printer_roller", "printer_pick"))))
for name in ("printer_roller", "printer_pick"):
    out = os.path.abspath(name)
    r = runs[name]
    ok = r.returncode == 0 and os.path.exists(os.path.join(out, "report.json"))
    c.check(ok, f"{name}: rollerreport.run exits 0 ({r.stderr.strip()[-300:]})")
    if not ok:
        continue
    rep = json.load(open(os.path.join(out, "report.json")))
    sc = json.load(open(os.path.join(out, "scene.json")))
    mech = {m["kind"]: m for m in rep["mechanisms"]}
    keys = ("verdict", "mechanisms", "spl_db", "wav_seconds", "propensity", "wav_source")
    with open(os.path.join(out, "propensity.csv"), newline="") as f:
        cases = list(csv.DictReader(f))
    c.check(all(k in rep for k in keys) and set(mech) == {"flutter", "stick-slip", "forced"} and rep["spl_db"] is not None and math.isfinite(rep["spl_db"])
            and rep["propensity"]["cases"] >= 64 and len(cases) == rep["propensity"]["cases"] and rep["wav_source"],
            f"{name}: report.json {', '.join(k for k in keys if k in rep)}; verdict {rep['verdict']} by {rep['squeals_by']}; "
            f"{rep['spl_db']:.1f} dB SPL; propensity {rep['propensity']['cases']} cases, {100 * rep['propensity']['fraction']:.1f} %")

    # the propensity by the finite elements: every case's reduced start ran and was classified; on the feed every case's
    # CEA ran too (on the pick, with the sheet's mass, none: the scene's CEA is refused)
    prop = rep["propensity"]
    want_cea = name == "printer_roller"
    c.check(prop.get("model", "").startswith("finite elements") and all(r["transient"] in ("stick-slip", "growing", "settled") for r in cases)
            and all((r["cea"] in ("stable", "flutter", "divergence")) if want_cea else r["cea"] == "not run" for r in cases),
            f"{name}: the propensity's {len(cases)} cases by the finite elements: starts {sorted(set(r['transient'] for r in cases))}, CEAs "
            f"{sorted(set(r['cea'] for r in cases))}; classes {prop['by_class']}; CEA against the start {prop.get('agreement')}; "
            f"1-DOF the same {prop.get('onedof_agreement')}; ranking {[(e['parameter'], round(e['spearman'], 2)) for e in prop['ranking'][:3]]}")

    # squeal.wav against its source
    src = rep["wav_source"]
    good, rate, x = wav(os.path.join(out, "squeal.wav"))
    span = (src["t1"] - src["t0"]) * src["seconds_per_unit"]
    c.check(good and len(x) / rate >= 0.5 and abs(len(x) / rate - span) <= 1.5 / rate and rep["wav_seconds"] == len(x) / rate,
            f"{name}: squeal.wav {len(x) / rate:.4f} s, the span {src['t0']:.4g}..{src['t1']:.5g} of {src['file']} x {src['seconds_per_unit']:g} s = {span:.4f} s")
    snd = column(os.path.join(out, "sound.csv"), ["t", "p"])
    full = rep["sound"]["wav_reference"]["full_scale_peak_pa"]
    want = np.clip(np.round(np.interp(np.arange(len(x)) / rate, snd["t"], snd["p"]) / full * 32767), -32768, 32767)
    dev = float(np.max(np.abs(x - want)))
    c.check(dev <= 1, f"{name}: the WAV is the pressure at the listener (sound.csv) at the stated full scale {full:.4g} Pa "
            f"({rep['sound']['wav_reference']['full_scale_db_spl']:g} dB SPL): samples within {dev:g} of the 16-bit code")
    tw = np.arange(len(x)) / rate
    mon = column(os.path.join(out, src["file"]), ["t", "friction_force", "contact_force", "hub_rate", "stick_nodes", "slip_nodes"])
    tm = mon["t"]
    early = [(a, a + 0.02) for a in np.arange(0.012, 0.06, 0.01)]
    kw = decay(early, band_rms(tw + src["t0"], x, 150, 270, early))
    kf = decay(early, band_rms(tm, mon["contact_force"], 150, 270, early))
    c.check(kw < 0 and kf < 0 and abs(kw / kf - 1) < 0.15, f"{name}: the bounce decays in the WAV at {kw:.1f} /s, in contact_force at {kf:.1f} /s ({100 * (kw / kf - 1):+.1f} %)")
    late = [(src["t1"] - 0.2, src["t1"] - 0.1), (src["t1"] - 0.1, src["t1"])]
    lw, lf = band_rms(tw + src["t0"], x, 800, 950, late), band_rms(tm, mon["friction_force"], 800, 950, late)
    c.check(abs(lw[1] / lw[0] - 1) < 0.10 and abs(lf[1] / lf[0] - 1) < 0.10,
            f"{name}: the ripple's line sustained over the last 0.2 s: WAV {lw[0]:.1f}, {lw[1]:.1f}; friction_force {lf[0]:.4g}, {lf[1]:.4g}")

    # stick-slip: the patch letting go whole
    after = tm > 0.012
    let_go = bool(np.any(mon["stick_nodes"][after] == 0) and np.any(mon["stick_nodes"][after] > 0))
    ss = mech["stick-slip"]
    c.check(ss["status"] == "run" and (not ss["squeals"] or let_go),
            f"{name}: stick-slip {ss['status']}, squeals {ss['squeals']}; stick_nodes after the nip {int(mon['stick_nodes'][after].min())}..{int(mon['stick_nodes'][after].max())}")

    # forced: the ripple's line against the two-degree-of-freedom closed form
    fo = mech["forced"]
    k_r = ref_forced.annulus_torsion(2.0e6 * branch_modulus(out), 0.49, 0.005, 0.0125)
    I_t = ref_forced.annulus_inertia(1200.0, 0.005, 0.0125)
    ref = ref_forced.two_dof(1.0e-4, I_t, 1000.0, 0.023, k_r, RIPPLE, 2.0e-3)["hub"]["rate_amplitude"]
    c.check(fo["status"] == "run" and abs(fo["frequency_hz"] - RIPPLE) < 1e-6 and abs(fo["response_rate_amplitude"] / ref - 1) < 0.05,
            f"{name}: forced at {fo['frequency_hz']:.1f} Hz: the hub rate's line {fo['response_rate_amplitude']:.4g} against two_dof's {ref:.4g} "
            f"({100 * (fo['response_rate_amplitude'] / ref - 1):+.2f} %), {fo['spl_db']:.1f} dB SPL")

    # the ripple swept (8 frequencies of the band and the CEA's modes, each a reduced start): its case at 873 Hz is the
    # scene's own forced line of the 0.51 s run (a shorter run: the bounce's start transient decays at 65 /s)
    sw = json.load(open(os.path.join(out, "ripple_sweep.json")))
    at = sw["scene_ripple"]
    c.check(sw["failed"] == 0 and abs(at["frequency_hz"] / RIPPLE - 1) < 1e-9 and abs(at["rate_amplitude"] / fo["response_rate_amplitude"] - 1) < 0.05,
            f"{name}: the ripple swept over {sw['cases']} frequencies {sw['band_hz'][0]:.0f}-{sw['band_hz'][1]:.0f} Hz: at 873 Hz "
            f"{at['rate_amplitude']:.4g} against the 0.51 s run's {fo['response_rate_amplitude']:.4g} "
            f"({100 * (at['rate_amplitude'] / fo['response_rate_amplitude'] - 1):+.2f} %); the peak {sw['peak']['frequency_hz']:.0f} Hz "
            f"({sw['peak']['rate_per_ripple']:.4g} per rad), the scene's ripple {-at['below_peak_db']:.1f} dB below it")

    # kicks of growing size about the steady state, and the animation of the heard run's end
    kd = json.load(open(os.path.join(out, "disturbances.json")))
    with open(os.path.join(out, "disturbances.csv"), newline="") as f:
        kicks = list(csv.DictReader(f))
    ss = mech["stick-slip"]
    c.check(kd["failed"] == 0 and len(kicks) == 16 and all(r["outcome"] in ("settled", "stick-slip", "forced stick-slip", "growing") for r in kicks)
            and (ss.get("disturbances") or {}).get("steady") == kd["steady"] and any("kick" in e for e in ss["evidence"])
            and (kd["returned_max"] is None or kd["returned_max"] < 0.02),
            f"{name}: kicks about the steady state: the approach {kd['steady']}, {[(r['kick_rate_fraction'], r['outcome']) for r in kicks]}; "
            f"the smallest reaching stick-slip {kd['smallest_kick']}; settled runs back within {kd['returned_max']} of the motor's rate")
    anim = rep.get("animation") or {}
    c.check("vibration.gif" in anim.get("files", []) and "heard run" in anim.get("reference", "") and anim.get("frames", 0) >= 100,
            f"{name}: the vibration seen: {anim.get('files')}, {anim.get('frames')} frames, {anim.get('reference')}")

    # flutter
    fl = mech["flutter"]
    sc = json.load(open(os.path.join(out, "scene.json")))
    rl = run_lines.read(out, sc, s=sc.get("seconds_per_unit", 1.0))  # the run read for a growing line, as without a CEA
    grow = run_lines.growing(rl, sc.get("seconds_per_unit", 1.0))
    if name == "printer_pick":
        c.check(fl["status"] == "run" and fl.get("method", "").startswith("the scene's own run") and "-sheet_mass" in fl["evidence"][0]
                and fl["squeals"] == bool(grow) and len(rl["lines"]) >= 4,
                f"{name}: flutter {fl['status']} by {fl.get('method')} (the CEA refused: {fl['evidence'][0][-60:]}), squeals {fl['squeals']}: "
                f"{len(rl['lines'])} lines followed, growing {grow}")
    else:
        with open(os.path.join(out, "modes.csv"), newline="") as f:
            modes = list(csv.DictReader(f))
        worst = max(float(m["re"]) for m in modes)
        b = max(modes, key=lambda m: float(m["axle_y"]))
        w = (tm >= 0.012) & (tm <= 0.03)
        cf = mon["contact_force"][w]
        s_fe, w_fe, _ = fit_maxwell_decay(tm[w] - tm[w][0], cf - cf.mean(), [0.0])  # a damped sine and a constant
        c.check(fl["status"] == "run" and (not fl["squeals"] or worst > 0), f"{name}: flutter {fl['status']}, squeals {fl['squeals']}; the largest Re of {len(modes)} eigenvalues {worst:+.4g}")
        # the reading without a CEA (the pick's) against the CEA where both exist: a line grows in the run iff an
        # oscillating eigenvalue has Re > 0
        osc = max(float(m["re"]) for m in modes if float(m["im"]) > 0)
        c.check(bool(grow) == (osc > 0) and len(rl["lines"]) >= 4, f"{name}: the run read for a growing line: {len(rl['lines'])} lines "
                f"followed, growing {grow}, the least stable {rl['lines'][0]['frequency']:.1f} Hz at {rl['lines'][0]['growth_rate']:+.3g} /s; "
                f"the CEA's least stable oscillating mode {osc:+.4g} /s")
        c.check(abs(float(b["im"]) / w_fe - 1) < 0.015 and abs(float(b["re"]) / s_fe - 1) < 0.10,
                f"{name}: the CEA's bounce {float(b['re']):.2f} + {float(b['im']) / (2 * math.pi):.2f} Hz i against the run's contact_force "
                f"{s_fe:.2f}, {w_fe / (2 * math.pi):.2f} Hz ({100 * (float(b['re']) / s_fe - 1):+.1f} %, {100 * (float(b['im']) / w_fe - 1):+.2f} %)")

    # the page
    page = open(os.path.join(out, "report.html")).read()
    if browser:
        got, p = chromium_probe(browser, out, page)
        got = got or {}
        imgs = got.get("images", [])
        c.check(got.get("audio") is not None and got.get("error") is None and abs(got["audio"] - rep["wav_seconds"]) < 1e-4
                and imgs and all(w > 0 for _, w, _ in imgs),
                f"{name}: report.html in Chromium: the audio {got.get('audio')} s (the WAV's {rep['wav_seconds']:.6f}), images {imgs}")
    else:
        c.check(False, "chromium on the PATH (scripts/install-deps.sh installs Debian's chromium)")
c.close()
