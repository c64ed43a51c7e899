"""The curved (isoparametric P2) boundary, src/mesh/geometry.c. The rotating annulus without obstacle has an
exact axisymmetric reference; run with the same DMF scheme and dt on its spectral radial
semi-discretization (scripts/rollerref/axisym.py --scheme dmf, exact in space), it isolates the space
error of the 2D run. With straight edges the P2 space error of R is second order (the inscribed polygon
makes the annulus too small by O(h^2)); with the curved boundary it falls faster (2.4 measured over
h = 0.05 .. 0.0125, tending to 3) and is 8-17x smaller.

Discretization: the 2D runs must use the reference's time scheme, so the Coriolis velocity is pinned to the
reference's (--coriolis backward, the paper's; Roller's default is extrapolated), as are degree, h and dt."""
import os
import subprocess
import sys

from rollertest import SOURCE, Checker, read_csv, rel_max_error, run, slope

c = Checker("geometry_curved")
T, DT = 2.0, 0.01
subprocess.run([sys.executable, "-m", "rollerref.axisym", "--scheme", "dmf",
                "--coriolis", "backward", "--dt", str(DT), "--t-end", str(T), "--dt-out", str(DT), "--out", "dmf.csv"], check=True)
ref = read_csv("dmf.csv")
hs = (0.05, 0.025, 0.0125)
err = {}
for curved in (0, 1):
    err[curved] = []
    for h in hs:
        name = f"c{curved}_h{h}.csv"
        run(["-ts_scheme", "dmf", "-degree", 2, "-coriolis_velocity", "backward", "-mesh_curved", curved, "-mesh_h", h, "-ts_dt", DT, "-ts_max_time", T, "-quiet", "-monitor_csv", name])
        d = read_csv(name)
        e = rel_max_error(d, ref, "R")
        print(f"P2 {'curved' if curved else 'straight'} h = {h}: space error of R {e:.3e} (relative to max |R|)")
        err[curved].append(e)
s_straight, s_curved = slope(hs, err[0]), slope(hs, err[1])
c.check(s_curved >= 2.3 and s_straight < 2.1,
        f"space error of R falls at order {s_curved:.2f} >= 2.3 with the curved boundary, {s_straight:.2f} < 2.1 with straight edges")
c.check(all(e1 * 3 <= e0 for e0, e1 in zip(err[0], err[1])) and err[1][-1] * 10 <= err[0][-1],
        "curved boundary: space error of R at least 3x smaller than straight at every h, 10x at the finest (" +
        ", ".join(f"{e0 / e1:.1f}x" for e0, e1 in zip(err[0], err[1])) + ")")

c.close()
