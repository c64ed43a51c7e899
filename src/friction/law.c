/* The friction coefficient of the slip speed (docs/friction.md section 1), the one law of the transient's Coulomb
   solves (contact/contact_friction*.c, coulomb.c) and of the steady state and its linearization (modes/). */
#include "friction/friction.h"

/* mu(|v|) = mu + (mu_s - mu) exp(-|v| / v_c), constant mu without -friction_decay (v_c = 0); *dmu its derivative
   in |v| (if dmu) */
PetscReal RollerFrictionLaw(PetscReal mu, PetscReal mu_s, PetscReal v_c, PetscReal v, PetscReal *dmu)
{
  const PetscReal e = v_c > 0 ? PetscExpReal(-PetscAbsReal(v) / v_c) : 0.0;

  if (dmu) *dmu = v_c > 0 ? -(mu_s - mu) / v_c * e : 0.0;
  return mu + (mu_s - mu) * e;
}
