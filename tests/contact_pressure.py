"""The contact pressure output and the contact options in -help (issue 4; docs/contact.md).

With -obstacle and -output, the vertex field contact_pressure is the multiplier of every Gamma_C node (a
nodal force) over the length it carries on the polygon of Gamma_C (half its two edges; for P2 an edge
midpoint's force is shared by the two ends of its edge), 0 elsewhere. So at every written step:
- its trapezoidal integral over Gamma_C, sum_v p_v (|e_v-| + |e_v+|)/2, is the contact_force of the CSV
  to 1e-10 (relative to the largest force of the run);
- it is >= 0, and 0 at every vertex off Gamma_C;
- P1: it is > 0 exactly at the contact_nodes nodes of the CSV;
- the XDMF index lists it, and scripts/rollerplots/fields.py --mode contact draws it.
Without -obstacle, -help still lists the contact options with their defaults (nothing is built).

Discretization: these are identities of the output, true for any discretization, so both scenes run on the
coarse mesh -mesh_h 0.05 with Roller's default dt (from -ts_phase_error: 0.0077 for t <= 1); the P2 rolling
scene with the default P2 curved, extrapolated Coriolis velocity; the P1 scene with -degree 1 given (the
default is P2), since the node-count check is P1's."""
import os
import subprocess
import sys

import h5py
import numpy as np

from rollertest import EXE, SOURCE, Checker, read_csv, run

c = Checker("contact_pressure")
BASE = ["-mesh_h", 0.05, "-obstacle", "-obstacle_speed", 0.05, "-obstacle_depth", 0.01, "-damping", 1,
        "-ts_max_time", 1, "-quiet", "-output_every", 5]

for name, extra in (("P1 compression", ["-omega", 0, "-degree", 1]), ("P2 rolling", ["-omega", 0.3141592653589793, "-degree", 2])):
    tag = name.split()[0].lower()
    run(BASE + extra + ["-monitor_csv", f"{tag}.csv", "-output", f"{tag}.h5"])
    d = read_csv(f"{tag}.csv")
    with h5py.File(f"{tag}.h5", "r") as f:
        x = f["geometry/vertices"][:]
        p = f["vertex_fields/contact_pressure_contact_pressure"][:]
        times = f["time"][:].ravel()
    r = np.hypot(x[:, 0], x[:, 1])
    on = np.abs(r - r.max()) <= 1e-6 * r.max()
    order = np.argsort(np.arctan2(x[on, 1], x[on, 0]))
    X = x[on][order]
    edge = np.hypot(*(np.roll(X, -1, axis=0) - X).T)  # edge from vertex i to i + 1, angle order
    tributary = 0.5 * (edge + np.roll(edge, 1))
    fmax = max(d["contact_force"])
    worst, off, neg, count_ok, touching = 0.0, 0.0, 0.0, True, 0
    for k, t in enumerate(times):
        row = int(np.argmin(np.abs(d["t"] - t)))
        pk = p[k]
        integral = float(np.sum(pk[on][order] * tributary))
        worst = max(worst, abs(integral - d["contact_force"][row]) / fmax)
        off = max(off, float(np.max(np.abs(pk[~on]))))
        neg = min(neg, float(np.min(pk)))
        touching += d["contact_force"][row] > 0
        if tag == "p1":
            count_ok &= int(np.sum(pk[on] > 0)) == int(d["contact_nodes"][row])
    c.check(touching >= 3, f"{name}: in contact at {touching} of the {len(times)} written steps (force up to {fmax:.3e})")
    c.check(worst < 1e-10, f"{name}: integral of contact_pressure over Gamma_C = contact_force to {worst:.1e} (< 1e-10 of the largest force)")
    c.check(neg >= 0 and off == 0, f"{name}: contact_pressure >= 0 (least {neg:.1e}) and 0 off Gamma_C (largest {off:.1e})")
    if tag == "p1":
        c.check(count_ok, f"{name}: contact_pressure > 0 exactly at the contact_nodes nodes of the CSV")
    xmf = open(f"{tag}.xmf").read()
    c.check('Name="contact_pressure"' in xmf, f"{name}: the XDMF index lists contact_pressure")

proc = subprocess.run([sys.executable, "-m", "rollerplots.fields", "p1.h5", "--mode", "contact",
                       "--times", "0.25", "1", "--out", "pressure.png"], capture_output=True, text=True)
c.check(proc.returncode == 0 and os.path.getsize("pressure.png") > 10000,
        f"rollerplots.fields --mode contact draws it (exit {proc.returncode}: {(proc.stdout + proc.stderr).strip()[:120]})")

# (bytes: PETSc 3.18 prints an uninitialized buffer as the default of -dm_plex_boundary_label)
out = subprocess.run([EXE, "-mesh_h", "0.1", "-help"], capture_output=True, check=True).stdout.decode(errors="replace")
listed = [o for o in ("-contact_solver <now condensed", "-contact_margin <0.001", "-contact_rtol <1e-12",
                      "-contact_max_resolves <now 20") if o in out]
c.check(len(listed) == 4, f"-help without -obstacle lists the contact options with their defaults ({len(listed)} of 4 found)")
c.close()
