/* Accurate by default (docs/model.md section 6.2): when -ts_dt or -mesh_h is not given, they are derived
   from the scene so that the max errors of R and alpha stay below the target -ts_phase_error P at the end
   time T. Each output's error is dominated by one mode and one source:
     time:  the scheme's phase error of the fastest mode the scene excites, max(w_b, b) (w_b the radial breathing
            mode, n = 0, P wave, which R swings at): dt makes it P after T (integrate/scheme.c, with each
            scheme's own phase error), which leaves P/2 of R's error for its spatial part (measured <= 0.2 P).
     space: alpha oscillates about 0 at the slow torsional mode w_t (n = 0, S wave), whose spatial frequency
            error accumulates: its phase error after T, calibrated on the exact axisymmetric reference, is
            C_k w_t T (h/L)^q_k with L = r_C - r_D; h makes it 0.7 P, which leaves 0.3 P for alpha's
            time error (measured <= 0.06 P) and the scatter of the calibration.
   Both frequencies are Bessel-root problems of the annulus clamped at r_D and free at r_C, solved once for the
   radii (ctx->modes): the h of the options' radii and the dt of the mesh's (a mesh file's own) share them. */
#include "model/model.h"

/* Calibration of the spatial phase error C_k w_t T (h/L)^q_k (docs/validation.md, "accurate defaults"):
   measured against the exact-in-space DMF reference for E = 0.05, 0.1, 0.2 and T = 20, 60 with the
   curved P2 boundary (largest C) and P1 (which locks at nu = 0.49: it needs far finer meshes). P3 (curved P2
   geometric map): errors of R, alpha 1.2 %, 2.0 % at h = 0.14, 0.53 %, 0.68 % at h = 0.1 (figure-4 scene, T = 20,
   the composed scheme): q = 2.5; C = 0.0062 gives h = 0.09 there and keeps -young 0.05 (h 0.104) below 1 %. */
static const PetscReal calibration_C[4] = {0, 1.2, 0.025, 0.0062};
static const PetscReal calibration_q[4] = {0, 1.7, 2.0, 2.5};

/* Contact scenes: edges of the graded layer across the contact half-width sqrt(r_C d) (RollerChooseMeshSize) */
#define ROLLER_CONTACT_ELEMENTS 14

/* Radial breathing mode u = A J1(kr) + B Y1(kr): u(r_D) = 0 and
   sigma_rr(r_C) = (lambda + 2 mu) u_r + lambda u/r = (lambda + 2 mu) k Z0(k r_C) - 2 mu Z1(k r_C)/r_C = 0,
   with u_r = k Z0 - Z1/r for Z = J, Y. Returned as the determinant of the 2x2 system in (A, B). */
static PetscReal BreathingDeterminant(PetscReal k, PetscReal ri, PetscReal ro, PetscReal lambda, PetscReal mu)
{
  const PetscReal sJ = (lambda + 2 * mu) * k * j0(k * ro) - 2 * mu * j1(k * ro) / ro;
  const PetscReal sY = (lambda + 2 * mu) * k * y0(k * ro) - 2 * mu * y1(k * ro) / ro;

  return j1(k * ri) * sY - y1(k * ri) * sJ;
}

/* Torsional mode v = A J1(kr) + B Y1(kr): v(r_D) = 0 and the shear traction mu (v_r - v/r) = -mu k Z2(k r_C)
   vanishes at r_C, Z2(x) = 2 Z1(x)/x - Z0(x). */
static PetscReal TorsionDeterminant(PetscReal k, PetscReal ri, PetscReal ro, PetscReal lambda, PetscReal mu)
{
  const PetscReal x = k * ro;

  return j1(k * ri) * (2 * y1(x) / x - y0(x)) - y1(k * ri) * (2 * j1(x) / x - j0(x));
}

typedef PetscReal (*Determinant)(PetscReal, PetscReal, PetscReal, PetscReal, PetscReal);

/* The lowest root k > 0 of det: scan k (r_C - r_D) in (0, 40] for the first sign change, then bisect. */
static PetscErrorCode LowestRoot(Roller ctx, Determinant det, const char *what, PetscReal *k)
{
  const PetscReal ri = ctx->mesh.r_inner, ro = ctx->mesh.r_outer, L = ro - ri;
  const PetscInt  n = 4000;
  PetscReal       lambda, mu, a, fa, b, fb;
  PetscInt        i;

  PetscFunctionBeginUser;
  RollerRubberInstantaneous(&ctx->material, &lambda, &mu);
  a = b = 1e-3 / L;
  fa = fb = det(a, ri, ro, lambda, mu);
  for (i = 1; i <= n; i++) {
    b  = 40.0 * i / (n * L);
    fb = det(b, ri, ro, lambda, mu);
    if ((fa < 0) != (fb < 0)) break;
    a  = b;
    fa = fb;
  }
  PetscCheck(i <= n, ctx->comm, PETSC_ERR_PLIB, "No %s mode found below k = %g for -r_inner %g -r_outer %g", what, (double)(40.0 / L), (double)ri, (double)ro);
  for (i = 0; i < 100 && b - a > 1e-15 * b; i++) {
    const PetscReal m = 0.5 * (a + b), fm = det(m, ri, ro, lambda, mu);

    if ((fa < 0) == (fm < 0)) {
      a  = m;
      fa = fm;
    } else b = m;
  }
  *k = 0.5 * (a + b);
  PetscFunctionReturn(0);
}

/* Angular frequencies of the breathing (P) and torsional (S) modes of the annulus at rest, computed when the
   radii are not those of the last computation (the material is set once, before either). With -rubber maxwell, of the
   instantaneous (unrelaxed) solid: the highest the modes reach, at frequencies far above the branches' 1/tau_i (the
   time step's phase error is that of the fastest mode; docs/model.md section 6.2). */
PetscErrorCode RollerModeFrequencies(Roller ctx, PetscReal *w_breathing, PetscReal *w_torsion)
{
  RollerModes *modes = &ctx->modes;
  PetscReal    k, lambda, mu, c_p, c_s;

  PetscFunctionBeginUser;
  RollerRubberInstantaneous(&ctx->material, &lambda, &mu);
  c_p = PetscSqrtReal((lambda + 2 * mu) / ctx->material.density);
  c_s = PetscSqrtReal(mu / ctx->material.density);
  if (modes->r_inner != ctx->mesh.r_inner || modes->r_outer != ctx->mesh.r_outer) {
    PetscCall(LowestRoot(ctx, BreathingDeterminant, "radial breathing", &k));
    modes->breathing = k * c_p;
    PetscCall(LowestRoot(ctx, TorsionDeterminant, "torsional", &k));
    modes->torsion = k * c_s;
    modes->r_inner = ctx->mesh.r_inner;
    modes->r_outer = ctx->mesh.r_outer;
  }
  *w_breathing = modes->breathing;
  *w_torsion   = modes->torsion;
  PetscFunctionReturn(0);
}

/* The radial (n = 0, P) modes that R carries, for the time schemes' dt (docs/model.md section 6.2): the first n
   roots w_j of the breathing determinant and the amplitudes a_j of the modes in R(t) = sum_j a_j (1 - cos(w_j t))
   when the centrifugal load rho omega^2 r is switched on at rest (the scenes' start), normalized to sum a_j = 1:
   a_j = F_j phi_j(r_C)/(w_j^2 m_j), F_j = int rho r phi_j r dr, m_j = int rho phi_j^2 r dr, phi_j = J1(k_j r) + B_j
   Y1(k_j r) (phi_j(r_D) = 0). The load's jump at r_D makes a_j decay only algebraically (~ j^-3): a higher-order
   scheme's error is then set by the second and third modes as much as by the first. */
PetscErrorCode RollerRadialModes(Roller ctx, PetscInt nmax, PetscReal w[], PetscReal a[], PetscInt *n)
{
  const PetscReal ri = ctx->mesh.r_inner, ro = ctx->mesh.r_outer, L = ro - ri;
  const PetscInt  nq = 200, nscan = 40000;
  PetscReal      *xq, *wq, k0 = 1e-3 / L, f0, sum = 0.0, lambda, mu, c_p;

  PetscFunctionBeginUser;
  RollerRubberInstantaneous(&ctx->material, &lambda, &mu); /* the unrelaxed solid's, as RollerModeFrequencies */
  c_p = PetscSqrtReal((lambda + 2 * mu) / ctx->material.density);
  PetscCall(PetscMalloc2(nq, &xq, nq, &wq));
  PetscCall(PetscDTGaussQuadrature(nq, ri, ro, xq, wq));
  f0 = BreathingDeterminant(k0, ri, ro, lambda, mu);
  *n = 0;
  for (PetscInt i = 1; i <= nscan && *n < nmax; i++) {
    const PetscReal k1 = (PetscReal)i * 4.0 * nmax / (nscan * L), f1 = BreathingDeterminant(k1, ri, ro, lambda, mu);

    if ((f0 < 0) != (f1 < 0)) {
      PetscReal lo = k0, hi = k1, flo = f0, k, B, m = 0.0, F = 0.0;

      for (PetscInt it = 0; it < 100 && hi - lo > 1e-14 * hi; it++) {
        const PetscReal mid = 0.5 * (lo + hi), fm = BreathingDeterminant(mid, ri, ro, lambda, mu);

        if ((flo < 0) == (fm < 0)) {
          lo  = mid;
          flo = fm;
        } else hi = mid;
      }
      k = 0.5 * (lo + hi);
      B = -j1(k * ri) / y1(k * ri);
      for (PetscInt q = 0; q < nq; q++) {
        const PetscReal phi = j1(k * xq[q]) + B * y1(k * xq[q]);

        m += wq[q] * phi * phi * xq[q];
        F += wq[q] * xq[q] * phi * xq[q];
      }
      w[*n] = k * c_p;
      a[*n] = F * (j1(k * ro) + B * y1(k * ro)) / (w[*n] * w[*n] * m);
      sum += a[*n];
      (*n)++;
    }
    k0 = k1;
    f0 = f1;
  }
  PetscCheck(*n > 0 && sum != 0, ctx->comm, PETSC_ERR_PLIB, "No radial breathing mode found for -r_inner %g -r_outer %g", (double)ri, (double)ro);
  for (PetscInt j = 0; j < *n; j++) a[j] /= sum;
  PetscCall(PetscFree2(xq, wq));
  PetscFunctionReturn(0);
}

/* The end time the error target refers to: -ts_max_time, at least one period of the fastest mode. */
PetscReal RollerEndTime(Roller ctx, PetscReal w_fast)
{
  return PetscMax(ctx->ts.max_time, 2 * PETSC_PI / w_fast);
}

/* The torsional mode's frequency as the rubber runs it: with -rubber maxwell w = w_r sqrt(G'(w)/mu) (a pure shear mode:
   its frequency scales with the shear modulus, w_r the relaxed solid's), by fixed-point iteration from the
   instantaneous solid's w_t (G' increases with w: the iterates decrease to the root); w_t itself otherwise. */
static PetscReal TorsionAtItsFrequency(const RollerMaterial *m, PetscReal w_t)
{
  PetscReal sum = 0.0, w = w_t;

  if (m->rubber != ROLLER_RUBBER_MAXWELL) return w_t;
  for (PetscInt i = 0; i < m->nbranch; ++i) sum += m->g[i];
  for (PetscInt it = 0; it < 200; ++it) {
    PetscReal re, im;

    RollerRubberModulus(m->nbranch, m->tau, m->g, 0.0, w, &re, &im);
    w = w_t * PetscSqrtReal(re / (1.0 + sum));
  }
  return w;
}

/* -mesh_h when not given: C_k w_t T (h/L)^q = 0.7 P. Needs the radii from the options (a mesh file sets its own h). */
PetscErrorCode RollerChooseMeshSize(Roller ctx)
{
  PetscReal w_b, w_t, T, L = ctx->mesh.r_outer - ctx->mesh.r_inner;

  PetscFunctionBeginUser;
  if (ctx->mesh.h_set || ctx->mesh.file[0]) PetscFunctionReturn(0);
  if (!ctx->disc.degree_set && !ctx->obstacle.on && !ctx->eig.on && !ctx->disc.static_solve && !ctx->ck.restart[0]) {
    /* P3 where it buys the most accuracy per CPU (no contact: the contact nodes and mass layer are P2) */
    ctx->disc.degree = 3;
    ctx->mesh.curved = PETSC_TRUE;
  }
  PetscCall(RollerModeFrequencies(ctx, &w_b, &w_t));
  w_t         = TorsionAtItsFrequency(&ctx->material, w_t); /* the spatial error of the mode alpha swings at */
  T           = RollerEndTime(ctx, PetscMax(w_b, ctx->rotation.b));
  ctx->mesh.h = L * PetscPowReal(0.7 * ctx->ts.phase_error / (calibration_C[ctx->disc.degree] * w_t * T), 1.0 / calibration_q[ctx->disc.degree]);
  ctx->mesh.h = PetscMin(ctx->mesh.h, 0.5 * L); /* at least two elements across the wall */
  if (ctx->ts.view && !ctx->disc.degree_set)
    PetscCall(PetscPrintf(ctx->comm, "roller: P%" PetscInt_FMT " (the default %s), -mesh_h %g from -ts_phase_error %g: spatial phase error %g w_t T (h/L)^%g = 0.7 P\n", ctx->disc.degree, ctx->disc.degree == 3 ? "without -obstacle: P3 at h 0.09 reaches P2's error at h 0.035 with 1/3 of the unknowns, docs/model.md 6.2" : "with -obstacle: the contact nodes are P2",
                          (double)ctx->mesh.h, (double)ctx->ts.phase_error, (double)calibration_C[ctx->disc.degree], (double)calibration_q[ctx->disc.degree]));
  PetscCall(PetscInfo(NULL, "-mesh_h %g from -ts_phase_error %g: torsional mode w_t = %g (period %g), T = %g, P%" PetscInt_FMT "\n", (double)ctx->mesh.h, (double)ctx->ts.phase_error, (double)w_t, (double)(2 * PETSC_PI / w_t), (double)T, ctx->disc.degree));
  if (ctx->obstacle.on && ctx->obstacle.depth > 0) {
    /* Contact: the patch's half-width a ~ sqrt(r_C d) (Hertz's a^2 = 4 P R/(pi E*) is close to r_C d for these
       depths). Default: a mesh graded toward Gamma_C (the patch travels around all of it in the rotating frame)
       with ROLLER_CONTACT_ELEMENTS edges across a, two rows of them, the bulk at the rule above: the rolling
       scene's element-passing line 0.08 % of the force at 2.3 times the uniform mesh's cost, the mean force
       within 0.12 % of the uniform h_c mesh (docs/contact.md "Graded mesh", docs/model.md section 6.2).
       -mesh_h_contact 0: the uniform mesh with five elements across a (1 % in R, alpha and the averaged force). */
    const PetscReal a = PetscSqrtReal(ctx->mesh.r_outer * ctx->obstacle.depth);

    if (!ctx->mesh.h_contact_set) { /* (a mesh file returned above) */
      if (a / ROLLER_CONTACT_ELEMENTS < ctx->mesh.h) {
        ctx->mesh.h_contact = a / ROLLER_CONTACT_ELEMENTS;
        if (ctx->mesh.contact_layer == 0) ctx->mesh.contact_layer = 2 * ctx->mesh.h_contact;
        PetscCall(PetscInfo(NULL, "-mesh_h_contact %g: %d elements across the contact half-width sqrt(r_outer depth) = %g, layer %g\n", (double)ctx->mesh.h_contact, ROLLER_CONTACT_ELEMENTS, (double)a, (double)ctx->mesh.contact_layer));
      }
    } else if (a / 5.0 < ctx->mesh.h && ctx->mesh.h_contact == 0) {
      ctx->mesh.h = a / 5.0;
      PetscCall(PetscInfo(NULL, "-mesh_h %g: five elements across the contact half-width sqrt(r_outer depth) = %g\n", (double)ctx->mesh.h, (double)a));
    }
  }
  PetscFunctionReturn(0);
}
