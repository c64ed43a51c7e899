"""Disturbances of growing size about the steady state (issue 38; docs/squeal.md 9.5): whether a stick-slip limit cycle
coexists with a steady state that the linearization calls stable, and the smallest disturbance that reaches it.

The steady state is approached without a start's stick: the motor turns at its speed from t = 0 (-theta_start 0
-drive_ramp 0: the hub, at rest in the motor's frame, turns with it) while the nip force ramps in over APPROACH_RAMP
times the scene's -nip_ramp, so that the contact slides from its first touch and the press excites the drive's mode
little; the run then settles for SETTLE_PERIODS periods of the drive's mode (the 1-DOF's frequency). At that time the hub
takes an angular impulse J (`roller -drive_kick J -drive_kick_time T`, a jump of its rate by J/I, I the hub's and the
rubber's polar inertia), against the motor (toward the sheet's speed: the direction that brings the patch toward
sticking), of the sizes KICKS of the surface speed (Delta Omega / omega), plus one case without a kick (the undisturbed
approach: the reference); every case runs PERIODS periods of the drive's mode after the kick. All of them are one
`roller -sweep -sweep_cases` map on the reduced model (the scene's basis; its ripple and everything else the scene's).

Each case's series is read as the propensity reads a start (rollerreport.propensity_fe.transient_verdict after the
kick): stick-slip (a sustained cycle, stuck and slipping whole every period), growing, or settled (neither: the
undisturbed state may itself oscillate, the motor's ripple's forced line); a stick-slip cycle at the motor's ripple
frequency (within 2 %) is the ripple's (forced). Each kicked run is also compared with the undisturbed one (the same
approach, the same ripple: their difference is the kick's own response): `returned`, the largest |hub rate difference|
over the last RETURN_PERIODS periods of the drive's mode as a fraction of the motor's rate.

disturbances.csv (a row per kick), disturbances.json (the undisturbed approach's verdict, the smallest kick reaching a
cycle, whether the cycle coexists with a steady state that settles), disturbances.png (each case's hub rate).
"""
import csv
import math
import os

import numpy as np

from . import onedof, propensity_fe, tables

CASES, RUNS, SERIES = "disturbances_cases.csv", "disturbances_runs.csv", os.path.join("disturbances", "series.csv")
# Delta Omega / omega of the kicks (0: the undisturbed approach): decades below a tenth, then steps of a tenth to 1.5
KICKS = (0.0, 0.001, 0.01, 0.03, 0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.7, 0.8, 0.9, 1.0, 1.25, 1.5)
APPROACH_RAMP = 3.0  # the approach's nip ramp, in the scene's -nip_ramp
SETTLE_PERIODS = 5  # periods of the drive's mode from the end of the press to the kick
PERIODS = 40  # periods of the drive's mode after the kick
RETURN_PERIODS = 5  # the kicked run against the undisturbed one over its last periods


def plan(opts, periods=PERIODS):
    """{'approach': the options of the approach, 't_kick', 't_end', 'inertia', 'omega', 'period', 'impulses'} of the scene
    ({name: string}), times per unit time; None without a drive (no mode to settle against)."""
    st = onedof.stability(opts)
    f, w = st["frequency"], onedof.value(opts, "omega")
    if not f or f <= 0 or w == 0:
        return None
    ramp = APPROACH_RAMP * float(opts.get("nip_ramp", 0.0) or 0.0)
    T = 1.0 / f
    t_kick = ramp + SETTLE_PERIODS * T
    I = st["inertia"]
    # against the motor: a jump of the hub's rate by -x omega
    return {"approach": ["-theta_start", "0", "-drive_ramp", "0", "-nip_ramp", repr(ramp), "-drive_kick_time", repr(t_kick)],
            "t_kick": t_kick, "t_end": t_kick + periods * T, "inertia": I, "omega": w, "period": T, "kicks": list(KICKS),
            "impulses": [-x * w * I for x in KICKS]}


def write_cases(folder, p):
    with open(os.path.join(folder, CASES), "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["case", "drive_kick"])
        for i, J in enumerate(p["impulses"]):
            w.writerow([i, repr(float(J))])


def command(base, extra, folder, p, ranks, mpiexec):
    j = lambda f: os.path.join(folder, f)  # noqa: E731
    mpi = [mpiexec, "-n", str(ranks)] if ranks > 1 else []
    return (mpi + base + p["approach"] + ["-ts_max_time", repr(p["t_end"]), "-sweep", j(RUNS), "-sweep_cases", j(CASES),
                                          "-sweep_monitor_csv", j(SERIES), "-sweep_fit", "friction_force", "-quiet"] + extra)


def hub_rate(path):
    return propensity_fe.read_series(path)[:2]


def residual(t, h, t_kick, period):
    """The hub rate's half peak-to-peak over the last period before the kick (the approach's own oscillation)."""
    m = (t >= t_kick - period) & (t < t_kick)
    return 0.5 * float(np.ptp(h[m])) if m.any() else math.nan


def classify(folder, opts, p, seconds_per_unit=1.0, cea_stable=None):
    """disturbances.csv and disturbances.json from the map's series; returns the summary."""
    runs = {int(r["case"]): r for r in csv.DictReader(open(os.path.join(folder, RUNS), newline=""))}
    stem = os.path.join(folder, SERIES)[: -len(".csv")]
    f_ripple = onedof.value(opts, "drive_ripple_frequency") if onedof.value(opts, "drive_ripple") else 0.0
    rows, ref = [], None
    for i, (x, J) in enumerate(zip(p["kicks"], p["impulses"])):
        ok = runs.get(i, {}).get("status") == "ok"
        back = math.nan
        if ok:
            series = propensity_fe.read_series(f"{stem}.case{i}.csv")  # read once: the verdict and the comparison
            kind, cyc = propensity_fe.transient_verdict(None, p["t_kick"], series)
            t, h = series[:2]
            floor = residual(t, h, p["t_kick"], p["period"])
            if i == 0:
                ref = (t, h)
            elif ref is not None and len(ref[0]) == len(t) and x > 0:
                tail = t >= t[-1] - RETURN_PERIODS * p["period"]
                back = float(np.max(np.abs(h[tail] - ref[1][tail]))) / abs(p["omega"])
        else:
            kind, cyc, floor = "failed", {"frequency": math.nan, "amplitude": math.nan, "growth_rate": math.nan}, math.nan
        forced = kind == "stick-slip" and f_ripple > 0 and abs(cyc["frequency"] / f_ripple - 1) < propensity_fe.FORCED_SPREAD
        rows.append({"case": i, "kick_rate_fraction": x, "drive_kick": J, "rate_jump": -x * p["omega"],
                     "outcome": "forced stick-slip" if forced else kind, "cycle_frequency": cyc["frequency"],
                     "cycle_frequency_hz": cyc["frequency"] / seconds_per_unit, "cycle_amplitude": cyc["amplitude"],
                     "cycle_growth_rate": cyc["growth_rate"], "residual_before_kick": floor, "returned": back,
                     "status": "ok" if ok else "failed"})
    base = rows[0]
    floor = base["residual_before_kick"]
    reach = [r for r in rows[1:] if r["outcome"] == "stick-slip"]
    smallest = min(reach, key=lambda r: r["kick_rate_fraction"]) if reach else None
    # the cycle coexists with a steady state when the undisturbed approach settles and a kick reaches the cycle
    coexists = bool(base["outcome"] == "settled" and smallest is not None)
    out = {"status": "run", "cases": len(rows), "failed": sum(r["status"] != "ok" for r in rows), "t_kick": p["t_kick"], "omega": p["omega"],
           "t_end": p["t_end"], "approach": p["approach"], "period": p["period"], "steady": base["outcome"],
           "steady_residual": floor, "steady_oscillation": base["cycle_amplitude"], "coexists": coexists, "cea_stable": cea_stable,
           "returned_max": max((r["returned"] for r in rows[1:] if r["outcome"] == "settled" and math.isfinite(r["returned"])), default=None),
           "smallest_kick": None if smallest is None else {k: smallest[k] for k in (
               "kick_rate_fraction", "drive_kick", "rate_jump", "cycle_frequency_hz", "cycle_amplitude")},
           "largest_settled": max((r["kick_rate_fraction"] for r in rows[1:] if r["outcome"] == "settled"), default=None),
           "onedof": onedof_threshold(opts), "ripple": f_ripple or None, "file": "disturbances.csv"}
    return tables.write(folder, "disturbances", rows, out)


def onedof_threshold(opts):
    """The 1-DOF's smallest kick toward stick that reaches its cycle (rollerref.basin.kick_threshold), as a fraction of
    the motor's rate; None on a sheet with its own mass (the 1-DOF's sheet is kinematic) or when no kick up to 4 times
    the slip rate does."""
    if float(opts.get("sheet_mass", 0.0) or 0.0) > 0:
        return None
    from rollerref import basin

    r = basin.kick_threshold(onedof.torsion(opts, ripple=False))
    w = abs(onedof.value(opts, "omega"))
    return None if r is None else {k: r[k] / w for k in ("threshold", "sliding_at", "cycle_at")}


def lines(d, s=1.0):
    """The evidence's sentences of a disturbances.json summary."""
    if not d or d.get("status") != "run":
        return []
    ev = [f"disturbances about the steady state (disturbances.csv, the reduced model): the approach (the motor turning from "
          f"t = 0, the nip ramped in while sliding) {'reaches no stick-slip' if d['steady'] == 'settled' else 'reaches ' + d['steady']} "
          f"(the hub rate's half peak-to-peak {d['steady_residual']:.3g} over the period before the kick at t = {d['t_kick']:.4g}"
          f"{', the motor' + chr(39) + 's ripple in it' if d.get('ripple') else ''})"]
    sk = d.get("smallest_kick")
    if sk:
        ev.append(f"the smallest kick that reaches a stick-slip cycle: the hub's rate jumped by {100 * sk['kick_rate_fraction']:g} % of the "
                  f"motor's (cycle at {sk['cycle_frequency_hz']:.4g} Hz)" + (f"; {100 * d['largest_settled']:g} % settles" if d.get("largest_settled") is not None else "")
                  + (": the cycle coexists with a steady state that settles" + (" and that the CEA calls stable (bistable)" if d.get("cea_stable") else "")
                     if d["coexists"] else ""))
    else:
        ev.append(f"no kick up to {100 * max(KICKS):g} % of the motor's rate reaches a stick-slip cycle: every disturbed run settles"
                  if d["steady"] == "settled" else "no kick reaches a stick-slip cycle")
    one = d.get("onedof")
    if one and one["threshold"] > 0:
        ev.append(f"1-DOF (rollerref.basin.kick_threshold, the same kick from its steady sliding): the cycle from "
                  f"{100 * one['threshold']:.3g} % of the motor's rate")
    elif one:
        ev.append("1-DOF (rollerref.basin.kick_threshold): its steady sliding is itself unstable, any kick reaches its cycle "
                  "(it slides the patch whole; where the finite elements' steady state rolls with a stick zone, it is not this scene's)")
    if d.get("returned_max") is not None:
        ev.append(f"the kicked runs that settle return to the undisturbed one: over their last {RETURN_PERIODS} periods of the drive's "
                  f"mode the hub rates differ by at most {100 * d['returned_max']:.3g} % of the motor's rate")
    return ev


def figure(folder, png="disturbances.png"):
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    summary, rows = tables.read(folder, "disturbances")
    stem = os.path.join(folder, SERIES)[: -len(".csv")]
    fig, ax = plt.subplots(figsize=(7.2, 4.4))
    colors = {"stick-slip": "tab:red", "forced stick-slip": "tab:orange", "growing": "tab:purple", "settled": "tab:blue"}
    ref = hub_rate(f"{stem}.case0.csv") if rows and rows[0]["status"] == "ok" else None
    for k, r in enumerate(rows):
        if r["status"] != "ok":
            continue
        t, h = hub_rate(f"{stem}.case{r['case']}.csv")
        m = t >= summary["t_kick"] - 2 * summary["period"]  # from two periods of the drive's mode before the kick
        # a kicked run less the undisturbed one (the kick's own response: the ripple's line cancels), the undisturbed
        # one less the motor's rate
        base = ref[1][m] if k > 0 and ref is not None and len(ref[1]) == len(h) else summary["omega"]
        dev = (h[m] - base) / summary["omega"]
        ax.plot(t[m], k + 0.45 * dev / max(1e-300, np.max(np.abs(dev))), lw=0.6, color=colors.get(r["outcome"], "grey"))
        ax.text(1.01, (k + 0.5) / len(rows), f"{100 * float(r['kick_rate_fraction']):g} %: {r['outcome']}", fontsize=6, va="center",
                transform=ax.transAxes)
    ax.axvline(summary["t_kick"], color="k", lw=0.5, ls=":")
    ax.set_xlabel("t (the kick at the dotted line)")
    ax.set_ylabel("hub rate - the undisturbed run's, each scaled")
    ax.set_yticks([])
    ax.set_ylim(-0.5, len(rows) - 0.5)
    sk, one = summary.get("smallest_kick"), summary.get("onedof")
    ax.set_title("kicks against the motor about the steady state: " + (
        f"stick-slip from {100 * sk['kick_rate_fraction']:g} % of its rate" if sk else "none reaches stick-slip")
        + (f" (1-DOF: {100 * one['threshold']:.3g} %)" if one and one["threshold"] > 0 else " (1-DOF: unstable sliding)" if one else ""), fontsize=9)
    fig.tight_layout()
    fig.savefig(os.path.join(folder, png), dpi=100)
    plt.close(fig)
    return png
