"""The contact QP solvers agree (issue 4): with -contact_check every step is solved by the condensed
active-set solver, SNES VI, TAO and the paper's projected CG from the same data. On every step their
solutions differ by less than 1e-8 (relative, max norm) and each satisfies the KKT conditions (primal and
dual feasibility, complementarity, stationarity; docs/contact.md) to 1e-9. Scenes: compression (P1), rolling
contact (P2, the contact set moves along Gamma_C), and the condensed problem solved by TAO instead.

Discretization: agreement and KKT are properties of the QP of every step, whatever the discretization, so the
P2 rolling scene runs Roller's default discretization (P2 curved, extrapolated Coriolis velocity, dt from
-ts_phase_error: 0.0109 for t <= 0.5) on the coarse mesh -mesh_h 0.05. The P1 scenes keep the discretization
they were written with (and the shrunk-candidate-set check relies on): -degree 1, -ts_dt 0.0125, the paper's
backward Coriolis velocity."""
import re

from rollertest import Checker, read_csv, run

CHECK = re.compile(r"^contact_check: step (\d+) t \S+ solver (\w+) its (\d+) diff (\S+) kkt (\S+) gap_min (\S+)$", re.M)
BASE = ["-mesh_h", 0.05, "-obstacle", "-obstacle_speed", 0.05, "-obstacle_depth", 0.01, "-damping", 1,
        "-ts_max_time", 0.5, "-quiet", "-contact_check"]
P1 = ["-degree", 1, "-ts_dt", 0.0125, "-coriolis_velocity", "backward"]

c = Checker("contact_agree")
for name, extra in (("compression P1", P1 + ["-omega", 0]),
                    ("rolling P2", ["-omega", 0.3141592653589793, "-degree", 2]),
                    ("compression P1, condensed QP by TAO gpcg", P1 + ["-omega", 0, "-contact_condensed_qp", "tao",
                                                                        "-contact_condensed_tao_type", "gpcg"]),
                    ("rolling P1, shrunk candidate set", P1 + ["-omega", 0.3141592653589793, "-contact_margin", -0.05,
                                                             "-contact_monitor", "ascii:agree_contact.csv:ascii_csv"])):
    csv = "agree_" + re.sub(r"\W+", "_", name) + ".csv"
    _, out, _ = run(BASE + extra + ["-monitor_csv", csv])
    rows = CHECK.findall(out)
    d = read_csv(csv)
    steps = {int(r[0]) for r in rows}
    solvers = {r[1] for r in rows}
    c.check(len(steps) == len(d["step"]) - 1 and solvers == {"condensed", "vi", "tao", "pcg"},
            f"{name}: {len(steps)} steps checked with solvers {sorted(solvers)}")
    if "-contact_monitor" in extra:
        resolves = int(sum(read_csv("agree_contact.csv")["resolves"]))
        c.check(resolves > 0, f"{name}: nodes outside the candidate set were caught and re-solved {resolves} times")
    c.check(max(d["contact_nodes"]) > 0, f"{name}: the obstacle touches (up to {int(max(d['contact_nodes']))} nodes)")
    for s in sorted(solvers):
        diff = max(float(r[3]) for r in rows if r[1] == s)
        kkt = max(float(r[4]) for r in rows if r[1] == s)
        gap = min(float(r[5]) for r in rows if r[1] == s)
        its = sum(int(r[2]) for r in rows if r[1] == s)
        c.check(diff < 1e-8, f"{name}: {s}: max relative difference {diff:.2e} < 1e-8")
        c.check(kkt < 1e-9 and gap >= -1e-10, f"{name}: {s}: max KKT residual {kkt:.2e} < 1e-9, least gap {gap:.2e} ({its} iterations in all)")
c.close()
