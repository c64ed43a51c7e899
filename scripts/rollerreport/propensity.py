"""The odds of a squeak over the real spread (issue 38; docs/squeal.md 9.4): a Latin hypercube over the uncertain
parameters about the scene, each case classified, the fraction that squeaks with its 95 % confidence interval (Wilson),
by mechanism, and a ranking of the parameters that matter.

The spread (issue 38; its sources in docs/squeal.md 9.4): kinetic friction of rubber on paper 0.65-1.4 and the static
over the kinetic 1.0-1.5, nip force 0.8-2.5 N/cm, the rubber's loss factor 0.05-0.3, surface speed 0.12-0.36 m/s, the
drive's and the bracket's (the pick spring's, -axle_stiffness) stiffness +-50 %. Each range is applied about the scene as
a factor, the range divided by its geometric centre (the scene is taken as the middle roller: a non-dimensional scene
has no N/cm), except the static-over-kinetic ratio, whose excess mu_s / mu_k - 1 is scaled by the factor
(ratio - 1) / 0.25 (0 to 2: no weakening to twice the scene's). The loss factor scales the rubber's
(-rubber_loss_factor of a Maxwell rubber, -viscosity of a Kelvin-Voigt one); the drive's damping follows its stiffness
at a constant damping ratio (c_d ~ sqrt(k_d)); a kinematic sheet's speed follows the surface speed (the creep kept).

Two classifiers (case_options maps a sample onto the scene's options for both):
- the finite elements (rollerreport.propensity_fe, the report's default on an axle scene): every case's CEA (-modes
  -sweep -sweep_cases) and its start from rest on the reduced model (-rom -sweep -sweep_cases -sweep_monitor_csv);
- rollerreport's 1-DOF of the scene (run below; rollerreport.onedof: docs/validation.md 10.5 measures it against the
  finite elements on -axle, the cycle's period within 2.2 %, its amplitude 0.2 %), the finite elements' cross-check:
  "unstable sliding" when steady sliding is linearly unstable (closed form: it grows into stick-slip), "bistable" when
  it is stable but the start from rest reaches the stick-slip cycle, else quiet; both squeak by stick-slip (the 1-DOF
  has one mode: no flutter). It has no rubber and no bracket: the loss factor and the bracket's stiffness do not enter.
"""
import math
import os

import numpy as np

from . import onedof, tables

# name: (option scaled, low, high, how the factor is formed)
SPREAD = {
    "friction_kinetic": ("friction", 0.65, 1.4),
    "friction_static_over_kinetic": ("friction_static", 1.0, 1.5),
    "nip_force_N_per_cm": ("nip_force", 0.8, 2.5),
    "loss_factor": ("rubber_loss_factor", 0.05, 0.3),  # -viscosity for a Kelvin-Voigt rubber (loss_option)
    "surface_speed_m_per_s": ("omega", 0.12, 0.36),
    "drive_stiffness_factor": ("drive_stiffness", 0.5, 1.5),
    "bracket_stiffness_factor": ("axle_stiffness", 0.5, 1.5),
}
# roller's defaults (src/app/options.c, src/model) of the options a case scales, for a scene that leaves them out
SCALED_DEFAULTS = {"viscosity": 0.0, "rubber_loss_factor": 0.1, "axle_stiffness": 0.0, "sheet_mass": 0.0}
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


def loss_option(opts):
    """The option that carries the rubber's loss factor: -rubber_loss_factor (Maxwell) or -viscosity (Kelvin-Voigt)."""
    return "rubber_loss_factor" if opts.get("rubber", "kelvin_voigt") == "maxwell" else "viscosity"


def scene_value(opts, name):
    """The scene's value of an option a case scales (its default when the scene leaves it out)."""
    if name in opts:
        return float(opts[name])
    return float(SCALED_DEFAULTS[name]) if name in SCALED_DEFAULTS else onedof.value(opts, name)


def case_options(opts, x):
    """The scene's options of one case: {name: value} of the sampled physical values (the issue's units) mapped onto
    the scene (module docstring)."""
    out = {}
    for name, (option, lo, hi) in SPREAD.items():
        if name == "friction_static_over_kinetic":
            continue
        option = loss_option(opts) if name == "loss_factor" else option
        out[option] = scene_value(opts, option) * x[name] / math.sqrt(lo * hi)
    base_mu, base_mus = scene_value(opts, "friction"), scene_value(opts, "friction_static")
    excess = (base_mus / base_mu - 1) if base_mu else 0.0
    out["friction_static"] = out["friction"] * (1 + excess * (x["friction_static_over_kinetic"] - 1) / 0.25)
    k0 = scene_value(opts, "drive_stiffness")
    if k0:  # the drive's damping ratio kept: c_d = 2 zeta sqrt(k_d I)
        out["drive_damping"] = scene_value(opts, "drive_damping") * math.sqrt(out["drive_stiffness"] / k0)
    if scene_value(opts, "sheet_mass") == 0 and scene_value(opts, "sheet_speed") != 0:  # a kinematic sheet: the creep kept
        out["sheet_speed"] = scene_value(opts, "sheet_speed") * out["omega"] / scene_value(opts, "omega")
    return out


def sample(opts, n, seed):
    """n cases of the Latin hypercube (seed): [(the sampled physical values, the case's options)]."""
    names = list(SPREAD)
    u = latin_hypercube(n, len(names), seed)
    out = []
    for i in range(n):
        x = {nm: SPREAD[nm][1] + u[i, j] * (SPREAD[nm][2] - SPREAD[nm][1]) for j, nm in enumerate(names)}
        out.append((x, case_options(opts, x)))
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
    """The 1-DOF's propensity: sample n cases (seed), classify each (classify), write propensity.csv and
    propensity.json (summarize); returns the summary."""
    rows = []
    for i, (x, case) in enumerate(sample(opts, n, seed)):
        kind, g, rest = classify(opts, case)
        rows.append(dict(case=i, **x, **{"opt_" + k: v for k, v in case.items()}, growth_rate=g, start_from_rest=rest,
                         squeaks=int(kind in ("unstable sliding", "bistable")), mechanism=kind))
    by_class = {m: sum(1 for r in rows if r["mechanism"] == m) / n for m in ("unstable sliding", "bistable", "quiet", "undecided")}
    # the 1-DOF has one mode: an unstable steady sliding grows into stick-slip too (no mode coupling, no flutter)
    k = sum(r["squeaks"] for r in rows)
    return summarize(folder, rows, seed, {"stick-slip": k / n, "flutter": None, "forced": None}, by_class,
                     "rollerreport's 1-DOF of the scene (rollerreport.onedof): unstable sliding (closed form) or bistable "
                     "(stable, but the start from rest reaches the stick-slip cycle) squeak by stick-slip")


def summarize(folder, rows, seed, by_mechanism, by_class, classifier, **more):
    """propensity.csv (every case: its sampled values, its options, its class, squeaks 0/1) and propensity.json (cases,
    fraction, its Wilson interval, by_mechanism, by_class, the ranges, the sampling, the ranking by Spearman's rank
    correlation of each sampled parameter with squeaking, the classifier, and `more`); returns the summary."""
    n, names = len(rows), list(SPREAD)
    k = sum(int(r["squeaks"]) for r in rows)
    squeak = np.array([int(r["squeaks"]) for r in rows], float)
    ranking = []
    for nm in names:  # the rank correlation of each parameter with squeaking (Spearman: ranks of both)
        x = np.argsort(np.argsort([r[nm] for r in rows])).astype(float)
        rho = float(np.corrcoef(x, squeak)[0, 1]) if squeak.std() > 0 else 0.0
        ranking.append({"parameter": nm, "spearman": rho})
    ranking.sort(key=lambda e: -abs(e["spearman"]))
    out = {"status": "run", "cases": n, "squeaking": k, "fraction": k / n, "confidence_95": wilson(k, n),
           "by_mechanism": by_mechanism, "by_class": by_class,
           "ranges": {nm: [lo, hi] for nm, (_, lo, hi) in SPREAD.items()}, "sampling": {"method": "latin hypercube",
           "seed": seed, "cases": n, "file": "propensity.csv"}, "classifier": classifier, "ranking": ranking}
    out.update(more)
    return tables.write(folder, "propensity", rows, out)


def figure(folder, png="propensity.png"):
    """The cases over the two top-ranked parameters, coloured by their class."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    summary, rows = tables.read(folder, "propensity")
    a, b = summary["ranking"][0]["parameter"], summary["ranking"][1]["parameter"]
    fig, ax = plt.subplots(figsize=(5.5, 4))
    for kind, col in (("quiet", "tab:blue"), ("bistable", "tab:red"), ("unstable sliding", "tab:orange"), ("stick-slip", "tab:brown"),
                      ("forced stick-slip", "tab:pink"), ("flutter", "tab:purple"), ("growing", "tab:olive"), ("undecided", "grey"),
                      ("failed", "black")):
        pts = [(float(r[a]), float(r[b])) for r in rows if r.get("class", r["mechanism"]) == kind]
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
