"""The squeal CEA against the transient (docs/squeal.md section 4.2): the DMF in the co-rotating frame with Coulomb's
law solved every step, undamped, V = 0, on the CEA's mesh (coarse graded: -mesh_h 0.05 -mesh_h_contact 0.0112).

mu = 0.3: the transient starts on the CEA's steady sliding state plus its order-1 backward mode (amplitude 1e-3,
-initial_condition mode with the lab-frame modes file: src/integrate/initial_mode.c), the sheet at its depth from
the first step, and runs to t = 60:
- it stays in the CEA's regime: the mean normal force equals the CEA's steady one (2 %), friction / normal = mu (1 %),
  fewer than one stick node on average, contact at every step;
- the order-1 whirl (the lab-frame displacement of the centre of Gamma_C, scripts/rollerreport/squeal_fit.py): frequency within
  2 %, growth rate by the matrix pencil over the whole run within 5 % (measured -1.7 %); the log-amplitude line
  within 10 % (measured -5.4 %). The estimates scatter (-12 % to +5.5 % over sub-windows): the transient's contact
  chatters (the contact force fluctuates by 5-30 % as nodes at the patch's edges open and close), which the CEA's
  bilateral patch does not have (docs/squeal.md section 4.2). The DMF's map of the eigenvalue at this dt changes
  the growth by 3e-5 relative (printed): the comparison is with the continuous eigenvalue.

mu = 0.8: the CEA's full spectrum (-modes_nev 400) has modes faster than the order-1 pair (growth >= 0.1 near
5.9 rad, order 8 forward): the transient leaves full sliding (contact lost at some step, or the friction ratio
below 0.98 mu) before t = 20, so the order-1 pair's growth cannot be compared there (asserted as such)."""
import csv
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from rollertest import Checker, SOURCE, read_csv, run  # noqa: E402

sys.path.insert(0, os.path.join(SOURCE, "scripts"))
from rollerreport import squeal_fit as sf  # noqa: E402

MESH = ["-mesh_h", "0.05", "-mesh_h_contact", "0.0112", "-mesh_contact_layer", "0.0224"]
DT = 0.01
c = Checker("squeal_transient")


def cea(name, mu, nev=40, output=None):
    out = run(["-modes", "-obstacle", "-friction", mu, "-modes_nev", nev, "-modes_csv", f"{name}.csv",
               "-modes_steady_csv", f"{name}_steady.csv"] + (["-modes_output", output] if output else []) + MESH)[1]
    with open(f"{name}.csv") as f:
        rows = [{k: (v if k == "wave" else float(v)) for k, v in r.items()} for r in csv.DictReader(f)]
    with open(f"{name}_steady.csv") as f:
        N = sum(float(r["normal_force"]) for r in csv.DictReader(f))
    return rows, N, out


def transient(name, mu, T, extra=()):
    run(["-ts_scheme", "dmf", "-obstacle", "-friction", mu, "-sheet_speed", 0, "-viscosity", 0, "-damping", 0, "-ts_dt", DT,
         "-ts_max_time", T, "-monitor_csv", f"{name}.csv", "-output", f"{name}.h5", "-output_every", 20, "-quiet"] + list(extra) + MESH)
    return read_csv(f"{name}.csv")


def saturation(d, mu, t0):
    """The first time after t0 with a step without contact or the 5-unit mean friction ratio below 0.98 mu."""
    t = d["t"]
    k = np.ones(int(round(5 / DT))) / round(5 / DT)
    ratio = np.convolve(-d["friction_force"], k, "same") / np.maximum(np.convolve(d["contact_force"], k, "same"), 1e-300)
    inside = (t > t0) & (t < t[-1] - 2.5)
    bad = t[inside & ((d["contact_nodes"] == 0) | (ratio < 0.98 * mu))]
    return bad[0] if len(bad) else t[-1] - 2.5


# mu = 0.3: the transient seeded on the steady state plus the order-1 backward mode (lab frame)
rows, N_cea, _ = cea("cea03", 0.3, output="cea03.h5")
j, p1 = max(((k, r) for k, r in enumerate(rows) if int(r["order"]) == 1 and r["wave"] == "backward"), key=lambda kr: kr[1]["growth_rate"])
g, w = p1["growth_rate"], p1["frequency"]
gd, wd = sf.dmf_map(complex(g, w), DT)
print(f"CEA mu 0.3: mode {j}, order-1 backward growth {g:.6f} frequency {w:.6f}; DMF map at dt {DT}: {gd:.6f} ({gd / g - 1:+.1e}), {wd:.6f}")
d = transient("tr03", 0.3, 60, ["-initial_condition", "mode", "-initial_mode_file", "cea03.h5", "-initial_mode", j, "-ic_amplitude", 1e-3, "-obstacle_speed", 1e6])
t0, t1 = 0.0, 60.0
m = d["t"] > 0
N_tr = d["contact_force"][m].mean()
c.check(abs(N_tr / N_cea - 1) < 0.02, f"mu 0.3: mean normal force {N_tr:.6f} vs CEA steady {N_cea:.6f} ({100 * (N_tr / N_cea - 1):+.2f} %, 2 %)")
ratio = -d["friction_force"][m].mean() / N_tr
c.check(abs(ratio / 0.3 - 1) < 0.01 and d["stick_nodes"][m].mean() < 1 and d["contact_nodes"][m].min() > 0,
        f"mu 0.3: friction / normal force {ratio:.5f} = mu (1 %), {d['stick_nodes'][m].mean():.2f} stick nodes on average, contact at every step: sliding")
t, U = sf.whirl("tr03.h5")
r = sf.fit(t, U, -w, t0, t1)
mm = (t >= t0) & (t <= t1)
glog = np.polyfit(t[mm], np.log(np.abs(U[mm] - U[mm].mean())), 1)[0]
eg, el = r["pencil_growth"] / g - 1, glog / g - 1
ew = abs(r["pencil_frequency"]) / w - 1
c.check(r["pencil_frequency"] < 0 and abs(ew) < 0.02,
        f"mu 0.3: whirl frequency {r['pencil_frequency']:+.5f} (backward) vs CEA {w:.5f}: {100 * ew:+.2f} % (2 %)")
c.check(abs(eg) < 0.05, f"mu 0.3: whirl growth {r['pencil_growth']:.5f} (matrix pencil, t in [0, 60]) vs CEA {g:.5f}: {100 * eg:+.1f} % (5 %)")
c.check(abs(el) < 0.10, f"mu 0.3: whirl growth {glog:.5f} (log-amplitude line, t in [0, 60]) vs CEA {g:.5f}: {100 * el:+.1f} % (10 %: the contact's chatter)")

# mu = 0.8
rows, N_cea, _ = cea("cea08", 0.8, nev=400)
top = max(rows, key=lambda r: r["growth_rate"])
p1 = max((r for r in rows if int(r["order"]) == 1 and r["wave"] == "backward"), key=lambda r: r["growth_rate"])
c.check(top["growth_rate"] > 1.5 * p1["growth_rate"],
        f"mu 0.8: the CEA's fastest mode, growth {top['growth_rate']:.4f} at {top['frequency']:.3f} (order {int(top['order'])} {top['wave']}), "
        f"outgrows the order-1 backward pair ({p1['growth_rate']:.4f} at {p1['frequency']:.4f})")
d = transient("tr08", 0.8, 25)
t1 = saturation(d, 0.8, 7.5)
c.check(t1 < 20, f"mu 0.8: the transient leaves full sliding at t = {t1:.1f} < 20: the order-1 pair cannot be measured in the linear regime")
c.close()
