"""A synthetic report folder for the report's quick tests (tests/rollerreport_unit.py, tests/report_page.py): a CEA with
one growing mode, a map over creep and friction, a transient whose contact force and mean radius R whirl at the
CEA's frequency (the contact force also carries the mesh-passing square wave), a small HDF5 file of a ring with stick
and slip; no roller run."""
import csv
import json
import math
import os

import numpy as np

F_ND, SIGMA, ETA, PITCH = 0.37, 0.012, 0.05, 1234.0
COLS = ["case", "re", "im", "frequency", "growth_rate", "order", "wave"]
N_RING, OMEGA = 48, 0.1  # the ring's vertices on its outer circle pass the patch at omega n / (2 pi) (2.06 f_nd)
F_MESH = OMEGA * N_RING / (2 * math.pi)


def write_csv(path, head, rows):
    with open(path, "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(head)
        w.writerows(rows)


def make(d, t_end=300.0, dt=0.02, sigma=SIGMA, r_amp=1e-4):
    """The folder d (created): scene.json (nd, heard at PITCH), modes.csv, sweep.csv, transient.csv (t, contact_force,
    R), transient.h5; returns the transient's times."""
    os.makedirs(d, exist_ok=True)
    json.dump({"name": "synthetic", "units": "nd", "loss_factor": ETA, "friction": 0.5, "creep": 0.02, "pitch_si_hz": PITCH,
               "r_outer": 0.5, "metres_per_unit": 0.0125 / 0.5}, open(os.path.join(d, "scene.json"), "w"))
    write_csv(os.path.join(d, "modes.csv"), COLS, [[0, sigma, 2 * math.pi * F_ND, F_ND, sigma, 1, "backward"],
                                                   [0, -0.02, 2 * math.pi * 0.8, 0.8, -0.02, 2, "forward"],
                                                   [0, sigma, -2 * math.pi * F_ND, -F_ND, sigma, 1, "backward"]])
    rows = []
    for creep in (0.01, 0.02, 0.04):
        for mu in (0.2, 0.3, 0.4, 0.5, 0.6):
            g = 0.06 * (mu - 0.35) - 0.1 * creep  # onset at mu = 0.35 + creep * 1.67
            rows.append([0, g, 2 * math.pi * F_ND, F_ND, g, 1, "backward", creep, mu])
    write_csv(os.path.join(d, "sweep.csv"), COLS + ["creep", "friction"], rows)
    t = dt * np.arange(int(round(t_end / dt)))
    mode = np.exp(sigma * t) * np.cos(2 * math.pi * F_ND * t + 0.3)
    force = 1.0 + 1e-3 * mode + 0.03 * np.sign(np.sin(2 * math.pi * F_MESH * t))
    write_csv(os.path.join(d, "transient.csv"), ["step", "t", "contact_force", "R"],
              [[k, t[k], force[k], -2e-3 + r_amp * mode[k]] for k in range(len(t))])
    import h5py

    n = N_RING
    ang = 2 * math.pi * np.arange(n) / n
    x = np.concatenate([0.5 * np.stack([np.cos(ang), np.sin(ang)], 1), 0.3 * np.stack([np.cos(ang), np.sin(ang)], 1)])
    cells = np.array([[i, (i + 1) % n, n + i] for i in range(n)] + [[(i + 1) % n, n + (i + 1) % n, n + i] for i in range(n)])
    frames = 6
    with h5py.File(os.path.join(d, "transient.h5"), "w") as f:
        f.create_group("parameters").attrs.update({"omega": OMEGA, "theta_start": 0.0, "r_outer": 0.5})
        f["geometry/vertices"] = x
        f["viz/topology/cells"] = cells
        tf = np.linspace(0, 3, frames)
        f["time"] = tf[:, None]
        xi = np.zeros((frames, 2 * n, 3))
        for k in range(frames):  # an order-2 breathing of the outer ring
            xi[k, :n, 0] = 0.01 * np.cos(2 * ang) * np.cos(ang) * math.cos(2 * math.pi * F_ND * tf[k])
            xi[k, :n, 1] = 0.01 * np.cos(2 * ang) * np.sin(ang) * math.cos(2 * math.pi * F_ND * tf[k])
        f["vertex_fields/displacement_displacement"] = xi
        st = np.zeros((frames, 2 * n))
        for k in range(frames):
            ring = (np.arange(n) + k) % n
            st[k, ring[:3]], st[k, ring[3:6]] = 1, 2
        f["vertex_fields/contact_state_contact_state"] = st
    return t
