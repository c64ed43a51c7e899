"""Static contact checks (issue 4; docs/validation.md section 5). Usage: contact_static.py [quick|long]

1. The contact force converges as h shrinks. The compression scene (jobs/compression.yaml: omega = 0, the
   obstacle stops at depth 0.025 at t = 5) with the paper's mass damping eta = 1 given here (the scene's
   Kelvin-Voigt damping leaves the slow modes ringing for long: the test needs the rest state, and eta is the
   quickest way there) is run until the damping has brought it to rest;
   the static force is the mean of contact_force over the last quarter of the run (the undamped
   high-frequency ringing averages out; the means of its two halves must agree to 1e-4). On gmsh's meshes
   for a sequence of h. P1 (error dominated by smooth O(h^1.5) locking error): the successive differences of
   the force shrink, and the mirror asymmetry (|alpha| and the force centroid along the obstacle, from
   -contact_monitor, written as a CSV) is smaller on the finest mesh than on the coarsest. P2 (long; curved boundary): its
   error is the contact-edge error, whose sign depends on where the edge of the contact zone falls between
   the nodes of each (non-nested) mesh, so successive differences need not shrink (measured 7.9e-8, 9.3e-6,
   1.4e-6: F(0.05) and F(0.025) both lie 8e-6 below the limit). It is checked against a reference instead:
   the exact static solution (-static) on a mirror-symmetric mesh graded to h_c = 0.002 at the contact (h_c =
   0.004 agrees to 2e-5): |F(h) - F_ref| / F_ref <= 0.01 (h/0.05)^1.5 at every h (the O(h^1.5) of P2 Signorini
   problems), < 2e-4 on the finest mesh, and the mirror asymmetry obeys the same envelope (|centroid| / a) and
   |alpha| shrinks from the coarsest to the finest mesh (docs/validation.md section 5.1).
2. Hertz line contact. A small indentation (depth 0.002: half-width a ~ 0.027, a tenth of the wall
   thickness 0.25) on a mirror-symmetric mesh graded to h_contact at the contact (tests/contact_meshes.py).
   For a rigid flat pressed into a cylinder of radius R in plane strain, locally (a << R and a << the
   wall), P = pi a^2 E* / (4 R), E* = E / (1 - nu^2), with the elliptic pressure p0 sqrt(1 - s^2/a^2), whose
   force-weighted RMS distance from the centre is a/2. With P the measured force and a = 2 s_rms (from
   -contact_monitor): P / (pi a^2 E* / (4 R)) = 1 within the tolerance on the finest mesh, and the Hertz
   half-width a_H = sqrt(4 P R / (pi E*)) lies beyond the outermost node in contact by less than 1.5
   h_contact. The tolerance allows for the finite wall: the deviation grows like (a/wall)^2, measured 0.33%,
   0.67%, 1.39% at depths 0.001, 0.002, 0.004 (docs/validation.md). A coarser mesh (the second reference
   is the finest) gives the same P and a to the mesh tolerance.
quick: P1 on h = 0.05, 0.025, 0.0125 to t = 20; Hertz with P2, h_contact = 0.004 and 0.002, tolerance 2%.
long:  P1 and P2 on h = 0.05 ... 0.00625 to t = 40; Hertz with P2, h_contact = 0.002 and 0.0005, tolerance
       1.5%. About 12 minutes on one core (691 s measured)."""
import math
import os
import sys

import numpy as np

from contact_meshes import symmetric_mesh
from rollertest import SOURCE, Checker, read_csv, run, slope

MODE = sys.argv[1] if len(sys.argv) > 1 else "quick"
E, NU, R = 0.1, 0.49, 0.5
E_STAR = E / (1 - NU**2)

if MODE == "quick":
    SERIES, T_END = [(1, (0.05, 0.025, 0.0125))], 20.0
    HERTZ = dict(degree=2, h=0.05, h_contacts=(0.004, 0.002), t_end=10.0, tol=0.02, mesh_tol=0.01)
else:
    SERIES, T_END = [(1, (0.05, 0.025, 0.0125, 0.00625)), (2, (0.05, 0.025, 0.0125, 0.00625))], 40.0
    HERTZ = dict(degree=2, h=0.025, h_contacts=(0.002, 0.0005), t_end=12.0, tol=0.015, mesh_tol=0.002)


def reference_force(h_contact):
    """The exact static force (-static) of the compression scene on a mirror-symmetric mesh graded at the contact."""
    symmetric_mesh(f"ref_{h_contact}.msh", 0.0125, h_contact, zone=0.16, grow=0.1)
    mon = f"ref_{h_contact}_contact.csv"
    run(["-dm_plex_filename", f"ref_{h_contact}.msh", "-degree", 2, "-obstacle", "-omega", 0, "-damping", 1,
         "-obstacle_speed", 0.005, "-obstacle_depth", 0.025, "-ts_max_time", 40, "-static", "-quiet", "-contact_monitor", f"ascii:{mon}:ascii_csv"])
    return float(read_csv(mon)["force"][-1])


def static_run(args, t_end, csv):
    """Run to t_end with -contact_monitor (a CSV); the static state as means over the last quarter of the run."""
    contact = csv.replace(".csv", "_contact.csv")
    run(args + ["-ts_max_time", t_end, "-quiet", "-contact_monitor", f"ascii:{contact}:ascii_csv", "-monitor_csv", csv])
    mon, d = read_csv(contact), read_csv(csv)
    t = mon["t"]
    w = t > 0.75 * t_end
    w1, w2 = w & (t <= 0.875 * t_end), t > 0.875 * t_end
    force = mon["force"][w].mean()
    return dict(force=force, drift=abs(mon["force"][w1].mean() - mon["force"][w2].mean()) / force,
                nodes=(int(mon["nodes"][w].min()), int(mon["nodes"][w].max())), s_min=mon["s_min"][-1], s_max=mon["s_max"][-1],
                centroid=abs(mon["s_centroid"][w].mean()), a=2 * math.sqrt(np.mean(mon["s_rms"][w] ** 2)), alpha=abs(d["alpha"][w].mean()))


c = Checker(f"contact_static ({MODE})")

# 1. convergence of the static force of the compression scene
scene = os.path.join(SOURCE, "jobs", "compression.yaml")
F_REF = None
if MODE == "long":
    f_coarse, F_REF = reference_force(0.004), reference_force(0.002)
    print(f"reference (P2 -static, symmetric mesh graded to h_c): {f_coarse:.9e} (h_c = 0.004), {F_REF:.9e} (h_c = 0.002)")
    c.check(abs(f_coarse / F_REF - 1) < 5e-5, f"reference: h_c = 0.004 and 0.002 agree to {abs(f_coarse / F_REF - 1):.1e} < 5e-5")
for degree, hs in SERIES:
    res = [static_run(["-options_file", scene, "-damping", 1, "-viscosity", 0, "-mesh_h", h, "-degree", degree, "-ts_dt", 0.0125, "-coriolis_velocity", "backward"], T_END, f"p{degree}_h{h}.csv") for h in hs]
    for h, r in zip(hs, res):
        print(f"P{degree} h = {h}: force {r['force']:.6e} (halves agree to {r['drift']:.1e}), nodes {r['nodes']}, "
              f"extent [{r['s_min']:+.5f}, {r['s_max']:+.5f}], 2 s_rms {r['a']:.5f}, |centroid| {r['centroid']:.2e}, |alpha| {r['alpha']:.2e}")
    c.check(max(r["drift"] for r in res) < 1e-4 and all(r["nodes"][0] == r["nodes"][1] for r in res),
            f"P{degree}: at rest by t = {T_END:g}: the contact set is fixed and the mean force of the two halves of the last quarter agree to {max(r['drift'] for r in res):.1e} < 1e-4")
    diffs = [abs(res[i + 1]["force"] - res[i]["force"]) for i in range(len(res) - 1)]
    ratios = [diffs[i] / diffs[i + 1] for i in range(len(diffs) - 1)]
    if F_REF is not None:
        errs = [abs(r["force"] / F_REF - 1) for r in res]
        print(f"P{degree}: |F - F_ref| / F_ref = {', '.join(f'{e:.2e}' for e in errs)}, fitted order {slope(hs, errs):.2f}")
    if degree == 1:
        c.check(all(q > 1.5 for q in ratios), f"P{degree}: the force converges: successive differences {', '.join(f'{x:.2e}' for x in diffs)} shrink by {', '.join(f'{q:.2f}' for q in ratios)} (> 1.5)")
        if F_REF is not None:
            c.check(all(errs[i] > 1.5 * errs[i + 1] for i in range(len(errs) - 1)), f"P1: the error against the P2 reference shrinks at every level: {', '.join(f'{e:.2e}' for e in errs)}")
        c.check(res[-1]["centroid"] < res[0]["centroid"] / 5 and res[-1]["alpha"] < res[0]["alpha"] / 2,
                f"P{degree}: mirror asymmetry shrinks from the coarsest to the finest mesh: |centroid| {res[0]['centroid']:.2e} -> {res[-1]['centroid']:.2e} (by > 5), "
                f"|alpha| {res[0]['alpha']:.2e} -> {res[-1]['alpha']:.2e} (by > 2)")
    else:
        env = [0.01 * (h / 0.05) ** 1.5 for h in hs]
        c.check(all(e <= b for e, b in zip(errs, env)) and errs[-1] < 2e-4,
                f"P2: the force converges to the reference {F_REF:.6e}: relative errors {', '.join(f'{e:.2e}' for e in errs)} within 0.01 (h/0.05)^1.5 = {', '.join(f'{b:.1e}' for b in env)}, finest < 2e-4")
        cents = [r["centroid"] / r["a"] for r in res]
        c.check(all(x <= b for x, b in zip(cents, env)) and res[-1]["alpha"] < res[0]["alpha"] / 2,
                f"P2: mirror asymmetry: |centroid| / a = {', '.join(f'{x:.1e}' for x in cents)} within the same envelope, |alpha| {res[0]['alpha']:.2e} -> {res[-1]['alpha']:.2e} (by > 2)")

# 2. Hertz line contact at a small indentation
hz, found = HERTZ, []
for h_contact in hz["h_contacts"]:
    symmetric_mesh(f"hertz_{h_contact}.msh", hz["h"], h_contact, zone=0.05, grow=0.15)
    r = static_run(["-dm_plex_filename", f"hertz_{h_contact}.msh", "-degree", hz["degree"], "-ts_dt", 0.0125, "-coriolis_velocity", "backward", "-obstacle", "-omega", 0,
                    "-damping", 1, "-obstacle_speed", 0.005, "-obstacle_depth", 0.002], hz["t_end"], f"hertz_{h_contact}.csv")
    r["a_hertz"] = math.sqrt(4 * r["force"] * R / (math.pi * E_STAR))
    r["ratio"] = r["force"] / (math.pi * r["a"] ** 2 * E_STAR / (4 * R))
    found.append(r)
    print(f"Hertz: P{hz['degree']} h_contact = {h_contact}: P = {r['force']:.6e}, a = 2 s_rms = {r['a']:.6f}, extent "
          f"[{r['s_min']:+.6f}, {r['s_max']:+.6f}] ({r['nodes'][1]} nodes), a_H(P) = {r['a_hertz']:.6f}, "
          f"P / P_H(a) = {r['ratio']:.4f}, a / a_H = {r['a'] / r['a_hertz']:.4f}")
    c.check(r["drift"] < 2e-3, f"Hertz, h_contact = {h_contact}: at rest (the halves of the last quarter agree to {r['drift']:.1e} < 2e-3)")
r, h_contact = found[-1], hz["h_contacts"][-1]
c.check(abs(r["ratio"] - 1) < hz["tol"], f"Hertz: P / (pi a^2 E*/(4R)) = {r['ratio']:.4f} within {100 * hz['tol']:.1f}% of 1 (a/wall = {r['a'] / 0.25:.3f})")
c.check(r["s_max"] <= r["a_hertz"] <= r["s_max"] + 1.5 * h_contact,
        f"Hertz: a_H = {r['a_hertz']:.5f} lies beyond the outermost node in contact ({r['s_max']:.5f}) by less than 1.5 h_contact = {1.5 * h_contact:.5f}")
for q, h_q in zip(found[:-1], hz["h_contacts"][:-1]):
    dP, da = abs(q["force"] / r["force"] - 1), abs(q["a"] / r["a"] - 1)
    c.check(dP < hz["mesh_tol"] and da < hz["mesh_tol"],
            f"Hertz: h_contact = {h_q} agrees with the finest mesh ({h_contact}): P to {dP:.1e}, a to {da:.1e} (< {hz['mesh_tol']:.0e})")
c.close()
