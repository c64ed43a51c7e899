"""The CEA about a rolling state with a stick zone converges on three contact meshes, and transients confirm it at
three creeps (docs/squeal.md 4.4.4): the feeder (jobs/feed.yaml) with its own Kelvin-Voigt damping (-viscosity 0.0115
-damping 0, the damped lab-frame CEA), the order-1 backward pair at the creeps CREEPS (the stick zone from about 0.055
long at 0.12 to a few nodes next to the stick/slip boundary), graded meshes h_c = MESHES, the default two-point slip
difference (-modes_slip_difference box: the slip midway between a node and its upstream neighbour, docs/squeal.md
section 3) and the rigid stick constraint.

- on the three meshes the pair's growth converges: the change from the middle to the fine mesh is smaller than from
  the coarse to the middle one, or both are within 10 % of the fine mesh's growth; the frequencies of the two finer
  meshes agree within 0.5 %. (The three-point difference, upwind2, fragments the stick zone and its CEA does not
  converge: at 0.12 -0.002, -0.004, +0.019 on these meshes, docs/squeal.md 4.4.2.) Not on every mesh: a fourth,
  h_c = 0.0014 (7 min, 3 GB each, not run here), keeps 0.12 at 0.0098 but moves 0.13 from 0.022 to -0.011 (the
  leading edge's P2 vertex/edge alternation, docs/squeal.md 4.4.4).
- at each creep the seed's own response on the coarse mesh (h_c = 0.0112), the transient seeded on the CEA's steady
  state and mode (1e-4, dt = 0.01) minus the same run unseeded (the start's whirl, common to both, cancels:
  rollerreport.squeal_fit --base), grows at the converged CEA's rate (the finest mesh's) within 20 % and at its
  frequency within 1 % (pencil and envelope, two windows each; at 0.12, where the rate is smallest, over t = 40-140
  of a run to t = 150). The converged CEA, not the same mesh's: the transient turns the mesh through the patch where
  the CEA differences the slip (first order in h_c), so the two agree in their limits; mesh by mesh they differ by
  up to 21 % at 0.13 (printed).
- the transient is converged in h_c: at 0.13 the seed's response on the medium mesh (to t = 80, window 10-60) grows
  within 10 % of the coarse mesh's.
- -modes_stick_margin m linearizes a stick node with |T| > (1 - m) mu N as sliding: at 0.12 the margin 0.05 frees
  exactly the steady state's stick nodes within 5 % of the cone and changes the eigenvalue; 0.02, within which no
  stick node lies, leaves it unchanged to the last digit.

Not asserted (docs/squeal.md 4.4.3-4.4.4): the fastest mode about a stick zone, a forward wave of order 8-10 near
6-7 rad / time, which needs -modes_nev 400 and transients with dt <= 0.00125; the press transients' finite-amplitude
rates. About 25 min of CPU."""
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from rollertest import SOURCE, Checker, read_csv, run  # noqa: E402

sys.path.insert(0, os.path.join(SOURCE, "scripts"))
from rollerreport.squeal_fit import fit, seed_response  # noqa: E402

SCENE = ["-options_file", os.path.join(SOURCE, "jobs", "feed.yaml"), "-viscosity", "0.0115", "-damping", "0", "-quiet"]
MESHES = [0.0112, 0.0056, 0.0028]
COARSE = MESHES[0]  # the transients' contact mesh
CREEPS = [0.12, 0.13, 0.135]
TRANSIENTS = {0.12: (150, [(40, 140), (60, 140)]), 0.13: (80, [(10, 60), (20, 80)]), 0.135: (80, [(10, 60), (20, 80)])}  # t_max, windows
MEDIUM = MESHES[1]  # the second transient mesh, at 0.13: the transient's own convergence
MEDIUM_RUN = (0.13, 80, (10, 60))  # creep, t_max, window (the envelope is fitted away from the record's end)
OMEGA_R = np.pi / 10 * 0.5
c = Checker("squeal_stick")


def mesh(hc):
    return ["-mesh_h", "0.05", "-mesh_h_contact", hc, "-mesh_contact_layer", 2 * hc]


def backward1(name):
    """growth, frequency of the lowest order-1 backward pair of a -modes_csv, and its row."""
    d = read_csv(name)
    k = [i for i in range(len(d["order"])) if int(d["order"][i]) == 1 and d["wave"][i] == "backward"]
    i = min(k, key=lambda i: d["frequency"][i])
    return d["growth_rate"][i], d["frequency"][i], i


def cea(xi, hc, extra=(), tag=""):
    name = f"cea_{xi}_{hc}{tag}"
    run(SCENE + mesh(hc) + ["-sheet_speed", repr(OMEGA_R * (1 - xi)), "-modes", "-modes_nev", 30, "-modes_csv", f"{name}.csv"] + list(extra))
    return backward1(f"{name}.csv")


def transient(xi, i, amp, tmax, hc=COARSE):
    """The transient seeded at amp on mode i of the CEA's modes file on hc (its steady state), to tmax on that mesh."""
    out = f"t{xi}_{hc}_{amp}.h5"
    run(SCENE + mesh(hc) + ["-sheet_speed", repr(OMEGA_R * (1 - xi)), "-ts_dt", "0.01", "-ts_max_time", tmax, "-obstacle_speed", "1e6", "-initial_condition", "mode",
                            "-initial_mode_file", modes_file(xi, hc), "-initial_mode", i, "-ic_amplitude", amp, "-output", out, "-output_every", "20"])
    return out


def modes_file(xi, hc):
    return f"m{xi}_{hc}.h5"


def agrees(label, g, w, t, U, windows):
    """The fits of U on each window against the CEA's (g, w): growth within 20 % (pencil, envelope), frequency 1 %."""
    for t0, t1 in windows:
        f = fit(t, U, -w, t0, t1)
        gp, wp, ge = f["pencil_growth"], abs(f["pencil_frequency"]), f["envelope_growth"]
        print(f"{label}, window {t0}-{t1}: CEA {g:.5f} @ {w:.5f}; pencil {gp:.5f} @ {wp:.5f}, envelope {ge:.5f}")
        c.check(abs(gp - g) < 0.2 * g, f"{label}, window {t0}-{t1}: growth (pencil) {gp:.5f} within 20 % of the CEA's {g:.5f}")
        c.check(abs(ge - g) < 0.2 * g, f"{label}, window {t0}-{t1}: growth (envelope) {ge:.5f} within 20 % of the CEA's {g:.5f}")
        c.check(abs(wp - w) < 0.01 * w, f"{label}, window {t0}-{t1}: frequency {wp:.5f} within 1 % of the CEA's {w:.5f}")


def outputs(xi, hc):
    """The CEA's outputs the later checks read: the coarse mesh's steady state and modes, the medium mesh's modes at
    the creep of its transient."""
    out = ["-modes_steady_csv", f"s{xi}.csv"] if hc == COARSE else []
    return out + (["-modes_output", modes_file(xi, hc)] if hc == COARSE or (hc == MEDIUM and xi == MEDIUM_RUN[0]) else [])


coarse, medium, fine = {}, {}, {}  # xi: (growth, frequency, row) on the three meshes
for xi in CREEPS:
    res = [cea(xi, hc, outputs(xi, hc)) for hc in MESHES]
    coarse[xi], medium[xi], fine[xi] = res
    g, w = np.array([r[:2] for r in res]).T
    print(f"xi {xi}: growth {g}, frequency {w}")
    d1, d2 = abs(g[1] - g[0]), abs(g[2] - g[1])
    c.check(d2 < d1 or max(d1, d2) < 0.1 * abs(g[2]), f"xi {xi}: the growth converges with h_c (changes {d1:.4f}, {d2:.4f}: shrinking, or both within 10 % of {g[2]:.4f})")
    c.check(abs(w[2] - w[1]) < 0.005 * w[2], f"xi {xi}: the two finer meshes' frequencies within 0.5 % ({w[1]:.5f}, {w[2]:.5f})")

# the stick margin at 0.12 (its most marginal stick node 3.8 % inside the cone on the coarse mesh): 0.05 frees exactly
# the stick nodes within it and moves the eigenvalue; 0.02 has none to free and nothing moves
for xi, m in ((0.12, 0.05), (0.12, 0.02)):
    g0, w0, _ = coarse[xi]
    st = read_csv(f"s{xi}.csv")
    stick = st["state"] == 1
    near = int(np.sum(np.abs(st["tangential_force"][stick]) > (1 - m) * st["mu"][stick] * st["normal_force"][stick]))
    gm, wm, _ = cea(xi, COARSE, ["-modes_stick_margin", m], f"_m{m}")
    print(f"xi {xi}, margin {m}: {near} of {int(stick.sum())} stick nodes within the margin; growth {g0:.5f} -> {gm:.5f}")
    if near:
        c.check(gm != g0, f"xi {xi}: the margin {m} frees {near} stick node(s) and moves the eigenvalue ({g0:.5f} -> {gm:.5f})")
    else:
        c.check(gm == g0 and wm == w0, f"xi {xi}: no stick node within the margin {m}, the eigenvalue unchanged ({g0:.6f} @ {w0:.6f} -> {gm:.6f} @ {wm:.6f})")

# the seed's response on the coarse mesh, seeded minus unseeded, against the converged CEA (the finest mesh's): the
# transient moves the mesh through the patch, where the CEA differences the slip (box, first order in h_c), so the two
# meet in their limits, not mesh by mesh (the coarse CEA is printed beside it)
response = {}
for xi, (tmax, windows) in TRANSIENTS.items():
    g, w, _ = fine[xi]
    i = coarse[xi][2]
    t, U = seed_response(transient(xi, i, "1e-4", tmax), transient(xi, i, "0", tmax))
    response[xi] = (t, U)
    print(f"xi {xi}: the coarse mesh's CEA {coarse[xi][0]:.5f} @ {coarse[xi][1]:.5f}")
    agrees(f"xi {xi}, the seed's response (h_c {COARSE}) against the CEA on h_c {MESHES[-1]}", g, w, t, U, windows)

# the transient's own mesh convergence at 0.13: the seed's response on the medium mesh grows as on the coarse one
xi, tmax, (t0, t1) = MEDIUM_RUN
i = medium[xi][2]
t, U = seed_response(transient(xi, i, "1e-4", tmax, MEDIUM), transient(xi, i, "0", tmax, MEDIUM))
fm, fc = fit(t, U, -fine[xi][1], t0, t1), fit(*response[xi], -fine[xi][1], t0, t1)
for key in ("pencil_growth", "envelope_growth"):
    c.check(abs(fm[key] - fc[key]) < 0.1 * abs(fc[key]),
            f"xi {xi}, window {t0}-{t1}: the seed's response's {key.replace('_', ' ')} on h_c {MEDIUM} {fm[key]:.5f} within 10 % of "
            f"h_c {COARSE}'s {fc[key]:.5f} (the transient converged in h_c)")
c.close()
