"""The report's stick-slip, forced and propensity mechanisms (scripts/rollerreport: cycle, onedof, propensity,
mechanisms, heard.write_cycle; docs/squeal.md 9.4) on synthetic monitor CSVs, no roller run:
- limit-cycle detection (rollerreport.cycle.detect) on rollerref's event-driven start from rest of
  jobs/axle_bistable.yaml's 1-DOF (the cycle the finite elements reach, docs/validation.md 10.5), sampled at the
  scene's step with a node-passing ripple of 3 % added: the period within 0.5 % of rollerref's own cycle, the amplitude
  within 4 %, stuck in every period, sustained; a decaying oscillation is not sustained, a sustained one without stick
  is not stick-slip, a series of two periods is too short;
- the report of that folder: verdict "squeals" by stick-slip; without modes.csv flutter "not run" (the 1-DOF closed
  form named "not a substitute"); with a modes.csv of the axle's columns (axle_y, hub_phi) flutter run by it, stable,
  the drive's mode (the largest hub_phi) beside the 1-DOF closed form, the stick-slip "bistable" by the CEA; with the
  CEA refused (roller's PETSc error for -sheet_mass, parsed by rollerreport.run.Steps from a log) flutter read from the
  scene's own run instead (rollerreport.run_lines: roller's reason first in its evidence; the stick-slip cycle's lines
  left out, no line grows: squeals False), the part not counted as failed; squeal.wav as long as the simulated span times the time scale, its pitch
  (measured here by the autocorrelation of its last two thirds) within 2 % of the cycle's, its envelope sustained (the
  RMS of the last two spans of four periods within 10 %), full scale the stated 94 dB SPL; the friction force's dipole against its
  closed form cos(phi) w F W / (4 pi c d);
- the forced response's lock-in (a ripple's line beside a decaying free oscillation) within 0.5 %, and the forced
  mechanism's ratio to the 1-DOF closed form;
- the propensity: a Latin hypercube has one point in each stratum of every axis, Wilson's interval at known values,
  the scene's own point maps onto the scene, 8 cases classified with the summary's keys;
- the kicks about the steady state (rollerreport.disturbances) from the files their map writes: kicks up to 80 % of the
  motor's rate decaying, from 90 % a stick-slip cycle: the smallest kick 90 %, the largest settled 80 %, the cycle
  coexisting with the settled approach, the 1-DOF's threshold (rollerref.basin.kick_threshold) between them, and the
  stick-slip mechanism's evidence saying so."""
import csv
import json
import math
import os
import subprocess
import sys
import wave

import numpy as np

from rollertest import SOURCE, Checker, scratch
from rollerreport import cycle, mechanisms, onedof, propensity, radiation, run, run_lines  # noqa: E402
from rollerref import stickslip  # noqa: E402

c = Checker("rollerreport_mechanisms")
opts = run.scene_options(os.path.join(SOURCE, "jobs", "axle_bistable.yaml"), [])
DT, T_END = 0.0632, 260.0


def write_csv(path, cols):
    names = list(cols)
    with open(path, "w") as f:
        f.write(",".join(names) + "\n")
        for k in range(len(cols["t"])):
            f.write(",".join(repr(float(cols[n][k])) for n in names) + "\n")


# ---- the cycle of the 1-DOF start from rest, as the monitor would write it
p = onedof.torsion(opts, ripple=False)
ref = stickslip.stick_slip_cycle(p)
res = stickslip.simulate(p, T_END, dt_out=DT / 4)
t = np.arange(1, int(T_END / DT)) * DT
rate = np.interp(t, res.t, res.u[:, 0])
stuck = np.interp(t, res.t, (res.mode[:, 0] == 0).astype(float)) > 0.5
force = np.interp(t, res.t, res.F[:, 0])
ripple = 0.03 * ref["rate_amplitude"] * np.sin(2 * math.pi * 0.47 * t)  # the node passing's ripple
d = scratch("rollerreport_mech_")
cols = {"step": np.arange(len(t) + 1), "t": np.concatenate([[0.0], t]), "friction_force": np.concatenate([[0.0], -force]),
        "stick_nodes": np.concatenate([[0], np.where(stuck, 11, 0)]), "slip_nodes": np.concatenate([[11], np.where(stuck, 0, 11)]),
        "hub_rate": np.concatenate([[0.0], rate + ripple]), "R": 0.0 * np.concatenate([[0.0], t])}
write_csv(os.path.join(d, "stickslip.csv"), cols)
surf = {"step": cols["step"], "t": cols["t"], "theta": 0 * cols["t"], "ur0": 0 * cols["t"], "ur1c": 1e-7 * cols["friction_force"],
        "ur1s": 0 * cols["t"]}
write_csv(os.path.join(d, "stickslip_surface.csv"), surf)
cyc = cycle.detect(t, rate + ripple, np.where(stuck, 11, 0), t_min=25.0)
c.check(ref["exists"] and abs(cyc["period"] / ref["period"] - 1) < 0.005 and abs(cyc["amplitude"] / ref["rate_amplitude"] - 1) < 0.04
        and cyc["stick_slip"] and cyc["sustained"] and cyc["stick_every_period"],
        f"the 1-DOF start from rest at dt {DT} with a 3 % ripple (the half peak-to-peak takes it in): period {cyc['period']:.4f} (rollerref {ref['period']:.4f}), amplitude "
        f"{cyc['amplitude']:.6f} ({ref['rate_amplitude']:.6f}), {cyc['why']}")
w = p.omega
dec = cycle.detect(t, w + 0.002 * np.exp(-0.0079 * t) * np.cos(2 * math.pi * 0.0503 * t), 0 * t, t_min=25.0)
sus = cycle.detect(t, w + 0.002 * np.cos(2 * math.pi * 0.0503 * t), 0 * t, t_min=25.0)
short = cycle.detect(t[t < 60], w + 0.002 * np.cos(2 * math.pi * 0.0503 * t[t < 60]), None, t_min=25.0)
c.check(not dec["sustained"] and dec["growth_rate"] < -0.007 and sus["sustained"] and not sus["stick_slip"]
        and sus["stick_every_period"] is False and not short["sustained"] and "needed" in short["why"],
        f"a decaying oscillation ({dec['growth_rate']:+.5f}, the envelope -0.0079): not sustained; a steady one without stick: "
        f"sustained, not stick-slip; a short series: {short['why']}")

# ---- the report of the folder
sc = run.scene_json("axle_bistable", opts, run.detect_units(opts), {"distance_m": 1.0, "width_m": 0.03, "angle_deg": 45.0})
json.dump(sc, open(os.path.join(d, "scene.json"), "w"))
lin = sc["onedof"]
c.check(sc["axle"] and sc["drive_started"] == 25.0 and lin["stable"] and abs(lin["growth_rate"] / -0.007939 - 1) < 1e-3
        and lin["start_from_rest"] == "cycle", f"scene.json on the axle: the 1-DOF closed form {lin['growth_rate']:+.6f} (docs/validation.md "
        f"10.5: -0.007939), its start from rest {lin['start_from_rest']}, the drive started at {sc['drive_started']}")
given = run.scene_json("axle_bistable", opts, "nd", None, seconds_per_unit=0.003)
c.check(given["seconds_per_unit"] == 0.003 and "given" in given["time_scale_note"]
        and abs(given["newtons_per_metre_per_unit"] / (1200.0 * (0.025 / 0.003) ** 2 * 0.025) - 1) < 1e-12
        and abs(sc["newtons_per_metre_per_unit"] / (1200.0 * 23.6 ** 2 / (10 / 2.98) * 0.025) - 1) < 1e-12,
        f"the time scale given (--seconds-per-unit 0.003) or the printer roller's ({sc['seconds_per_unit']:.5g} s per unit); the force "
        f"scale rho_ref (L/s)^2 L: {given['newtons_per_metre_per_unit']:.5g}, {sc['newtons_per_metre_per_unit']:.5g} N/m per unit")
r = subprocess.run([sys.executable, "-m", "rollerreport", d], capture_output=True, text=True)
out = json.load(open(os.path.join(d, "report.json"))) if r.returncode == 0 else {}
mech = {m["kind"]: m for m in out.get("mechanisms", [])}
s = sc["seconds_per_unit"]
ss = mech.get("stick-slip", {})
c.check(out.get("verdict") == "squeals" and out.get("squeals_by") == ["stick-slip"] and ss.get("squeals") is True and abs(ss["frequency_hz"] * s * cyc["period"] - 1) < 1e-9
        and mech["flutter"]["status"].startswith("not run: no CEA") and "not a substitute" in mech["flutter"]["evidence"][0]
        and mech["flutter"]["squeals"] is None and mech["forced"]["status"].startswith("not run"),
        f"report.json: verdict {out.get('verdict')}, stick-slip at {ss.get('frequency_hz', 0):.3f} Hz; flutter {mech.get('flutter', {}).get('status')} "
        f"({r.stderr.strip()[-300:]})")
with wave.open(os.path.join(d, "squeal.wav"), "rb") as f:
    rate_wav, n = f.getframerate(), f.getnframes()
    x = np.frombuffer(f.readframes(n), "<i2").astype(float)
src = out["wav_source"]
span = (src["t1"] - src["t0"]) * s
k = len(x) // 3
y = x[k:] - x[k:].mean()
ac = np.correlate(y, y, "full")[len(y) - 1:] / (len(y) - np.arange(len(y)))
z = int(np.argmax(ac < 0))  # the first maximum above half the zero lag after the first zero
lag = z + next(i for i in range(len(ac) - z - 2) if ac[z + i + 1] > 0.5 * ac[0] and ac[z + i + 1] >= ac[z + i] and ac[z + i + 1] >= ac[z + i + 2]) + 1
pitch = rate_wav / lag
four = int(round(4 * rate_wav / ss["frequency_hz"]))  # four periods of the cycle
rms = [math.sqrt(np.mean(x[a:a + four] ** 2)) for a in (len(x) - 2 * four, len(x) - four)]
c.check(src["file"] == "stickslip.csv" and abs(n / rate_wav - span) <= 1.5 / rate_wav and abs(pitch / ss["frequency_hz"] - 1) < 0.02
        and abs(rms[1] / rms[0] - 1) < 0.10 and out["sound"]["wav_reference"]["full_scale_db_spl"] == 94.0 and math.isfinite(out["spl_db"]),
        f"squeal.wav: {n / rate_wav:.4f} s (span x scale {span:.4f}), pitch {pitch:.3f} Hz (the cycle's {ss['frequency_hz']:.3f}), "
        f"the RMS of the last two spans of four periods {rms[0]:.1f}, {rms[1]:.1f}; {out['spl_db']:.1f} dB SPL at full scale 94 dB")
# ---- the CEA on the axle: a modes.csv as roller -modes -axle writes it (docs/squeal.md 3.1), the drive's mode the
# largest hub_phi (tests/axle_modes_onset.py's -0.0080459 + 0.32001 i), a rubber mode stabler, a real one
DRIVE = -0.0080459
with open(os.path.join(d, "modes.csv"), "w") as f:
    f.write("re,im,frequency,growth_rate,order,wave,error,axle_y,hub_phi\n")
    f.write(f"{DRIVE!r},0.32001,{0.32001 / (2 * math.pi)!r},{DRIVE!r},1,forward,1e-9,0.001,2.5\n")
    f.write("-0.05,7.23,1.1507,-0.05,0,standing,1e-9,0.0002,0.01\n")
    f.write("-0.2,0,0,-0.2,0,standing,1e-9,0.9,0.003\n")
r = subprocess.run([sys.executable, "-m", "rollerreport", d], capture_output=True, text=True)
out2 = json.load(open(os.path.join(d, "report.json"))) if r.returncode == 0 else {}
m2 = {m["kind"]: m for m in out2.get("mechanisms", [])}
fl, dm = m2.get("flutter", {}), (out2.get("cea") or {}).get("drive_mode") or {}
c.check(fl.get("status") == "run" and fl.get("squeals") is False and dm.get("row") == 0 and dm.get("growth_rate") == DRIVE
        and abs(dm["ratio"] - DRIVE / lin["growth_rate"]) < 1e-12 and any("1-DOF closed form" in e and "%" in e for e in fl["evidence"])
        and abs(fl["growth_rate_per_s"] * s / DRIVE - 1) < 1e-12 and abs(fl["loss_factor_margin"] - 2 * DRIVE / 0.32001) < 1e-12
        and fl["spl_db"] is None and out2["verdict"] == "squeals" and out2["squeals_by"] == ["stick-slip"] and out2["verdict_complete"] is False
        and any("CEA" in e and "bistable" in e for e in m2["stick-slip"]["evidence"]),
        f"with modes.csv: flutter {fl.get('status')}, squeals {fl.get('squeals')}; the drive's mode row {dm.get('row')} against the 1-DOF "
        f"{100 * (dm.get('ratio', math.nan) - 1):+.2f} %; verdict {out2.get('verdict')} by {out2.get('squeals_by')} ({r.stderr.strip()[-300:]})")
os.remove(os.path.join(d, "modes.csv"))
log = ("[0]PETSC ERROR: --------------------- Error Message -------\n[0]PETSC ERROR: No support for this operation for this object type\n"
       "[0]PETSC ERROR: -sheet_mass with -modes: the steady state takes the sheet's speed -sheet_speed (the force balance of a moving sheet is the transient's)\n"
       "[0]PETSC ERROR: See https://petsc.org/release/faq/ for trouble shooting.\n[0]PETSC ERROR: #1 RollerSetFromOptions() at options.c:167\n"
       "[0]PETSC ERROR: WARNING! There are option(s) set that were not used!\n[0]PETSC ERROR: Option left: name:-sheet_mass value: 0.1\n")
steps = run.Steps(d, "/bin/sh")
with open("refused.log", "w") as f:  # roller's words, quotes and all, as its stderr
    f.write(log)
steps.run("cea", ["/bin/sh", "-c", f"cat {os.path.abspath('refused.log')}; exit 56"], "the CEA", outputs=["modes.csv"])
rec = steps.done[-1]
r = subprocess.run([sys.executable, "-m", "rollerreport", d], capture_output=True, text=True)
out3 = json.load(open(os.path.join(d, "report.json"))) if r.returncode == 0 else {}
fl3 = {m["kind"]: m for m in out3.get("mechanisms", [])}.get("flutter", {})
why = "-sheet_mass with -modes: the steady state takes the sheet's speed -sheet_speed (the force balance of a moving sheet is the transient's)"
# the CEA refused (a sheet with its own mass): flutter read from the scene's own run instead (rollerreport.run_lines),
# the stick-slip cycle's lines left out (stick-slip's, not a growing mode): no line grows
c.check(rec.get("refused") is True and rec["error"].endswith(why) and fl3.get("status") == "run"
        and fl3.get("method", "").startswith("the scene's own run") and fl3["evidence"][0] == f"no CEA: roller -modes refused the scene: {why}"
        and "none grows" in fl3["evidence"][1] and fl3.get("squeals") is False and "not a substitute" in fl3["evidence"][2]
        and out3["squeals_by"] == ["stick-slip"],
        f"the CEA refused: flutter {fl3.get('status')} by {fl3.get('method')}, squeals {fl3.get('squeals')}: "
        f"{(fl3.get('evidence') or ['', ''])[1][-160:]} (the part refused, not failed: {rec.get('refused')})")
os.remove(os.path.join(d, "commands.json"))

tt = np.arange(20000) / 20000.0
F0, f0, phi, dist = 0.3, 200.0, 30.0, 2.0
pd = radiation.force_dipole(tt, F0 * np.sin(2 * math.pi * f0 * tt), dist, phi)
mid = pd[5000:15000]
want = math.cos(math.radians(phi)) * 2 * math.pi * f0 * F0 / (4 * math.pi * radiation.C_AIR * dist)
c.check(abs(0.5 * np.ptp(mid) / want - 1) < 1e-3, f"the force dipole: {0.5 * np.ptp(mid):.6g} Pa against cos(phi) w F / (4 pi c d) = {want:.6g}")

# ---- the forced response: the ripple's line beside a decaying free oscillation
f_r, A_r = 0.03, 2.9e-4
hub = w + A_r * np.sin(2 * math.pi * f_r * t + 0.4) + 3e-4 * np.exp(-0.0079 * t) * np.sin(2 * math.pi * 0.0503 * t)  # 1-DOF's
amp, ph = cycle.lock_in(t[t > 100], hub[t > 100], f_r, free=[(0.0503, -0.0079)])
c.check(abs(amp / A_r - 1) < 0.005 and abs(ph - 0.4) < 0.01, f"lock-in at the ripple: {amp:.5g} ({A_r}), phase {ph:.4f} (0.4)")
df = scratch("rollerreport_forced_")
write_csv(os.path.join(df, "forced.csv"), {"step": np.arange(len(t)), "t": t, "hub_rate": hub, "stick_nodes": 0 * t})
scf = dict(sc, ripple={"amplitude": 1e-3, "frequency": f_r, "one_dof": {"rate_amplitude": A_r / 1.01}})
json.dump(scf, open(os.path.join(df, "scene.json"), "w"))
r = subprocess.run([sys.executable, "-m", "rollerreport", df], capture_output=True, text=True)
fo = {m["kind"]: m for m in json.load(open(os.path.join(df, "report.json")))["mechanisms"]}.get("forced", {}) if r.returncode == 0 else {}
c.check(fo.get("status") == "run" and abs(fo["response_rate_amplitude"] / A_r - 1) < 0.01 and any("+1.0 %" in e for e in fo["evidence"]),
        f"forced: {fo.get('status')}, {fo.get('response_rate_amplitude')}; {fo.get('evidence')} ({r.stderr.strip()[-300:]})")

# ---- the propensity
u = propensity.latin_hypercube(64, 7, 1)
c.check(all(sorted((u[:, j] * 64).astype(int).tolist()) == list(range(64)) for j in range(7)),
        "a Latin hypercube of 64 points in 7 dimensions: one point in each of the 64 strata of every axis")
w0, w32 = propensity.wilson(0, 64), propensity.wilson(32, 64)
c.check(w0[0] == 0 and abs(w0[1] - 0.05654) < 1e-4 and abs(w32[0] - 0.3801) < 1e-3 and abs(w32[1] - 0.6199) < 1e-3,
        f"Wilson's 95 % interval: 0/64 {w0}, 32/64 {w32}")
mid_sample = {nm: (math.sqrt(lo_ * hi_) if nm != "friction_static_over_kinetic" else 1.25) for nm, (_, lo_, hi_) in propensity.SPREAD.items()}
case = propensity.case_options(opts, mid_sample)
same = {k: propensity.scene_value(opts, k) for k in case}
c.check(all(abs(case[k] / same[k] - 1) < 1e-12 for k in case) and {"viscosity", "axle_stiffness", "drive_damping"} <= set(case),
        f"the ranges' centres map onto the scene (the loss factor on -viscosity, the bracket on -axle_stiffness): {case}")
kin = dict(opts, sheet_speed="0.99", omega="2.0", r_outer="0.5")
hi = propensity.case_options(kin, dict(mid_sample, surface_speed_m_per_s=0.36))
c.check(abs(hi["omega"] / 2.0 - 0.36 / math.sqrt(0.12 * 0.36)) < 1e-12 and abs(hi["sheet_speed"] / hi["omega"] - 0.99 / 2.0) < 1e-12,
        f"a kinematic sheet's speed follows the surface speed, the creep kept: omega {hi['omega']:.5g}, sheet_speed {hi['sheet_speed']:.5g}")
dp = scratch("rollerreport_prop_")
pr = propensity.run(opts, dp, n=8, seed=3)
rows = open(os.path.join(dp, "propensity.csv")).read().splitlines()
c.check(pr["cases"] == 8 and len(rows) == 9 and pr["fraction"] == pr["squeaking"] / 8 and pr["confidence_95"][0] <= pr["fraction"] <= pr["confidence_95"][1]
        and set(pr) >= {"cases", "fraction", "by_mechanism", "ranges", "sampling", "ranking"} and pr["sampling"]["seed"] == 3,
        f"8 cases: {pr['squeaking']} squeak ({pr['by_class']}), interval {[round(x, 3) for x in pr['confidence_95']]}")

# the finite elements' classification of the cases (rollerreport.propensity_fe) from the files the two maps write:
# case 0 the stick-slip series above with a stable CEA (bistable), case 1 a decaying oscillation with a growing
# oscillating CEA mode (flutter), case 2 decaying with a stable CEA (quiet), case 3 a failed run
from rollerreport import propensity_fe  # noqa: E402

dq = scratch("rollerreport_prop_fe_")
cases = propensity.sample(opts, 4, 5)
names = propensity_fe.write_cases(dq, cases)
os.makedirs(os.path.join(dq, "propensity"))
heads = "case," + ",".join(names)
with open(os.path.join(dq, propensity_fe.RUNS), "w") as f:
    f.write(heads + ",status\n" + "".join(f"{i}," + ",".join("0" for _ in names) + f",{'failed' if i == 3 else 'ok'}\n" for i in range(4)))
with open(os.path.join(dq, propensity_fe.CEA), "w") as f:
    f.write(heads + ",re,im\n" + "".join(f"{i}," + ",".join("0" for _ in names) + f",{re},{im}\n" for i, re, im in
                                        ((0, -0.008, 0.32), (1, 0.004, 0.32), (1, -0.5, 3.0), (2, -0.008, 0.32))))
decay = w + 0.002 * np.exp(-0.0079 * t) * np.cos(2 * math.pi * 0.0503 * t)
for i, (rate_i, stick_i) in enumerate([(rate + ripple, np.where(stuck, 11, 0)), (decay, 0 * t), (decay, 0 * t)]):
    write_csv(os.path.join(dq, "propensity", f"series.case{i}.csv"), dict(cols, hub_rate=np.concatenate([[0.0], rate_i]),
                                                                         stick_nodes=np.concatenate([[0], stick_i])))
fe = propensity_fe.summarize(dq, propensity_fe.classify(dq, opts, cases, True), 5, True, T_END, 8)
got = [(r["class"], r["mechanism"], r["squeaks"]) for r in csv.DictReader(open(os.path.join(dq, "propensity.csv")))]
c.check(got == [("bistable", "stick-slip", "1"), ("flutter", "flutter", "1"), ("quiet", "quiet", "0"), ("failed", "failed", "0")]
        and fe["fraction"] == 0.5 and fe["by_mechanism"]["stick-slip"] == 0.25 and fe["by_mechanism"]["flutter"] == 0.25
        and fe["agreement"]["stable_and_stick_slip"] == 1 and fe["agreement"]["unstable_and_settled"] == 1,
        f"the finite elements' classes from the maps' files: {got}; {fe['by_mechanism']}, agreement {fe['agreement']}")
# the same stick-slip series with the motor's ripple at the cycle's frequency (1 % off): the ripple drives the patch
rippled = dict(opts, drive_ripple="0.001", drive_ripple_frequency=repr(1.01 / cyc["period"]))
first = propensity_fe.classify(dq, rippled, cases, True)[0]
c.check((first["class"], first["mechanism"], first["squeaks"]) == ("forced stick-slip", "forced", 1),
        f"a stick-slip cycle at the motor's ripple (1 % off) is forced: {first['class']}, {first['mechanism']}")

# the kicks about the steady state (rollerreport.disturbances): synthetic series of the map, settled below 90 % of the
# motor's rate, a stick-slip cycle from it (stuck at the bottom of every period, slipping whole otherwise)
from rollerreport import disturbances  # noqa: E402

dk = scratch("rollerreport_kicks_")
plan = disturbances.plan(opts, periods=12)
disturbances.write_cases(dk, plan)
os.makedirs(os.path.join(dk, "disturbances"))
with open(os.path.join(dk, disturbances.RUNS), "w") as f:
    f.write("case,drive_kick,status\n" + "".join(f"{i},{J!r},ok\n" for i, J in enumerate(plan["impulses"])))
tk = np.arange(1, int(plan["t_end"] / DT)) * DT
after, ph = tk >= plan["t_kick"], 2 * math.pi * 0.0511 * (tk - plan["t_kick"])
for i, x in enumerate(plan["kicks"]):
    if x >= 0.9:
        hub, st = w + after * 0.0075 * np.sin(ph), np.where(after & (np.sin(ph) < -0.9), 11, 0)
    else:
        hub, st = w + 1e-5 * np.cos(0.3 * tk) + after * x * w * np.exp(-0.008 * (tk - plan["t_kick"])) * np.cos(ph), 0 * tk
    write_csv(os.path.join(dk, "disturbances", f"series.case{i}.csv"), {"t": np.concatenate([[0.0], tk]), "hub_rate": np.concatenate([[w], hub]),
                                                                         "stick_nodes": np.concatenate([[0], st])})
ks = disturbances.classify(dk, opts, plan, 1.0, True)
ev = mechanisms.stick_slip(dict(stick_slip_cycle=dict(cyc, column="hub_rate", t_min=25.0, t1=T_END), disturbances=ks, seconds_per_unit=1.0))
one = ks["onedof"] or {}
c.check(ks["steady"] == "settled" and ks["coexists"] and ks["smallest_kick"]["kick_rate_fraction"] == 0.9 and ks["largest_settled"] == 0.8
        and 0.8 <= one.get("threshold", 0) <= 0.9 and ev["disturbances"]["coexists"] and any("bistable" in e and "90 %" in e for e in ev["evidence"]),
        f"kicks: the approach {ks['steady']}, stick-slip from {ks['smallest_kick']}, {ks['largest_settled']} settles; the 1-DOF's threshold "
        f"{one.get('threshold')}; evidence: {[e for e in ev['evidence'] if 'kick' in e]}")

# the CEA's unstable mode against the scene's own run (mechanisms.run_growth): a line at f growing at g is confirmed,
# the same line steady (beside a louder steady line elsewhere) is not
dg = scratch("run_growth_")
tt = np.arange(0, 0.5, 5e-6)
F0, G0 = 1158.6, 64.7
for grow, want in ((G0, True), (0.0, False)):
    with open(os.path.join(dg, "stickslip.csv"), "w") as f:
        f.write("t,contact_force,friction_force,hub_rate\n")
        y = 1e-6 * np.exp(grow * tt) * np.sin(2 * math.pi * F0 * tt) + 0.01 * np.sin(2 * math.pi * 873 * tt)
        f.write("0,0,0,0\n" + "".join(f"{a:.9g},{100 + b:.12g},{b:.12g},0\n" for a, b in zip(tt[1:], y[1:])))
    rg = mechanisms.run_growth(dg, F0, G0)
    c.check(rg is not None and rg["confirmed"] is want and (abs(rg["growth_rate"] / G0 - 1) < 0.05 if want else abs(rg["growth_rate"]) < 0.05 * G0),
            f"run_growth: a line growing at {grow} /s measured at {rg['growth_rate'] if rg else math.nan:+.3f} /s, confirmed {rg['confirmed'] if rg else None}")
    # without a CEA (rollerreport.run_lines): the same run read for any line that grows; the ripple's left out
    rl = run_lines.read(dg, {"ripple": {"frequency": 873.0}})
    top = next((x for x in rl["lines"] if abs(x["frequency"] / F0 - 1) < 0.01), {}) if rl else {}
    c.check(all(abs(x["frequency"] / 873 - 1) > 0.03 for x in rl["lines"]) and top.get("grows") is want
            and len(run_lines.growing(rl)) == int(want)
            and (abs(top["growth_rate"] / G0 - 1) < 0.1 if want else abs(top["growth_rate"]) < 0.1 * G0),
            f"run_lines: the line at {top.get('frequency', math.nan):.1f} Hz ({top.get('column')}) at "
            f"{top.get('growth_rate', math.nan):+.2f} /s against {grow} /s, grows {top.get('grows')}; the ripple's 873 Hz left out; "
            f"lines that grow: {run_lines.growing(rl)} (of {len(rl['lines'])} followed)")

# a clamped scene's starts (rollerreport.divergent): the map's divergent cells (a real positive eigenvalue in
# sweep.csv) and the scene's own, each series classified: chatter (the stick count changing at most steps, the force
# holding), stick-slip (a saw-tooth, stuck then slipping whole every period), growing, settled
from rollerreport import divergent  # noqa: E402

dd = scratch("rollerreport_starts_")
V0, MU0 = 0.2356, 0.8
cells = [(V0, MU0, 3537.0), (0.0, 0.8, 11198.0), (V0, 0.4, 8054.0), (0.1, 0.4, 2000.0), (0.0, 0.4, -94.0)]
with open(os.path.join(dd, "sweep.csv"), "w") as f:
    f.write("case,sheet_speed,friction,re,im,frequency,growth_rate,order,wave,error\n")
    for i, (v, mu, g) in enumerate(cells):
        f.write(f"{i},{v!r},{mu!r},-30,3000,3000,-30,0,standing,1e-9\n{i},{v!r},{mu!r},{g!r},0,0,{g!r},1,standing,1e-9\n")
scene_c = {"sheet_speed": V0, "friction": MU0, "surface_speed": V0 / 0.99}
sp = divergent.plan({"ts_max_time": "0.01", "obstacle_speed": "0.025", "obstacle_depth": "7.5e-5"}, scene_c, os.path.join(dd, "sweep.csv"))
divergent.write_cases(dd, sp)
os.makedirs(os.path.join(dd, "divergent"))
with open(os.path.join(dd, divergent.RUNS), "w") as f:
    f.write("case,friction,sheet_speed,status\n" + "".join(f"{i},0,0,ok\n" for i in range(len(sp["cases"]))))
ts = np.arange(0, 0.01, 5e-6)
ph = (2000 * ts) % 1.0
rng = np.random.default_rng(5)
series = [(-30 + 0.01 * rng.standard_normal(len(ts)), 10 + (np.arange(len(ts)) % 2)),  # chatter
          (-30 + 5 * ph, np.where(ph < 0.6, 8, 0)),  # stick-slip at 2 kHz
          (-30 + 0.5 * np.exp(300 * (ts - 0.005)) * np.sin(2 * math.pi * 1500 * ts), 8 + 0 * ts),  # growing
          (-30 + 0.01 * np.exp(-500 * ts) * np.sin(2 * math.pi * 1500 * ts), 8 + 0 * ts)]  # settled
for i, (q, st) in enumerate(series):
    write_csv(os.path.join(dd, "divergent", f"series.case{i}.csv"), {"t": ts, "friction_force": q, "contact_force": 100 + 0 * ts, "stick_nodes": st})
ds = divergent.classify(dd, sp, 1.0)
rows = divergent.read(dd)["rows"]
mech = mechanisms.stick_slip(dict(starts=divergent.read(dd), scene=scene_c, seconds_per_unit=1.0))
long_plan = divergent.plan({"ts_max_time": "0.01", "obstacle_speed": "0.025", "obstacle_depth": "7.5e-5"}, scene_c, os.path.join(dd, "sweep.csv"), 100.0)
c.check([x["map_case"] for x in sp["cases"]] == [0, 1, 2, 3] and sp["t_min"] == 0.005
        and abs(long_plan["t_end"] - (0.003 + divergent.SETTLE / 100.0)) < 1e-15 and long_plan["t_min"] == 0.5 * long_plan["t_end"] and [r["outcome"] for r in rows] == ["chatter", "stick-slip", "growing", "settled"]
        and ds["scene"] == "chatter" and ds["squeak"] == [1, 2] and abs(float(rows[1]["cycle_frequency_hz"]) / 2000 - 1) < 0.01
        and abs(float(rows[0]["friction_ratio"]) - 0.3) < 1e-3 and mech["status"] == "run" and mech["squeals"] is False
        and any("2 of the map's 3 other divergent cells squeak" in e for e in mech["evidence"]),
        f"starts: the scene and its map's 3 other divergent cells (the stable one left out) read as {[r['outcome'] for r in rows]}, "
        f"the stick-slip cycle at {float(rows[1]['cycle_frequency_hz']):.1f} Hz; the mechanism {mech['status']}, squeals {mech['squeals']}")
c.close()
