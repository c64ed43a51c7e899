"""Quiet rolling contact (issue 13): in the rolling scene at Roller's default discretization (jobs/rolling.yaml
as it stands: eta = 0 and the rubber's Kelvin-Voigt damping, the mesh graded toward Gamma_C that Roller
chooses for contact scenes, P2 curved, dt from -ts_phase_error) the contact force has no line at the
element-passing frequency f_e = omega N_C / (2 pi) (N_C edges on Gamma_C): its amplitude is below 0.2 % of the
mean force (docs/contact.md "Cogging"; 0.87 % on the uniform default mesh with eta = 1 before).

Shorter than the scene (t <= T_END instead of 20): the obstacle stops at t = 5, the window is
T_START <= t <= T_END, about 5 / (1/f_e) periods of the element passing. N_C is counted from the mesh the run
writes (/geometry/vertices of the HDF5 output: the vertices on the outer circle), omega from theta.
Also checked on the same run: no node flickers (contact_reversals = 0 after the obstacle stopped)."""
import math
import os
import sys

import h5py
import numpy as np

from rollertest import SOURCE, Checker, read_csv, run

sys.path.insert(0, os.path.join(SOURCE, "scripts"))
from rollerreport import spectrum as sp  # noqa: E402

T_START, T_END = 7.0, 12.0
c = Checker("contact_quiet")
run(["-options_file", os.path.join(SOURCE, "jobs", "rolling.yaml"), "-ts_max_time", T_END, "-quiet",
     "-monitor_csv", "quiet.csv", "-output", "quiet.h5", "-output_every", 1000000])
d = read_csv("quiet.csv")
with h5py.File("quiet.h5", "r") as f:
    x = f["geometry/vertices"][:]
r = np.hypot(x[:, 0], x[:, 1])
n_c = int(np.sum(np.abs(r - r.max()) < 1e-9 * r.max()))
omega = (d["theta"][-1] - d["theta"][0]) / (d["t"][-1] - d["t"][0])
f_e = omega * n_c / (2 * math.pi)
t, force = sp.window(d["t"], d["contact_force"], T_START, T_END)
line, f_line = sp.relative_amplitude(t, force, f_e)
bg = sp.background(t, force, f_e) / abs(np.mean(force))
print(f"N_C = {n_c}, f_e = {f_e:.3f}; mean force {np.mean(force):.6e}, std/mean {np.std(force) / np.mean(force):.2e}; "
      f"line at f_e {100 * line:.4f} % (at {f_line:.3f}; background {100 * bg:.4f} %)")
c.check(line < 2e-3, f"contact force line at the element-passing frequency {f_e:.2f}: {100 * line:.4f} % of the mean < 0.2 %")
w = d["t"] >= 6.0
c.check(d["contact_reversals"][w].sum() == 0, f"no flicker after the obstacle stopped: {d['contact_reversals'][w].sum():.0f} reversals")
c.close()
