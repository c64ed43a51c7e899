/* Coulomb's law on the dual data of the steady state's contact candidates (docs/squeal.md section 3): the gaps and
   the slips (over a speed scale) of the n candidates are affine in their normal and tangential forces,
   w = G x + d, x = (N, T), w = (gaps, slips) (G 2n x 2n column-major; without friction the n x n normal block only).
   Solved by alternating the normal contact at fixed T (an LCP with a symmetric positive definite matrix: Lemke's
   method) and the tangential forces at fixed N (Tresca with the bound mu_j N_j: a primal-dual active set on the
   stick/slip states) until both settle. Coulomb as one LCP of 4 n unknowns ends on a secondary ray here (the slip
   matrix, the derivative along Gamma_C of a compliance, is nearly skew: not copositive). */
#include "modes/modes.h"

/* The tangential forces T of the contact nodes (N_j > 0) for given normal forces N: Tresca with the bound mu_j N_j,
   on the slips v = Gtt T + Gtn N + dt (G m x m, m = 2 n: rows/columns n.. the tangential ones). A node sticks
   (v_j = 0, |T_j| <= mu_j N_j) or slips (T_j = -s_j mu_j N_j, s_j v_j >= 0). Primal-dual active set on the states
   (state 1 stick, 2 slip with the sign s; warm-started from the caller's, a node new in contact slips with its
   slip's sign): the stick nodes' forces from Gtt_SS T_S = -(v without them); every slip node whose slip turned
   sticks, but of the stick nodes over their bound only the one furthest over it (|T_j| / (mu_j N_j) largest)
   slips in one iteration. Why one: Gtt is not an M-matrix (nearly skew, the transport of the stick condition
   along Gamma_C), and a node set slipping inside a stick zone pushes its upstream neighbour over the bound in the
   next solve while its own slip comes out backwards: flipping every node over the bound at once sent such a
   spurious slip node up the stick zone one node per iteration (one iteration per stick node, 73 on Carter's
   scene at h_c = 0.001, past any fixed limit on finer meshes; docs/squeal.md section 3). The limit, n + 100, leaves
   room for one stick-to-slip switch per node (2-10 iterations measured). */
static PetscErrorCode Tangential(MPI_Comm comm, PetscInt n, const PetscReal G[], const PetscReal d[], const PetscReal mu[], const PetscReal N[], PetscInt state[], PetscReal s[], PetscReal T[], PetscInt *its)
{
  const PetscInt m = 2 * n, maxit = n + 100;
  PetscInt      *S, ns, it;
  PetscReal     *v, *r, *x, *scratch;

  PetscFunctionBeginUser;
  PetscCall(PetscMalloc5(n, &S, n, &v, n, &r, n, &x, (size_t)n * n, &scratch));
  for (it = 0; it < maxit; ++it) {
    PetscInt  changed = 0, worst = -1;
    PetscReal over = 1.0;

    ns = 0;
    for (PetscInt j = 0; j < n; ++j) {
      T[j] = state[j] == 2 ? -s[j] * mu[j] * N[j] : 0.0;
      if (state[j] == 1) S[ns++] = j;
    }
    for (PetscInt j = 0; j < n; ++j) { /* the slips without the stick nodes' forces */
      v[j] = d[n + j];
      for (PetscInt k = 0; k < n; ++k) v[j] += G[n + j + (size_t)k * m] * N[k] + G[n + j + (size_t)(n + k) * m] * T[k];
    }
    if (ns) {
      for (PetscInt p = 0; p < ns; ++p) r[p] = -v[S[p]];
      PetscCall(RollerContactDenseSolve(G + n + (size_t)n * m, m, S, ns, PETSC_FALSE, scratch, r, x)); /* the slip matrix Gtt on S */
      for (PetscInt p = 0; p < ns; ++p) T[S[p]] = x[p];
      for (PetscInt j = 0; j < n; ++j)
        for (PetscInt p = 0; p < ns; ++p) v[j] += G[n + j + (size_t)(n + S[p]) * m] * x[p];
    }
    for (PetscInt j = 0; j < n; ++j) {
      if (N[j] <= 0) {
        if (state[j]) ++changed;
        state[j] = 0;
        T[j]     = 0.0;
      } else if (state[j] == 1 && PetscAbsReal(T[j]) > over * mu[j] * N[j]) {
        worst = j; /* over its bound, and further than every stick node before it */
        over  = PetscAbsReal(T[j]) / (mu[j] * N[j]);
      } else if (state[j] == 2 && s[j] * v[j] < 0) {
        state[j] = 1;
        ++changed;
      } else if (state[j] == 0) {
        state[j] = 2;
        s[j]     = v[j] >= 0 ? 1.0 : -1.0;
        ++changed;
      }
    }
    if (worst >= 0) {
      state[worst] = 2;
      s[worst]     = T[worst] > 0 ? -1.0 : 1.0;
      ++changed;
    }
    if (!changed) break;
  }
  PetscCheck(it < maxit, comm, PETSC_ERR_NOT_CONVERGED, "The steady state's stick/slip states did not settle in %" PetscInt_FMT " active-set iterations (%" PetscInt_FMT " candidates)", maxit, n);
  *its = it + 1;
  PetscCall(PetscFree5(S, v, r, x, scratch));
  PetscFunctionReturn(0);
}

PetscErrorCode RollerSteadyCoulomb(MPI_Comm comm, PetscInt n, const PetscReal G[], const PetscReal d[], PetscBool friction, const PetscReal mu[], PetscReal N[], PetscReal T[], PetscInt state[], PetscInt *alternations, PetscInt *active_set)
{
  const PetscInt m = friction ? 2 * n : n;
  PetscReal     *xs, *Gnn, *q, *s, last = PETSC_MAX_REAL;
  PetscInt       pivots, k, its = 0;
  PetscBool      solved;

  PetscFunctionBeginUser;
  *active_set = 0;
  PetscCall(PetscMalloc4(n, &xs, (size_t)n * n, &Gnn, n, &q, n, &s));
  for (PetscInt j = 0; j < n; ++j) {
    for (PetscInt i = 0; i < n; ++i) Gnn[i + (size_t)j * n] = G[i + (size_t)j * m];
    if (!friction) T[j] = 0.0;
    s[j] = T[j] > 0 ? -1.0 : 1.0; /* the last call's forces and states: a warm start */
  }
  for (k = 0; k < 100; ++k) {
    PetscReal dN = 0, dT = 0, big = 0, change;

    for (PetscInt i = 0; i < n; ++i) {
      q[i] = d[i];
      if (friction)
        for (PetscInt j = 0; j < n; ++j) q[i] += G[i + (size_t)(n + j) * m] * T[j];
    }
    PetscCall(RollerContactLemke(n, Gnn, q, xs, &pivots, &solved));
    PetscCheck(solved, comm, PETSC_ERR_NOT_CONVERGED, "The steady state's normal contact LCP (%" PetscInt_FMT " nodes) has no solution by Lemke's method (a secondary ray after %" PetscInt_FMT " pivots)", n, pivots);
    for (PetscInt j = 0; j < n; ++j) {
      dN   = PetscMax(dN, PetscAbsReal(xs[j] - N[j]));
      N[j] = xs[j];
      big  = PetscMax(big, N[j]);
    }
    if (!friction) break;
    PetscCall(PetscArraycpy(xs, T, n));
    PetscCall(Tangential(comm, n, G, d, mu, N, state, s, T, &its));
    *active_set = PetscMax(*active_set, its);
    for (PetscInt j = 0; j < n; ++j) dT = PetscMax(dT, PetscAbsReal(xs[j] - T[j]));
    change = PetscMax(dN, dT);
    /* settled: below 1e-13 of the largest force, or at the round-off of the dense solves, which grows with the
       stick zone (2e-13 with 131 stick nodes, Carter's scene at h_c = 0.0007): the states kept and the change no
       longer shrinking (the alternation contracts by about 0.2 per pass, docs/squeal.md section 3) */
    if (k && (change <= 1e-13 * big || (its == 1 && change <= 1e-10 * big && change >= last))) break;
    last = change;
  }
  PetscCheck(k < 100, comm, PETSC_ERR_NOT_CONVERGED, "The steady state's normal and tangential forces did not settle in 100 alternations");
  *alternations = k + 1;
  PetscCall(PetscFree4(xs, Gnn, q, s));
  PetscFunctionReturn(0);
}
