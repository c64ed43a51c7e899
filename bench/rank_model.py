#!/usr/bin/env python3
"""A model of the rolling scene's wall time on P ranks (issue 27, docs/performance.md "Beyond this machine"), from
the costs measured on 1 and 2 ranks of this machine (bench/large_ranks.py, P2 h = 0.005, 221k unknowns) and the
substructured Cholesky's structure (src/model/solver_schur.c). Per step and for the set-up:

  solve(P)  = c_sub m log2 m                          each rank's forward + backward substitution, m = n / P
            + 2 * 12 B * nnz(G_r) / B_mem             G_r^T y and G_r x (nnz(G_r) = g0 * ng_r * sqrt(m))
            + 2 (alpha ceil(log2 P) + 8 B * ng / beta)  the interface's reduction (allreduce: reduce + broadcast)
            + 8 B * ng^2 / B_mem                      the dense interface solve (its Cholesky triangle read twice)
  step(P)   = k_s solve(P) + w_rest / P + w_serial + r alpha ceil(log2 P)
  setup(P)  = w_asm / P + w_fact / P^1.5 (2-D nested dissection: flops ~ m^1.5)
            + 2 m_c solve(P)                          the contact condensation's columns (S = E^T A^-1 E)
            + ng^3 / (3 F) + 8 B * ng^2 / beta        the interface's Cholesky, its allreduce
  T(P)      = setup(P) + N_steps step(P)

The interface ng(P) of the annulus (r 0.25 to 0.5): METIS cuts it into sectors while a sector is wider than the ring
(P <= 8: P cuts across the ring, each 240 unknowns at h = 0.005, measured), then into blocks (the interface's length
~ 2 sqrt(A P) less half the boundary); both scale as 1/h. The dense interface is what stops the method: its memory
(8 ng^2 bytes on every rank) and its Cholesky grow as P^2 and P^3.

Constants: c_sub, k_s, w_* and m_c fitted to the 1- and 2-rank measurements (printed); alpha, beta for a cluster
(InfiniBand: 2 us, 10 GB/s) and B_mem, F for one core (10 GB/s, 10 GFlop/s), stated, not measured.
Usage: /usr/bin/python3 bench/rank_model.py [--alpha 2e-6] [--beta 1e10]"""
import argparse
import math

N221 = 221420
A_RING = math.pi * (0.5 ** 2 - 0.25 ** 2)
L_BOUNDARY = 2 * math.pi * (0.5 + 0.25)


def interface(P, h):
    if P == 1:
        return 0.0
    per_length = 240 / 0.25 * (0.005 / h)  # unknowns per unit length of cut (240 per cut across the ring, measured)
    sectors = P * 0.25
    blocks = 2 * math.sqrt(A_RING * P) - L_BOUNDARY / 2
    return per_length * (sectors if P <= 8 else blocks)


def model(P, n, h, c, o, group=None):
    """(set-up, per step, interface, its dense factor in GiB) on P ranks; with group G < P the substructuring on
    groups of G ranks, each a copy of the matrix (-solver_schur_ranks): a group's solve plus the copy's scatter and
    gather of the whole vector, the assembly still over all P ranks."""
    if group and P > group:
        setup, step, ng, gib = model(group, n, h, c, o)
        copy = 2 * 8 * n / o.beta  # each solve: the right-hand side to the group, the solution back
        asm = c["w_asm"] * (n / N221)
        setup += -asm / group + asm / P + 12 * 19 * n / o.beta  # the matrix copied to each group once (19 nonzeros a row)
        step += c["k_s"] * copy - c["w_rest"] * (n / N221) * (1 / group - 1 / P)
        return setup, step, ng, gib
    m = n / P
    ng = interface(P, h)
    ngr = min(ng, 2 * 240 * (0.005 / h)) if P > 1 else 0  # the interface columns one rank's interior touches
    lg = math.ceil(math.log2(P)) if P > 1 else 0
    solve = c["c_sub"] * m * math.log2(m)
    if P > 1:
        solve += 2 * 12 * c["g0"] * ngr * math.sqrt(m) / o.bmem + 2 * (o.alpha * lg + 8 * ng / o.beta) + 8 * ng ** 2 / o.bmem
    step = c["k_s"] * solve + c["w_rest"] * (n / N221) / P + c["w_serial"] + c["r"] * o.alpha * lg
    setup = c["w_asm"] * (n / N221) / P + c["w_fact"] * (n / N221) ** 1.5 / P ** 1.5 + 2 * c["m_c"] * math.sqrt(n / N221) * solve
    if P > 1:
        setup += ng ** 3 / (3 * o.flops) + 8 * ng ** 2 / o.beta
    return setup, step, ng, 8 * ng ** 2 / 2 ** 30


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--alpha", type=float, default=2e-6, help="network latency per message [s]")
    ap.add_argument("--beta", type=float, default=1e10, help="network bandwidth [B/s]")
    ap.add_argument("--bmem", type=float, default=1e10, help="memory bandwidth of one core [B/s]")
    ap.add_argument("--flops", type=float, default=1e10, help="dense flop rate of one core [flop/s]")
    ap.add_argument("--group", type=int, default=8, help="-solver_schur_ranks")
    o = ap.parse_args()
    # fitted on this machine (docs/performance.md): 1-rank serial solve 36.0 ms at 221k unknowns (c_sub), 2.2 solves a
    # step and 10.5 ms of other work (rolling, 88.8 ms a step), set-up 143.5 s of which assembly 20 s and the step
    # matrix's factorization 7 s, the rest the condensation's 2 m_c column solves; 31 reductions a step; G_r's
    # nonzeros 3.6 ng_r sqrt(m) (h = 0.01: 143k); 1412 steps to t = 20
    c = {"c_sub": 0.036 / (N221 * math.log2(N221)), "k_s": 2.2, "w_rest": 0.0095, "w_serial": 0.001, "r": 31,
         "w_asm": 20.0, "w_fact": 7.0, "m_c": (143.5 - 27.0) / (2 * 0.036), "g0": 3.6}
    nsteps = 1412
    print(f"model constants: {', '.join(f'{k} {v:.3g}' for k, v in c.items())}; alpha {o.alpha:g} s, beta {o.beta:g} B/s, "
          f"B_mem {o.bmem:g} B/s, F {o.flops:g} flop/s\n")
    print("| unknowns | ranks | interface (all ranks) | its dense factor per rank [GiB] | set-up [s] | per step [ms] | whole run [s] | speed-up | "
          "groups of 8 (default): whole run [s] | speed-up |")
    print("|---|---|---|---|---|---|---|---|---|---|")
    for n, h in ((N221, 0.005), (2.0e6, 0.005 * math.sqrt(N221 / 2.0e6))):
        t1 = None
        best = (None, float("inf"))
        for P in (1, 2, 4, 8, 16, 32, 64):
            setup, step, ng, gib = model(P, n, h, c, o)
            T = setup + nsteps * step
            sg, stg, _, _ = model(P, n, h, c, o, group=o.group)
            Tg = sg + nsteps * stg
            t1 = t1 or T
            best = (P, T) if T < best[1] else best
            print(f"| {n / 1e3:.0f}k | {P} | {ng:.0f} | {gib:.3f} | {setup:.1f} | {1e3 * step:.1f} | {T:.0f} | {t1 / T:.2f} | {Tg:.0f} | {t1 / Tg:.2f} |")
        print(f"| {n / 1e3:.0f}k | one group, fastest: {best[0]} ranks | | | | | {best[1]:.0f} | {t1 / best[1]:.2f} | | |")


if __name__ == "__main__":
    main()
