"""The figure of Carter's rolling contact (docs/friction.md section 5.2) from the JSON files tests/friction_carter.py
writes (carter_<mode>.json in its working directory).

    PYTHONPATH=scripts python3 -m rollerplots.carter docs/figures/friction_carter.png carter_long.json [carter_dynamic.json ...]

Left: |Q|/(mu P) against the creep |xi - xi_0| / (mu a / R) (xi_0 the free-rolling creep measured at each speed, a
the Hertz half-width from the run's P): Carter's curve 1 - (1 - x)^2 and the runs (filled: the roller drives the sheet, open: the sheet drives the roller). Right: the tangential traction
|tau|/(mu p0) along the lab coordinate s/a (p0 = 2 P/(pi a)) of the middle creep of each file with Carter's
distribution at the measured Q/(mu P), stick vertices filled, slip open; the pressure p/p0 in grey."""
import json
import math
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

LABEL = {"quick": "omega = 0.025 (quick)", "long": "omega = 0.025", "dynamic": "omega = pi/10 (0.9 c_R)"}
MARK = {"quick": "s", "long": "o", "dynamic": "^"}


def carter_traction(s, a, q):
    """Carter's |tau|/(mu p0) at s (the stick zone of half-width c at the leading edge s = -a)."""
    c = a * math.sqrt(max(0.0, 1 - q))
    full = np.sqrt(np.clip(1 - (s / a) ** 2, 0, None))
    corr = (c / a) * np.sqrt(np.clip(1 - ((s - (-a + c)) / c) ** 2, 0, None)) if c > 0 else 0
    return full - corr


def main():
    out, files = sys.argv[1], sys.argv[2:]
    fig, (ax, bx) = plt.subplots(1, 2, figsize=(12, 4.8))
    x = np.linspace(0, 1.2, 200)
    ax.plot(x, np.where(x < 1, 1 - (1 - np.minimum(x, 1)) ** 2, 1), "k-", label="Carter (static)")
    colors = ["C0", "C3", "C2", "C1"]
    for k, path in enumerate(files):
        d = json.load(open(path))
        mu, R = d["mu"], d["R"]
        runs = [r for r in d["runs"]]
        for sign, fill, word in ((1, colors[k], "driving, xi > xi_0"), (-1, "none", "braking, xi < xi_0")):
            sel = [r for r in runs if r["creep"] * sign > 0]
            if not sel:
                continue
            ax.plot([abs(r["creep"]) / (mu * r["a"] / R) for r in sel], [abs(r["q"]) for r in sel], MARK.get(d["mode"], "o"), color=colors[k], ms=7, mfc=fill,
                    label=f"{LABEL.get(d['mode'], d['mode'])} ({word}); xi_0 = {d['xi0']:+.5f}")
        # the traction profile of the creep run nearest |q| = 0.55
        r = min((r for r in runs if abs(r["q"]) > 0.1), key=lambda r: abs(abs(r["q"]) - 0.55))
        a, P = r["a"], r["P"]
        p0 = 2 * P / (math.pi * a)
        if "avg" in r:  # averaged over the last window's frames, in bins along s
            s, tau, p = (np.array(r["avg"][key]) for key in ("s", "tau", "p"))
            st = np.where(np.array(r["avg"]["stick_fraction"]) > 0.5, 1, 2)
        else:
            s, tau, p, st = (np.array(r[key]) for key in ("s", "tau", "p", "state"))
        ss = np.linspace(-a, a, 400)
        bx.plot(ss / a, carter_traction(ss, a, abs(r["q"])), "-", color=colors[k], lw=1,
                label=f"Carter at |Q|/(mu P) = {abs(r['q']):.3f} ({LABEL.get(d['mode'], d['mode'])})")
        for state, fill in ((1, colors[k]), (2, "none")):
            m = st == state
            bx.plot(s[m] / a, np.abs(tau[m]) / (mu * p0), MARK.get(d["mode"], "o"), color=colors[k], mfc=fill, ms=5)
        bx.plot(s / a, p / p0, ".", color="0.6" if k == 0 else "0.3", ms=3)
    bx.plot(ss / ss[-1], np.sqrt(1 - (ss / ss[-1]) ** 2), ":", color="0.5", label="Hertz p/p0 (dots: measured)")
    ax.set_xlabel("|xi - xi_0| / (mu a / R)")
    ax.set_ylabel("|Q| / (mu P)")
    ax.set_xlim(0, 1.2)
    ax.set_ylim(0, 1.05)
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8, loc="lower right")
    ax.set_title("Creep curve: steady rolling, mu = 0.8, depth 0.002")
    bx.set_xlabel("s / a  (lab, along e1; the surface enters at s = -a)")
    bx.set_ylabel("|tau| / (mu p0)")
    bx.set_xlim(-1.7, 1.4)
    bx.set_ylim(0, 1.1)
    bx.grid(alpha=0.3)
    bx.legend(fontsize=7, loc="upper right")
    bx.set_title("Traction (a JSON without frames: the final state; else the mean over the last window)\nfilled: stick, open: slip", fontsize=9)
    fig.tight_layout()
    fig.savefig(out, dpi=120)


if __name__ == "__main__":
    main()
