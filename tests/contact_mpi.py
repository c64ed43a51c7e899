"""1 rank and 2 ranks give the same contact time series (issue 4): rolling contact (the contact set moves
across the partition boundary) on a coarse mesh; every CSV column agrees to 1e-9 relative to its range and
the number of contact nodes is identical at every step. Both the condensed default and SNES VI, and the condensed
solver with each parallel layout of the step factorization: the substructured Cholesky (the default: each rank
factors its interior, the interface's Schur complement on every rank, src/model/solver_schur.c), the whole matrix on
every rank (-solver_schur false; the condensation's columns split over the ranks) and MUMPS (-solver_schur false
-solver_redundant_max 0); and the substructuring on groups of ranks (3 ranks, -solver_schur_ranks 2).

Discretization: rank independence must hold for whatever users run, so this is Roller's default (P2 curved,
extrapolated Coriolis velocity, dt from -ts_phase_error: 0.0054 for t <= 2, 0.0109 for t <= 0.5) on the
coarse mesh -mesh_h 0.05."""
import numpy as np

from rollertest import Checker, read_csv, run

c = Checker("contact_mpi")
base = ["-mesh_h", 0.05, "-obstacle", "-obstacle_speed", 0.05, "-obstacle_depth", 0.01, "-omega", 0.3141592653589793,
        "-damping", 1, "-quiet"]
for solver, t_end, extra in (("condensed", 2.0, []), ("vi", 0.5, []), ("condensed_redundant", 2.0, ["-solver_schur", "false"]),
                            ("condensed_mumps", 2.0, ["-solver_schur", "false", "-solver_redundant_max", 0])):
    d = []
    for n in (1, 2):
        run(base + ["-contact_solver", solver.split("_")[0], "-ts_max_time", t_end, "-monitor_csv", f"{solver}_np{n}.csv"] + extra, nproc=n)
        d.append(read_csv(f"{solver}_np{n}.csv"))
    c.check(max(d[0]["contact_nodes"]) > 0, f"{solver}: contact happens (up to {int(max(d[0]['contact_nodes']))} nodes)")
    c.check(np.array_equal(d[0]["contact_nodes"], d[1]["contact_nodes"]), f"{solver}: the same number of contact nodes at every step on 1 and 2 ranks")
    for col in ("R", "alpha", "energy", "contact_force", "gap_min"):
        scale = max(abs(d[0][col]))
        diff = max(abs(d[0][col] - d[1][col])) / scale
        c.check(diff < 1e-9, f"{solver}: {col} agrees to {diff:.2e} (relative to max {scale:.3e}) < 1e-9")
# Groups of ranks (-solver_schur_ranks): 3 ranks in groups of at most 2 (a group of 2, substructured, and a group of
# 1, serial), each group holding a copy of the step matrix (PCREDUNDANT), against 1 rank
run(base + ["-ts_max_time", 2.0, "-monitor_csv", "groups_np3.csv", "-solver_schur_ranks", 2], nproc=3)
d = [read_csv("condensed_np1.csv"), read_csv("groups_np3.csv")]
c.check(np.array_equal(d[0]["contact_nodes"], d[1]["contact_nodes"]), "groups: the same number of contact nodes at every step on 1 and 3 ranks")
for col in ("R", "alpha", "energy", "contact_force", "gap_min"):
    scale = max(abs(d[0][col]))
    diff = max(abs(d[0][col] - d[1][col])) / scale
    c.check(diff < 1e-9, f"groups: {col} agrees to {diff:.2e} (relative to max {scale:.3e}) < 1e-9")
c.close()
