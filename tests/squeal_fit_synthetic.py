"""scripts/rollerreport/squeal_fit.py on a synthetic monitor CSV (no roller run; docs/squeal.md 4.4.3): the column path that fits a
mode of any order in the contact force.

1. Two CSVs written every step (dt = 0.0025, t <= 60), as -monitor_csv writes them: the unseeded one carries the
   steady force, the start's own excitation of the same mode (a line at the same frequency, larger than the seed and
   decaying), a line at 6.1, the mesh-passing line at 88.6 rad / time and noise; the seeded one adds
   e^{g t} cos(w t) at the CEA's w = 6.857, g = 0.05. rollerreport.squeal_fit SEEDED.csv --base UNSEEDED.csv --cea F.csv
   --order 10 --wave forward fits the difference: growth within 5 % (pencil and envelope), frequency within 0.5 %
   (the seeded run alone mixes the two lines of the same frequency: its fit is not the seed's).
2. A column the CSV does not have is an error that names it."""
import os
import subprocess
import sys

import numpy as np

from rollertest import SOURCE, Checker

FIT = ["-m", "rollerreport.squeal_fit"]
c = Checker("squeal_fit_synthetic")
rng = np.random.default_rng(5)
g, w, dt = 0.05, 6.857, 0.0025
t = np.arange(0, 60 + dt / 2, dt)
start = 2e-5 * np.exp(-0.04 * t) * np.cos(w * t + 1.1)  # the start's own excitation of the mode, decaying
base = 3.46e-3 + start + 2e-6 * np.exp(-0.03 * t) * np.cos(6.1 * t) + 1e-6 * np.cos(88.6 * t) + 2e-8 * rng.standard_normal(len(t))
seeded = base + 1e-6 * np.exp(g * t) * np.cos(w * t + 0.4)


def write(name, force):
    with open(name, "w") as f:
        f.write("step,t,contact_force,friction_force\n")
        for k in range(len(t)):
            f.write(f"{k},{t[k]:.10g},{force[k]:.17g},{-0.78 * force[k]:.17g}\n")


write("unseeded.csv", base)
write("seeded.csv", seeded)
with open("cea.csv", "w") as f:
    f.write("re,im,frequency,growth_rate,order,wave,error\n")
    f.write(f"-0.002,0.803,0.803,-0.002,1,backward,1e-16\n{g},{w},{w},{g},10,forward,1e-16\n")


def fit(*args):
    r = subprocess.run([sys.executable, *FIT, "seeded.csv", "--cea", "cea.csv", "--order", "10", "--wave", "forward", "--dt", str(dt)] + list(args), capture_output=True, text=True)
    line = [ln for ln in r.stdout.splitlines() if ln.startswith("transient")]
    if r.returncode or not line:
        return r.returncode, r.stdout + r.stderr, None
    words = line[0].replace(",", "").replace(";", "").split()
    return 0, line[0], (float(words[words.index("pencil") + 2]), abs(float(words[words.index("frequency") + 1])), float(words[words.index("envelope") + 2]))


for label, args, tol in (("seeded - unseeded", ["--base", "unseeded.csv", "--window", "5", "55"], 0.05),):
    code, text, got = fit(*args)
    print(label, text)
    c.check(got is not None, f"{label}: the fit ran ({code})")
    if got:
        gp, wp, ge = got
        c.check(abs(gp - g) < tol * g, f"{label}: pencil growth {gp:.5f} within {tol:.0%} of {g}")
        c.check(abs(ge - g) < tol * g, f"{label}: envelope growth {ge:.5f} within {tol:.0%} of {g}")
        c.check(abs(wp - w) < 0.005 * w, f"{label}: frequency {wp:.4f} within 0.5 % of {w}")

code, text, _ = fit("--signal", "no_such_column", "--window", "5", "55")
c.check(code != 0 and "no_such_column" in text, f"an unknown column is an error naming it (exit {code})")
c.close()
