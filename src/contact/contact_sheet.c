/* The sheet's own motion (-sheet_mass, docs/model.md section 10.1, docs/friction.md): the sheet a rigid body of mass m per
   unit width moving along e1, driven by the friction of the roller and held back by the stack or the separation pad,
   a Coulomb element of strength F_r (-sheet_resistance) on its own position X. In the three-level step the friction
   pairs with the slip Delta s_n = s_n^k - s_n^{k-2} - (X^k - X^{k-2}) and the sheet's equation is
     m (X^k - 2 X^{k-1} + X^{k-2})/dt^2 = T^k + R^k,   T^k = -sum_n lambda_T,n (the friction on the sheet),
   R^k the resistance: -F_r s if the sheet slides in the direction s (sign of X^k - X^{k-2}), |R^k| <= F_r if it is held
   (X^k = X^{k-2}: no displacement over the step's pair of intervals, the pairing of the friction's). Sliding, X^k =
   X_f - dt^2/m sum_n lambda_T,n, X_f = 2 X^{k-1} - X^{k-2} - dt^2/m F_r s: the slips gain the compliance dt^2/m between
   every two contact nodes' tangential multipliers (a rank-one term of the condensed problem, contact_friction.c) and
   the free advance X_f - X^{k-2}. Held, the sheet does not move. The three cases (slide forward, held, slide back) are
   exclusive: the step is solved in the sheet's last case, checked, and solved again in the consistent one (at most
   twice more). Energy: the sheet's kinetic energy m/2 ((X^k - X^{k-1})/dt)^2 is part of E (as the roller's, the
   three-level form), the resistance dissipates F_r |X^k - X^{k-2}|/2 (in friction_work), and the sheet no longer does
   work from outside (sheet_work: only its approach). */
#include "contact_impl.h"

PetscErrorCode RollerContactSheetSetUp(Roller ctx, RollerContact c)
{
  RollerContactSheet *sh = &c->sheet;
  const PetscReal     V = ctx->obstacle.sheet_speed, dt = ctx->ts.dt;

  PetscFunctionBeginUser;
  sh->mass       = ctx->obstacle.sheet_mass;
  sh->resistance = ctx->obstacle.sheet_resistance;
  if (sh->mass <= 0) PetscFunctionReturn(0);
  /* the levels X^0, X^{-1}, X^{-2} of a sheet at -sheet_speed (0: at rest); a restart reads the checkpoint's */
  sh->X[0] = 0.0;
  sh->X[1] = -V * dt;
  sh->X[2] = -2.0 * V * dt;
  sh->X[3] = V > 0 ? 1.0 : (V < 0 ? -1.0 : 0.0);
  PetscFunctionReturn(0);
}

PetscBool RollerContactSheetMoves(RollerContact c)
{
  return (PetscBool)(c && c->sheet.mass > 0);
}

/* For the step from the levels X^{k-1} = X[0], X^{k-2} = X[1] in the sheet's current case: its advance X^k - X^{k-2}
   without the friction (held: 0) and its compliance dt^2/m to the tangential multipliers (held: 0). */
void RollerContactSheetFree(Roller ctx, RollerContact c, PetscReal *dX, PetscReal *compliance)
{
  const RollerContactSheet *sh = &c->sheet;
  const PetscReal           dt = ctx->ts.dt;

  if (sh->X[3] == 0.0) {
    *dX         = 0.0;
    *compliance = 0.0;
    return;
  }
  *compliance = dt * dt / sh->mass;
  *dX         = (2.0 * sh->X[0] - sh->X[1] - *compliance * sh->resistance * sh->X[3]) - sh->X[1];
}

/* After the step's solve with the tangential multipliers lt[]: the sheet's X^k in its case, and whether that case holds;
   if it does, the levels move up (X[0] = X^k) and the resistance's dissipation is kept; if not, the case to solve the
   step again in. */
PetscErrorCode RollerContactSheetAccept(Roller ctx, RollerContact c, const PetscReal lt[], PetscBool *holds)
{
  RollerContactSheet *sh = &c->sheet;
  const PetscReal     dt = ctx->ts.dt;
  PetscReal           T  = 0.0, Xk, dX, compliance;

  PetscFunctionBeginUser;
  for (PetscInt i = 0; i < c->nodes.nc; ++i) T -= lt ? lt[i] : 0.0;
  RollerContactSheetFree(ctx, c, &dX, &compliance);
  Xk = sh->X[1] + dX + compliance * T;
  if (sh->X[3] != 0.0) {
    *holds = (PetscBool)(sh->X[3] * (Xk - sh->X[1]) >= 0.0);
    if (!*holds) sh->X[3] = 0.0; /* it would slide backwards: held */
  } else {
    const PetscReal R = -2.0 * sh->mass * (sh->X[0] - sh->X[1]) / (dt * dt) - T; /* the holding force the step needs */

    *holds = (PetscBool)(PetscAbsReal(R) <= sh->resistance);
    if (!*holds) sh->X[3] = R < 0 ? 1.0 : -1.0; /* the resistance gives way: it slides where the rest pulls it */
  }
  if (!*holds) PetscFunctionReturn(0);
  sh->dissipation = 0.5 * sh->resistance * PetscAbsReal(Xk - sh->X[1]);
  sh->X[2]        = sh->X[1];
  sh->X[1]        = sh->X[0];
  sh->X[0]        = Xk;
  PetscFunctionReturn(0);
}

/* The sheet's part of E^k (three-level: (X^k - X^{k-1})/dt), its speed, the levels' addresses for the checkpoint (X^k,
   X^{k-1}, X^{k-2} and its case: 4 reals). */
PetscReal RollerContactSheetEnergy(Roller ctx, RollerContact c)
{
  const PetscReal d = c->sheet.X[0] - c->sheet.X[1];

  return RollerContactSheetMoves(c) ? 0.5 * c->sheet.mass * d * d / (ctx->ts.dt * ctx->ts.dt) : 0.0;
}

PetscReal RollerContactSheetSpeed(Roller ctx, RollerContact c)
{
  return RollerContactSheetMoves(c) ? (c->sheet.X[0] - c->sheet.X[1]) / ctx->ts.dt : ctx->obstacle.sheet_speed;
}

PetscReal *RollerContactSheetState(RollerContact c)
{
  return RollerContactSheetMoves(c) ? c->sheet.X : NULL;
}
