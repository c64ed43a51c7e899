"""Figure docs/figures/friction_stickslip.png (docs/friction.md section 5.3): alpha, the friction force and the
slipping nodes against t for jobs/stickslip.yaml with velocity weakening and with constant mu.
Usage: PYTHONPATH=scripts python3 -m rollerplots.stickslip VW.csv CONST.csv OUT.png"""
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np


def read_csv(path):
    """A monitor CSV as {column: numpy array}."""
    data = np.genfromtxt(path, delimiter=",", names=True)
    return {k: data[k] for k in data.dtype.names}


def main(argv=None):
    argv = sys.argv if argv is None else ["stickslip"] + list(argv)
    if len(argv) != 4:
        raise SystemExit(__doc__)
    vw, co = read_csv(argv[1]), read_csv(argv[2])
    fig, ax = plt.subplots(3, 1, figsize=(9, 8), sharex=True)
    for d, lab, col in ((vw, "mu(v) = 0.5 + 0.5 exp(-v/0.03)", "C3"), (co, "constant mu = 0.5", "C0")):
        t = d["t"]
        n = int(round(0.05 / (t[1] - t[0])))
        ff = np.convolve(d["friction_force"], np.ones(n) / n, mode="same")  # the two-step alternation averaged out
        ax[0].plot(t, d["alpha"], col, lw=1, label=lab)
        ax[1].plot(t, ff, col, lw=1, label=lab)
        ax[2].plot(t, d["slip_nodes"], col, lw=0.8, label=lab + ": slipping")
        ax[2].plot(t, d["stick_nodes"], col, lw=0.8, ls=":", label=lab + ": sticking")
    ax[1].plot(vw["t"], -vw["contact_force"], "k", lw=0.6, label="-contact_force (mu_s = 1)")
    ax[1].plot(vw["t"], -0.5 * vw["contact_force"], "k--", lw=0.6, label="-0.5 contact_force (mu = 0.5)")
    ax[0].set_ylabel("alpha")
    ax[1].set_ylabel("friction_force (0.05 avg)")
    ax[2].set_ylabel("contact nodes")
    ax[2].set_xlabel("t  (shaft starts at t = 7, omega = 0.06)")
    for a in ax:
        a.axvline(7, color="0.6", lw=0.6)
        a.legend(fontsize=7, loc="lower left")
        a.grid(alpha=0.3)
    ax[0].set_title("jobs/stickslip.yaml: stick-slip (velocity weakening) vs steady sliding (constant mu)")
    fig.tight_layout()
    fig.savefig(argv[3], dpi=110)


if __name__ == "__main__":
    main()
