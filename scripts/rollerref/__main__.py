"""python3 -m rollerref COMMAND [options]: reference numbers of the 1-DOF models as JSON (stdout or --json FILE),
time series as CSV (--csv FILE). Commands (docs/validation.md section 10):

  stability  steady sliding and its closed-form linear stability (eigenvalues, growth rate, onset speeds)
  cycle      the stick-slip cycle by its single slip (period, amplitudes, stick fraction); --long also integrates
             from rest and extracts the cycle; --csv writes that run
  basin      bistability: linear stability, the start from rest (or --kick), a small kick, the smallest kick, the
             longest ramp
  propose    a bistable set in roller variables (Stender's nondimensional numbers mapped), with its checks
  stender    Stender, Hoffmann, Papangelo's oscillator over belt speeds --v_d (stable?, cycle?, kick threshold)
  sheet      the sheet picked from rest by a roller at constant speed: closed form, integration, settle points
  forced     the hub's response to the ripple at --f (1-DOF; with --k_r the hub + tyre 2-DOF)
  simulate   integrate from --th0 --w0 (default: rest) to --t_end, --csv the samples
"""
import argparse
import csv
import json
import math
import sys

import numpy as np

from . import basin, forced, sheet, stickslip
from .drive import Motor
from .friction import Friction


def _clean(x):
    if isinstance(x, dict):
        return {str(k): _clean(v) for k, v in x.items() if not callable(v)}
    if isinstance(x, (list, tuple)):
        return [_clean(v) for v in x]
    if isinstance(x, complex):
        return {"re": x.real, "im": x.imag}
    if isinstance(x, (np.floating, float)):
        x = float(x)
        return x if math.isfinite(x) else str(x)
    if isinstance(x, np.integer):
        return int(x)
    if isinstance(x, np.bool_):
        return bool(x)
    if isinstance(x, np.ndarray):
        return _clean(x.tolist())
    return x


def _torsion(a):
    return stickslip.Torsion(I=a.I, k_d=a.k_d, c_d=a.c_d, r=a.r, N=a.N, friction=Friction(a.mu_k, a.mu_s, a.v_c),
                             V=a.V, V_ramp=a.V_ramp,
                             motor=Motor(omega=a.omega, t0=a.t0, t_ramp=a.t_ramp, ramp=a.ramp, ripple=a.ripple,
                                         ripple_frequency=a.ripple_frequency))


def _write_csv(path, res, p=None):
    with open(path, "w", newline="") as f:
        w = csv.writer(f)
        m = res.g.shape[1]
        head = ["t"] + [f"q{i}" for i in range(res.q.shape[1])] + [f"u{i}" for i in range(res.u.shape[1])]
        head += [f"slip{j}" for j in range(m)] + [f"force{j}" for j in range(m)] + [f"mode{j}" for j in range(m)]
        if p is not None:
            head += ["theta_m", "hub_rate", "drive_torque"]
        w.writerow(head)
        for i in range(len(res.t)):
            row = [res.t[i], *res.q[i], *res.u[i], *res.g[i], *res.F[i], *res.mode[i]]
            if p is not None:
                a, v, _ = p.motor.state(res.t[i])
                row += [a, res.u[i, 0], p.k_d * (a - res.q[i, 0]) + p.c_d * (v - res.u[i, 0])]
            w.writerow([f"{float(x):.17g}" for x in row])


DEFAULTS = {}


def main(argv=None):
    ap = argparse.ArgumentParser(prog="rollerref", description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("command", choices=["stability", "cycle", "basin", "propose", "stender", "sheet", "forced", "simulate"])
    g = ap.add_argument_group("the torsional 1-DOF (defaults: Stender's oscillator at v_d = 1.5)")
    for name, d, h in [("I", 1.0, "total polar inertia"), ("k_d", 1.0, "drive stiffness"), ("c_d", 0.1, "drive damping"),
                       ("r", 1.0, "contact radius"), ("N", 1.0, "normal force per unit width"),
                       ("mu_k", 0.5, "kinetic friction"), ("mu_s", 1.0, "static friction mu(0)"),
                       ("v_c", 0.5, "decay speed of mu (0: constant)"), ("omega", 0.0, "motor speed"),
                       ("V", 1.5, "sheet speed"), ("V_ramp", 0.0, "sheet's ramp from rest (0: none)"),
                       ("t0", 0.0, "motor start"), ("t_ramp", 0.0, "motor ramp"), ("ripple", 0.0, "ripple a (rad)"),
                       ("ripple_frequency", 0.0, "ripple f (cycles per unit time)")]:
        g.add_argument("--" + name, type=float, default=None, help=f"{h} (default {d}; propose: its own)")
        DEFAULTS[name] = d
    g.add_argument("--ramp", default="linear", choices=["linear", "cosine", "cubic"])
    ap.add_argument("--kick", type=float, default=None, help="basin: the large disturbance is this kick of th' toward "
                    "stick from steady sliding (default: the start from rest, th = th' = 0)")
    ap.add_argument("--long", action="store_true", help="cycle: also integrate from rest and extract the cycle")
    ap.add_argument("--t_end", type=float, default=None, help="simulate/cycle --long: end time (default 300 periods)")
    ap.add_argument("--th0", type=float, default=0.0)
    ap.add_argument("--w0", type=float, default=0.0)
    ap.add_argument("--dt_out", type=float, default=None, help="sample interval of --csv (default period/200)")
    ap.add_argument("--v_d", type=float, nargs="*", default=[1.0, 1.2, 1.5, 1.8, 1.9], help="stender: belt speeds")
    ap.add_argument("--xi", type=float, default=0.05, help="propose/stender: damping ratio")
    ap.add_argument("--v0", type=float, default=0.5, help="propose/stender: v_c in units of U = r^2 N/sqrt(k_d I)")
    ap.add_argument("--w_n", type=float, default=1.0, help="propose: sqrt(k_d/I)")
    ap.add_argument("--I_hub", type=float, default=0.1, help="propose: hub inertia")
    ap.add_argument("--I_rubber", type=float, default=0.092, help="propose: rubber inertia")
    ap.add_argument("--m_s", type=float, default=0.05, help="sheet: mass per unit width")
    ap.add_argument("--F_r", type=float, default=0.3, help="sheet: resistance per unit width")
    ap.add_argument("--f", type=float, nargs="*", default=None, help="forced: ripple frequencies (default w_n/2pi)")
    ap.add_argument("--c_f", type=float, default=None, help="forced: linearized friction damping (default: c_eff - c_d)")
    ap.add_argument("--I_t", type=float, default=None, help="forced: tyre inertia (2-DOF, with --k_r)")
    ap.add_argument("--k_r", type=float, default=None, help="forced: rubber torsional stiffness (2-DOF)")
    ap.add_argument("--c_r", type=float, default=0.0, help="forced: rubber torsional damping (2-DOF)")
    ap.add_argument("--json", default=None, help="write the JSON here (default stdout)")
    ap.add_argument("--csv", default=None, help="write the time series here")
    a = ap.parse_args(argv)
    given = {k: getattr(a, k) for k in DEFAULTS if getattr(a, k) is not None}
    for k, d in DEFAULTS.items():
        if getattr(a, k) is None:
            setattr(a, k, d)
    p = _torsion(a)
    T_n = 2 * math.pi / p.w_n
    out = {"command": a.command}
    res = None
    if a.command == "stability":
        out.update(steady_sliding=stickslip.steady_sliding(p), linear=stickslip.linear_stability(p),
                   nondimensional=stickslip.to_nondimensional(p))
    elif a.command == "cycle":
        out["cycle"] = stickslip.stick_slip_cycle(p)
        if a.long or a.csv:
            res = stickslip.simulate(p, a.t_end or 300 * T_n, th0=a.th0, w0=a.w0, dt_out=a.dt_out or T_n / 200)
            out["long"] = stickslip.limit_cycle(p, res, t_min=res.t[-1] - 60 * T_n)
    elif a.command == "basin":
        b = basin.bistability(p, start_from_rest=a.kick is None, kick=a.kick)
        out.update(bistability=b, kick_threshold=basin.kick_threshold(p), ramp_threshold=basin.ramp_threshold(p, a.ramp))
    elif a.command == "propose":
        kw = {k: given[k] for k in ("N", "r", "mu_k", "mu_s") if k in given}
        out.update(basin.propose(w_n=a.w_n, I_hub=a.I_hub, I_rubber=a.I_rubber, xi=a.xi, v0=a.v0,
                                     v_d=a.v_d[0] if len(a.v_d) == 1 else 1.5, **kw))
    elif a.command == "stender":
        rows = []
        for vd in a.v_d:
            q = stickslip.stender(xi=a.xi, v_d=vd, v0=a.v0, mu_d=a.mu_k, mu_sd=a.mu_s / a.mu_k)
            lin = stickslip.linear_stability(q)
            cyc = stickslip.stick_slip_cycle(q)
            kick = basin.kick_threshold(q, rel_tol=1e-2) if lin["stable"] and cyc["exists"] else None
            rows.append({"v_d": vd, "sliding_stable": lin["stable"], "growth_rate": lin["growth_rate"],
                         "cycle": cyc["exists"], "period": cyc.get("period"), "stick_fraction": cyc.get("stick_fraction"),
                         "kick_threshold": kick and kick["threshold"]})
        out["rows"] = rows
        out["window"] = basin.bistable_window(stickslip.stender(xi=a.xi, v0=a.v0, mu_d=a.mu_k, mu_sd=a.mu_s / a.mu_k))
    elif a.command == "sheet":
        S = sheet.Sheet(m_s=a.m_s, F_r=a.F_r)
        cf = sheet.closed_form(S, p.friction, p.N, p.r, p.omega)
        t_end = a.t_end or (2 * cf["t_stick"] if math.isfinite(cf["t_stick"]) else 10.0)
        res = sheet.pick(S, p.friction, p.N, p.r, Motor(omega=p.omega), t_end, dt_out=a.dt_out)
        V = res.u[:, 0]
        out["closed_form"] = cf
        out["integrated"] = {"t_stick": next((e[0] for e in res.events if e[2] == "stick" and e[1] == 0), math.inf),
                             "final_speed": V[-1],
                             "max_difference": float(np.abs(V - cf["V_of_t"](res.t)).max()) if cf["moves"] else float(np.abs(V).max())}
        out["coupled_steady"] = sheet.coupled_steady(S, p)
    elif a.command == "forced":
        lin = stickslip.linear_stability(p)
        c_f = a.c_f if a.c_f is not None else (lin["c_eff"] - p.c_d if p.r * p.omega != p.V else 0.0)
        fs = a.f or [p.w_n / (2 * math.pi)]
        out["c_f"] = c_f
        out["one_dof"] = [dict(f=f, **forced.one_dof(p.I, p.k_d, p.c_d, f, a=a.ripple or 1.0, c_f=c_f)) for f in fs]
        v0 = abs(p.r * p.omega - p.V)
        for row in out["one_dof"]:  # the linearization holds while the contact keeps sliding (and mu' stays put)
            row["stays_sliding"] = p.r * row["rate_amplitude"] < v0
            row["small_against_v_c"] = p.friction.v_c == 0 or p.r * row["rate_amplitude"] < 0.1 * p.friction.v_c
        if a.k_r is not None:
            I_t = a.I_t if a.I_t is not None else 0.5 * p.I
            I_h = p.I - I_t
            out["two_dof"] = [dict(f=f, **forced.two_dof(I_h, I_t, p.k_d, p.c_d, a.k_r, f, a=a.ripple or 1.0, c_r=a.c_r,
                                                          c_f=c_f)) for f in fs]
            out["natural_frequencies"] = forced.natural_frequencies(I_h, I_t, p.k_d, a.k_r)
    elif a.command == "simulate":
        res = stickslip.simulate(p, a.t_end or 300 * T_n, th0=a.th0, w0=a.w0, dt_out=a.dt_out or T_n / 200)
        out["events"] = res.events[:1000]
        out["limit_cycle"] = stickslip.limit_cycle(p, res, t_min=res.t[-1] - min(60 * T_n, 0.5 * res.t[-1]))
    out["parameters"] = out.get("parameters") or {k: getattr(a, k) for k in
                                                  ("I", "k_d", "c_d", "r", "N", "mu_k", "mu_s", "v_c", "omega", "V")}
    text = json.dumps(_clean(out), indent=1)
    if a.json:
        with open(a.json, "w") as f:
            f.write(text + "\n")
    else:
        print(text)
    if a.csv and res is not None:
        _write_csv(a.csv, res, p if a.command in ("cycle", "simulate") else None)
    return 0


if __name__ == "__main__":
    sys.exit(main())
