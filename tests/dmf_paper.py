"""The paper's observations without obstacle (docs/model.md section 5), as assertions:
- doubling E halves the amplitude of R and shortens its period by sqrt(2) (the radial P mode);
- alpha's amplitude falls as E grows, and its period shortens too (the slow, Coriolis-driven S mode;
  the Coriolis coupling 2 omega is not small against its frequency, so the scaling is only roughly
  1/sqrt(E): the bound is loose on purpose, docs/validation.md has the numbers);
- the perturbed rotation theta = omega t + a cos(b t), b = 2 pi / 9.75 (figure 7) makes alpha grow
  steadily, while the unperturbed amplitude stays constant (energy conservation).

Discretization: these are the paper's observations with the paper's scheme, so it is pinned: P1 (-degree 1),
the backward Coriolis velocity, h = 0.025, dt = 0.025 (the defaults are P2 curved, extrapolated, and dt, h
from -ts_phase_error)."""
import numpy as np

from rollertest import Checker, read_csv, run

c = Checker("dmf_paper")
base = ["-ts_scheme", "dmf", "-mesh_h", 0.025, "-ts_dt", 0.025, "-degree", 1, "-coriolis_velocity", "backward", "-quiet"]


def period(t, x):
    """Dominant period by a zero-padded, windowed FFT."""
    x = x - x.mean()
    n = 16 * len(x)
    f = np.abs(np.fft.rfft(x * np.hanning(len(x)), n))
    fr = np.fft.rfftfreq(n, t[1] - t[0])
    return 1.0 / fr[np.argmax(f[1:]) + 1]


series = {}
for E in (0.05, 0.1, 0.2):
    run(base + ["-young", E, "-ts_max_time", 40, "-monitor_csv", f"E{E}.csv"])
    series[E] = read_csv(f"E{E}.csv")
for lo, hi in ((0.05, 0.1), (0.1, 0.2)):
    a, b = series[lo], series[hi]
    amp = a["R"].max() / b["R"].max()
    pr = period(a["t"], a["R"]) / period(b["t"], b["R"])
    pa = period(a["t"], a["alpha"]) / period(b["t"], b["alpha"])
    aa = np.abs(a["alpha"]).max() / np.abs(b["alpha"]).max()
    c.check(abs(amp - 2) < 0.1, f"E {lo} -> {hi}: R amplitude ratio {amp:.3f} = 2 +- 0.1")
    c.check(abs(pr - np.sqrt(2)) < 0.04, f"E {lo} -> {hi}: R period ratio {pr:.3f} = sqrt(2) +- 0.04")
    c.check(aa > 1.2, f"E {lo} -> {hi}: alpha amplitude falls, ratio {aa:.3f} > 1.2")
    c.check(1.2 < pa < 1.8, f"E {lo} -> {hi}: alpha period ratio {pa:.3f} in (1.2, 1.8)")

sixth = {}
for name, extra in (("steady", []), ("perturbed", ["-theta_a", 0.001, "-theta_b", 2 * np.pi / 9.75])):
    run(base + ["-ts_max_time", 60, "-monitor_csv", f"{name}.csv"] + extra)
    a = read_csv(f"{name}.csv")["alpha"]
    q = len(a) // 6
    sixth[name] = [np.abs(a[i * q:(i + 1) * q]).max() for i in range(6)]
s, p = sixth["steady"], sixth["perturbed"]
c.check(max(s) / min(s) < 1.2, f"steady rotation: alpha amplitude constant over 6 windows (max/min {max(s) / min(s):.3f} < 1.2)")
c.check(all(np.diff(p) > 0) and p[-1] > 5 * p[0], f"perturbed rotation: alpha grows in every window, {p[0]:.2e} -> {p[-1]:.2e} (> 5x)")
c.close()
