"""The contact pressure and the tangential traction across the contact patch, from a Roller -output HDF5
written with -friction (docs/friction.md section 4): the vertex fields contact_pressure, contact_traction and
contact_state at the Gamma_C vertices, against the lab coordinate along the sheet (x + displacement_lab along
e1), at one stored step. The stick zone (state 1) is shaded: the interval from midway to the first non-stick
vertex on either side of the stick vertices around the patch centre.

    PYTHONPATH=scripts python3 -m rollerplots.traction F.h5 --time 22 --out traction.png
    PYTHONPATH=scripts python3 -m rollerplots.traction F.h5 --time 22 --time 67 --theory cattaneo --qstar 1 --reversal 50 --normalize --out traction.png

P, Q, the centre and the half-width a come from the fields themselves: P and Q are the trapezoidal integrals
of pressure and traction over the Gamma_C polygon (exactly contact_force and friction_force, docs/contact.md),
the centre the pressure centroid, a = 2 x the pressure-weighted RMS distance from it (Hertz's elliptic
pressure has a/2). mu is the run's -friction (/parameters) unless --mu is given. With --theory the analytic
curves (p0 = 2 P/(pi a)) are drawn dashed:
  hertz     the elliptic pressure p0 sqrt(1 - x^2/a^2) (always drawn with any --theory)
  cattaneo  q = mu p0 [sqrt(1 - x^2/a^2) - (c/a) sqrt(1 - x^2/c^2)], c/a = sqrt(1 - |Q|/(mu P)) (monotone
            loading from zero); with --qstar Q*/(mu P) (the largest before a reversal; at the steps after
            --reversal TIME if given) Mindlin's reversal
            q = q*(x) - 2 mu p0 [sqrt(1 - x^2/a^2) - (b/a) sqrt(1 - x^2/b^2)], b/a = sqrt(1 - (Q* - Q)/(2 mu P))
  carter    steady rolling with creep: the stick zone of half-width c = a sqrt(1 - |Q|/(mu P)) at the leading
            edge, q = mu p0 [sqrt(1 - x^2/a^2) - (c/a) sqrt(1 - (x - x0)^2/c^2)], x0 = +-(a - c)
            (--leading +1 or -1: the side the sheet enters from)
The step is the stored one nearest --time (or --step K, the index in /time). One panel per step; with
--normalize the axes are x/a, p/p0 and q/(mu p0). Prints one line per step: t, P, Q/(mu P), a, the
measured stick half-width and centre (and the theory's c or b).
"""
import argparse
import math
import sys

import h5py
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402


def ell(x, w):
    return np.sqrt(np.clip(1.0 - (x / w) ** 2, 0.0, None)) if w > 0 else 0.0 * x


def field(f, name):
    group = f["vertex_fields"]
    cands = sorted((k for k in group if k.startswith(name + "_")), key=len)
    if not cands:
        raise SystemExit(f"rollerplots.traction: {name} is not in {f.filename} (run with -obstacle -friction MU -output F.h5)")
    return group[cands[0]]


def ring_of(f):
    """The Gamma_C vertices in angle order and their tributary lengths on the polygon (reference chords)."""
    x = f["geometry/vertices"][:, :2]
    r_outer = float(f["parameters"].attrs.get("r_outer", 0.5)) if "parameters" in f else 0.5
    outer = np.where(np.abs(np.hypot(x[:, 0], x[:, 1]) - r_outer) < 1e-6 * r_outer)[0]
    ring = outer[np.argsort(np.arctan2(x[outer, 1], x[outer, 0]))]
    edge = np.hypot(*(np.roll(x[ring], -1, axis=0) - x[ring]).T)
    return x, ring, 0.5 * (edge + np.roll(edge, 1))


def stick_interval(s, st, centre):
    """(left, right) edges of the stick interval around centre, or None; s sorted, st the states."""
    on = np.where(st > 0)[0]
    if not len(on):
        return None
    i0 = on[np.argmin(np.abs(s[on] - centre))]
    if st[i0] != 1:
        return None
    l = r = i0
    while r + 1 < len(s) and st[r + 1] == 1:
        r += 1
    while l >= 1 and st[l - 1] == 1:
        l -= 1
    right = 0.5 * (s[r] + s[r + 1]) if r + 1 < len(s) else s[r]
    left = 0.5 * (s[l] + s[l - 1]) if l >= 1 else s[l]
    return left, right


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0], formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("h5")
    ap.add_argument("--time", type=float, action="append", help="the stored step nearest this time (repeatable)")
    ap.add_argument("--step", type=int, action="append", help="the stored step of this index in /time (repeatable)")
    ap.add_argument("--mu", type=float, help="friction coefficient (default: the run's -friction)")
    ap.add_argument("--theory", choices=["none", "hertz", "cattaneo", "carter"], default="none")
    ap.add_argument("--qstar", type=float, help="cattaneo: Q*/(mu P) before a reversal: Mindlin's reversal curve")
    ap.add_argument("--reversal", type=float, help="cattaneo with --qstar: the time of the reversal; steps before it get Cattaneo's loading curve")
    ap.add_argument("--leading", type=float, default=1.0, help="carter: +1 the stick zone at the +x edge, -1 at the -x edge")
    ap.add_argument("--normalize", action="store_true", help="x/a, p/p0, q/(mu p0)")
    ap.add_argument("--margin", type=float, default=0.3, help="plotted range beyond the patch, in units of a")
    ap.add_argument("--title")
    ap.add_argument("--out", default="traction.png")
    args = ap.parse_args(argv)

    with h5py.File(args.h5, "r") as f:
        par = dict(f["parameters"].attrs) if "parameters" in f else {}
        mu = args.mu if args.mu is not None else float(par.get("friction", 0.0))
        if mu <= 0:
            raise SystemExit("rollerplots.traction: no friction coefficient: the run has -friction 0; give --mu")
        times = f["time"][:, 0]
        steps = list(args.step or [])
        for t in args.time or []:
            steps.append(int(np.argmin(np.abs(times - t))))
        if not steps:
            steps = [len(times) - 1]
        x, ring, trib = ring_of(f)
        P_f, T_f, S_f, L_f = field(f, "contact_pressure"), field(f, "contact_traction"), field(f, "contact_state"), field(f, "displacement_lab")
        fig, axes = plt.subplots(len(steps), 1, figsize=(7.5, 3.6 * len(steps)), squeeze=False)
        for ax, k in zip(axes[:, 0], steps):
            if not 0 <= k < len(times):
                raise SystemExit(f"rollerplots.traction: step {k} is not stored (0 ... {len(times) - 1})")
            p, q, st = P_f[k][ring], T_f[k][ring], S_f[k][ring]
            s = x[ring, 0] + L_f[k][ring, 0]
            P, Q = float(np.sum(p * trib)), float(np.sum(q * trib))
            if P <= 0:
                print(f"rollerplots.traction: t = {times[k]:g}: no contact", file=sys.stderr)
                continue
            w = p * trib
            centre = float(np.sum(w * s) / P)
            a = 2.0 * math.sqrt(float(np.sum(w * (s - centre) ** 2)) / P)
            p0 = 2.0 * P / (math.pi * a)
            lower = np.where(x[ring, 1] + L_f[k][ring, 1] < 0)[0]  # the half of Gamma_C facing the sheet
            o = lower[np.argsort(s[lower])]
            s, p, q, st = s[o], p[o], q[o], st[o]
            keep = np.abs(s - centre) <= (1.0 + args.margin) * a
            sx, ps, qs = (s - centre) / a if args.normalize else s, p / p0 if args.normalize else p, q / (mu * p0) if args.normalize else q
            zone = stick_interval(s, st, centre)
            line = f"t = {times[k]:g}: P = {P:.6e}, Q/(mu P) = {Q / (mu * P):+.4f}, a = {a:.5f}, centre = {centre:+.6f}"
            if zone:
                half, zc = 0.5 * (zone[1] - zone[0]), 0.5 * (zone[1] + zone[0])
                line += f", stick half-width {half:.5f} (c/a = {half / a:.3f}) centred at {zc - centre:+.2e}"
                lo, hi = ((zone[0] - centre) / a, (zone[1] - centre) / a) if args.normalize else zone
                ax.axvspan(lo, hi, color="tab:green", alpha=0.15, label="stick zone (state 1)")
            else:
                line += ", no stick zone"
            ax.plot(sx[keep], ps[keep], "o-", ms=3, color="tab:blue", label="pressure p")
            ax.plot(sx[keep], qs[keep], "s-", ms=3, color="tab:red", label="traction q (along e1)")
            ax.plot(sx[keep], (mu * p / (mu * p0) if args.normalize else mu * p)[keep] * np.sign(Q or 1.0), ":", color="gray", lw=1, label="mu p (slip bound)")
            if args.theory != "none":
                xs = np.linspace(-a, a, 801)
                ph = p0 * ell(xs, a)
                sg, qn = (1.0 if Q >= 0 else -1.0), abs(Q) / (mu * P)
                qh, extra = None, ""
                mindlin = args.qstar is not None and (args.reversal is None or times[k] > args.reversal)
                if args.theory == "cattaneo" and not mindlin:
                    c = a * math.sqrt(max(0.0, 1.0 - qn))
                    qh, extra = sg * mu * p0 * (ell(xs, a) - c / a * ell(xs, c)), f", Cattaneo c/a = {c / a:.3f}"
                elif args.theory == "cattaneo":
                    qsn = args.qstar
                    qr = Q / (mu * P) * (1.0 if qsn >= 0 else -1.0)
                    cs = a * math.sqrt(max(0.0, 1.0 - abs(qsn)))
                    b = a * math.sqrt(max(0.0, 1.0 - (abs(qsn) - qr) / 2.0))
                    qh = (1.0 if qsn >= 0 else -1.0) * (mu * p0 * (ell(xs, a) - cs / a * ell(xs, cs)) - 2 * mu * p0 * (ell(xs, a) - b / a * ell(xs, b)))
                    extra = f", Mindlin reversal b/a = {b / a:.3f}"
                elif args.theory == "carter":
                    c = a * math.sqrt(max(0.0, 1.0 - qn))
                    x0 = math.copysign(a - c, args.leading)
                    qh, extra = sg * mu * p0 * (ell(xs, a) - c / a * ell(xs - x0, c)), f", Carter c/a = {c / a:.3f}"
                line += extra
                xt = xs / a if args.normalize else xs + centre
                ax.plot(xt, ph / p0 if args.normalize else ph, "--", color="tab:blue", lw=1, label="Hertz")
                if qh is not None:
                    ax.plot(xt, qh / (mu * p0) if args.normalize else qh, "--", color="tab:red", lw=1, label="Mindlin (reversal)" if args.theory == "cattaneo" and mindlin else args.theory.capitalize())
            print(line)
            ax.axhline(0, color="k", lw=0.5)
            ax.set_xlabel("x / a" if args.normalize else "lab coordinate along the sheet")
            ax.set_ylabel("p / p0,  q / (mu p0)" if args.normalize else "traction")
            ax.set_title(f"t = {times[k]:g}, Q/(mu P) = {Q / (mu * P):+.3f}, mu = {mu:g}" if not args.title else f"{args.title} (t = {times[k]:g}, Q/(mu P) = {Q / (mu * P):+.3f})", fontsize=10)
            ax.legend(fontsize=7, loc="best", ncol=2)
            ax.grid(alpha=0.3)
        fig.tight_layout()
        fig.savefig(args.out, dpi=120)
    print(f"rollerplots.traction: wrote {args.out}")


if __name__ == "__main__":
    main()
