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
    "stick-slip": (["-axle"], "the start from rest on the real axle (-axle, branch axle) and transients long enough to "
                   "reach a limit cycle (-rom, branch rom)"),
    "forced": (["-drive_ripple"], "the drive's ripple swept over the audible modes (-axle -drive_ripple, branch axle)"),
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
    if v is None:
        return not_run("flutter", "no CEA (modes.csv missing or its run failed)")
    s = v["seconds_per_unit"]
    ev = [f"CEA: the least stable oscillating mode (order {v['order']}, {v['wave']}) grows at {v['growth_rate'] / s:+.4g} /s "
          f"at {v['pitch_hz']:.1f} Hz; loss-factor margin {v['loss_factor_margin']:+.3g} (modes.csv)"]
    fit = ctx.get("fit")
    if fit:
        ev.append(f"seeded transient ({'the seed' + chr(39) + 's response' if fit.get('response') else 'the seeded run alone'}, "
                  f"{fit.get('column')}): {fit['growth_rate'] / s:+.4g} /s at {fit['frequency'] / s:.1f} Hz (transient.csv)")
    if ctx.get("friction_onset") is not None:
        ev.append(f"map: squeal from friction {ctx['friction_onset']:g} at the scene's creep (sweep.csv)")
    elif "friction_onset" in ctx:
        ev.append("map: no squeal at any swept point (sweep.csv)")
    snd = ctx.get("sound") or {}
    return {"kind": "flutter", "status": "run", "squeals": bool(v["squeals"]), "frequency_hz": v["pitch_hz"],
            "growth_rate_per_s": v["growth_rate"] / s, "limit_cycle_amplitude": None,
            "spl_db": snd.get("spl_mode_db"), "spl_note": ("the level of the mode's line (within 20 % of its pitch) in the "
            "seeded transient's sound, its line at {:.1f} Hz".format(snd.get("mode_line_hz", 0)) if snd.get("mode_line_resolved", True)
            else "an upper bound: the sound within 20 % of the pitch has no line at it (its loudest at "
            f"{snd.get('mode_line_hz', 0):.1f} Hz): the mode hardly moves the surface normally (a torsional mode moves it "
            "tangentially)") + "; " + (snd.get("level_note") or ""), "evidence": ev}


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


def stick_slip(ctx):
    """Stick-slip: the start from rest on the real axle run to its limit cycle (stickslip.csv), and disturbances of
    growing size about the steady state. Today: the map's divergences (a real positive eigenvalue: the onset of
    stick-slip predicted by the linearization) are evidence, not a result."""
    ev = [f"map: a real positive eigenvalue (divergence, the stick-slip onset of the linearization) at {d}" for d in
          ctx.get("divergent", [])]
    v = ctx.get("verdict") or {}
    if v.get("diverges"):
        ev.append(f"CEA: the scene's steady state diverges (real eigenvalue {v['real_growth_rate']:+.4g})")
    path = os.path.join(ctx["folder"], "stickslip.csv")
    if not os.path.exists(path):
        return not_run("stick-slip", NEEDS["stick-slip"][1], ev)
    from .report import num, read_rows

    rows = read_rows(path)[1:]
    column = next((c for c in ("hub_rate", "friction_force", "alpha") if rows and c in rows[0]), None)
    t = np.array([num(r["t"]) for r in rows])
    cyc = limit_cycle(t, [num(r[column]) for r in rows])
    s = ctx.get("seconds_per_unit", 1.0)
    sustained = abs(cyc["growth_rate"]) < 0.01 * 2 * math.pi * cyc["frequency"] and cyc["amplitude"] > 0
    ev.append(f"start from rest (stickslip.csv, {column}): the last third oscillates at {cyc['frequency'] / s:.1f} Hz, "
              f"amplitude {cyc['amplitude']:.4g}, envelope {cyc['growth_rate'] / s:+.3g} /s")
    return {"kind": "stick-slip", "status": "run", "squeals": bool(sustained), "frequency_hz": cyc["frequency"] / s,
            "growth_rate_per_s": None, "limit_cycle_amplitude": cyc["amplitude"], "limit_cycle_column": column,
            "spl_db": None, "evidence": ev}


def forced(ctx):
    """Forced resonance: the drive's ripple swept over the audible modes, the response's peak with and without
    stick-slip (forced.csv)."""
    if not os.path.exists(os.path.join(ctx["folder"], "forced.csv")):
        return not_run("forced", NEEDS["forced"][1])
    return not_run("forced", "forced.csv present but its analysis is not built")


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
    """The odds over the real spread: not run until the physics of the axle, the Maxwell rubber and the reduced
    transient are merged (the cases would be classified by the CEA and the reduced transient)."""
    return {"cases": 0, "fraction": None, "by_mechanism": {}, "ranges": PROPENSITY_RANGES,
            "status": "not run: the nip force, the drive and bracket stiffness need -axle (branch axle), the loss factor "
                      "over the band -rubber maxwell (branch maxwell), the classification of each case the reduced "
                      "transient (-rom, branch rom)"}
