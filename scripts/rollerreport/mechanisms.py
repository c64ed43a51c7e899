"""The squeak's mechanisms, each a function of the report's context (the folder, the scene, what the parts found)
returning a dict with the keys of SPEC section 10: kind (flutter, stick-slip, forced), status ("run", or "not run:
WHY"), squeals (True, False, or None when not run), frequency_hz, growth_rate_per_s or limit_cycle_amplitude,
spl_db, evidence (a list of sentences). A mechanism that cannot be computed yet says so and what it needs; it never
invents a result. New mechanisms plug in by adding a function to MECHANISMS; one that needs roller runs declares
them in NEEDS (the options the roller must know: the driver runs it only when `roller -help` lists them).
"""
import math
import os

import numpy as np

# what each mechanism needs of the roller that main does not have yet (the branches that bring it)
NEEDS = {
    "stick-slip": (["-axle"], "stickslip.csv, the scene's start from rest on the axle run to its limit cycle "
                   "(rollerreport.run runs it for a scene with axle: true)"),
    "forced": (["-drive_ripple"], "forced.csv, the scene driven with the motor's ripple (rollerreport.run --ripple "
               "AMPLITUDE,FREQUENCY on a scene with axle: true)"),
}
PROPENSITY_RANGES = {  # issue 38: the spread of real rollers
    "friction_kinetic": [0.65, 1.4], "friction_static_over_kinetic": [1.0, 1.5], "nip_force_N_per_cm": [0.8, 2.5],
    "loss_factor": [0.05, 0.3], "surface_speed_m_per_s": [0.12, 0.36], "drive_stiffness_factor": [0.5, 1.5],
    "bracket_stiffness_factor": [0.5, 1.5]}


def not_run(kind, why, evidence=()):
    return {"kind": kind, "status": f"not run: {why}", "squeals": None, "frequency_hz": None, "growth_rate_per_s": None,
            "limit_cycle_amplitude": None, "spl_db": None, "evidence": list(evidence)}


def flutter(ctx):
    """Mode coupling about the steady rolling state: the CEA's least stable mode (modes.csv), the map, the seeded
    transient's fit of the seed's response."""
    v = ctx.get("verdict")
    axle = bool(ctx.get("scene", {}).get("axle"))
    if v is None:
        lin = ctx.get("onedof") if axle else None
        ev = [] if not lin else [
            f"not a substitute: the 1-DOF closed form (rollerref.stickslip.linear_stability) of the scene's drive alone "
            f"(no rubber modes, no mode coupling) has steady sliding {'stable' if lin['stable'] else 'UNSTABLE'}, growth "
            f"rate {lin['growth_rate']:+.4g} per unit time at {lin['frequency']:.4g} cycles per unit time"]
        if ctx.get("cea_error") and ctx.get("run_lines"):
            return flutter_from_run(ctx, ev)
        if ctx.get("cea_error"):
            return not_run("flutter", f"roller -modes refused the scene: {ctx['cea_error']}", ev)
        return not_run("flutter", "no CEA (modes.csv missing or its run failed)", ev)
    s = v["seconds_per_unit"]
    ev = [f"CEA: the least stable oscillating mode (order {v['order']}, {v['wave']}) grows at {v['growth_rate'] / s:+.4g} /s "
          f"at {v['pitch_hz']:.1f} Hz; loss-factor margin {v['loss_factor_margin']:+.3g} (modes.csv)"]
    if v.get("diverges"):
        ev.append(f"CEA: a real positive eigenvalue {v['real_growth_rate']:+.4g}: the steady state diverges (no pitch)")
    dm = v.get("drive_mode")
    if dm:
        from .report import drive_mode_line

        ev.append("CEA on the axle: " + drive_mode_line(dm))
    fit = ctx.get("fit")
    if fit:
        ev.append(f"seeded transient ({'the seed' + chr(39) + 's response' if fit.get('response') else 'the seeded run alone'}, "
                  f"{fit.get('column')}): {fit['growth_rate'] / s:+.4g} /s at {fit['frequency'] / s:.1f} Hz (transient.csv)")
    if ctx.get("friction_onset") is not None:
        ev.append(f"map: squeal from friction {ctx['friction_onset']:g} at the scene's creep (sweep.csv)")
    elif "friction_onset" in ctx:
        ev.append("map: no squeal at any swept point (sweep.csv)")
    snd = ctx.get("sound") or {}
    squeals = bool(v["squeals"])
    run = run_growth(ctx["folder"], v["frequency"], v["growth_rate"]) if axle and squeals and ctx.get("folder") else None
    if run:  # the scene's own run (stickslip.csv) was seeded by its start: a growing mode grows in it
        ev.append(f"the scene's own run (stickslip.csv, {run['column']} within 3 % of {v['pitch_hz']:.1f} Hz, windows of "
                  f"{run['window']:.3g} from t = {run['t0']:.4g} to {run['t1']:.4g}): its amplitude grows at "
                  f"{run['growth_rate'] / s:+.4g} /s against the CEA's {v['growth_rate'] / s:+.4g} /s: "
                  + ("confirmed" if run["confirmed"] else "NOT confirmed: the CEA's instability does not grow in the run "
                     "(a linearization artefact or one the contact's nonlinearity holds: docs/squeal.md 7.10)"))
        squeals = run["confirmed"]
    if axle and not snd:  # no seeded transient on the axle: the mode's level is not computed
        return {"kind": "flutter", "status": "run", "squeals": squeals, "frequency_hz": v["pitch_hz"],
                "growth_rate_per_s": v["growth_rate"] / s, "limit_cycle_amplitude": None, "spl_db": None,
                "loss_factor_margin": v["loss_factor_margin"],
                "spl_note": "not computed: on the axle the report runs no seeded transient (docs/squeal.md 10)",
                "drive_mode": dm, "evidence": ev}
    return {"kind": "flutter", "status": "run", "squeals": squeals, "frequency_hz": v["pitch_hz"],
            "growth_rate_per_s": v["growth_rate"] / s, "limit_cycle_amplitude": None,
            "loss_factor_margin": v["loss_factor_margin"], "spl_db": snd.get("spl_mode_db"), "spl_note": ("the level of the mode's line (within 20 % of its pitch) in the "
            "seeded transient's sound, its line at {:.1f} Hz".format(snd.get("mode_line_hz", 0)) if snd.get("mode_line_resolved", True)
            else "an upper bound: the sound within 20 % of the pitch has no line at it (its loudest at "
            f"{snd.get('mode_line_hz', 0):.1f} Hz): the mode hardly moves the surface normally (a torsional mode moves it "
            "tangentially)") + "; " + (snd.get("level_note") or ""), "evidence": ev}


def flutter_from_run(ctx, ev):
    """Flutter without a CEA (roller -modes refused the scene: a sheet with its own mass): the scene's own run read for
    a line that grows (rollerreport.run_lines); squeals when one does."""
    from . import run_lines

    r, s = ctx["run_lines"], ctx.get("seconds_per_unit", 1.0)
    grow = [x for x in r["lines"] if x["grows"]]
    top = (grow or r["lines"] or [None])[0]
    return {"kind": "flutter", "status": "run", "method": "the scene's own run (no CEA)", "squeals": bool(grow),
            "frequency_hz": top["frequency"] / s if top else None, "growth_rate_per_s": top["growth_rate"] / s if top else None,
            "limit_cycle_amplitude": None, "spl_db": None, "spl_note": "the run's sound is the WAV's (its loudest line)",
            "evidence": [f"no CEA: roller -modes refused the scene: {ctx['cea_error']}"] + run_lines.sentences(r, s) + ev}


def run_growth(folder, f, g, columns=("contact_force", "friction_force", "hub_rate")):
    """The growth of the CEA's unstable mode (frequency f, growth rate g > 0, per unit time) in the scene's own run
    (stickslip.csv, seeded by its start): the amplitude within 3 % of f in windows of 20 periods (Hann), fitted as
    log-linear over the run after its first tenth, on the column where it is largest. Confirmed when it grows at more
    than half of g; None without the run or with fewer than four windows."""
    path = os.path.join(folder, "stickslip.csv")
    if not os.path.exists(path) or not f or not g or g <= 0:
        return None
    d = _monitor(folder, "stickslip.csv", ["t"] + list(columns))
    t = d["t"]
    win = 20.0 / f
    starts = np.arange(t[0] + 0.1 * (t[-1] - t[0]), t[-1] - win, win)
    if len(starts) < 4:
        return None
    best = None
    for c in columns:
        if c not in d:
            continue
        amps = []
        for a in starts:
            w = (t >= a) & (t < a + win)
            y = d[c][w] - np.mean(d[c][w])
            F = np.abs(np.fft.rfft(y * np.hanning(len(y))))
            fr = np.fft.rfftfreq(len(y), t[w][1] - t[w][0])
            band = np.abs(fr / f - 1) < 0.03
            amps.append(float(F[band].max()) if band.any() else 0.0)
        amps = np.array(amps)
        if np.all(amps > 0) and (best is None or amps.max() > best[1].max()):
            best = (c, amps)
    if best is None:
        return None
    rate = float(np.polyfit(starts + 0.5 * win, np.log(best[1]), 1)[0])
    return {"column": best[0], "growth_rate": rate, "confirmed": bool(rate > 0.5 * g), "window": win,
            "t0": float(starts[0]), "t1": float(starts[-1] + win)}


def limit_cycle(t, y, tail=1.0 / 3):
    """The last `tail` of a series: {frequency, amplitude (half the peak-to-peak), envelope growth rate}: a limit
    cycle is a sustained oscillation (|growth| small against the frequency), the start of stick-slip from rest
    reaches one (rollerref's 1-DOF references, docs/validation.md 9)."""
    from .sound import envelope_rate, loudest_line

    t, y = np.asarray(t, float), np.asarray(y, float)
    m = t >= t[0] + (1 - tail) * (t[-1] - t[0])
    yt = y[m] - np.mean(y[m])
    rate = 1.0 / (t[1] - t[0])
    f = loudest_line(yt, rate, fmin=2.0 / (t[-1] - t[0]) if t[-1] > t[0] else 0.0, pad=8)
    return {"frequency": f, "amplitude": 0.5 * float(np.ptp(yt)), "growth_rate": envelope_rate(yt, rate, f) if f > 0 else math.nan}


def _monitor(folder, name, columns):
    """{column: array} of a monitor CSV of the folder (row 0, the state before the first contact solve, left out)."""
    from .report import num, read_rows

    rows = read_rows(os.path.join(folder, name))[1:]
    return {c: np.array([num(r.get(c)) for r in rows]) for c in columns if rows and c in rows[0]}


def stick_slip_cycle(folder, scene):
    """The limit cycle of the stick-slip run (stickslip.csv: the scene's start from rest on -axle, roller
    -monitor_csv): rollerreport.cycle.detect on hub_rate (the hub's speed) after the motor's ramp (scene.json's
    "drive_started", else the last two thirds), with stick_nodes; None without stickslip.csv."""
    from . import cycle

    if not os.path.exists(os.path.join(folder, "stickslip.csv")):
        return None
    d = _monitor(folder, "stickslip.csv", ["t", "hub_rate", "stick_nodes", "slip_nodes", "friction_force"])
    column = "hub_rate" if "hub_rate" in d else "friction_force"
    t = d["t"]
    t_min = scene.get("drive_started")
    t_min = float(t_min) if t_min is not None else t[0] + (t[-1] - t[0]) / 3
    cyc = cycle.detect(t, d[column], d.get("stick_nodes"), t_min=t_min)
    cyc.update(column=column, t_min=t_min, t0=float(t[0]), t1=float(t[-1]))
    return cyc


def stick_slip(ctx):
    """Stick-slip: the start from rest on the real axle run to its limit cycle (stickslip.csv). Squeaks when the
    cycle is sustained and the patch sticks in every period (rollerreport.cycle.detect); the map's divergences and the
    1-DOF closed form are evidence beside it."""
    ev = [f"map: a real positive eigenvalue (divergence, the stick-slip onset of the linearization) at {d}" for d in
          ctx.get("divergent", [])]
    v = ctx.get("verdict") or {}
    if v.get("diverges"):
        ev.append(f"CEA: the scene's steady state diverges (real eigenvalue {v['real_growth_rate']:+.4g})")
    cyc = ctx.get("stick_slip_cycle")
    if cyc is None and (ctx.get("starts") or {}).get("status") == "run":
        return clamped_starts(ctx, ev)
    if cyc is None:
        return not_run("stick-slip", NEEDS["stick-slip"][1], ev)
    s = ctx.get("seconds_per_unit", 1.0)
    ev.append(f"start from rest (stickslip.csv, {cyc['column']} from t = {cyc['t_min']:.4g} to {cyc['t1']:.4g}): "
              + cyc["why"] + (": a sustained stick-slip limit cycle" if cyc["stick_slip"] else
                              ": a sustained oscillation without stick" if cyc["sustained"] else ": no sustained cycle"))
    lin = ctx.get("onedof")
    cea_stable = None if not v else not v.get("unstable")
    if v:
        ev.append(f"CEA (modes.csv): steady sliding {'stable' if cea_stable else 'UNSTABLE'}, the least stable mode "
                  f"{v['growth_rate']:+.4g} per unit time" + (": the cycle coexists with a stable steady state (bistable)"
                                                              if cea_stable and cyc["stick_slip"] else ""))
    if lin:
        ev.append(f"1-DOF closed form (rollerref, the CEA's cross-check on the drive): steady "
                  f"sliding {'stable' if lin['stable'] else 'UNSTABLE'}, growth rate {lin['growth_rate']:+.4g} per unit time"
                  + (": the cycle coexists with a stable steady state (bistable)" if not v and lin["stable"] and cyc["stick_slip"] else ""))
        if lin.get("start_from_rest"):
            ev.append(f"1-DOF start from rest (rollerref.basin.classify): {lin['start_from_rest']}")
        if ctx.get("steady_stuck"):
            ev.append(f"the 1-DOF slides whole, the CEA's steady state rolls with {ctx['steady_stuck']} nodes stuck: its "
                      "sliding closed form is not this scene's")
    dist = ctx.get("disturbances") or {}
    if dist.get("status") == "run":
        from .disturbances import lines as disturbance_lines

        ev += disturbance_lines(dist)
    ok = math.isfinite(cyc["frequency"])
    snd = ctx.get("stick_slip_sound") or {}
    return {"kind": "stick-slip", "status": "run", "squeals": bool(cyc["stick_slip"]),
            "frequency_hz": cyc["frequency"] / s if ok else None, "period": cyc["period"] if ok else None,
            "growth_rate_per_s": cyc["growth_rate"] / s if ok else None,
            "limit_cycle_amplitude": cyc["amplitude"] if ok else None, "limit_cycle_column": cyc["column"],
            "stick_every_period": cyc["stick_every_period"], "sustained": cyc["sustained"],
            "periods_used": cyc["periods_used"], "spl_db": snd.get("spl_db"),
            "disturbances": {k: dist.get(k) for k in ("steady", "coexists", "smallest_kick", "largest_settled", "onedof", "file")} if dist.get("status") == "run" else None,
            "spl_note": snd.get("level_note") if snd else None, "evidence": ev}


def clamped_starts(ctx, ev):
    """Stick-slip on a clamped hub: the scene's own start from rest (case 0 of rollerreport.divergent) squeaks when it
    reaches a stick-slip cycle, a growing oscillation or an irregular vibration of the friction force; the map's
    divergent cells' starts beside it as evidence."""
    from . import divergent

    d = ctx["starts"]
    row = d["rows"][0]
    s = ctx.get("seconds_per_unit", 1.0)
    ev = ev + divergent.lines(d, ctx.get("scene", {}))
    others = [r for r in d["rows"][1:] if r["outcome"] in divergent.SQUEAKS]
    if others:
        ev.append(f"{len(others)} of the map's {len(d['rows']) - 1} other divergent cells squeak by their starts")
    f = float(row["cycle_frequency_hz"]) if row["outcome"] == "stick-slip" else math.nan
    return {"kind": "stick-slip", "status": "run", "squeals": row["outcome"] in divergent.SQUEAKS,
            "frequency_hz": f if math.isfinite(f) else None, "growth_rate_per_s": float(row["cycle_growth_rate"]) / s
            if row["outcome"] == "growing" else None, "limit_cycle_amplitude": float(row["cycle_amplitude"])
            if row["outcome"] == "stick-slip" else None, "limit_cycle_column": "friction_force", "outcome": row["outcome"],
            "spl_db": None, "spl_note": "not computed: the starts of a clamped scene are not radiated (the WAV is the seeded "
            "transient's)", "evidence": ev}


def forced_response(folder, scene):
    """The forced run (forced.csv: the scene with -drive_ripple A -drive_ripple_frequency F, scene.json's "ripple"):
    the hub rate's amplitude at F over the last half (whole periods; rollerreport.cycle.lock_in, beside the drive's
    own decaying oscillation at the 1-DOF's frequency and rate) against the 1-DOF
    closed form rollerref.forced.one_dof (with the friction's slope about steady sliding, c_f); stick_nodes over that
    window (stick-slip: the closed form, a linearization about sliding, does not hold). None without forced.csv."""
    from . import cycle

    rip = scene.get("ripple") or {}
    monitor = (rip.get("files") or ["forced.csv"])[0]
    if not os.path.exists(os.path.join(folder, monitor)) or not rip.get("frequency"):
        return None
    d = _monitor(folder, monitor, ["t", "hub_rate", "stick_nodes"])
    t, f, a = d["t"], float(rip["frequency"]), float(rip["amplitude"])
    keep = t >= t[-1] - max((t[-1] - t[0]) / 2, 1.0 / f)
    lin = scene.get("onedof") or {}
    # the drive's own oscillation, decaying, fitted beside the line (a growing one, the 1-DOF's unstable sliding, is not
    # in a run that stays bounded: left out, it would swamp the fit)
    free = [(lin["frequency"], lin["growth_rate"])] if lin.get("frequency") and lin.get("growth_rate", 0) < 0 else []
    amp, phase = cycle.lock_in(t[keep], d["hub_rate"][keep], f, free=free)
    out = {"frequency": f, "ripple": a, "rate_amplitude": amp, "phase": phase, "t_window": [float(t[keep][0]), float(t[-1])], "file": monitor,
           "stick_nodes_max": int(np.max(d["stick_nodes"][keep])) if "stick_nodes" in d else None}
    ref = rip.get("one_dof")
    if ref:
        out["one_dof_rate_amplitude"] = ref["rate_amplitude"]
        out["ratio"] = amp / ref["rate_amplitude"] if ref["rate_amplitude"] else math.nan
    return out


def forced(ctx):
    """Forced resonance: the drive's ripple, the hub's response at the ripple's frequency (forced.csv) against the 1-DOF
    closed form, and its level at the listener."""
    r = ctx.get("forced_response")
    if r is None:
        return not_run("forced", NEEDS["forced"][1])
    s = ctx.get("seconds_per_unit", 1.0)
    snd = ctx.get("forced_sound") or {}
    ev = [f"ripple {r['ripple']:.4g} rad at {r['frequency']:.5g} per unit time ({r['frequency'] / s:.2f} Hz): the hub rate's "
          f"amplitude at it {r['rate_amplitude']:.5g} over t = {r['t_window'][0]:.4g}..{r['t_window'][1]:.4g} ({r.get('file', 'forced.csv')})"]
    if "one_dof_rate_amplitude" in r:
        ev.append(f"1-DOF closed form (rollerref.forced.one_dof, the friction's slope about steady sliding): "
                  f"{r['one_dof_rate_amplitude']:.5g} ({100 * (r['ratio'] - 1):+.1f} %)")
    if r.get("stick_nodes_max"):
        ev.append(f"the patch sticks in the window (stick_nodes up to {r['stick_nodes_max']}): the response is not the "
                  "linear one about sliding")
    if snd:
        ev.append(f"the radiated level at the ripple's frequency (within 20 %): {snd.get('spl_line_db', math.nan):.1f} dB SPL")
    sw = ctx.get("ripple_sweep") or {}
    if sw.get("peak"):
        pk, at = sw["peak"], sw.get("scene_ripple") or {}
        ev.append(f"the ripple swept over {sw['cases']} frequencies {sw['band_hz'][0]:.4g}-{sw['band_hz'][1]:.4g} Hz and the CEA's "
                  f"modes (ripple_sweep.csv, the reduced model): the hub's response peaks at {pk['frequency_hz']:.5g} Hz "
                  f"({pk['rate_per_ripple']:.4g} per rad of ripple{', stick-slip riding on it' if pk['stick_slip_in_window'] else ', sliding'})"
                  + (f"; the scene's ripple at {at['frequency_hz']:.5g} Hz is {-at['below_peak_db']:.1f} dB below the peak" if at.get("below_peak_db") is not None else "")
                  + (f"; the patch stick-slips in {sw['stick_slip_cases']} of the runs" if sw.get("stick_slip_cases") else ""))
    # squeals: the ripple's line is audible (above 0 dB SPL) at a frequency a listener hears (>= 20 Hz)
    spl = snd.get("spl_line_db")
    audible = spl is not None and math.isfinite(spl) and spl > 0 and r["frequency"] / s >= 20.0
    return {"kind": "forced", "status": "run", "squeals": bool(audible), "frequency_hz": r["frequency"] / s,
            "growth_rate_per_s": None, "limit_cycle_amplitude": None, "response_rate_amplitude": r["rate_amplitude"],
            "spl_db": spl, "sweep": sw.get("peak") and {"peak": sw["peak"], "scene_ripple": sw.get("scene_ripple"), "file": sw["file"]},
            "evidence": ev}


MECHANISMS = [flutter, stick_slip, forced]


def evaluate(ctx):
    """Every mechanism's dict, in order."""
    return [m(ctx) for m in MECHANISMS]


def verdict_word(mechs):
    """("squeals" | "does not squeal", complete): squeals if any mechanism that ran squeals; complete when every
    mechanism ran."""
    ran = [m for m in mechs if m["status"] == "run"]
    return ("squeals" if any(m["squeals"] for m in ran) else "does not squeal"), len(ran) == len(mechs)


def propensity(folder):
    """The odds over the real spread: propensity.json (rollerreport.propensity, the driver's part) when the folder
    holds it, else "not run" with what it needs."""
    path = os.path.join(folder, "propensity.json")
    if os.path.exists(path):
        import json

        with open(path) as f:
            return json.load(f)
    return {"cases": 0, "fraction": None, "by_mechanism": {}, "ranges": PROPENSITY_RANGES,
            "status": "not run: propensity.json missing (rollerreport.run runs the study for a scene with axle: true: "
                      "rollerreport.propensity)"}
