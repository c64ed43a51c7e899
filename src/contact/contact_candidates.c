/* The step's data: the contact basis and bounds at t_k, the candidate set (the nodes that carry a bound) and
   the nodes it gains when a solution penetrates outside it (docs/contact.md, "the candidate set"). */
#include "contact_impl.h"

/* theta^k, n^k = (sin theta, cos theta), t^k = (cos theta, -sin theta), g^k and the bounds
   q_n >= g^k - x_n . n^k of every node (docs/model.md sections 1-2). */
PetscErrorCode RollerContactSetTime(Roller ctx, RollerContact c, PetscReal t)
{
  RollerContactStep *st = &c->step;

  PetscFunctionBeginUser;
  st->t = t;
  RollerTheta(ctx, t, &st->theta, NULL, NULL);
  RollerContactObstacleAt(ctx, t, st->normal, &st->g);
  st->tangent[0] = st->normal[1];
  st->tangent[1] = -st->normal[0];
  for (PetscInt i = 0; i < c->nodes.nc; ++i) st->lower[i] = st->g - (c->nodes.xc[2 * i] * st->normal[0] + c->nodes.xc[2 * i + 1] * st->normal[1]);
  if (c->nodes.phi) RollerContactReducedWindow(ctx, c); /* -rom: the nodes this step gathers */
  PetscFunctionReturn(0);
}

static void CandidateList(RollerContact c)
{
  c->step.ncand = 0;
  for (PetscInt i = 0; i < c->nodes.nc; ++i)
    if (c->step.is_cand[i]) c->step.cand[c->step.ncand++] = i;
}

/* The step at t from the level x_cur at t_cur and the prediction of the stage (RollerContactStage): basis, bounds,
   and the nodes the obstacle can reach in this step: the gap of the predicted position x_n + x_pred,n against the
   obstacle at t (its motion and the rotation of n are exact in this prediction) is below the reach:
   -contact_margin, plus the obstacle's advance since t_cur, plus twice the largest nodal increment of Gamma_C
   (for the three-level schemes the last step's displacement: a bound on the change of velocity a contact shock can
   bring). A node that still penetrates is added after the solve (RollerContactAddPenetrating).
   Also the nodes on the obstacle at t_cur (gap <= tol of x_cur with n and g at t_cur): the initial active set of
   the condensed solver. It is derived from the state, not remembered from the last solve, so that the step is a
   function of the checkpointed state only and a restart repeats it exactly. */
PetscErrorCode RollerContactSetUpStep(Roller ctx, RollerContact c, const RollerContactStage *stage, PetscReal t)
{
  RollerContactStep *st = &c->step;
  const PetscScalar *u1, *u2;
  const PetscReal    tol = RollerContactGapTolerance(ctx), *p = stage->p, *d = stage->d;
  PetscReal          dmax = 0.0, reach;

  PetscFunctionBeginUser;
  PetscCall(RollerContactSetTime(ctx, c, t));
  st->resolves = 0;
  PetscCall(RollerContactGather(c, stage->x_cur, c->nodes.red1));
  PetscCall(RollerContactGather(c, stage->x_aux, c->nodes.red2));
  PetscCall(VecGetArrayRead(c->nodes.red1, &u1));
  PetscCall(VecGetArrayRead(c->nodes.red2, &u2));
  for (PetscInt i = 0; i < c->nodes.nc; ++i) {
    const PetscReal d0 = d[0] * PetscRealPart(u1[2 * i]) + d[1] * PetscRealPart(u2[2 * i]), d1 = d[0] * PetscRealPart(u1[2 * i + 1]) + d[1] * PetscRealPart(u2[2 * i + 1]);

    dmax = PetscMax(dmax, PetscSqrtReal(PetscSqr(d0) + PetscSqr(d1)));
  }
  reach = c->opt.margin + PetscAbsReal(st->g - RollerObstacleHeight(ctx, stage->t_cur)) + 2.0 * dmax;
  PetscCall(RollerContactGapsAt(ctx, c, c->nodes.red1, stage->t_cur, st->gap)); /* gaps of x_cur; st->gap is scratch until the solve */
  for (PetscInt i = 0; i < c->nodes.nc; ++i) {
    const PetscReal p0 = p[0] * PetscRealPart(u1[2 * i]) + p[1] * PetscRealPart(u2[2 * i]), p1 = p[0] * PetscRealPart(u1[2 * i + 1]) + p[1] * PetscRealPart(u2[2 * i + 1]);

    st->is_cand[i]     = (p0 * st->normal[0] + p1 * st->normal[1] - st->lower[i] <= reach) ? PETSC_TRUE : PETSC_FALSE;
    st->on_obstacle[i] = st->gap[i] <= tol ? PETSC_TRUE : PETSC_FALSE;
  }
  PetscCall(VecRestoreArrayRead(c->nodes.red1, &u1));
  PetscCall(VecRestoreArrayRead(c->nodes.red2, &u2));
  CandidateList(c);
  PetscFunctionReturn(0);
}

/* After a solve, with c->step.gap holding the gaps of ALL Gamma_C nodes: every non-candidate that penetrates
   (gap < -tol) joins the candidate set; added = how many did. */
PetscErrorCode RollerContactAddPenetrating(Roller ctx, RollerContact c, PetscInt *added)
{
  const PetscReal tol = RollerContactGapTolerance(ctx);

  PetscFunctionBeginUser;
  *added = 0;
  for (PetscInt i = 0; i < c->nodes.nc; ++i)
    if (!c->step.is_cand[i] && c->step.gap[i] < -tol) {
      c->step.is_cand[i] = PETSC_TRUE;
      (*added)++;
    }
  if (*added) CandidateList(c);
  PetscFunctionReturn(0);
}
