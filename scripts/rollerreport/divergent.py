"""The starts of a scene on a clamped hub (issue 38; docs/squeal.md 7.7.2, 9.6): the scene's own start from rest and the
start of every cell of its map that diverges (a real positive eigenvalue in sweep.csv: the steady state the
linearization says leaves without a pitch), each run as a transient and classified, so that a divergence is not named
and left.

Every case is the scene's own transient (its press, its feeding) with the cell's swept options (sheet speed, friction),
on the CEA's mesh and the reduced model (its basis.h5), long enough for the start's own oscillation to die out: the
press plus SETTLE decay times of the CEA's least stable oscillating mode (at least the scene's -ts_max_time, at most
MAX_SPAN times it); case 0 is the scene itself. All of them are one `roller -sweep -sweep_cases` map
(divergent_cases.csv; divergent_runs.csv; each case's series divergent/series.case<c>.csv). Each series is read over
its last half (after the press) on the friction force:

- stick-slip: rollerreport.cycle.detect with stick_nodes finds a sustained cycle that sticks and slips whole in every
  period;
- growing: the friction force's oscillation, a clean one of at least 1 % of its mean, still grows
  (rollerreport.propensity_fe.grows, as a propensity case's hub rate);
- irregular: the friction force in the audible band (below 20 kHz and an eighth of the step's rate: not the reduced
  contact's ringing near a quarter of it), less the mesh-passing lines (rollerreport.lines.notch: the
  discretization's), keeps a fluctuation of at least IRREGULAR of its mean over the window's last quarter, not DECAYED against its first quarter,
  without a clean cycle: a sustained vibration with no single pitch (noise);
- chatter: the stick count changes at more than CHATTER of the window's steps while the friction force holds (the step
  problem's node-level stick-slip under a steep mu(v), docs/squeal.md 7.7.2: its totals are the steady state's, no tone);
- settled: else.

stick-slip, growing and irregular squeak (a sustained vibration). divergent.csv (a row per case: its cell, the CEA's real growth rate, the outcome, the
friction ratio, the friction force's fluctuation and its loudest line) and divergent.json (the summary, with the CEA's
steady state that the scene's own start should reach)."""
import csv
import math
import os

import numpy as np

from . import cycle, propensity_fe, tables

CASES, RUNS, SERIES = "divergent_cases.csv", "divergent_runs.csv", os.path.join("divergent", "series.csv")
CHATTER = 1.0 / 3  # the fraction of steps whose stick count changes above which the patch chatters
NAMES = {"sheet_speed", "friction"}  # the map's swept options a case sets (rollerreport.run.map_command)
IRREGULAR = 0.01  # the last quarter's standard deviation of the friction force, against its mean
DECAYED = 0.5  # ... and against the first quarter's: below this fraction, the fluctuation is dying out
SQUEAKS = ("stick-slip", "growing", "irregular")
AUDIBLE = 20000.0  # Hz: the fluctuation read below it
SETTLE = 4.0  # decay times of the CEA's least stable oscillating mode after the press (its start's amplitude e^-4)
MAX_SPAN = 20.0  # the run at most this many times the scene's -ts_max_time


def cells(sweep_csv):
    """The map's divergent cells: [(map case, {swept option: value}, real growth rate)] of sweep.csv, the cases with a
    real eigenvalue of positive growth rate (the largest)."""
    from .report import is_real, num, read_rows

    rows = read_rows(sweep_csv)
    names = [k for k in rows[0] if k in NAMES] if rows else []
    out = {}
    for r in rows:
        g = num(r.get("growth_rate"))
        if is_real(r) and g > 0:
            c = int(r["case"])
            if c not in out or g > out[c][2]:
                out[c] = (c, {k: num(r[k]) for k in names}, g)
    return [out[c] for c in sorted(out)]


def plan(opts, scene, sweep_csv, decay=None):
    """{'cases': [{'map_case', 'options', 'cea_real_growth_rate'}], 't_end', 't_min'}: the scene (map case None) and
    its map's divergent cells, run to the press + SETTLE / decay (decay: the CEA's least stable oscillating mode's
    -growth rate, per unit time; the scene's -ts_max_time without one, and within 1 to MAX_SPAN times it); None without
    a -ts_max_time (the scene states no transient)."""
    T = float(opts.get("ts_max_time", 0.0) or 0.0)
    if T <= 0:
        return None
    own = {"sheet_speed": float(scene.get("sheet_speed", 0.0)), "friction": float(scene.get("friction", 0.0))}
    cases = [{"map_case": None, "options": own, "cea_real_growth_rate": None}]
    for c, x, g in cells(sweep_csv) if os.path.exists(sweep_csv) else []:
        x = {**own, **x}
        if all(abs(x[k] - own[k]) <= 1e-12 * max(1.0, abs(own[k])) for k in own):  # the scene's own cell: case 0
            cases[0].update(map_case=c, cea_real_growth_rate=g)
        else:
            cases.append({"map_case": c, "options": x, "cea_real_growth_rate": g})
    # the press: the obstacle's approach at -obstacle_speed to its depth (the window starts after it, at least at T/2)
    speed, depth = float(opts.get("obstacle_speed", 0.0) or 0.0), float(opts.get("obstacle_depth", 0.0) or 0.0)
    press = depth / speed if speed > 0 and speed < 1e6 else 0.0
    t_end = min(max(T, press + SETTLE / decay), MAX_SPAN * T) if decay and decay > 0 else T
    return {"cases": cases, "t_end": t_end, "t_min": max(0.5 * t_end, press), "decay": decay}


def write_cases(folder, p):
    names = sorted(NAMES)
    with open(os.path.join(folder, CASES), "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["case"] + names)
        for i, c in enumerate(p["cases"]):
            w.writerow([i] + [repr(float(c["options"][k])) for k in names])


def command(base, extra, folder, p, ranks, mpiexec, basis):
    j = lambda f: os.path.join(folder, f)  # noqa: E731
    mpi = [mpiexec, "-n", str(ranks)] if ranks > 1 else []
    return (mpi + base + ["-rom", "-rom_input", basis, "-ts_max_time", repr(p["t_end"]), "-sweep", j(RUNS), "-sweep_cases", j(CASES), "-sweep_monitor_csv",
                          j(SERIES), "-sweep_fit", "friction_force", "-quiet"] + extra)


def read_series(path):
    """(t, friction_force, contact_force, stick_nodes) of a case's series (propensity_fe.read_series)."""
    return propensity_fe.read_series(path, ("t", "friction_force", "contact_force", "stick_nodes"))


def verdict(series, t_min, f_m=None, seconds_per_unit=1.0):
    """A case's outcome (module docstring) and what it was read from; the fluctuation and its loudest line are the
    friction force's in the audible band below AUDIBLE Hz and an eighth of the step's rate, without the mesh-passing
    lines at f_m (rollerreport.lines.notch): the discretization's, as the reduced contact's ringing near a quarter of
    the step's rate (docs/squeal.md 9.4), not the roller's."""
    from .lines import notch

    t, q, p, st = series
    cyc = cycle.detect(t, q, st, t_min=t_min)
    m = t >= t_min
    qm, pm, sm = q[m], p[m], st[m]
    mean = float(np.mean(qm))
    vib = notch(t[m], qm, f_m, f_max=min(AUDIBLE * seconds_per_unit, 0.125 / (t[1] - t[0])))
    changes = float(np.mean(np.diff(sm) != 0)) if len(sm) > 1 else 0.0
    fluct = float(np.std(qm)) / max(abs(mean), 1e-300)
    f_line, a_line = math.nan, math.nan
    if len(qm) > 8:  # the fluctuation's loudest line over the window (Hann), its amplitude against the mean
        F = np.abs(np.fft.rfft(vib * np.hanning(len(vib)))) * 4.0 / len(vib)
        fr = np.fft.rfftfreq(len(vib), (t[m][-1] - t[m][0]) / (len(vib) - 1))
        k = 1 + int(np.argmax(F[1:])) if len(F) > 1 else 0
        f_line, a_line = float(fr[k]), float(F[k]) / max(abs(mean), 1e-300)
    quarter = len(qm) // 4
    first, last = (float(np.std(vib[:quarter])), float(np.std(vib[-quarter:]))) if quarter > 1 else (0.0, 0.0)
    sustained = last / max(abs(mean), 1e-300) >= IRREGULAR and last >= DECAYED * first
    outcome = ("stick-slip" if cyc["stick_slip"] else "growing" if propensity_fe.grows(cyc) else "irregular" if sustained else
               "chatter" if changes > CHATTER else "settled")
    return outcome, {"cycle": cyc, "friction_ratio": abs(mean) / max(float(np.mean(pm)), 1e-300), "stick_changes": changes,
                     "stick_mean": float(np.mean(sm)), "stick_min": int(np.min(sm)), "stick_max": int(np.max(sm)),
                     "fluctuation": fluct, "fluctuation_last": last / max(abs(mean), 1e-300), "fluctuation_first": first / max(abs(mean), 1e-300),
                     "line_frequency": f_line, "line_amplitude": a_line}


def steady_state(folder):
    """(-Q/P, stuck nodes) of the CEA's steady state (steady.csv), None without it."""
    from .report import read_rows

    path = os.path.join(folder, "steady.csv")
    if not os.path.exists(path):
        return None
    rows = read_rows(path)
    N = sum(float(r["normal_force"]) for r in rows)
    T = sum(float(r["tangential_force"]) for r in rows)
    return abs(T) / N if N > 0 else math.nan, sum(str(r["state"]).strip() in ("1", "1.0") for r in rows)


def classify(folder, p, seconds_per_unit=1.0, f_m=None):
    """divergent.csv and divergent.json from the map's series; returns the summary (with the scene's steady state:
    its start should end there)."""
    runs = {int(r["case"]): r for r in csv.DictReader(open(os.path.join(folder, RUNS), newline=""))}
    stem = os.path.join(folder, SERIES)[: -len(".csv")]
    rows = []
    for i, c in enumerate(p["cases"]):
        ok = runs.get(i, {}).get("status") == "ok"
        if ok:
            outcome, r = verdict(read_series(f"{stem}.case{i}.csv"), p["t_min"], f_m, seconds_per_unit)
            cyc = r["cycle"]
        else:
            outcome, r, cyc = "failed", {}, {"frequency": math.nan, "amplitude": math.nan, "growth_rate": math.nan}
        rows.append({"case": i, "map_case": "" if c["map_case"] is None else c["map_case"], "scene": int(i == 0),
                     **c["options"], "cea_real_growth_rate": c["cea_real_growth_rate"] if c["cea_real_growth_rate"] is not None else "",
                     "outcome": outcome, "friction_ratio": r.get("friction_ratio", math.nan),
                     "stick_changes": r.get("stick_changes", math.nan), "stick_mean": r.get("stick_mean", math.nan),
                     "stick_min": r.get("stick_min", ""), "stick_max": r.get("stick_max", ""),
                     "fluctuation": r.get("fluctuation", math.nan), "fluctuation_first": r.get("fluctuation_first", math.nan),
                     "fluctuation_last": r.get("fluctuation_last", math.nan), "line_hz": r.get("line_frequency", math.nan) / seconds_per_unit,
                     "line_amplitude": r.get("line_amplitude", math.nan), "cycle_frequency_hz": cyc["frequency"] / seconds_per_unit,
                     "cycle_amplitude": cyc["amplitude"], "cycle_growth_rate": cyc["growth_rate"], "status": "ok" if ok else "failed"})
    steady = steady_state(folder) or (None, None)
    out = {"status": "run", "cases": len(rows), "failed": sum(r["status"] != "ok" for r in rows), "t_end": p["t_end"],
           "t_min": p["t_min"], "scene": rows[0]["outcome"], "scene_diverges": p["cases"][0]["map_case"] is not None,
           "divergent_cells": len(rows) - 1 + int(p["cases"][0]["map_case"] is not None),
           "squeak": [r["case"] for r in rows if r["outcome"] in SQUEAKS], "file": "divergent.csv",
           "steady_friction_ratio": steady[0], "steady_stick_nodes": steady[1], "mesh_passing": f_m,
           "by_outcome": {k: sum(r["outcome"] == k for r in rows) for k in ("stick-slip", "growing", "irregular", "chatter", "settled", "failed")}}
    return tables.write(folder, "divergent", rows, out)


def lines(d, scene):
    """The evidence's sentences of the starts (divergent.json and divergent.csv's rows)."""
    if not d or d.get("status") != "run":
        return []
    surface = float(scene.get("surface_speed", 0.0) or 0.0)
    ev = []
    for r in d.get("rows", []):
        x = float(r["sheet_speed"])
        cell = (f"creep {1 - x / surface:.4g}" if surface else f"sheet_speed {x:.4g}") + f", friction {float(r['friction']):.4g}"
        g = r.get("cea_real_growth_rate")
        what = ("the scene's own start from rest" if r["scene"] in ("1", 1) else "the map's divergent cell") + f" ({cell}"
        what += f"; CEA: diverges, {float(g):+.4g} per unit time)" if g not in ("", None) else ")"
        if r["status"] != "ok":
            ev.append(f"{what}: its run failed (logs/divergent_runs.log)")
            continue
        ev.append(f"{what}, run to t = {d['t_end']:.4g} (divergent/series.case{r['case']}.csv, friction force from t = {d['t_min']:.4g}): "
                  f"{r['outcome'].upper() if r['outcome'] in SQUEAKS else r['outcome']}: -Q/P {float(r['friction_ratio']):.4g}"
                  + (f" (the CEA's steady state {d['steady_friction_ratio']:.4g}, {d['steady_stick_nodes']} nodes stuck)"
                     if r["scene"] in ("1", 1) and d.get("steady_friction_ratio") is not None else "") + ", "
                  + f"the friction force's fluctuation {100 * float(r['fluctuation_first']):.3g} % of its mean over the window's first "
                  f"quarter, {100 * float(r['fluctuation_last']):.3g} % over its last (its loudest line "
                  f"{float(r['line_hz']):.4g} Hz at {100 * float(r['line_amplitude']):.3g} %), the stick count "
                  f"{r['stick_min']}-{r['stick_max']} changing at {100 * float(r['stick_changes']):.3g} % of the steps"
                  + (": node-level chatter whose totals hold, not a tone (docs/squeal.md 7.7.2)" if r["outcome"] == "chatter" else
                     ": a sustained vibration without a single pitch" if r["outcome"] == "irregular" else ""))
    return ev


def read(folder):
    """divergent.json with its rows under 'rows'; None when the part has not run."""
    if not os.path.exists(os.path.join(folder, "divergent.json")):
        return None
    summary, rows = tables.read(folder, "divergent")
    summary["rows"] = rows
    return summary
