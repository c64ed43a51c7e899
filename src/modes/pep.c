/* The quadratic eigenproblem (lambda^2 M + lambda C + K) x = 0 by SLEPc's PEP: TOAR on the linearization,
   shift-and-invert about the target (default 0: the slowest modes; one factorization of K - sigma C + sigma^2 M,
   a direct solve like the time step's), every -pep_* / -st_* option honoured. With real scalars a complex pair
   lambda, conj(lambda) comes back as two eigenvalues: one of each is kept (im >= 0), with its vector
   x_re + i x_im. Optionally a band of overdamped eigenvalues is left out (the Maxwell branches' relaxation
   spectrum). The same path serves the roller (modes.c) and the 2-DOF friction model of the unit test. */
#include "modes/modes.h"

struct _n_RollerPEP {
  PEP        pep;
  PetscInt   n;     /* pairs kept */
  PetscInt  *index; /* their index among PEP's converged eigenpairs, sorted */
  PetscReal *re, *im;
};

/* The region of the wanted eigenvalues: all but the trapezoid -band[1] <= Re <= -band[0], |Im| <= -Re (the
   eigenvalues there have a modal loss factor 2|Re|/|Im| >= 2: overdamped; branches.c puts the Maxwell branches'
   relaxation spectrum there, docs/squeal.md section 1.2). */
static PetscErrorCode ExcludeBand(PEP pep, const PetscReal band[2])
{
  RG          rg;
  PetscScalar vr[4] = {-band[0], -band[1], -band[1], -band[0]}, vi[4] = {band[0], band[1], -band[1], -band[0]};

  PetscFunctionBeginUser;
  PetscCall(PEPGetRG(pep, &rg));
  PetscCall(RGSetType(rg, RGPOLYGON));
  PetscCall(RGPolygonSetVertices(rg, 4, vr, vi));
  PetscCall(RGSetComplement(rg, PETSC_TRUE));
  PetscFunctionReturn(0);
}

PetscErrorCode RollerPEPCreate(MPI_Comm comm, Mat M, Mat C, Mat K, PetscInt nev, PetscBool pivot, const PetscReal exclude[2], RollerPEP *p)
{
  RollerPEP r;
  Mat       ops[3] = {K, C, M};
  ST        st;
  KSP       ksp;
  PetscInt  N;

  PetscFunctionBeginUser;
  PetscCall(PetscNew(&r));
  PetscCall(MatGetSize(M, &N, NULL));
  PetscCall(PEPCreate(comm, &r->pep));
  PetscCall(PEPSetOperators(r->pep, 3, ops));
  PetscCall(PEPSetProblemType(r->pep, PEP_GENERAL));
  PetscCall(PEPSetType(r->pep, PEPTOAR));
  PetscCall(PEPSetDimensions(r->pep, PetscMin(nev, 2 * N), PETSC_DEFAULT, PETSC_DEFAULT));
  PetscCall(PEPSetTarget(r->pep, 0.0));
  PetscCall(PEPSetWhichEigenpairs(r->pep, PEP_TARGET_MAGNITUDE));
  PetscCall(PEPSetTolerances(r->pep, 1e-10, PETSC_DEFAULT));
  PetscCall(PEPGetST(r->pep, &st));
  PetscCall(STSetType(st, STSINVERT));
  PetscCall(STGetKSP(st, &ksp));
  PetscCall(RollerDirectSolverDefaults(ksp, PCLU));
  if (pivot) { /* a saddle point (zero diagonal): LU with pivoting, SuperLU on one rank (MUMPS and UMFPACK took 5-10
                   times longer on the feeder's 20k unknowns), MUMPS in parallel */
    PC          pc;
    PetscMPIInt size;

    PetscCallMPI(MPI_Comm_size(comm, &size));
    PetscCall(KSPGetPC(ksp, &pc));
    PetscCall(PCFactorSetMatSolverType(pc, size > 1 ? MATSOLVERMUMPS : MATSOLVERSUPERLU));
  }
  if (exclude) PetscCall(ExcludeBand(r->pep, exclude));
  PetscCall(PEPSetFromOptions(r->pep));
  *p = r;
  PetscFunctionReturn(0);
}

/* Solves and keeps one eigenvalue of each conjugate pair (and every real one), sorted by frequency. */
PetscErrorCode RollerPEPSolve(RollerPEP r, PetscInt *n)
{
  PetscInt           nconv, k = 0;
  PetscReal         *re, *im;
  PEPConvergedReason reason;

  PetscFunctionBeginUser;
  PetscCall(PEPSolve(r->pep));
  PetscCall(PEPGetConvergedReason(r->pep, &reason));
  PetscCall(PEPGetConverged(r->pep, &nconv));
  PetscCheck(reason > 0 || nconv > 0, PetscObjectComm((PetscObject)r->pep), PETSC_ERR_NOT_CONVERGED, "The eigensolver (SLEPc PEP) did not converge: %s; try a larger -pep_ncv or -pep_max_it", PEPConvergedReasons[reason]);
  PetscCall(PetscFree3(r->index, r->re, r->im));
  PetscCall(PetscMalloc3(nconv, &r->index, nconv, &re, nconv, &im));
  r->re = re;
  r->im = im;
  for (PetscInt i = 0; i < nconv; ++i) {
    PetscScalar kr, ki;

    PetscCall(PEPGetEigenpair(r->pep, i, &kr, &ki, NULL, NULL));
    if (PetscRealPart(ki) < 0) continue;
    r->index[k] = i;
    r->re[k]    = PetscRealPart(kr);
    r->im[k]    = PetscRealPart(ki);
    ++k;
  }
  r->n = k;
  for (PetscInt i = 1; i < k; ++i) { /* insertion sort by (im, re): a few dozen pairs */
    const PetscInt  idx = r->index[i];
    const PetscReal a = r->re[i], b = r->im[i];
    PetscInt        j = i - 1;

    for (; j >= 0 && (r->im[j] > b || (r->im[j] == b && r->re[j] > a)); --j) {
      r->index[j + 1] = r->index[j];
      r->re[j + 1]    = r->re[j];
      r->im[j + 1]    = r->im[j];
    }
    r->index[j + 1] = idx;
    r->re[j + 1]    = a;
    r->im[j + 1]    = b;
  }
  *n = k;
  PetscFunctionReturn(0);
}

PetscErrorCode RollerPEPGetPair(RollerPEP r, PetscInt i, PetscReal *re, PetscReal *im, Vec xr, Vec xi)
{
  PetscScalar kr, ki;

  PetscFunctionBeginUser;
  PetscCheck(i >= 0 && i < r->n, PETSC_COMM_SELF, PETSC_ERR_ARG_OUTOFRANGE, "Eigenpair %" PetscInt_FMT " of %" PetscInt_FMT, i, r->n);
  if (re) *re = r->re[i];
  if (im) *im = r->im[i];
  if (xr && xi) {
    PetscCall(PEPGetEigenpair(r->pep, r->index[i], &kr, &ki, xr, xi));
    if (r->im[i] == 0) PetscCall(VecZeroEntries(xi));
  }
  PetscFunctionReturn(0);
}

PetscErrorCode RollerPEPGetError(RollerPEP r, PetscInt i, PetscReal *err)
{
  PetscFunctionBeginUser;
  PetscCall(PEPComputeError(r->pep, r->index[i], PEP_ERROR_BACKWARD, err));
  PetscFunctionReturn(0);
}

PetscErrorCode RollerPEPDestroy(RollerPEP *p)
{
  PetscFunctionBeginUser;
  if (!*p) PetscFunctionReturn(0);
  PetscCall(PEPDestroy(&(*p)->pep));
  PetscCall(PetscFree3((*p)->index, (*p)->re, (*p)->im));
  PetscCall(PetscFree(*p));
  PetscFunctionReturn(0);
}
