"""The odds of a squeak over the real spread (issue 38; docs/squeal.md 9.4): a Latin hypercube over the uncertain
parameters about the scene, each case classified, the fraction that squeaks with its 95 % confidence interval (Wilson),
by mechanism, and a ranking of the parameters that matter.

The spread (issue 38; its sources in docs/squeal.md 9.4): kinetic friction of rubber on paper 0.65-1.4 and the static
over the kinetic 1.0-1.5, nip force 0.8-2.5 N/cm, loss factor 0.05-0.3, surface speed 0.12-0.36 m/s, drive stiffness
+-50 %. Each range is applied about the scene as a factor, the range divided by its geometric centre (the scene is
taken as the middle roller: a non-dimensional scene has no N/cm), except the static-over-kinetic ratio, whose excess
mu_s / mu_k - 1 is scaled by the factor (ratio - 1) / 0.25 (0 to 2: no weakening to twice the scene's). The loss factor
scales the drive's damping c_d (the 1-DOF's only damping). The bracket's stiffness (-axle_stiffness, vertical) does not
enter the torsional model and is not sampled.

Classification (each case, rollerref's 1-DOF of the scene, rollerreport.onedof: docs/validation.md 10.5 measures it
against the finite elements on -axle, the cycle's period within 2.2 %, its amplitude 0.2 %): "unstable sliding" when
steady sliding is linearly unstable (closed form: it grows into stick-slip), "bistable" when it is stable but the start
from rest reaches the stick-slip cycle, else quiet; both squeak by stick-slip (the 1-DOF has one mode: no flutter). The finite elements per case (5 CPU minutes each on jobs/axle_bistable.yaml) are not run.
"""
import csv
import json
import math
import os

import numpy as np

from . import onedof

# name: (option scaled, low, high, how the factor is formed)
SPREAD = {
    "friction_kinetic": ("friction", 0.65, 1.4),
    "friction_static_over_kinetic": ("friction_static", 1.0, 1.5),
    "nip_force_N_per_cm": ("nip_force", 0.8, 2.5),
    "loss_factor": ("drive_damping", 0.05, 0.3),
    "surface_speed_m_per_s": ("omega", 0.12, 0.36),
    "drive_stiffness_factor": ("drive_stiffness", 0.5, 1.5),
}
Z95 = 1.959963984540054


def latin_hypercube(n, d, seed):
    """n points in [0, 1)^d, one in each of the n strata of every axis (McKay, Beckman and Conover 1979)."""
    rng = np.random.default_rng(seed)
    u = (rng.random((n, d)) + np.arange(n)[:, None]) / n
    for j in range(d):
        u[:, j] = u[rng.permutation(n), j]
    return u


def wilson(k, n, z=Z95):
    """The Wilson score interval of a binomial proportion k/n."""
    if n == 0:
        return [math.nan, math.nan]
    p = k / n
    c = (p + z * z / (2 * n)) / (1 + z * z / n)
    h = z * math.sqrt(p * (1 - p) / n + z * z / (4 * n * n)) / (1 + z * z / n)
    return [max(0.0, c - h), min(1.0, c + h)]


def case_options(opts, sample):
    """The scene's options of one case: {name: value} of the sampled physical values (the issue's units) mapped onto
    the scene (module docstring)."""
    base = {k: onedof.value(opts, k) for k in ("friction", "friction_static", "nip_force", "drive_damping", "omega",
                                                 "drive_stiffness")}
    out = {}
    for name, (option, lo, hi) in SPREAD.items():
        x = sample[name]
        if name == "friction_static_over_kinetic":
            continue
        out[option] = base[option] * x / math.sqrt(lo * hi)
    excess = (base["friction_static"] / base["friction"] - 1) if base["friction"] else 0.0
    ratio = sample["friction_static_over_kinetic"]
    out["friction_static"] = out["friction"] * (1 + excess * (ratio - 1) / 0.25)
    if base["drive_stiffness"]:  # a loss factor eta damps the drive's mode by c_d = eta k_d / w_n = eta sqrt(k_d I)
        out["drive_damping"] *= math.sqrt(out["drive_stiffness"] / base["drive_stiffness"])
    return out


def classify(opts, case):
    """(class, linear growth rate, start from rest) of one case: 'unstable sliding' (steady sliding linearly unstable:
    it grows into stick-slip), 'bistable' (stable, but the start from rest reaches the stick-slip cycle), 'quiet' (the
    start from rest settles to sliding) or 'undecided' (neither within rollerref's 400 periods)."""
    o = dict(opts)
    o.update({k: repr(v) for k, v in case.items()})
    lin = onedof.stability(o)
    rest = onedof.start_from_rest(o)
    kind = "unstable sliding" if not lin["stable"] else ("bistable" if rest == "cycle" else
                                                         "quiet" if rest == "sliding" else "undecided")
    return kind, lin["growth_rate"], rest


def run(opts, folder, n=64, seed=38):
    """Sample n cases (seed), classify each, write propensity.csv (every case) and propensity.json (the summary:
    cases, fraction, its interval, by_mechanism, ranges, the ranking, seed); returns the summary."""
    names = list(SPREAD)
    u = latin_hypercube(n, len(names), seed)
    rows, kinds = [], []
    for i in range(n):
        sample = {nm: SPREAD[nm][1] + u[i, j] * (SPREAD[nm][2] - SPREAD[nm][1]) for j, nm in enumerate(names)}
        case = case_options(opts, sample)
        kind, g, rest = classify(opts, case)
        kinds.append(kind)
        rows.append(dict(case=i, **sample, **{"opt_" + k: v for k, v in case.items()}, growth_rate=g,
                         start_from_rest=rest, squeaks=int(kind in ("unstable sliding", "bistable")), mechanism=kind))
    with open(os.path.join(folder, "propensity.csv"), "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(rows[0]))
        w.writeheader()
        w.writerows(rows)
    k = sum(r["squeaks"] for r in rows)
    squeak = np.array([r["squeaks"] for r in rows], float)
    ranking = []
    for nm in names:  # the rank correlation of each parameter with squeaking (Spearman: ranks of both)
        x = np.argsort(np.argsort([r[nm] for r in rows])).astype(float)
        rho = float(np.corrcoef(x, squeak)[0, 1]) if squeak.std() > 0 else 0.0
        ranking.append({"parameter": nm, "spearman": rho})
    ranking.sort(key=lambda e: -abs(e["spearman"]))
    out = {"status": "run", "cases": n, "squeaking": k, "fraction": k / n, "confidence_95": wilson(k, n),
           # the 1-DOF has one mode: an unstable steady sliding grows into stick-slip too (no mode coupling, no flutter)
           "by_mechanism": {"stick-slip": k / n, "flutter": None, "forced": None},
           "by_class": {m: sum(1 for x in kinds if x == m) / n for m in ("unstable sliding", "bistable", "quiet", "undecided")},
           "ranges": {nm: [lo, hi] for nm, (_, lo, hi) in SPREAD.items()}, "sampling": {"method": "latin hypercube",
           "seed": seed, "cases": n, "file": "propensity.csv"},
           "classifier": "rollerref's 1-DOF of the scene (rollerreport.onedof): unstable sliding (closed form) or bistable "
                         "(stable, but the start from rest reaches the stick-slip cycle) squeak by stick-slip",
           "ranking": ranking}
    with open(os.path.join(folder, "propensity.json"), "w") as f:
        json.dump(out, f, indent=1)
    return out


def figure(folder, png="propensity.png"):
    """The cases over the two top-ranked parameters, coloured by their class."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    with open(os.path.join(folder, "propensity.json")) as f:
        summary = json.load(f)
    with open(os.path.join(folder, "propensity.csv"), newline="") as f:
        rows = list(csv.DictReader(f))
    a, b = summary["ranking"][0]["parameter"], summary["ranking"][1]["parameter"]
    fig, ax = plt.subplots(figsize=(5.5, 4))
    for kind, col in (("quiet", "tab:blue"), ("bistable", "tab:red"), ("unstable sliding", "tab:orange"), ("undecided", "grey")):
        pts = [(float(r[a]), float(r[b])) for r in rows if r["mechanism"] == kind]
        if pts:
            ax.plot(*zip(*pts), "o", color=col, label=f"{kind} ({len(pts)})")
    ax.set_xlabel(a)
    ax.set_ylabel(b)
    lo, hi = summary["confidence_95"]
    ax.set_title(f"{summary['cases']} cases: {100 * summary['fraction']:.0f} % squeak (95 %: {100 * lo:.0f}-{100 * hi:.0f} %)",
                 fontsize=9)
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(os.path.join(folder, png), dpi=100)
    plt.close(fig)
    return png
