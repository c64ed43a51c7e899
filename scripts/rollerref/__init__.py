"""rollerref: independent one-degree-of-freedom references for Roller's axle, drive and sheet (issue 36;
docs/validation.md section 10, "One-degree-of-freedom references"). Python only (numpy, scipy).

- friction: Roller's law mu(v) = mu_k + (mu_s - mu_k) exp(-|v|/v_c);
- drive: the motor's angle (a start from rest, a speed ramp, a ripple);
- engine: an event-driven integrator with exact stick/slip switching for small systems with Coulomb contacts;
- stickslip: the torsional 1-DOF on a sheet: steady sliding, closed-form linear stability and onset, the
  stick-slip cycle, Stender, Hoffmann and Papangelo's oscillator, the mapping to roller variables;
- basin: bistability, the smallest disturbance (kick, ramp) that reaches the cycle, the bistable band, basin
  stability, a proposed bistable set in roller variables;
- timestep: Moreau's time-stepping of the same 1-DOF (first order), an independent check of engine;
- sheet: the sheet picked from rest (kinematic or coupled roller): closed forms, settle points, integration;
- forced: the hub's forced response to the motor's ripple, 1-DOF and hub + tyre 2-DOF.

The references of the elastic roller itself (commands: `python3 -m rollerref.NAME --help`):
- axisym: the exact axisymmetric solution (1-D radial problem, exact in time or by the DMF variants;
  docs/validation.md 2);
- annulus_modes: the free rotating annulus's modes per circumferential order (docs/squeal.md 2);
- mode_transient: a mode's frequency and growth measured in a seeded transient (docs/squeal.md 4.1).

Run `PYTHONPATH=scripts python3 -m rollerref --help` for the command line (JSON/CSV reference numbers).
"""
__all__ = ["friction", "drive", "engine", "stickslip", "basin", "timestep", "sheet", "forced", "axisym", "annulus_modes",
           "mode_transient"]
