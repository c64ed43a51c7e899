"""scripts/rollerreport/spectrum.py and scripts/rollerplots/spectrum.py on synthetic signals (no roller run; docs/contact.md,
"Cogging: the force spectrum").

1. A pure sinusoid c + a cos(2 pi f t + phi) off the FFT's bins: relative_amplitude returns a/c to 1e-6 and
   f to 1e-4 of a bin, also when asked at a nominal frequency 0.6 bins off (the Hann window alone, read at
   the nearest bin, would lose up to 15 %: checked that the search is what recovers it).
2. Two lines, a slow drift-free mode and noise: each line within 1 %, strongest_line finds the larger one.
3. A non-uniform t (jittered samples): uniform_series resamples, the amplitude is recovered to 1e-3.
4. flicker counts the reversals of an integer series; element_passing_frequency gives the period 0.0796
   of the paper's rolling scene (P1, h = 0.0125, omega = pi/10, r_C = 0.5), the issue's "0.080".
5. The CLI: --table/--json on a synthetic CSV give the same numbers; an unknown column is an error naming it
   and listing the available columns."""
import json
import math
import os
import subprocess
import sys

import numpy as np

from rollertest import SOURCE, Checker

sys.path.insert(0, os.path.join(SOURCE, "scripts"))
from rollerreport import spectrum as sp  # noqa: E402

c = Checker("spectrum_synthetic")
rng = np.random.default_rng(13)

# 1. a pure sinusoid off the bins, on Roller's default rolling window (dt = 0.00171757, 10 <= t <= 20)
dt = 0.00171757
t = 10 + dt * np.arange(int(10 / dt) + 1)
T = t[-1] - t[0]
mean, amp, f0 = 3.4e-3, 3.0e-5, 7.1 + 0.37 / T  # 0.37 bins off the FFT grid of the window
y = mean + amp * np.cos(2 * math.pi * f0 * t + 0.7)
a, f = sp.line_amplitude(t, y, f0)
c.check(abs(a / amp - 1) < 1e-6, f"pure sinusoid at f0: amplitude {a / amp:.9f} of the true one")
c.check(abs(f - f0) < 1e-4 / T, f"pure sinusoid: peak at {f:.9g} vs {f0:.9g}")
a, f = sp.line_amplitude(t, y, f0 - 0.6 / T)
c.check(abs(a / amp - 1) < 1e-6 and abs(f - f0) < 1e-4 / T,
        f"asked 0.6 bins off: amplitude {a / amp:.9f} of the true one, found at {f:.9g} (f0 {f0:.9g})")
# relative to the sample mean, which differs from c by the partial period in the window (amp / (2 pi f T))
rel, f = sp.relative_amplitude(t, y, f0)
c.check(abs(rel / (amp / mean) - 1) < 1e-4, f"relative amplitude {rel:.9g} vs {amp / mean:.9g}")
a_fixed = sp.line_amplitude(t, y, f0 - 0.5 / T, band=0)[0]
c.check(a_fixed / amp < 0.9, f"without the search, half a bin off: {a_fixed / amp:.3f} of the amplitude (scalloping)")
fs, A = sp.spectrum(t, y)
c.check(abs(A.max() / amp - 1) < 5e-3, f"zero-padded spectrum's maximum {A.max() / amp:.5f} of the amplitude")
# a mean far larger than the line and a linear drift: detrend='linear' removes the drift
yd = y + 1e-5 * (t - t[0])
rel_d = sp.relative_amplitude(t, yd, f0, detrend="linear")[0] * np.mean(yd) / mean
c.check(abs(rel_d / (amp / mean) - 1) < 1e-4, f"with a linear drift, detrend=linear: {rel_d:.7g}")

# 2. two lines (f_e and 3 f_e), a slow mode and noise
f1, f3, a1, a3 = 7.1, 21.3, 2.0e-5, 3.5e-5
y2 = (mean + a1 * np.sin(2 * math.pi * f1 * t) + a3 * np.cos(2 * math.pi * f3 * t + 1.0)
      + 1e-5 * np.cos(2 * math.pi * 0.29 * t) + 2e-6 * rng.standard_normal(t.size))
r1, _ = sp.relative_amplitude(t, y2, f1)
r3, _ = sp.relative_amplitude(t, y2, f3)
c.check(abs(r1 / (a1 / mean) - 1) < 0.01 and abs(r3 / (a3 / mean) - 1) < 0.01,
        f"two lines and noise: {r1 / (a1 / mean):.4f}, {r3 / (a3 / mean):.4f} of the true amplitudes")
A_s, f_s = sp.strongest_line(t, y2)
c.check(abs(f_s - f3) < 0.5 / T and abs(A_s / a3 - 1) < 0.01, f"strongest line at {f_s:.4f} (amplitude {A_s / a3:.4f} of a3)")

# 3. non-uniform sampling
tj = np.sort(t + 0.3 * dt * rng.uniform(-1, 1, t.size))
yj = mean + amp * np.cos(2 * math.pi * f0 * tj + 0.7)
tu, yu, resampled = sp.uniform_series(tj, yj)
rel_j = sp.relative_amplitude(tu, yu, f0)[0]
c.check(resampled and abs(rel_j / (amp / mean) - 1) < 1e-3, f"jittered t resampled: {rel_j / (amp / mean):.6f} of the amplitude")
c.check(not sp.uniform_series(t, y)[2], "uniform t is left alone")

# 4. flicker and the element-passing frequency
fl = sp.flicker([3, 3, 4, 3, 3, 3, 4, 4, 5, 5, 4], within=3)
c.check(fl["changes"] == 5 and fl["reversals"] == 3 and fl["immediate"] == 1 and fl["max_jump"] == 1, f"flicker {fl}")
period = 1 / sp.element_passing_frequency(math.pi / 10, 0.0125, 0.5)
c.check(abs(period - 0.0796) < 1e-4, f"element-passing period of the paper's scene {period:.5f} (issue 13: 0.080)")

# 5. the CLI on a synthetic CSV (columns as Roller writes them)
step = np.arange(int(20 / dt) + 1)
tt = dt * step
force = mean + amp * np.cos(2 * math.pi * f0 * tt)
with open("synthetic.csv", "w") as f:
    f.write("step,t,R,alpha,energy,contact_nodes,contact_force,gap_min,qp_iterations,kkt_residual,theta\n")
    for k, tk in enumerate(tt):
        f.write(f"{k},{tk!r},0,{-1e-3 + 1e-6 * math.sin(tk)!r},0,{25 + (k % 7 == 0)},{force[k]!r},0,1,0,"
                f"{math.pi / 10 * tk!r}\n")
cli = [sys.executable, "-m", "rollerplots.spectrum", "synthetic.csv"]
p = subprocess.run(cli + ["--tmin", "10", "--tmax", "20", "--h", "0.0125", "--table", "--json", "s.json"],
                   capture_output=True, text=True)
print(p.stdout + p.stderr)
if p.returncode == 0:
    s = json.load(open("s.json"))[0]
    cf = s["columns"]["contact_force"]
    c.check(abs(s["omega"] - math.pi / 10) < 1e-9 and abs(s["f_e"] - (math.pi / 10) * 0.5 / 0.0125) < 1e-9,
            f"omega from theta {s['omega']:.9g}, f_e {s['f_e']:.6g}")
    c.check(abs(cf["strongest_rel"] / (amp / mean) - 1) < 1e-4 and cf["tmin"] >= 10 - dt,
            f"CLI strongest line {cf['strongest_f']:.5g}, {cf['strongest_rel']:.6g} (true {amp / mean:.6g})")
    c.check(s["contact_nodes"]["changes"] > 0, f"CLI contact_nodes {s['contact_nodes']}")
else:
    c.check(False, f"rollerplots.spectrum exited {p.returncode}")
p = subprocess.run(cli + ["--columns", "friction_force"], capture_output=True, text=True)
c.check(p.returncode != 0 and "friction_force" in p.stderr and "contact_force" in p.stderr,
        f"unknown column: exit {p.returncode}, {p.stderr.strip()}")
c.close()
