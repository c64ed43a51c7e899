"""docs/figures/squeal_transient.png: the order-1 whirl of transient runs against the CEA (docs/squeal.md section 4.2).

  PYTHONPATH=scripts python3 -m rollerplots.squeal_transient --run LABEL RUN.h5 CEA.csv T0 T1 [--run ...] --out F.png

One row of two panels per run: the lab-frame centre displacement of Gamma_C minus its mean over [T0, T1] (x
component, linear scale) with the fitted envelope +-e^(g t) and the CEA's +-e^(g_CEA t) through the same
mid-window amplitude; and |U - mean| on a log scale with the same lines. The fit: rollerreport.squeal_fit."""
import argparse

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

from rollerreport import squeal_fit as sf  # noqa: E402

def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--run", nargs=5, action="append", metavar=("LABEL", "H5", "CEA", "T0", "T1"), required=True)
    ap.add_argument("--out", required=True)
    a = ap.parse_args(argv)
    fig, axes = plt.subplots(len(a.run), 2, figsize=(12, 3.6 * len(a.run)), squeeze=False)
    for (label, h5, cea, t0, t1), (ax0, ax1) in zip(a.run, axes):
        t0, t1 = float(t0), float(t1)
        g, w = sf.cea_mode(cea, 1, "backward")
        t, U = sf.whirl(h5)
        r = sf.fit(t, U, -w, t0, t1)
        m = (t >= t0) & (t <= t1)
        y = U - U[m].mean()
        tm = 0.5 * (t0 + t1)
        tt = np.linspace(t0, t1, 200)
        fitted = np.exp(r["envelope_log0"] + r["envelope_growth"] * tt)
        a_mid = np.exp(r["envelope_log0"] + r["envelope_growth"] * tm)
        predicted = a_mid * np.exp(g * (tt - tm))
        ax0.plot(t, y.real, lw=0.6, color="0.4", label="Ux - mean")
        for s in (1, -1):
            ax0.plot(tt, s * fitted, "C3--", lw=1.2, label=f"fit: g = {r['envelope_growth']:.4f} (pencil {r['pencil_growth']:.4f})" if s > 0 else None)
            ax0.plot(tt, s * predicted, "k:", lw=1.4, label=f"CEA: g = {g:.4f}" if s > 0 else None)
        ax0.axvspan(t0, t1, color="C2", alpha=0.08)
        ax0.set_title(f"{label}: order-1 backward whirl, CEA {g:.4f} + {w:.4f} i", fontsize=9)
        ax0.set_xlabel("t")
        ax0.legend(fontsize=7, loc="upper left")
        ax1.semilogy(t, np.abs(y), lw=0.5, color="C0", label="|U - mean|")
        ax1.semilogy(t, r["envelope"], lw=1.0, color="C1", label=f"band-passed at -{w:.3f} rad/t")
        ax1.semilogy(tt, fitted, "C3--", lw=1.2, label="fitted envelope")
        ax1.semilogy(tt, predicted, "k:", lw=1.4, label="CEA e^(g t)")
        ax1.axvspan(t0, t1, color="C2", alpha=0.08)
        ax1.set_ylim(np.abs(y).max() * 3e-3, np.abs(y).max() * 2)
        ax1.set_xlabel("t")
        ax1.set_title(f"{label}: fit window {t0:g}-{t1:g}; pencil frequency {r['pencil_frequency']:+.4f}", fontsize=9)
        ax1.legend(fontsize=7, loc="lower right")
    fig.tight_layout()
    fig.savefig(a.out, dpi=100)


if __name__ == "__main__":
    main()
