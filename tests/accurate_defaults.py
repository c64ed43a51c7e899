"""Accurate by default (docs/model.md section 6.2): `roller` with physical options only (no -degree, -mesh_h,
-ts_dt, -coriolis_velocity) is within 1 % of the exact axisymmetric solution (scripts/rollerref/axisym.py,
~1e-9) in the max error of R(t) and alpha(t), relative to the reference's max, for the paper's roller
(Table 1) and for softer, stiffer and longer runs: dt and h follow the scene's modes and end time.
Usage: accurate_defaults.py [quick|long]. quick: E = 0.1, 0.05, 0.2 to t = 20; long: E = 0.1 to t = 60.
"""
import os
import subprocess
import sys

from rollertest import SOURCE, Checker, read_csv, rel_max_error, run

MODE = sys.argv[1] if len(sys.argv) > 1 else "quick"
CASES = [(0.1, 20.0), (0.05, 20.0), (0.2, 20.0)] if MODE == "quick" else [(0.1, 60.0)]
REFERENCE = ["-m", "rollerref.axisym"]

c = Checker(f"accurate_defaults ({MODE})")
for young, t_end in CASES:
    name = f"E{young}_T{t_end:g}"
    subprocess.run([sys.executable, *REFERENCE, "--scheme", "exact", "--young", str(young), "--t-end", str(t_end),
                    "--dt-out", "0.001", "--out", f"reference_{name}.csv"], check=True)
    ref = read_csv(f"reference_{name}.csv")
    run(["-young", young, "-ts_max_time", t_end, "-quiet", "-monitor_csv", f"{name}.csv"])
    d = read_csv(f"{name}.csv")
    dt = d["t"][1] - d["t"][0]
    c.check(abs(d["t"][-1] - t_end) < dt, f"-young {young} -ts_max_time {t_end:g}: the run reaches t = {d['t'][-1]:.6g} (dt = {dt:.4g})")
    eR, ea = rel_max_error(d, ref, "R"), rel_max_error(d, ref, "alpha")
    c.check(eR < 0.01 and ea < 0.01, f"-young {young} -ts_max_time {t_end:g}: max error R {eR:.3%}, alpha {ea:.3%} < 1 %")
c.close()
