"""Manufactured solutions (src/mms.c) verify the discretization with the rotation on.
Space: u = (1 + t) U(x) is integrated exactly in time by the DMF scheme, so the error is spatial only:
fitted L2 slopes about 2 (P1) and 3 (P2), H1 slopes about 1 and 2.
Time: u = sin(2 pi t) U(x) on a fixed fine P2 mesh: slope 2 without rotation (the scheme is
Newmark beta = gamma = 1/2); with rotation the paper's backward-difference Coriolis velocity makes it
first order; the extrapolated (explicit) and centred (implicit) velocities restore order 2, also with the
Kelvin-Voigt damping (-viscosity).

Discretization: every run gives its degree, h and Coriolis velocity. The space runs also pin -ts_dt 0.0125 and
the backward Coriolis velocity (what they were written with: the scheme integrates u = (1 + t) U exactly with
either, and the default dt from -ts_phase_error, 0.00172, would only make the 20 steps span a shorter time).

The errors at the end of a run are read from the CSV that -mms_view ascii:F:ascii_csv writes (header t,L2,H1)."""
import os

from rollertest import Checker, read_csv, run, slope

c = Checker("dmf_mms")


def errors(args):
    if os.path.exists("errors.csv"):
        os.remove("errors.csv")
    run(["-ts_scheme", "dmf", "-clamp_outer", "-quiet", "-mms_view", "ascii:errors.csv:ascii_csv"] + args)
    e = read_csv("errors.csv")
    assert list(e) == ["t", "L2", "H1"] and len(e["t"]) == 1, f"errors.csv: columns {list(e)}, {len(e['t'])} rows"
    return float(e["L2"][0]), float(e["H1"][0])


# Space. P1 at nu = 0.3 (at nu = 0.49 P1 locks and the rates are pre-asymptotic on these meshes).
for degree, nu, hs, l2_min, h1_min in ((1, 0.3, [0.025, 0.0125, 0.00625], 1.85, 0.9), (2, 0.49, [0.05, 0.025, 0.0125], 2.7, 1.8)):
    e = [errors(["-mms", "linear", "-omega", 0.3, "-theta_a", 0.1, "-theta_b", 2, "-degree", degree,
                 "-poisson", nu, "-mesh_h", h, "-ts_dt", 0.0125,
                 "-coriolis_velocity", "backward", "-ts_max_steps", 20]) for h in hs]
    sl2, sh1 = slope(hs, [x[0] for x in e]), slope(hs, [x[1] for x in e])
    print(f"P{degree} space: " + ", ".join(f"h={h} L2={x[0]:.3e} H1={x[1]:.3e}" for h, x in zip(hs, e)))
    c.check(sl2 >= l2_min, f"P{degree}: L2 slope {sl2:.2f} >= {l2_min}")
    c.check(sh1 >= h1_min, f"P{degree}: H1 slope {sh1:.2f} >= {h1_min}")

# Time, on a fixed P2 mesh fine enough that the spatial error is far below the time error.
dts = [0.04, 0.02, 0.01]
# The Kelvin-Voigt term tau K (xi^k - xi^{k-2})/(2 dt) is centred: order 2 kept (with tau = 0.05 the viscous
# stress is 30 % of the elastic one at this frequency, so a wrong term would show as an O(1) error).
for omega, coriolis, tau, lo, hi in ((0, "backward", 0, 1.8, 2.5), (2, "backward", 0, 0.8, 1.3), (2, "extrapolated", 0, 1.8, 2.5),
                                     (2, "centered", 0, 1.8, 2.5), (2, "extrapolated", 0.05, 1.8, 2.5)):
    e = [errors(["-mms", "sine", "-omega", omega, "-coriolis_velocity", coriolis, "-degree", 2, "-mesh_h", 0.0125,
                 "-ts_dt", dt, "-ts_max_time", 0.4, "-viscosity", tau])[0] for dt in dts]
    s = slope(dts, e)
    print(f"time omega={omega} {coriolis} viscosity={tau}: " + ", ".join(f"dt={dt} L2={x:.3e}" for dt, x in zip(dts, e)))
    c.check(lo <= s <= hi, f"time, omega = {omega}, {coriolis} Coriolis velocity, viscosity {tau}: L2 slope {s:.2f} in [{lo}, {hi}]")
c.close()
