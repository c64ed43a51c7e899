"""A transient seeded with one mode oscillates at the computed eigenvalue, in both frames (docs/squeal.md section 4).

At omega = pi/10 (Table 1, coarse P2 mesh h = 0.05): `roller -modes` (co-rotating and lab frames), then for the
n = 0 torsional mode, the n = 1 forward and backward modes, the n = 2 and n = 3 forward modes a transient from
the steady state plus the mode (`-initial_condition mode`), analysed by scripts/rollerref/mode_transient.py from the HDF5
output:

- the frequency of the order-n projection (matrix pencil) and of a Gamma_C probe (DTFT) match the eigenvalue
  within the DMF's time-discretization shift: |dW/W| <= the bound of mode_transient.shift_bound (the first-order
  shift of the three-level Newmark beta = 1/2 scheme with explicit Coriolis velocity, maximized over the
  admissible gyroscopic ratio |g| <= 2 omega/W) plus the measurement error, and agree with the shift predicted
  from the mode's own g to 10 %. Note: this is 5/24 (W dt)^2 without rotation, 2.5 times the trapezoidal
  (average acceleration) (W dt)^2/12: the DMF is Newmark beta = 1/2 (docs/model.md section 6.2);
- the shift falls as dt^2 (dt halved: ratio 4 +- 0.4; the Richardson extrapolation hits the eigenvalue to 3e-5);
- the growth rate is below the (W dt)^3 bound of the explicit Coriolis velocity plus the measurement error;
- the travelling direction of c_n matches the CSV's wave;
- the radial displacement at a fixed lab point has the frequency of the lab-frame eigenvalue of that mode
  (`-modes_frame lab`), within the same time shift plus the difference between the two frames' discrete
  eigenvalues;
- with Kelvin-Voigt damping (-viscosity 0.0115) the measured decay rate of the n = 2 forward mode matches the
  eigenvalue's growth_rate to 5 %.
"""
import math
import os
import sys

sys.path.insert(0, os.path.join(os.environ.get("ROLLER_SOURCE_DIR", os.path.dirname(os.path.dirname(os.path.abspath(__file__)))), "scripts"))
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from rollertest import Checker, run  # noqa: E402
from rollerref import mode_transient as mt  # noqa: E402

OMEGA = math.pi / 10
MESH = ["-mesh_h", 0.05, "-omega", OMEGA]
DT, T, EVERY = 0.05, 60.0, 4
MEAS = 2e-5        # relative frequency measurement error of the projection (matrix pencil over ~10 periods)
MEAS_DTFT = 6e-5   # of the single-probe DTFT peak (Hann window, T = 60)
MEAS_GROWTH = 2e-5  # |growth|/W measurement floor


def modes(tag, frame, extra=(), nev=20):
    run(["-modes", "-modes_frame", frame, "-modes_nev", nev, "-modes_csv", f"{tag}.csv", "-modes_output", f"{tag}.h5", "-quiet"] + MESH + list(extra))
    return mt.read_modes_csv(f"{tag}.csv")


def pick(rows, order, wave):
    j = next(i for i, r in enumerate(rows) if r["order"] == order and r["wave"] == wave)
    return j, rows[j]


def transient(tag, modes_h5, j, dt=DT, extra=()):
    run(["-ts_scheme", "dmf", "-initial_condition", "mode", "-initial_mode_file", modes_h5, "-initial_mode", j, "-ic_amplitude", 1e-3,
         "-ts_dt", dt, "-ts_max_time", T, "-output", f"{tag}.h5", "-output_every", EVERY, "-quiet"] + MESH + list(extra))
    return f"{tag}.h5"


def main():
    c = Checker("modes_transient")
    rot = modes("rot", "rotating")
    lab = modes("lab", "lab", nev=100)
    print(f"{'mode':>14s} {'j':>2s} {'W_eig':>10s} {'W_meas':>10s} {'rel_err':>10s} {'predicted':>10s} {'bound':>9s} "
          f"{'(Wdt)^2/12':>10s} {'probe_err':>10s} {'growth/W':>10s} {'lab_eig':>9s} {'lab_meas':>9s} {'lab_err':>9s}")
    results = {}
    for order, wave in ((0, "standing"), (1, "forward"), (1, "backward"), (2, "forward"), (3, "forward")):
        j, row = pick(rot, order, wave)
        W = row["frequency"]
        a = mt.analyse(transient(f"n{order}{wave}", "rot.h5", j), "rot.h5", j, lab_csv="lab.csv")
        results[(order, wave)] = a
        err, growth = a["rel_error"], a["lambda"][0] / W
        name = f"n={order} {wave}"
        print(f"{name:>14s} {j:2d} {W:10.6f} {a['lambda'][1]:10.6f} {err:10.3e} {a['predicted_rel_shift']:10.3e} {a['shift_bound']:9.2e} "
              f"{a['wdt2_12']:10.3e} {a['probe_rel_error']:10.3e} {growth:10.2e} {a.get('lab_eigen_w', math.nan):9.6f} {a['lab_probe_w']:9.6f} "
              f"{a.get('lab_rel_error', math.nan):9.2e}", flush=True)
        c.check(a["order"] == order and a["wave"] == wave, f"{name}: the transient's order {a['order']} and direction {a['wave']} are the CSV's")
        c.check(abs(err) <= a["shift_bound"] + MEAS, f"{name}: |W_meas/W_eig - 1| = {abs(err):.3e} <= time-shift bound {a['shift_bound']:.3e} + {MEAS:g}")
        pred = a["predicted_rel_shift"]
        c.check(abs(err - pred) <= 0.1 * abs(pred) + MEAS, f"{name}: shift {err:.4e} = predicted {pred:.4e} (g = {a['gyro_ratio']:+.3f}) within 10 % + {MEAS:g}")
        c.check(abs(a["probe_rel_error"] - err) <= MEAS_DTFT, f"{name}: the Gamma_C probe's DTFT line agrees with the projection: {a['probe_rel_error']:.3e} vs {err:.3e} (+- {MEAS_DTFT:g})")
        c.check(abs(growth) <= a["growth_bound"] + MEAS_GROWTH, f"{name}: |growth|/W = {abs(growth):.2e} <= (W dt)^3 bound {a['growth_bound']:.2e} + {MEAS_GROWTH:g} (predicted {a['predicted_growth_over_w']:+.2e})")
        # the lab: the rotating measurement shifted by -m omega (kinematics), and the lab-frame eigenvalue
        wl_rot = mt.lab_frequency(W, order, wave, OMEGA)
        frames = abs(a["lab_eigen_w"] - wl_rot)  # the two frames' discrete eigenvalues differ by O(h^p)
        c.check(abs(a["lab_probe_w"] - a["lab_expected_from_rotating"]) <= MEAS_DTFT * a["lab_probe_w"],
                f"{name}: lab probe {a['lab_probe_w']:.6f} = W_meas -/+ n omega {a['lab_expected_from_rotating']:.6f}")
        c.check(abs(a["lab_probe_w"] - a["lab_eigen_w"]) <= W * a["shift_bound"] + frames + MEAS_DTFT * a["lab_probe_w"],
                f"{name}: lab probe {a['lab_probe_w']:.6f} vs lab eigenvalue {a['lab_eigen_w']:.6f}: within W x bound {W * a['shift_bound']:.2e} + frames {frames:.1e}")

    # dt^2: the n = 3 forward mode at dt/2
    j, row = pick(rot, 3, "forward")
    W = row["frequency"]
    a2 = mt.analyse(transient("n3half", "rot.h5", j, dt=DT / 2), "rot.h5", j)
    e1, e2 = results[(3, "forward")]["rel_error"], a2["rel_error"]
    rich = (4 * a2["lambda"][1] - results[(3, "forward")]["lambda"][1]) / 3
    print(f"dt^2: n=3 forward, dt {DT}: {e1:.4e}, dt {DT / 2}: {e2:.4e}, ratio {e1 / e2:.3f}, Richardson {rich:.8f} vs {W:.8f} ({rich / W - 1:.2e}); "
          f"growth/W {a2['lambda'][0] / W:.2e}")
    c.check(3.6 <= e1 / e2 <= 4.4, f"the frequency error falls as dt^2: ratio {e1 / e2:.3f} in [3.6, 4.4]")
    c.check(abs(rich / W - 1) <= 3e-5, f"Richardson extrapolation {rich:.7f} = W_eig {W:.7f} to {abs(rich / W - 1):.1e} <= 3e-5")

    # Kelvin-Voigt damping: the decay rate
    tau = 0.0115
    vis = modes("rot_kv", "rotating", extra=["-viscosity", tau])
    j, row = pick(vis, 2, "forward")
    a = mt.analyse(transient("kv", "rot_kv.h5", j, extra=["-viscosity", tau]), "rot_kv.h5", j)
    re_eig, re_meas, W = row["growth_rate"], a["lambda"][0], row["frequency"]
    print(f"Kelvin-Voigt tau {tau}: n=2 forward W {W:.6f} growth_rate {re_eig:.6e} (zeta {-re_eig / math.hypot(re_eig, W):.4f}); measured {a['lambda'][1]:.6f}, "
          f"{re_meas:.6e} ({re_meas / re_eig - 1:+.2%}); logphase {a.get('lambda_logphase')}")
    c.check(re_eig < 0, f"the damped eigenvalue decays: growth_rate {re_eig:.3e} < 0")
    c.check(abs(re_meas / re_eig - 1) <= 0.05, f"decay rate {re_meas:.4e} = eigenvalue's {re_eig:.4e} within 5 % ({re_meas / re_eig - 1:+.2%})")
    c.check(abs(a["rel_error"]) <= a["shift_bound"] + MEAS, f"damped frequency {a['lambda'][1]:.6f} vs {W:.6f}: {abs(a['rel_error']):.2e} <= {a['shift_bound']:.2e} + {MEAS:g}")
    c.close()


if __name__ == "__main__":
    main()
