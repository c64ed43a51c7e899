"""Theorem 1 (docs/model.md section 2): theta = 0, xi = 0 on the whole boundary, no damping, a non-zero initial
state: the discrete energy E^k is the same for every k, to solver tolerance (1e-9 relative over 500
steps), for P1 and P2. With damping eta > 0 the energy must decrease at every step instead.

Discretization: the identity holds for every h and dt; -ts_dt 0.0125 is given (as in jobs/theorem1.yaml) so
that 500 steps span t = 6.25, several periods of the motion: the default dt from -ts_phase_error (0.00172)
would cover only t = 0.86. The degree is given for the conservation runs; the damped run uses the default
(P2 curved). The Coriolis velocity plays no part at omega = 0."""
from rollertest import Checker, read_csv, run

c = Checker("dmf_energy")
base = ["-ts_scheme", "dmf", "-mesh_h", 0.05, "-ts_dt", 0.0125, "-clamp_outer", "-initial_condition", "bump", "-omega", 0, "-quiet"]
for degree in (1, 2):
    run(base + ["-degree", degree, "-ts_max_steps", 500, "-monitor_csv", f"energy_p{degree}.csv"])
    d = read_csv(f"energy_p{degree}.csv")
    e = d["energy"]
    drift = max(abs(e - e[0])) / e[0]
    c.check(e[0] > 0 and drift < 1e-9, f"P{degree}: energy drift over 500 steps {drift:.2e} < 1e-9 (E = {e[0]:.6e})")

run(base + ["-ts_max_steps", 200, "-damping", 1, "-monitor_csv", "energy_damped.csv"])
e = read_csv("energy_damped.csv")["energy"]
c.check(all(e[1:] < e[:-1]) and e[-1] < 0.99 * e[0], f"damping 1: energy decreases at every step ({e[0]:.4e} -> {e[-1]:.4e})")

run(base + ["-ts_max_steps", 200, "-viscosity", 0.01, "-monitor_csv", "energy_viscous.csv"])
d = read_csv("energy_viscous.csv")
e, dv = d["energy"], d["viscous_dissipation"]
closure = max(abs(e[1:] - e[:-1] + dv[1:])) / e[0]
c.check(all(e[1:] < e[:-1]) and all(dv[1:] > 0) and closure < 1e-12,
        f"viscosity 0.01: energy decreases at every step ({e[0]:.4e} -> {e[-1]:.4e}) by the viscous dissipation (closure {closure:.1e} < 1e-12)")

# rotation on (omega, theta_a: Euler, centrifugal and Coriolis loads), both dampings, every Coriolis velocity
for coriolis in ("backward", "extrapolated", "centered"):
    csv = f"energy_rot_{coriolis}.csv"
    run(["-ts_scheme", "dmf", "-mesh_h", 0.05, "-ts_dt", 0.0125, "-theta_a", 0.1, "-theta_b", 2, "-damping", 0.3, "-viscosity", 0.005,
         "-coriolis_velocity", coriolis, "-ts_max_steps", 300, "-quiet", "-monitor_csv", csv])
    d = read_csv(csv)
    e = d["energy"]
    terms = d["load_work"] - d["damping_dissipation"] - d["viscous_dissipation"]
    closure = max(abs(e[1:] - e[:-1] - terms[1:])) / max(e)
    c.check(closure < 1e-12 and min(d["damping_dissipation"]) >= 0 and min(d["viscous_dissipation"]) >= 0,
            f"rotating, {coriolis}: E^k - E^(k-1) = load_work - dissipations at every step (closure {closure:.1e} < 1e-12 of max E)")
c.close()
