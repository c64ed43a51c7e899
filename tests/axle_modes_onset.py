"""The complex eigenvalue analysis on the axle's stick-slip onset (issue 36; docs/validation.md 10.5,
docs/squeal.md section 3.1): roller -modes -axle on the scenes of tests/axle_stickslip.py (a), the motor at rest, the sheet sliding
under the roller at V = -v, velocity weakening mu(v) = mu + (mu_s - mu) exp(-|v|/v_c).

The steady sliding state is pressed by the spring's preload (-nip_force N: the hub's height solved for that contact
force), the drive's mode is the one with the largest hub_phi. At the three slip speeds v* + (-0.5, +0.5, +1) v_c about
the closed-form onset v* = v_c ln(r^2 N (mu_s - mu)/(c_d v_c)):
- the contact force N within 1e-8 and every contact node sliding (-modes_steady_csv: state 2, at least 10 nodes);
- the drive's growth rate within 5 % of the 1-DOF's -c_eff/(2 I), c_eff = c_d + r^2 N mu'(v) (rollerref, in-process),
  and within 5 % of the finite elements' transient (the rates tests/axle_stickslip.py fits to hub_rate's envelope,
  docs/validation.md 10.5: +0.020738, -0.012534, -0.020101), its sign that of the closed form;
- the onset: log(rate + c_d/(2 I)) is a straight line in v (r^2 N |mu'(v)|/(2 I) an exponential), its crossing of
  log(c_d/(2 I)) within 5 % of v*.
And turning (the lab frame's convective D, P and Kelvin-Voigt A_L border the hub's rows): jobs/axle_bistable.yaml's
steady sliding (set 1 on the roller, the motor at omega, the sheet at rest), the drive's growth rate within 5 % of the
closed form's and of the transient's decay in tests/axle_stickslip.py (b) (-0.008053, docs/validation.md 10.5), stable.
long: four eigenproblems of 40k unknowns (about a minute each), two at a time."""
import math
import os
import sys
from concurrent.futures import ThreadPoolExecutor

from rollertest import SOURCE, Checker, read_csv, run

sys.path.insert(0, os.path.join(SOURCE, "scripts"))
from rollerref import stickslip  # noqa: E402
from rollerref.drive import Motor  # noqa: E402
from rollerref.friction import Friction  # noqa: E402

RHO, RI, RO = 1.0, 0.25, 0.5
I_R = RHO * math.pi * (RO**4 - RI**4) / 2
I_HUB, K_D, N, MU, MU_S = 0.308, 0.04, 0.0025, 0.25, 0.5
I = I_HUB + I_R
SCENE = ["-obstacle", "-axle", "-young", 10, "-viscosity", 0.1, "-nip_force", N, "-axle_inertia", I_HUB, "-axle_mass", 0.1, "-axle_stiffness", 0.01,
         "-drive_stiffness", K_D, "-friction", MU, "-friction_static", MU_S, "-mesh_h", 0.1, "-mesh_h_contact", 0.004, "-omega", 0, "-modes", "-modes_nev", 8, "-quiet"]
XI = 0.1
C_D = 2 * XI * math.sqrt(K_D * I)
V_C = RO**2 * N * (MU_S - MU) / (math.exp(2.5) * C_D)  # v* = 2.5 v_c, as tests/axle_stickslip.py
FE_RATES = [0.020738, -0.012534, -0.020101]  # tests/axle_stickslip.py (a), docs/validation.md 10.5
FE_SLIDE = -0.008053  # tests/axle_stickslip.py (b), the motor turning from the start


def torsion(v):
    return stickslip.Torsion(I=I, k_d=K_D, c_d=C_D, r=RO, N=N, friction=Friction(MU, MU_S, V_C), V=-v, motor=Motor(omega=0.0, t_ramp=0.0, ramp="cubic"))


v_star = stickslip.linear_stability(torsion(0.0))["onset_slip_speed"]
speeds = [v_star + x * V_C for x in (-0.5, 0.5, 1.0)]


def cea(k):
    if k == 3:  # set 1 turning, sheet at rest
        run(["-options_file", os.path.join(SOURCE, "jobs", "axle_bistable.yaml"), "-theta_start", 0, "-drive_ramp", 0, "-modes", "-modes_nev", 8, "-quiet", "-modes_csv", "turning.csv"])
        return k
    run(SCENE + ["-drive_damping", repr(C_D), "-friction_decay", repr(V_C), "-sheet_speed", repr(-speeds[k]), "-modes_csv", f"modes{k}.csv", "-modes_steady_csv", f"steady{k}.csv"])
    return k


c = Checker("axle_modes_onset")
with ThreadPoolExecutor(max_workers=2) as pool:
    list(pool.map(cea, range(4)))
rates = []
for k, v in enumerate(speeds):
    st = read_csv(f"steady{k}.csv")
    on = st["state"] > 0
    c.check(abs(st["normal_force"].sum() / N - 1) < 1e-8 and (st["state"][on] == 2).all() and on.sum() >= 10,
            f"slip {v:.6g}: the steady state's contact force {st['normal_force'].sum():.10g} (-nip_force {N}), {int(on.sum())} nodes in contact, {int((st['state'] == 1).sum())} stuck")
    d = read_csv(f"modes{k}.csv")
    j = int(d["hub_phi"].argmax())
    rate, w = float(d["re"][j]), float(d["im"][j])
    rates.append(rate)
    lin = stickslip.linear_stability(torsion(v))
    ref = lin["growth_rate"]
    c.check(abs(rate / ref - 1) < 0.05, f"slip {v:.6g} ({(v - v_star) / V_C:+.1f} v_c from onset): the CEA's drive mode {rate:+.6f} + {w:.5f} i against -c_eff/(2I) = {ref:+.6f} ({100 * (rate / ref - 1):+.2f} %; "
            f"closed-form frequency {2 * math.pi * lin['frequency']:.5f}, with the rim's spurious N r {math.sqrt(K_D / I + N * RO / I - (lin['c_eff'] / (2 * I))**2):.5f})")
    c.check(abs(rate / FE_RATES[k] - 1) < 0.05, f"  against the finite elements' transient {FE_RATES[k]:+.6f} ({100 * (rate / FE_RATES[k] - 1):+.2f} %)")
    c.check((rate < 0) == lin["stable"], f"  stable by the CEA: {rate < 0}, by the closed form: {lin['stable']}")
y = [math.log(r + C_D / (2 * I)) for r in rates]
n = len(speeds)
mv, my = sum(speeds) / n, sum(y) / n
slope = sum((v - mv) * (a - my) for v, a in zip(speeds, y)) / sum((v - mv)**2 for v in speeds)
v_cea = mv + (math.log(C_D / (2 * I)) - my) / slope
c.check(abs(v_cea / v_star - 1) < 0.05, f"onset slip from the CEA's rates {v_cea:.6g} against v* = {v_star:.6g} ({100 * (v_cea / v_star - 1):+.2f} %; the fitted decay speed {-1 / slope:.4g} against v_c = {V_C:.4g})")

# set 1 turning: the closed form with jobs/axle_bistable.yaml's numbers (tests/axle_stickslip.py (b))
W_N = math.sqrt(K_D / I)
ref_set = stickslip.roller_set(I_rubber=I_R, I_hub=I_HUB, r=RO, N=N * MU / 0.5, w_n=W_N)
p = stickslip.Torsion(I=I, k_d=K_D, c_d=ref_set.c_d, r=RO, N=N, friction=Friction(MU, MU_S, ref_set.friction.v_c), V=0.0, motor=Motor(omega=ref_set.omega, t_ramp=0.0, ramp="cubic"))
lin = stickslip.linear_stability(p)
d = read_csv("turning.csv")
j = int(d["hub_phi"].argmax())
rate = float(d["re"][j])
c.check(lin["stable"] and rate < 0 and abs(rate / lin["growth_rate"] - 1) < 0.05 and abs(rate / FE_SLIDE - 1) < 0.05,
        f"set 1 turning (omega {ref_set.omega:.6g}, slip r omega {RO * ref_set.omega:.6g}): the CEA's drive mode {rate:+.6f} + {float(d['im'][j]):.5f} i against -c_eff/(2I) = {lin['growth_rate']:+.6f} ({100 * (rate / lin['growth_rate'] - 1):+.2f} %) "
        f"and the transient's {FE_SLIDE:+.6f} ({100 * (rate / FE_SLIDE - 1):+.2f} %)")
c.close()
