"""scripts/rollerplots/traction.py on a small friction run (docs/friction.md section 5.1): the roller pressed and its
shaft turned (P1, graded at the contact, a few seconds of CPU), -output every 20 steps. The script's printed
P and Q/(mu P) at two stored steps are the CSV's contact_force and friction_force/(mu contact_force) at
those steps (to the printed digits: the fields integrate to them exactly, docs/contact.md), every theory option
draws, and each call writes a non-empty PNG."""
import os
import re
import subprocess
import sys

import numpy as np

from rollertest import SOURCE, Checker, read_csv, run

MU = 0.5
run(["-mesh_h", 0.05, "-mesh_h_contact", 0.008, "-mesh_contact_layer", 0.03, "-degree", 1, "-obstacle", "-omega", 0, "-damping", 1,
     "-viscosity", 0.01, "-obstacle_speed", 0.005, "-obstacle_depth", 0.002, "-friction", MU, "-theta_a", 0.004, "-theta_b", 0.5,
     "-theta_start", 2, "-ts_dt", 0.05, "-ts_max_time", 5, "-output", "smoke.h5", "-output_every", 20, "-monitor_csv", "smoke.csv", "-quiet"])
d = read_csv("smoke.csv")
script = ["-m", "rollerplots.traction"]
c = Checker("plot_traction_smoke")
for extra in (["--theory", "cattaneo"], ["--theory", "cattaneo", "--qstar", "0.9", "--reversal", "4", "--normalize"], ["--theory", "carter", "--leading", "-1"], []):
    if os.path.exists("smoke.png"):
        os.remove("smoke.png")
    proc = subprocess.run([sys.executable, *script, "smoke.h5", "--time", "3", "--time", "5", "--out", "smoke.png"] + extra, capture_output=True, text=True)
    lines = [l for l in proc.stdout.splitlines() if l.startswith("t = ")]
    ok = proc.returncode == 0 and len(lines) == 2 and os.path.getsize("smoke.png") > 10000 if os.path.exists("smoke.png") else False
    worst = 1.0
    for l in lines:
        m = re.match(r"t = ([-\d.e+]+): P = ([-\d.e+]+), Q/\(mu P\) = ([-+\d.e]+)", l)
        i = int(np.argmin(np.abs(d["t"] - float(m.group(1)))))
        # printed: P to 7 digits (5e-7 relative), Q/(mu P) to 4 decimals (5e-5)
        worst = max(abs(float(m.group(2)) / d["contact_force"][i] - 1) / 1e-6, abs(float(m.group(3)) - d["friction_force"][i] / (MU * d["contact_force"][i])) / 6e-5)
        worst = min(worst, 1.0) if ok else 1.0
    c.check(ok and worst < 1, f"plot_traction {' '.join(extra) or '(no theory)'}: exit {proc.returncode}, 2 panels, PNG written; P and Q/(mu P) = the CSV's "
            f"to {worst:.2f} of the printed precision (P 1e-6, Q/(mu P) 6e-5)"
            + ("" if ok else f"\n{proc.stdout}{proc.stderr}"))
c.close()
