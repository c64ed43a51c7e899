static const char help[] = "Roller: a rubber roller (elastic annulus) driven in rotation and pressed by a moving flat\n"
                           "obstacle, in the co-rotating frame, advanced by the energy-conserving discrete Morse flow.\n"
                           "Scenes are YAML options files: roller -options_file jobs/rolling.yaml\n"
                           "Model and options: docs/model.md, docs/options.md.\n\n";

#include <roller.h>
#include <slepcsys.h>

int main(int argc, char **argv)
{
  Roller    roller;
  PetscBool sweep;

  if (RollerOptionsFilesParse(argc, argv)) return 1;    /* a YAML error: the file and the line */
  PetscCall(SlepcInitialize(&argc, &argv, NULL, help)); /* PETSc and SLEPc (-modes) */
  PetscCall(PetscOptionsHasName(NULL, NULL, "-sweep", &sweep));
  if (sweep) PetscCall(RollerSweep(PETSC_COMM_WORLD)); /* many scenes, each a Roller on a sub-communicator */
  else {
    PetscCall(RollerCreate(PETSC_COMM_WORLD, &roller));
    PetscCall(RollerSetFromOptions(roller));
    PetscCall(RollerSetUp(roller));
    PetscCall(RollerSolve(roller));
    PetscCall(RollerDestroy(&roller));
  }
  PetscCall(RollerOptionsCheck(PETSC_COMM_WORLD, PETSC_TRUE)); /* what no solver used: an error (docs/options.md) */
  PetscCall(SlepcFinalize());
  return 0;
}
