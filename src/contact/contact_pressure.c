/* The contact output fields (docs/contact.md, "Contact pressure"; docs/friction.md): the accepted normal and
   tangential multipliers as tractions at the Gamma_C vertices, and the stick/slip state there. */
#include "contact_impl.h"

/* The contact pressure at the Gamma_C vertices (output field contact_pressure, docs/contact.md). The multipliers
   are nodal forces, lambda_n = int_{Gamma_C} p phi_n ds for a normal traction p. With h_v the P1 hat function
   of vertex v on the polygon of the Gamma_C vertices, the lumped L2 projection of the traction onto P1 is
     p_v = sum_n lambda_n h_v(x_n) / int h_v ds,   int h_v ds = half the lengths of the two polygon edges at v:
   for P1 the nodal force over its tributary length; for P2 an edge midpoint gives half its force to each end
   of its edge. The trapezoidal integral of p over the polygon, sum_v p_v int h_v ds, is then exactly
   sum_n lambda_n, the contact force. p is a global Vec of a P1 scalar space on (a clone of) the mesh; on return
   it holds p_v at every Gamma_C vertex and 0 everywhere else. */
static PetscErrorCode VertexField(Roller ctx, RollerContact c, const PetscReal lambda[], PetscBool lumped, Vec p)
{
  PetscReal   *force, *trib;
  PetscScalar *pa;
  PetscInt     first = -1, rstart;
  DM           dm;
  PetscSection gsection;

  PetscFunctionBeginUser;
  PetscCall(VecGetDM(p, &dm));
  PetscCheck(dm, ctx->comm, PETSC_ERR_ARG_WRONG, "The contact pressure Vec needs a DM (a P1 scalar space on the mesh)");
  PetscCall(DMGetGlobalSection(dm, &gsection));
  PetscCall(VecGetOwnershipRange(p, &rstart, NULL));
  PetscCall(PetscCalloc2(c->nodes.nc, &force, c->nodes.nc, &trib));
  for (PetscInt i = 0; i < c->nodes.nc && first < 0; ++i)
    if (c->nodes.is_vertex[i]) first = i;
  PetscCheck(first >= 0, ctx->comm, PETSC_ERR_PLIB, "Gamma_C has no vertex");
  /* walk the polygon edge by edge: from vertex v to the next vertex w (cyclic, angle order), the nodes between */
  for (PetscInt v = first, walked = 0; walked < c->nodes.nc;) {
    PetscInt  w = (v + 1) % c->nodes.nc, len;
    PetscReal L;

    while (!c->nodes.is_vertex[w]) w = (w + 1) % c->nodes.nc;
    len = w > v ? w - v : w + c->nodes.nc - v;
    L   = PetscSqrtReal(PetscSqr(c->nodes.xc[2 * w] - c->nodes.xc[2 * v]) + PetscSqr(c->nodes.xc[2 * w + 1] - c->nodes.xc[2 * v + 1]));
    PetscCheck(L > 0.0, ctx->comm, PETSC_ERR_PLIB, "Gamma_C edge of zero length");
    force[v] += lambda[v];
    trib[v] += 0.5 * L;
    trib[w] += 0.5 * L;
    for (PetscInt j = 1; j < len; ++j) { /* P2: the edge midpoint */
      const PetscInt  m  = (v + j) % c->nodes.nc;
      const PetscReal hv = PetscSqrtReal(PetscSqr(c->nodes.xc[2 * w] - c->nodes.xc[2 * m]) + PetscSqr(c->nodes.xc[2 * w + 1] - c->nodes.xc[2 * m + 1])) / L;

      force[v] += hv * lambda[m];
      force[w] += (1.0 - hv) * lambda[m];
    }
    walked += len;
    v = w;
  }
  PetscCall(VecZeroEntries(p));
  PetscCall(VecGetArray(p, &pa));
  for (PetscInt k = 0; k < c->nodes.nown; ++k) {
    const PetscInt i = c->nodes.own_node[k];
    PetscInt       dof, off;

    if (!c->nodes.is_vertex[i]) continue;
    PetscCall(PetscSectionGetDof(gsection, c->nodes.own_point[k], &dof));
    PetscCall(PetscSectionGetOffset(gsection, c->nodes.own_point[k], &off));
    PetscCheck(dof == 1 && off >= rstart, PETSC_COMM_SELF, PETSC_ERR_ARG_WRONG, "The contact pressure Vec is not a P1 scalar space with the mesh's partition (vertex %" PetscInt_FMT ": %" PetscInt_FMT " dofs at %" PetscInt_FMT ")", c->nodes.own_point[k], dof, off);
    pa[off - rstart] = lumped ? force[i] / trib[i] : lambda[i];
  }
  PetscCall(VecRestoreArray(p, &pa));
  PetscCall(PetscFree2(force, trib));
  PetscFunctionReturn(0);
}

/* The contact pressure (the normal multipliers), and with friction the tangential traction along e1 (the
   tangential multipliers, the same lumped projection) and the state of every vertex (0 off the sheet, 1
   stick, 2 slip); traction and state may be NULL. */
PetscErrorCode RollerContactFields(Roller ctx, RollerContact c, Vec pressure, Vec traction, Vec state)
{
  PetscReal *st;

  PetscFunctionBeginUser;
  PetscCall(VertexField(ctx, c, c->acc.result.lambda, PETSC_TRUE, pressure));
  if (traction) PetscCall(VertexField(ctx, c, c->acc.result.lambda_t, PETSC_TRUE, traction));
  if (state) {
    PetscCall(PetscMalloc1(c->nodes.nc, &st));
    PetscCall(RollerContactFrictionState(c, st));
    PetscCall(VertexField(ctx, c, st, PETSC_FALSE, state));
    PetscCall(PetscFree(st));
  }
  PetscFunctionReturn(0);
}

PetscBool RollerContactHasFriction(RollerContact c)
{
  return c && c->friction ? PETSC_TRUE : PETSC_FALSE;
}

/* The last solve's multipliers of every Gamma_C node (the same on every rank), which the next solve's friction starts
   from: a part of the run's state for the checkpoint. */
PetscErrorCode RollerContactMultipliers(RollerContact c, PetscInt *nc, PetscReal **lambda, PetscReal **lambda_t)
{
  PetscFunctionBeginUser;
  *nc       = c->nodes.nc;
  *lambda   = c->acc.result.lambda;
  *lambda_t = c->friction ? c->acc.result.lambda_t : NULL;
  PetscFunctionReturn(0);
}

/* Whether the contact needs its row every step: the friction's dissipation (a cumulative column) or -contact_monitor. */
PetscBool RollerContactWantsRow(RollerContact c)
{
  return c && (c->friction || c->opt.monitor) ? PETSC_TRUE : PETSC_FALSE;
}
