static const char help[] = "Unit test of the generalized Maxwell solid's fit (src/model/rubber.c, docs/model.md section 1.1):\n"
                           "RollerRubberFit for several loss factors and bands; the fitted loss factor G''/G' within 5 %% of the target\n"
                           "on a dense grid of the band (10 times the fit's own check grid), weights > 0, relaxation times > 0, at most\n"
                           "16 branches, the storage modulus G' increasing with the frequency (1/100 of the band's low end to 100 times\n"
                           "its high end), RollerRubberModulus against the Prony sum written out here; with a Kelvin-Voigt term\n"
                           "tau_kv beside the branches (-viscosity with -rubber maxwell) the loss factor (G'' + w tau_kv mu)/G' within 5 %%.\n";

#include "model/model.h"

typedef struct {
  PetscReal eta, f1, f2, tau_kv;
} Case;

/* G'/mu and G''/mu of the Prony series written out, independently of RollerRubberModulus */
static void Storage(PetscInt n, const PetscReal tau[], const PetscReal g[], PetscReal w, PetscReal *Gs, PetscReal *Gl)
{
  *Gs = 1.0;
  *Gl = 0.0;
  for (PetscInt i = 0; i < n; ++i) {
    const PetscReal x = w * tau[i];

    *Gs += g[i] * x * x / (1.0 + x * x);
    *Gl += g[i] * x / (1.0 + x * x);
  }
}

static PetscErrorCode Check(const Case *c, PetscInt *failed)
{
  const PetscInt npts = 20000;
  PetscInt       n;
  PetscReal      tau[ROLLER_MAX_BRANCHES], g[ROLLER_MAX_BRANCHES], err, maxerr = 0.0, modulus = 0.0, sum = 0.0, prev = 0.0, G1, G2, Gl;
  PetscBool      positive = PETSC_TRUE, monotone = PETSC_TRUE, ok;

  PetscFunctionBeginUser;
  PetscCall(RollerRubberFit(c->eta, c->tau_kv, c->f1, c->f2, 0.04, ROLLER_MAX_BRANCHES, &n, tau, g, &err));
  for (PetscInt i = 0; i < n; ++i) {
    positive = (PetscBool)(positive && g[i] > 0 && tau[i] > 0);
    sum += g[i];
  }
  for (PetscInt k = 0; k < npts; ++k) { /* the band */
    const PetscReal w = 2 * PETSC_PI * c->f1 * PetscPowReal(c->f2 / c->f1, (PetscReal)k / (npts - 1));
    PetscReal       Gs, Gl, re, im;

    Storage(n, tau, g, w, &Gs, &Gl);
    maxerr = PetscMax(maxerr, PetscAbsReal((Gl + w * c->tau_kv) / Gs / c->eta - 1.0));
    RollerRubberModulus(n, tau, g, 0.0, w, &re, &im);
    modulus = PetscMax(modulus, PetscMax(PetscAbsReal(re - Gs), PetscAbsReal(im - Gl)) / Gs);
  }
  for (PetscInt k = 0; k < npts; ++k) { /* four decades beyond it: G' increases */
    const PetscReal w = 2 * PETSC_PI * c->f1 / 100 * PetscPowReal(100 * c->f2 / (c->f1 / 100), (PetscReal)k / (npts - 1));
    PetscReal       Gs, Gl;

    Storage(n, tau, g, w, &Gs, &Gl);
    monotone = (PetscBool)(monotone && (k == 0 || Gs >= prev));
    prev     = Gs;
  }
  Storage(n, tau, g, 2 * PETSC_PI * c->f1, &G1, &Gl);
  Storage(n, tau, g, 2 * PETSC_PI * c->f2, &G2, &Gl);
  ok = (PetscBool)(n >= 1 && n <= ROLLER_MAX_BRANCHES && maxerr <= 0.05 && PetscAbsReal(maxerr - err) < 1e-3 && positive && monotone && modulus < 1e-14);
  PetscCall(PetscPrintf(PETSC_COMM_SELF, "%s loss factor %g over %g-%g (Kelvin-Voigt tau %g beside): %" PetscInt_FMT " branches, max |eta/ETA - 1| %.4f on %" PetscInt_FMT " points (<= 0.05; the fit's own %.4f), weights %s, G' %s (G'/mu %.4f to %.4f over the band, instantaneous %.4f), RollerRubberModulus %.1e\n", ok ? "PASS" : "FAIL",
                        (double)c->eta, (double)c->f1, (double)c->f2, (double)c->tau_kv, n, (double)maxerr, npts, (double)err, positive ? "> 0" : "NOT > 0", monotone ? "increasing" : "NOT increasing", (double)G1, (double)G2, (double)(1 + sum), (double)modulus));
  *failed += !ok;
  PetscFunctionReturn(0);
}

int main(int argc, char **argv)
{
  const Case cases[] = {
    {0.05, 100,  5000, 0     },
    {0.1,  100,  5000, 0     },
    {0.2,  100,  5000, 0     },
    {0.3,  100,  5000, 0     },
    {0.05, 0.01, 1,    0     },
    {0.1,  0.01, 1,    0     },
    {0.2,  0.01, 1,    0     },
    {0.3,  0.01, 1,    0     },
    {0.1,  500,  500,  0     }, /* a single frequency: one branch */
    {0.1,  1,    1e5,  0     }, /* five decades */
    {1.0,  100,  5000, 0     }, /* the largest loss factor allowed */
    {0.1,  100,  5000, 3.2e-7}, /* a Kelvin-Voigt term beside the branches: 0.01 of the loss factor at 5000 */
    {0.1,  100,  5000, 1.5e-6}, /* ... 0.047 of it at 5000: the largest share -rubber maxwell allows */
  };
  PetscInt failed = 0;

  PetscCall(PetscInitialize(&argc, &argv, NULL, help));
  for (size_t i = 0; i < sizeof(cases) / sizeof(cases[0]); ++i) PetscCall(Check(&cases[i], &failed));
  PetscCheck(!failed, PETSC_COMM_SELF, PETSC_ERR_PLIB, "%" PetscInt_FMT " fits out of their tolerance", failed);
  PetscCall(PetscFinalize());
  return 0;
}
