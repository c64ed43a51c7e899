"""Growth rate and frequency of the squeal whirl in a transient run (docs/squeal.md section 4.2).

The transient (roller -obstacle -friction mu -output F.h5) stores the displacement xi of the co-rotating mesh
vertices. The mean of xi over the Gamma_C vertices, turned into the lab by R(theta(t)), is the lab-frame
displacement of the outer circle's centre, U = Ux + i Uy: the order-1 content of the field (R and alpha of
the CSV carry order 0). An order-1 wave of lab frequency w makes it whirl, e^{(g - i w) t} for a backward
(clockwise, against omega > 0) wave, e^{(g + i w) t} forward. Two fits on a window [t0, t1]:

- the matrix pencil (Hua & Sarkar 1990) of U - mean(U): p complex exponentials, the largest-amplitude one
  near the expected frequency gives g and w;
- the envelope: U - mean(U) band-passed (FFT mask, |w' - w_sign| < bw) and log |.| fitted by a line.

--base BASE.h5, the same run unseeded (-ic_amplitude 0): U - U_base is fitted, the seed's own response. The start
(the time step's contact law settling from the CEA's steady state) excites the same whirl in both runs; to first
order in the seed the difference is the seeded mode alone, so a seed need not stand far above the start's noise.

The DMF's map of a continuous eigenvalue lambda (dmf_map): the scalar mode with lambda and conj(lambda) as
roots, m = 1, c = -2 Re lambda, k = |lambda|^2, stepped by the three-level scheme
  (z - 1)^2/dt^2 + c (z^2 - 1)/(2 dt) + k (z^2 + 1)/2 = 0,
gives the growth log|z|/dt and the frequency arg(z)/dt of the root with arg(z) > 0.

RUN.csv (a -monitor_csv, every step) instead of RUN.h5: the column --signal (contact_force by default) is fitted at
the CEA's frequency: a mode of any order (the order-10 stick-zone mode of docs/squeal.md 4.4.3) shows in the contact
force, where the whirl shows order 1 only.

--stick-zone T0: where the run's Gamma_C vertices stick, in lab x bins, from T0 on (the time step's own stick zone, to
set against the steady state's, -modes_steady_csv).

  PYTHONPATH=scripts python3 -m rollerreport.squeal_fit RUN.h5 --cea F.csv --order 1 --wave backward --window 10 100 [--base UNSEEDED.h5] [--stick-zone T0] [--plot out.png]
"""
import argparse
import csv

import numpy as np


def gamma_c(f, omega=None, theta_start=None):
    """Of an open output file: the output times t, the rotation angles theta(t) (theta_a = 0 in these runs), the
    vertex coordinates x and the mask of the Gamma_C (outer circle) vertices."""
    par = f["parameters"].attrs
    omega = float(par["omega"]) if omega is None else omega
    theta_start = float(par["theta_start"]) if theta_start is None else theta_start
    r_outer = float(par["r_outer"])
    x = f["geometry/vertices"][:]
    t = f["time"][:, 0]
    return t, omega * np.maximum(t - theta_start, 0.0), x, np.abs(np.hypot(x[:, 0], x[:, 1]) - r_outer) < 1e-6 * r_outer


def to_lab(th, a, b):
    """The co-rotating components (a, b) turned by theta into the lab's."""
    return np.cos(th) * a - np.sin(th) * b, np.sin(th) * a + np.cos(th) * b


def whirl(h5, omega=None, theta_start=None):
    """t and the complex lab-frame mean displacement U of the Gamma_C vertices."""
    import h5py

    with h5py.File(h5, "r") as f:
        t, th, _, outer = gamma_c(f, omega, theta_start)
        xi = f["vertex_fields/displacement_displacement"][:, :, :2][:, outer, :].mean(1)
    u, v = to_lab(th, xi[:, 0], xi[:, 1])
    return t, u + 1j * v


def monitor_signal(path, column):
    """t and one column of a -monitor_csv (every step), as a complex signal: a mode of any order shows in the contact
    force, where the whirl (order 1) does not."""
    with open(path) as f:
        rows = list(csv.DictReader(f))
    if not rows or column not in rows[0]:
        raise SystemExit(f"rollerreport.squeal_fit: {path} has no column {column!r} (a -monitor_csv is needed)")
    return np.array([float(r["t"]) for r in rows]), np.array([float(r[column]) for r in rows], dtype=complex)


def signal(path, column=None):
    """The whirl of an output .h5, or a column of a monitor .csv."""
    return monitor_signal(path, column or "contact_force") if path.endswith(".csv") else whirl(path)


def seed_response(h5, base, column=None):
    """t and U - U_base: the seeded run's whirl (or monitor column) minus the unseeded one's (the same times are needed)."""
    t, U = signal(h5, column)
    tb, Ub = signal(base, column)
    if len(tb) != len(t) or np.max(np.abs(tb - t)) > 1e-9 * max(1.0, t[-1]):
        raise SystemExit(f"rollerreport.squeal_fit: --base {base}: its times differ from {h5}'s (the same -ts_dt, -ts_max_time, -output_every are needed)")
    return t, U - Ub


def stick_zone(h5, t0, width=0.005):
    """Where the run's Gamma_C vertices stick, in the lab: bin centres x (bins of this width across the sheet) and
    the fractions of the outputs from t0 on in which a vertex in the bin is in contact and in which it sticks
    (contact_state 1); the steady state's stick zone to compare is the -modes_steady_csv's state 1 nodes."""
    import h5py

    with h5py.File(h5, "r") as f:
        t, th, x, outer = gamma_c(f)
        r_outer = float(f["parameters"].attrs["r_outer"])
        states = f["vertex_fields/contact_state_contact_state"]
        edges = np.arange(-r_outer, r_outer + width, width)
        seen, contact, stick = (np.zeros(len(edges) - 1) for _ in range(3))
        for k in np.flatnonzero(t >= t0):
            s = states[k, :][outer]
            X, Y = to_lab(th[k], x[outer, 0], x[outer, 1])
            b = np.digitize(X, edges) - 1
            low = (Y < 0) & (b >= 0) & (b < len(seen))  # the half facing the sheet
            np.add.at(seen, b[low], 1)
            np.add.at(contact, b[low], s[low] > 0)
            np.add.at(stick, b[low], s[low] == 1)
    m = contact > 0
    return 0.5 * (edges[:-1] + edges[1:])[m], contact[m] / seen[m], stick[m] / seen[m]


def pencil(y, dt, p=10):
    """Matrix pencil: continuous exponents s and amplitudes a, largest |a| first."""
    n = len(y)
    L = n // 3
    Y = np.array([y[i:i + L + 1] for i in range(n - L)])
    _, _, vh = np.linalg.svd(Y, full_matrices=False)
    V = vh[:p].conj().T
    z = np.linalg.eigvals(np.linalg.pinv(V[:-1]) @ V[1:])
    a = np.linalg.lstsq(np.vander(z, n, increasing=True).T, y, rcond=None)[0]
    o = np.argsort(-np.abs(a))
    return np.log(z[o]) / dt, a[o]


def envelope(t, y, w, bw):
    """|band-passed y| around the signed angular frequency w (complex y)."""
    F = np.fft.fft(y - y.mean())
    ww = 2 * np.pi * np.fft.fftfreq(len(y), t[1] - t[0])
    F[np.abs(ww - w) > bw] = 0
    return np.abs(np.fft.ifft(F))


def fit(t, U, w_signed, t0, t1, p=10, bw=None):
    """(growth, signed frequency) by the pencil, (growth, log-amplitude intercept) by the envelope, on [t0, t1]."""
    m = (t >= t0) & (t <= t1)
    y = U[m] - U[m].mean()
    s, a = pencil(y, t[1] - t[0], p)
    near = [k for k in range(len(s)) if abs(s[k].imag - w_signed) < 0.1 * abs(w_signed)]
    k = near[0] if near else 0
    bw = bw or 0.4 * abs(w_signed)
    env = envelope(t, U - U[m].mean(), w_signed, bw)
    edge = (t >= t0 + np.pi / bw) & (t <= t1 - np.pi / bw)  # away from the window's ends
    g_env, c_env = np.polyfit(t[edge], np.log(env[edge]), 1)
    return {"pencil_growth": s[k].real, "pencil_frequency": s[k].imag, "pencil_amplitude": abs(a[k]),
            "envelope_growth": g_env, "envelope_log0": c_env, "envelope": env, "window": (t0, t1)}


def dmf_map(lam, dt):
    """The three-level DMF's growth and frequency for the continuous eigenvalue lam (Im lam > 0)."""
    c, k = -2 * lam.real, abs(lam) ** 2
    z = np.roots([1 / dt**2 + c / (2 * dt) + k / 2, -2 / dt**2, 1 / dt**2 - c / (2 * dt) + k / 2])
    z = z[np.argmax(z.imag)]
    return np.log(abs(z)) / dt, np.angle(z) / dt


def cea_mode(path, order, wave):
    """The fastest-growing row of the CEA CSV with this order and wave: (growth, frequency)."""
    with open(path) as f:
        rows = [r for r in csv.DictReader(f) if int(r["order"]) == order and r["wave"] == wave]
    r = max(rows, key=lambda r: float(r["growth_rate"]))
    return float(r["growth_rate"]), float(r["frequency"])


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("h5", help="the run's -output .h5 (the order-1 whirl) or its -monitor_csv .csv (a column, --signal)")
    ap.add_argument("--signal", help="the .csv column fitted (default contact_force)")
    ap.add_argument("--cea", required=True, help="roller -modes -modes_csv of the same scene and mesh")
    ap.add_argument("--order", type=int, default=1)
    ap.add_argument("--wave", default="backward")
    ap.add_argument("--window", type=float, nargs=2, default=(10, 100))
    ap.add_argument("--dt", type=float, default=0.01, help="the run's -ts_dt, for the DMF map")
    ap.add_argument("--omega", type=float, default=np.pi / 10)
    ap.add_argument("--base", help="the same run without the seed: fit the difference (the seed's response)")
    ap.add_argument("--stick-zone", type=float, metavar="T0", help="also print where the run sticks from T0 on (lab x bins)")
    ap.add_argument("--plot")
    ap.add_argument("--title", default="")
    a = ap.parse_args()
    csv_run = a.h5.endswith(".csv")
    if a.signal and not csv_run:
        ap.error(f"--signal {a.signal}: a column of a monitor .csv; {a.h5} is an output .h5 (its whirl is fitted)")
    if a.stick_zone is not None and csv_run:
        ap.error(f"--stick-zone {a.stick_zone:g}: needs the run's output .h5 (its contact_state), not {a.h5}")
    g, w = cea_mode(a.cea, a.order, a.wave)
    ws = -w if a.wave == "backward" else w
    t, U = seed_response(a.h5, a.base, a.signal) if a.base else signal(a.h5, a.signal)
    if csv_run:  # a real signal, every step: its line at +w, block means at about 20 per period
        ws = abs(w)
        k = max(1, int(2 * np.pi / abs(w) / 20 / (t[1] - t[0])))
        n = len(t) // k
        t, U = t[:n * k].reshape(n, k).mean(1), U[:n * k].reshape(n, k).mean(1)
    r = fit(t, U, ws, *a.window)
    gl, wl = dmf_map(complex(g, w), a.dt)
    gr, wr = dmf_map(complex(g, w + a.order * a.omega if a.wave == "backward" else abs(w - a.order * a.omega)), a.dt)
    print(f"CEA: growth {g:.6f} frequency {w:.6f} (order {a.order} {a.wave})")
    print(f"DMF map at dt {a.dt}: lab-frame lambda -> growth {gl:.6f} frequency {wl:.6f}; "
          f"co-rotating frequency {w + a.order * a.omega if a.wave == 'backward' else abs(w - a.order * a.omega):.4f} -> growth {gr:.6f}")
    print(f"transient, window {a.window[0]:g}-{a.window[1]:g}: pencil growth {r['pencil_growth']:.6f} "
          f"({100 * (r['pencil_growth'] / g - 1):+.1f} %), frequency {r['pencil_frequency']:+.6f} "
          f"({100 * (abs(r['pencil_frequency']) / w - 1):+.2f} %); envelope growth {r['envelope_growth']:.6f} "
          f"({100 * (r['envelope_growth'] / g - 1):+.1f} %)")
    if a.stick_zone is not None:
        print(f"where {a.h5} sticks from t = {a.stick_zone:g} (lab x, fractions of the outputs): x, in contact, stick")
        for x, fc, fs in zip(*stick_zone(a.h5, a.stick_zone)):
            print(f"  {x:+.4f}  {fc:.2f}  {fs:.2f}")
    if a.plot:
        import matplotlib

        matplotlib.use("Agg")
        import matplotlib.pyplot as plt

        t0, t1 = a.window
        m = (t >= t0) & (t <= t1)
        y = U - U[m].mean()
        fig, ax = plt.subplots(figsize=(9, 4.5))
        ax.plot(t, y.real, lw=0.7, color="0.6", label="Ux - mean (lab, centre of Gamma_C)")
        ax.plot(t, np.abs(y), lw=0.6, color="C0", label="|U - mean|")
        ax.plot(t, r["envelope"], lw=1.2, color="C1", label=f"band-passed envelope (order {a.order} {a.wave}, {w:.3f})")
        tt = np.linspace(t0, t1, 200)
        ax.plot(tt, np.exp(r["envelope_log0"] + r["envelope_growth"] * tt), "C3--",
                label=f"fitted e^(g t), g = {r['envelope_growth']:.4f} (pencil {r['pencil_growth']:.4f})")
        tm = 0.5 * (t0 + t1)
        ax.plot(tt, np.exp(r["envelope_log0"] + r["envelope_growth"] * tm + g * (tt - tm)), "k:",
                label=f"CEA e^(g t), g = {g:.4f}")
        ax.set_yscale("log")
        ax.set_ylim(max(1e-5, np.abs(y).max() * 1e-3), np.abs(y).max() * 3)
        ax.axvspan(t0, t1, color="C2", alpha=0.07)
        ax.set_xlabel("t")
        ax.set_ylabel("displacement")
        ax.set_title(a.title)
        ax.legend(fontsize=7, loc="lower right")
        fig.tight_layout()
        fig.savefig(a.plot, dpi=110)


if __name__ == "__main__":
    main()
