/* What the unit tests share: a Roller made through the public life cycle from a small scene. */
#ifndef ROLLER_UNIT_H
#define ROLLER_UNIT_H

#include <roller.h>

/* Set each option of scene[] (name, value; value NULL for a flag) unless the command line gives it, then create,
   set from options and set up a Roller. One per process: RollerCreate registers the log stages. */
static inline PetscErrorCode RollerUnitSetUp(const char *const scene[][2], size_t n, Roller *ctx)
{
  PetscFunctionBeginUser;
  for (size_t i = 0; i < n; ++i) {
    PetscBool set;

    PetscCall(PetscOptionsHasName(NULL, NULL, scene[i][0], &set));
    if (!set) PetscCall(PetscOptionsSetValue(NULL, scene[i][0], scene[i][1]));
  }
  PetscCall(RollerCreate(PETSC_COMM_WORLD, ctx));
  PetscCall(RollerSetFromOptions(*ctx));
  PetscCall(RollerSetUp(*ctx));
  PetscFunctionReturn(0);
}

#define ROLLER_UNIT_COUNT(a) (sizeof(a) / sizeof((a)[0]))

/* The free annulus at rest on a coarse mesh (-mesh_h 0.1, -ts_dt 0.01, -omega 0 unless given): the set-up the
   kernel and geometry tests check. */
static inline PetscErrorCode RollerUnitAnnulus(Roller *ctx)
{
  const char *const scene[][2] = {
    {"-mesh_h", "0.1" },
    {"-ts_dt",  "0.01"},
    {"-omega",  "0"   }
  };

  PetscFunctionBeginUser;
  PetscCall(RollerUnitSetUp(scene, ROLLER_UNIT_COUNT(scene), ctx));
  PetscFunctionReturn(0);
}

#endif
