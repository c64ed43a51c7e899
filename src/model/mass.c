/* The mass matrix of the Gamma_C dofs (docs/contact.md "Massless contact nodes", docs/model.md section 2):
   -contact_mass, and with "redistributed" the massless contact nodes M_red = T^T M T (T: mass_transfer.c),
   made once at set-up by RollerOperatorsSetUp, with the rigid loads that go with it, T^T L: since T reproduces
   affine fields, M_red x = T^T M x, so b^k and the energy stay consistent. The total mass, centre of mass and
   inertia tensor (the kinetic energy of every affine velocity) are those of M; the Gamma_C rows and columns
   are exactly zero. */
#include "model/model.h"

const char *const RollerContactMasses[] = {"consistent", "redistributed", "RollerContactMass", "ROLLER_CONTACT_MASS_", NULL};

PetscErrorCode RollerMassSetFromOptions(Roller ctx)
{
  PetscFunctionBeginUser;
  ctx->disc.contact_mass = ROLLER_CONTACT_MASS_CONSISTENT;
  PetscOptionsBegin(ctx->comm, NULL, "Roller: mass matrix", NULL);
  PetscCall(PetscOptionsEnum("-contact_mass", "Mass of the Gamma_C nodes: consistent (the FE mass M) or redistributed (M_red = T^T M T: massless Gamma_C nodes, their inertia carried by nearby interior nodes, total mass, centre and inertia kept)", "RollerContactMass", RollerContactMasses,
                             (PetscEnum)ctx->disc.contact_mass, (PetscEnum *)&ctx->disc.contact_mass, NULL));
  PetscOptionsEnd();
  PetscCheck(ctx->disc.contact_mass == ROLLER_CONTACT_MASS_CONSISTENT || !ctx->disc.clamp_outer, ctx->comm, PETSC_ERR_ARG_INCOMP, "-contact_mass redistributed needs free Gamma_C dofs: not with -clamp_outer");
  PetscFunctionReturn(0);
}

/* T for -contact_mass redistributed, NULL for the consistent mass; -log_view event RollerMassTransfer */
PetscErrorCode RollerMassTransfer(Roller ctx, Mat *T)
{
  static PetscLogEvent event = -1;

  PetscFunctionBeginUser;
  *T = NULL;
  if (ctx->disc.contact_mass != ROLLER_CONTACT_MASS_REDISTRIBUTED) PetscFunctionReturn(0);
  if (event < 0) PetscCall(PetscLogEventRegister("RollerMassTransfer", MAT_CLASSID, &event));
  PetscCall(PetscLogEventBegin(event, 0, 0, 0, 0));
  PetscCall(RollerMassTransferCreate(ctx, T));
  PetscCall(PetscLogEventEnd(event, 0, 0, 0, 0));
  PetscFunctionReturn(0);
}

/* B <- T^T B T for a symmetric (sign +1) or skew (sign -1) B, made exactly so: (C + sign C^T)/2 */
PetscErrorCode RollerMassReduce(Mat T, PetscReal sign, Mat *B)
{
  Mat         C, Ct;
  const char *name;

  PetscFunctionBeginUser;
  PetscCall(MatPtAP(*B, T, MAT_INITIAL_MATRIX, 2.0, &C));
  PetscCall(MatTranspose(C, MAT_INITIAL_MATRIX, &Ct));
  PetscCall(MatAXPY(C, sign, Ct, DIFFERENT_NONZERO_PATTERN));
  PetscCall(MatScale(C, 0.5));
  PetscCall(MatDestroy(&Ct));
  PetscCall(PetscObjectGetName((PetscObject)*B, &name));
  PetscCall(PetscObjectSetName((PetscObject)C, name));
  PetscCall(MatDestroy(B));
  *B = C;
  PetscFunctionReturn(0);
}

/* L <- T^T L */
PetscErrorCode RollerMassReduceLoad(Mat T, Vec L)
{
  Vec t;

  PetscFunctionBeginUser;
  PetscCall(VecDuplicate(L, &t));
  PetscCall(MatMultTranspose(T, L, t));
  PetscCall(VecCopy(t, L));
  PetscCall(VecDestroy(&t));
  PetscFunctionReturn(0);
}

/* G <- T^T G T (skew) on the pattern of A, which is widened to hold it: A = A0 - c G must keep one pattern
   (RollerUpdateGyroscopic); A's values are unchanged */
PetscErrorCode RollerMassReducePattern(Mat T, Mat A, Mat *G)
{
  Mat Z;

  PetscFunctionBeginUser;
  PetscCall(RollerMassReduce(T, -1.0, G));
  PetscCall(MatDuplicate(*G, MAT_COPY_VALUES, &Z));
  PetscCall(MatZeroEntries(Z));
  PetscCall(MatAXPY(A, 1.0, Z, DIFFERENT_NONZERO_PATTERN));
  PetscCall(MatDestroy(&Z));
  PetscCall(MatDuplicate(A, MAT_DO_NOT_COPY_VALUES, &Z));
  PetscCall(MatZeroEntries(Z));
  PetscCall(MatAXPY(Z, 1.0, *G, SUBSET_NONZERO_PATTERN));
  PetscCall(PetscObjectSetName((PetscObject)Z, "G"));
  PetscCall(MatDestroy(G));
  *G = Z;
  PetscFunctionReturn(0);
}
