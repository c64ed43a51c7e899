"""The generalized Maxwell rubber in the time step (-rubber maxwell, issue 35; docs/model.md sections 1.1 and 2.2).

1. The energy balance on a frictional rolling scene (the feeder, jobs/feed.yaml: mu = 0.8, the sheet at 0.99 of the
   surface speed, pressed quickly to 0.01 so that the test is short; -mesh_h 0.05 graded to 0.0112: the identity holds
   on any mesh), the rubber fitted to a loss factor of 0.1 over 0.1-10 cycles per unit time (the breathing mode, 1.5,
   and the torsional one, 0.12-0.15, inside), with dmf and with the trapezoidal rule: every step
     E^k - E^{k-1} = d(shaft_work) + d(sheet_work) - d(friction_work) - contact_dissipation - damping_dissipation
                     - viscous_dissipation
   (the energy with the branches' stored energy, viscous_dissipation the branches' dissipation) closes to 1e-12 of the
   largest energy; the branches' dissipation >= 0 every step and > 0 in all, the friction and contact dissipations
   >= 0 (to 1e-15, 1e-13 of E_max: round-off).
2. The decay of the torsional mode of the free roller at rest (-omega 0, no contact), started on the undamped mode
   of -modes (-initial_condition mode; -mesh_h 0.05, P2; the branches start unstretched): the mode is purely
   deviatoric (div xi = 0), so its complex frequency solves lambda^2 + w0^2 G*(lambda)/mu = 0, w0 the undamped
   (relaxed) frequency -modes gives on the same mesh and G*(s)/mu = 1 + sum_i g_i s tau_i/(1 + s tau_i): a
   polynomial of degree 2 + n, one oscillating pair and n real roots (the branches' creep). alpha(t) over
   0 <= t <= 60 (-ts_dt 0.05) is fitted by exp(sigma t)(a cos w t + b sin w t) + sum_j c_j exp(r_j t), the r_j the
   closed form's real roots, sigma and w free: the fitted sigma within 2 % and w within 0.5 % of the closed form's,
   for dmf and trapezoidal (the modal loss factor 2|sigma|/|lambda| is printed beside the material's at |lambda|).
   The branches are given (-maxwell_tau, -maxwell_weight: the fit of 0.1 over 0.02-2 rounded to 4 digits) so that
   the closed form has them exactly.
3. A Kelvin-Voigt term beside the branches (-viscosity with -rubber maxwell, docs/model.md section 1.1): the balance
   of 1 (trapezoidal, -viscosity 5e-4: its loss factor 0.031 at the band's high end, the fit's branches the rest),
   its dissipation in viscous_dissipation with theirs, to 1e-12; the decay of 2 with -viscosity 0.05 (0.036 of loss
   at the mode, a third of the branches'), against the closed form with G*(s)/mu + s tau: sigma within 2 %, w 0.5 %,
   and sigma at least 20 % beyond the branches' alone (the term is in the step)."""
import numpy as np

from rollertest import SOURCE, Checker, read_csv, run, maxwell_oscillator_roots, fit_maxwell_decay

c = Checker("maxwell")

# 1. the energy balance on the frictional rolling scene
MESH = ["-mesh_h", 0.05, "-mesh_h_contact", 0.0112, "-mesh_contact_layer", 0.0224]
RUBBER = ["-rubber", "maxwell", "-rubber_loss_factor", 0.1, "-rubber_band", "0.1,10"]
for scheme, kv in (("dmf", 0), ("trapezoidal", 0), ("trapezoidal", 5e-4)):
    csv = f"feed_{scheme}{'_kv' if kv else ''}.csv"
    run(["-options_file", f"{SOURCE}/jobs/feed.yaml", *MESH, *RUBBER, "-viscosity", kv, "-obstacle_speed", 0.05, "-obstacle_depth", 0.01,
         "-ts_max_time", 3, "-ts_scheme", scheme, "-quiet", "-monitor_csv", csv])
    if kv:
        scheme += f" with -viscosity {kv:g} beside the branches"
    d = read_csv(csv)
    emax = np.abs(d["energy"]).max()
    works = np.diff(d["shaft_work"] + d["sheet_work"] - d["friction_work"])
    losses = (d["contact_dissipation"] + d["damping_dissipation"] + d["viscous_dissipation"])[1:]
    balance = np.abs(np.diff(d["energy"]) - works + losses).max() / emax
    viscous = d["viscous_dissipation"][1:]
    c.check(balance < 1e-12, f"{scheme}: the energy balance with the branches closes at every step ({len(d['t']) - 1} steps): max |dE - works + dissipations| / E_max = {balance:.1e} < 1e-12")
    c.check(viscous.min() >= -1e-15 * emax and viscous.sum() > 0,
            f"{scheme}: the branches' dissipation >= 0 at every step (min {viscous.min() / emax:.1e} E_max), {viscous.sum() / emax:.3f} E_max in all")
    df, dc = np.diff(d["friction_work"]).min() / emax, d["contact_dissipation"].min() / emax
    c.check(df > -1e-15 and dc > -1e-13 and d["stick_nodes"][-1] > 0 and d["slip_nodes"][-1] > 0,
            f"{scheme}: friction dissipation >= 0 (min {df:.1e} E_max), contact dissipation >= 0 (min {dc:.1e} E_max); rolling with {d['stick_nodes'][-1]:.0f} stick and {d['slip_nodes'][-1]:.0f} slip nodes")

# 2. the torsional mode's decay
TAU = [0.05967, 0.3356, 1.887, 10.61]
G = [0.2262, 0.1421, 0.1308, 0.1513]
H, DT, T = 0.05, 0.05, 60.0
run(["-modes", "-omega", 0, "-mesh_h", H, "-degree", 2, "-modes_nev", 2, "-modes_csv", "modes.csv", "-modes_output", "modes.h5", "-quiet"])
m = read_csv("modes.csv")
w0 = m["im"][0]
c.check(m["order"][0] == 0 and abs(w0 / 0.7229 - 1) < 0.01, f"the torsional mode (order 0) is -modes' lowest: w0 = {w0:.6f} (the annulus' 0.7229)")


lam, creep = maxwell_oscillator_roots(w0, np.array(TAU), np.array(G))
s_tau = np.array(TAU) * 1j * abs(lam)
modulus = 1 + np.sum(np.array(G) * s_tau / (1 + s_tau))
print(f"closed form: lambda = {lam.real:.6f} + {lam.imag:.6f} i, creep roots {', '.join(f'{r:.4f}' for r in creep)}; "
      f"modal loss factor 2|sigma|/|lambda| = {2 * abs(lam.real) / abs(lam):.4f}, the material's at |lambda|: {modulus.imag / modulus.real:.4f}")
for scheme, kv in (("dmf", 0.0), ("trapezoidal", 0.0), ("trapezoidal", 0.05)):
    csv = f"decay_{scheme}{'_kv' if kv else ''}.csv"
    if kv:  # the mode file carries the run's -viscosity (the torsional shape is the undamped one: C = tau K is proportional)
        run(["-modes", "-omega", 0, "-mesh_h", H, "-degree", 2, "-viscosity", kv, "-modes_nev", 2, "-modes_output", "modes_kv.h5", "-quiet"])
    run(["-omega", 0, "-mesh_h", H, "-degree", 2, "-initial_condition", "mode", "-initial_mode_file", "modes_kv.h5" if kv else "modes.h5", "-initial_mode", 0,
         "-ic_amplitude", 1e-3, "-rubber", "maxwell", "-maxwell_tau", ",".join(map(str, TAU)), "-maxwell_weight", ",".join(map(str, G)),
         "-viscosity", kv, "-ts_dt", DT, "-ts_max_time", T, "-ts_scheme", scheme, "-quiet", "-monitor_csv", csv])
    d = read_csv(csv)
    t, a = d["t"], d["alpha"]
    lk, ck = maxwell_oscillator_roots(w0, np.array(TAU), np.array(G), kv) if kv else (lam, creep)

    sigma, w, r = fit_maxwell_decay(t, a, ck)
    es, ew = sigma / lk.real - 1, w / lk.imag - 1
    name = scheme + (f" with -viscosity {kv:g} (closed form {lk.real:.6f} + {lk.imag:.6f} i, the branches' alone {lam.real:.6f})" if kv else "")
    c.check(abs(es) < 0.02 and abs(ew) < 0.005 and (not kv or sigma / lam.real > 1.2),
            f"{name}: torsional decay sigma = {sigma:.6f} (closed form {lk.real:.6f}: {100 * es:+.2f} %), w = {w:.6f} ({lk.imag:.6f}: {100 * ew:+.3f} %); "
            f"the fit's largest residual {r:.1e} of max |alpha|")
c.close()
