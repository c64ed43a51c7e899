"""The propensity's cases on the finite elements (issue 38; docs/squeal.md 9.4): each case of the Latin hypercube
(rollerreport.propensity.sample) classified by its own CEA and by its own start from rest on the reduced model, both as
one `roller -sweep` map over the table of cases (-sweep_cases: the cases on sub-communicators, resumable, sliceable
into a Slurm array: jobs/slurm/propensity.sbatch), the 1-DOF's class beside them as the cross-check.

- propensity_cases.csv: the table (case, then one column per scene option a case sets);
- the CEA map (propensity_cea.csv: `roller -options_file SCENE -modes -sweep ... -sweep_cases ...`), run when the scene's
  own CEA ran (a scene the CEA does not carry, e.g. a sheet with its own mass, has none): the case's steady sliding is
  unstable with an oscillating eigenvalue of positive real part (flutter), or a real one (divergence);
- the transient map (propensity_runs.csv, every case's series propensity/series.case<c>.csv: `roller -options_file SCENE
  -rom -rom_input BASIS -sweep ... -sweep_cases ... -sweep_monitor_csv ...`): the start from rest of the scene (its nip,
  its motor's ramp and ripple) for `periods` periods of the drive's mode (the 1-DOF's frequency) after the motor has
  started, read as the report reads the scene's own (rollerreport.cycle.detect on hub_rate with stick_nodes, after the
  drive started): stick-slip when it reaches a sustained cycle that sticks and lets go whole in every period; growing
  when the hub's oscillation, a clean one of at least 1 % of its mean rate, still grows at the end (more than 2 % a
  period over its last periods).

A case's mechanism: forced when its start reaches a stick-slip cycle at the motor's ripple frequency (within 2 %: the
ripple drives the patch through stick and slip, class "forced stick-slip"); stick-slip when it reaches another one
(class "unstable sliding" when its CEA is unstable too: the negative slope's onset grown into stick-slip; "bistable"
when the CEA is stable: the cycle beside a stable steady state, which only the transient sees); flutter when the CEA
has a growing oscillating mode and the start does not reach stick-slip; growing when the start's oscillation still
grows at its end without either; else quiet ("failed" when its run failed). All but quiet and failed squeak. The CEA's
and the transient's verdicts are both in propensity.csv (cea, transient columns), and how often they agree is in
propensity.json ("agreement").
"""
import csv
import math
import os

import numpy as np

from . import cycle, onedof, propensity

PEP_MAX_IT = 100  # the cases' eigensolver restarts (docs/squeal.md 9.4: a case's partial answer keeps the least stable)
GROWING_PER_PERIOD = 0.02  # the envelope's growth a period above which an oscillation that has not settled grows
GROWING_SIZE = 0.01  # ... when its half peak-to-peak is at least this fraction of the hub's mean rate
FORCED_SPREAD = 0.02  # a stick-slip cycle within 2 % of the motor's ripple frequency is the ripple's (forced)
CASES, CEA, RUNS, SERIES = "propensity_cases.csv", "propensity_cea.csv", "propensity_runs.csv", os.path.join("propensity", "series.csv")


def write_cases(folder, cases):
    """propensity_cases.csv: the table of -sweep_cases (every case sets the same options, in a fixed order)."""
    names = sorted(cases[0][1])
    with open(os.path.join(folder, CASES), "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["case"] + names)
        for i, (_, opt) in enumerate(cases):
            w.writerow([i] + [repr(float(opt[k])) for k in names])
    return names


def run_length(opts, periods):
    """The transient's -ts_max_time: the motor started (theta_start + drive_ramp) plus `periods` periods of the drive's
    mode (the 1-DOF's frequency, cycles per unit time); the scene's own -ts_max_time without a drive."""
    started = onedof.value(opts, "theta_start") + onedof.value(opts, "drive_ramp")
    f = onedof.stability(opts)["frequency"] if onedof.value(opts, "drive_stiffness") > 0 else 0.0
    return started + periods / f if f > 0 else float(opts.get("ts_max_time", 0.0))


def commands(base, extra, folder, basis, t_end, ranks, mpiexec, nev, with_cea):
    """{part: (command, what)} of the two maps."""
    j = lambda f: os.path.join(folder, f)  # noqa: E731
    mpi = [mpiexec, "-n", str(ranks)] if ranks > 1 else []
    table = ["-sweep_cases", j(CASES), "-quiet"]
    out = {"propensity_runs": (mpi + base + ["-rom", "-rom_input", basis, "-ts_max_time", repr(t_end), "-sweep", j(RUNS),
                                             "-sweep_monitor_csv", j(SERIES), "-sweep_fit", "friction_force"] + table + extra,
                               f"each case's start from rest on the reduced model to t = {t_end:.5g} (propensity_runs.csv, "
                               "propensity/series.case<c>.csv)")}
    if with_cea:
        # at most PEP_MAX_IT restarts (the options after it may give another): on some cases the eigensolver's default
        # (about 2 N / ncv) spends minutes on modes that never converge, after the smallest (the drive's) have
        out["propensity_cea"] = (mpi + base + ["-modes", "-modes_nev", str(nev), "-pep_max_it", str(PEP_MAX_IT), "-sweep", j(CEA)]
                                 + table + extra, f"each case's CEA ({nev} eigenvalues, at most {PEP_MAX_IT} restarts; propensity_cea.csv)")
    return out


def cea_verdict(rows):
    """A case's CEA rows -> 'flutter' (an oscillating eigenvalue with Re > 0), 'divergence' (a real one), 'stable';
    with the largest growth rate of the oscillating modes and its frequency (rad per unit time)."""
    osc = [r for r in rows if float(r["im"]) > 0]
    real = [r for r in rows if float(r["im"]) == 0]
    top = max(osc, key=lambda r: float(r["re"])) if osc else None
    g, w = (float(top["re"]), float(top["im"])) if top else (math.nan, math.nan)
    kind = "flutter" if g > 0 else "divergence" if any(float(r["re"]) > 0 for r in real) else "stable"
    return kind, g, w


def read_series(path, columns=("t", "hub_rate", "stick_nodes")):
    """A case's series: its columns as arrays, row 0 (the state before the first contact solve) left out."""
    with open(path, newline="") as f:
        rows = list(csv.DictReader(f))[1:]
    return tuple(np.array([float(r[c]) for r in rows]) for c in columns)


def grows(cyc):
    """A cycle.detect result that still grows: a clean oscillation (its periods within cycle.PERIOD_SPREAD) of a visible
    size (GROWING_SIZE of the series' mean: not the node passing's ripple of a settled run) whose envelope grows by more
    than GROWING_PER_PERIOD a period."""
    return bool(math.isfinite(cyc["growth_rate"]) and cyc["growth_rate"] * cyc["period"] > GROWING_PER_PERIOD
                and cyc.get("period_spread", 1.0) < cycle.PERIOD_SPREAD and cyc["amplitude"] > GROWING_SIZE * abs(cyc["level"]))


def transient_verdict(path, t_min, series=None):
    """A case's series (read from path unless given: read_series) -> ('stick-slip' | 'growing' | 'settled', the
    cycle.detect dict)."""
    t, hub, stick = series if series is not None else read_series(path)
    cyc = cycle.detect(t, hub, stick, t_min=t_min)
    return ("stick-slip" if cyc["stick_slip"] else "growing" if grows(cyc) else "settled"), cyc


def classify(folder, opts, cases, with_cea):
    """Every case's row of propensity.csv from the two maps (module docstring)."""
    runs = {int(r["case"]): r for r in csv.DictReader(open(os.path.join(folder, RUNS), newline=""))}
    cea = {}
    if with_cea:
        for r in csv.DictReader(open(os.path.join(folder, CEA), newline="")):
            cea.setdefault(int(r["case"]), []).append(r)
    t_min = onedof.value(opts, "theta_start") + onedof.value(opts, "drive_ramp")
    f_ripple = onedof.value(opts, "drive_ripple_frequency") if onedof.value(opts, "drive_ripple") else 0.0
    stem = os.path.join(folder, SERIES)[: -len(".csv")]
    rows = []
    for i, (x, case) in enumerate(cases):
        c_kind, c_g, c_w = cea_verdict(cea.get(i, [])) if with_cea else ("not run", math.nan, math.nan)
        if runs.get(i, {}).get("status") == "ok":
            t_kind, cyc = transient_verdict(f"{stem}.case{i}.csv", t_min)
        else:
            t_kind, cyc = "failed", {"frequency": math.nan, "amplitude": math.nan, "growth_rate": math.nan}
        one_kind = propensity.classify(opts, case)[0]
        # a cycle at the motor's ripple is the ripple driving the patch through stick and slip: forced, not self-excited
        forced = t_kind == "stick-slip" and f_ripple > 0 and abs(cyc["frequency"] / f_ripple - 1) < FORCED_SPREAD
        kind = ("forced" if forced else "stick-slip" if t_kind == "stick-slip" else "flutter" if c_kind == "flutter" else
                t_kind if t_kind in ("growing", "failed") else "quiet")
        klass = ({"flutter": "unstable sliding", "divergence": "unstable sliding", "stable": "bistable"}.get(c_kind, "stick-slip")
                 if kind == "stick-slip" else "forced stick-slip" if forced else kind)
        rows.append(dict(case=i, **x, **{"opt_" + k: v for k, v in case.items()}, cea=c_kind, cea_growth_rate=c_g,
                         cea_frequency=c_w, transient=t_kind, cycle_frequency=cyc["frequency"], cycle_amplitude=cyc["amplitude"],
                         cycle_growth_rate=cyc["growth_rate"], onedof=one_kind,
                         squeaks=int(kind in ("flutter", "stick-slip", "growing", "forced")), mechanism=kind, **{"class": klass}))
    return rows


def summarize(folder, rows, seed, with_cea, t_end, nev):
    """propensity.json and propensity.csv of the finite elements' cases (rollerreport.propensity.summarize)."""
    n = len(rows)
    frac = lambda kind: sum(1 for r in rows if r["mechanism"] == kind) / n  # noqa: E731
    ran = [r for r in rows if r["transient"] != "failed"]
    # the CEA against the transient: an unstable steady state whose start from rest grows or cycles, a stable one whose
    # start settles or reaches a stick-slip cycle beside it (bistable: the CEA cannot see it)
    agree = ({"cases": len(ran), "unstable_and_oscillating": sum(1 for r in ran if r["cea"] == "flutter" and r["transient"] != "settled"),
              "unstable_and_settled": sum(1 for r in ran if r["cea"] == "flutter" and r["transient"] == "settled"),
              "stable_and_stick_slip": sum(1 for r in ran if r["cea"] != "flutter" and r["transient"] == "stick-slip")} if with_cea else None)
    onedof_agrees = sum(1 for r in ran if (r["onedof"] in ("unstable sliding", "bistable")) == (r["transient"] == "stick-slip"))
    by_mechanism = {"flutter": frac("flutter") if with_cea else None, "stick-slip": frac("stick-slip"), "growing": frac("growing"),
                    "forced": frac("forced")}
    classifier = ("the finite elements, case by case: " + (f"its CEA ({nev} eigenvalues: flutter when an oscillating mode "
                  "grows), " if with_cea else "no CEA (the scene's own CEA did not run), ") + "its start from rest on the "
                  f"reduced model to t = {t_end:.5g} (stick-slip: a sustained cycle stuck and slipping whole every period; "
                  "growing: still growing at the end); the 1-DOF's class beside them (column onedof)")
    by_class = {m: sum(1 for r in rows if r["class"] == m) / n for m in
                ("unstable sliding", "bistable", "stick-slip", "forced stick-slip", "flutter", "growing", "quiet", "failed")}
    return propensity.summarize(folder, rows, seed, by_mechanism, by_class, classifier,
                                model="finite elements (CEA + reduced transient)", run_time=t_end, agreement=agree,
                                onedof_agreement={"cases": len(ran), "same_stick_slip_verdict": onedof_agrees},
                                forced_note="the motor's ripple is in every case's run: a case is 'forced' only when the "
                                            "ripple drives its patch through stick and slip (a stick-slip cycle at the ripple's "
                                            "frequency); the ripple's line itself, in every case, is the scene's forced mechanism")
