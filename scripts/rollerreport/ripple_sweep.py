"""The forced mechanism's sweep (issue 38; docs/squeal.md 9.4): the motor's ripple swept over the audible band and the
roller's own modes, every frequency a case of one `roller -sweep -sweep_cases` map on the reduced model (the scene's
ripple amplitude, its start, each case's series kept), and the hub's response at each frequency read from its series.

- frequencies: log-spaced from the band's low end (100 Hz, or half the lowest oscillating mode of the CEA when lower) to
  its top (5 kHz, at most a tenth of the step's rate: ten steps a period), plus every CEA mode's frequency and the
  scene's own ripple frequency inside;
  a non-dimensional scene's band at its audio time scale;
- each run lasts the motor's start plus ten periods of the lowest frequency swept;
- the response: rollerreport.cycle.lock_in of hub_rate (and friction_force) at the ripple's frequency over the run's
  last half, whole periods, and whether the patch stuck and slipped whole in that window (stick-slip riding on the
  forced line: the linear response about sliding does not hold there).

ripple_sweep.csv (a row per frequency), ripple_sweep.json (the peak, the scene's ripple's place on the curve),
ripple_sweep.png (the response against frequency, the CEA's modes marked).
"""
import csv
import math
import os

import numpy as np

from . import cycle, tables

CASES, RUNS, SERIES = "ripple_sweep_cases.csv", "ripple_sweep_runs.csv", os.path.join("ripple_sweep", "series.csv")
BAND_HZ = (100.0, 5000.0)


def frequencies(modes_rows, seconds_per_unit, dt, n=24, also=()):
    """The swept frequencies (cycles per unit time), sorted: n log-spaced over the band plus the CEA's modes and `also`
    (the scene's own ripple) in it."""
    s = seconds_per_unit
    modes = sorted(float(r["im"]) / (2 * math.pi) for r in modes_rows if float(r["im"]) > 0)
    lo = min(BAND_HZ[0] * s, 0.5 * modes[0]) if modes else BAND_HZ[0] * s
    hi = min(BAND_HZ[1] * s, 0.1 / dt)
    grid = list(np.geomspace(lo, hi, n)) if n > 1 else [lo]
    return sorted(set(grid + [f for f in list(modes) + list(also) if lo <= f <= hi])), modes


def write_cases(folder, freqs, amplitude):
    with open(os.path.join(folder, CASES), "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["case", "drive_ripple", "drive_ripple_frequency"])
        for i, fr in enumerate(freqs):
            w.writerow([i, repr(float(amplitude)), repr(float(fr))])


def run_length(started, freqs):
    """The motor's start plus ten periods of the lowest frequency."""
    return started + 10.0 / min(freqs)


def command(base, extra, folder, t_end, ranks, mpiexec):
    j = lambda f: os.path.join(folder, f)  # noqa: E731
    mpi = [mpiexec, "-n", str(ranks)] if ranks > 1 else []
    return (mpi + base + ["-ts_max_time", repr(t_end), "-sweep", j(RUNS), "-sweep_cases", j(CASES), "-sweep_monitor_csv", j(SERIES),
                          "-sweep_fit", "friction_force", "-quiet"] + extra)


def response(path, f, t_min):
    """(hub-rate amplitude, friction-force amplitude, stick-slip in the window) at the frequency f over the run's last
    half after t_min (whole periods)."""
    with open(path, newline="") as fh:
        rows = list(csv.DictReader(fh))[1:]
    d = {c: np.array([float(r[c]) for r in rows]) for c in ("t", "hub_rate", "friction_force", "stick_nodes")}
    t = d["t"]
    keep = t >= max(t_min, t[-1] - max((t[-1] - t_min) / 2, 1.0 / f))
    a_rate = cycle.lock_in(t[keep], d["hub_rate"][keep], f)[0]
    a_fric = cycle.lock_in(t[keep], d["friction_force"][keep], f)[0]
    st = d["stick_nodes"][keep]
    return a_rate, a_fric, bool(np.any(st > 0) and np.any(st == 0))


def classify(folder, freqs, amplitude, modes, started, seconds_per_unit, scene_frequency):
    """ripple_sweep.csv and ripple_sweep.json from the map's series; returns the summary."""
    runs = {int(r["case"]): r for r in csv.DictReader(open(os.path.join(folder, RUNS), newline=""))}
    stem = os.path.join(folder, SERIES)[: -len(".csv")]
    rows = []
    for i, f in enumerate(freqs):
        ok = runs.get(i, {}).get("status") == "ok"
        a, q, ss = response(f"{stem}.case{i}.csv", f, started) if ok else (math.nan, math.nan, False)
        rows.append({"case": i, "frequency": f, "frequency_hz": f / seconds_per_unit, "rate_amplitude": a,
                     "rate_per_ripple": a / amplitude, "friction_amplitude": q, "stick_slip_in_window": int(ss),
                     "status": "ok" if ok else "failed"})
    good = [r for r in rows if r["status"] == "ok"]
    peak = max(good, key=lambda r: r["rate_amplitude"]) if good else None
    at = None
    if good and scene_frequency:
        near = min(good, key=lambda r: abs(math.log(r["frequency"] / scene_frequency)))
        at = {"frequency_hz": near["frequency_hz"], "rate_amplitude": near["rate_amplitude"],
              "below_peak_db": 20 * math.log10(near["rate_amplitude"] / peak["rate_amplitude"]) if peak["rate_amplitude"] > 0 else None}
    out = {"status": "run", "cases": len(rows), "failed": len(rows) - len(good), "ripple": amplitude,
           "band_hz": [rows[0]["frequency_hz"], rows[-1]["frequency_hz"]], "modes_hz": [m / seconds_per_unit for m in modes],
           "peak": {k: peak[k] for k in ("frequency_hz", "rate_amplitude", "rate_per_ripple", "friction_amplitude", "stick_slip_in_window")} if peak else None,
           "stick_slip_cases": sum(r["stick_slip_in_window"] for r in good), "scene_ripple": at, "file": "ripple_sweep.csv"}
    return tables.write(folder, "ripple_sweep", rows, out)


def figure(folder, png="ripple_sweep.png"):
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    summary, rows = tables.read(folder, "ripple_sweep")
    rows = [r for r in rows if r["status"] == "ok"]
    f = np.array([float(r["frequency_hz"]) for r in rows])
    a = np.array([float(r["rate_per_ripple"]) for r in rows])
    ss = np.array([int(r["stick_slip_in_window"]) for r in rows], bool)
    fig, ax = plt.subplots(figsize=(6, 3.6))
    ax.loglog(f, a, "-", color="tab:blue", lw=1)
    ax.loglog(f[~ss], a[~ss], "o", color="tab:blue", ms=4, label="sliding in the window")
    if ss.any():
        ax.loglog(f[ss], a[ss], "s", color="tab:red", ms=5, label="stick-slip in the window")
    for m in summary["modes_hz"]:
        if f.min() <= m <= f.max():
            ax.axvline(m, color="grey", lw=0.5, ls=":")
    if summary.get("scene_ripple"):
        ax.axvline(summary["scene_ripple"]["frequency_hz"], color="tab:green", lw=1, label="the scene's ripple")
    ax.set_xlabel("ripple frequency (Hz)")
    ax.set_ylabel("hub rate amplitude / ripple (1/s)")
    pk = summary.get("peak") or {}
    ax.set_title(f"the drive's ripple swept: peak at {pk.get('frequency_hz', math.nan):.0f} Hz (dotted: the CEA's modes)", fontsize=9)
    ax.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(os.path.join(folder, png), dpi=100)
    plt.close(fig)
    return png
