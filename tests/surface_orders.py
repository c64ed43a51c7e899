"""-monitor_surface_csv (docs/output.md): the lab-frame circumferential orders of the radial displacement of Gamma_C,
the sound's source (scripts/rollerreport/heard.py). On the rolling scene (pressed by the sheet, turning):
- ur0 is the monitor's R (the same functional: bit for bit);
- the orders 1-4 (cos, sin) agree with an independent quadrature of the HDF5 output at every stored step: the
  radial component of R(theta) xi at the outer vertices, at their lab angles, by the periodic trapezoid rule (the
  P1 rule on the vertices against the FE's 5-point rule on the curved edges: within 3 % of each order's largest value);
- the sheet below the roller flattens it: ur1s > 0 (the surface pushed in at -90 degrees) and ur2c > 0 (an ellipse
  wider than tall);
- 2 ranks write the same rows (1e-9 of each column's largest value)."""
import math

import h5py
import numpy as np

from rollertest import SOURCE, Checker, read_csv, run

c = Checker("surface_orders")
BASE = ["-options_file", f"{SOURCE}/jobs/rolling.yaml", "-mesh_h", "0.06", "-ts_max_time", "4", "-quiet"]
run(BASE + ["-monitor_csv", "m.csv", "-monitor_surface_csv", "s.csv", "-output", "f.h5", "-output_every", "25"])
s, m = read_csv("s.csv"), read_csv("m.csv")
head = open("s.csv").readline().strip().split(",")
c.check(head == ["step", "t", "theta", "ur0"] + [f"ur{n}{p}" for n in range(1, 5) for p in "cs"], f"the header: {','.join(head)}")
c.check(len(s["t"]) == len(m["t"]) and np.array_equal(s["t"], m["t"]) and np.array_equal(s["ur0"], m["R"]) and np.array_equal(s["theta"], m["theta"]),
        f"{len(s['t'])} rows; ur0 is the monitor's R and theta its theta, bit for bit")
worst = {}
with h5py.File("f.h5", "r") as f:
    x = f["geometry/vertices"][:][:, :2]
    ro = float(np.ravel(f["parameters"].attrs["r_outer"])[0])
    outer = np.abs(np.hypot(x[:, 0], x[:, 1]) - ro) < 1e-6 * ro
    for k, tk in enumerate(f["time"][:].ravel()):
        row = int(np.argmin(np.abs(s["t"] - tk)))
        th = s["theta"][row]
        rot = lambda p: np.stack([math.cos(th) * p[:, 0] - math.sin(th) * p[:, 1], math.sin(th) * p[:, 0] + math.cos(th) * p[:, 1]], 1)  # noqa: E731
        X, U = rot(x[outer]), rot(f["vertex_fields/displacement_displacement"][k][:, :2][outer])
        phi, ur = np.arctan2(X[:, 1], X[:, 0]), (U * X).sum(1) / ro
        o = np.argsort(phi)
        P, Y = np.append(phi[o], phi[o][0] + 2 * math.pi), np.append(ur[o], ur[o][0])
        for n in range(1, 5):
            for part, g in (("c", np.cos), ("s", np.sin)):
                ref = np.trapz(Y * g(n * P), P) / math.pi
                worst.setdefault(f"ur{n}{part}", []).append((ref, s[f"ur{n}{part}"][row]))
bad = {}
for name, pairs in worst.items():
    ref, got = np.array(pairs).T
    bad[name] = float(np.max(np.abs(got - ref)) / max(np.max(np.abs(ref)), 1e-300))
c.check(max(bad.values()) < 0.03, "the orders against the vertices' trapezoid rule in the lab (HDF5, "
        f"{len(worst['ur1c'])} steps): " + ", ".join(f"{k} {v:.1e}" for k, v in bad.items()))
c.check(s["ur1s"][-1] > 0 and s["ur2c"][-1] > 0 and abs(s["ur1c"][-1]) < 0.3 * s["ur1s"][-1],
        f"the sheet below flattens the roller: ur1s {s['ur1s'][-1]:.3e} > 0, ur2c {s['ur2c'][-1]:.3e} > 0, |ur1c| {abs(s['ur1c'][-1]):.3e} small")
run(BASE + ["-monitor_surface_csv", "s2.csv"], nproc=2)
s2 = read_csv("s2.csv")
diff = max(float(np.max(np.abs(s2[k] - s[k])) / max(np.max(np.abs(s[k])), 1e-300)) for k in head[3:])
c.check(len(s2["t"]) == len(s["t"]) and diff < 1e-9, f"2 ranks: the same rows (largest relative difference {diff:.1e})")
c.close()
