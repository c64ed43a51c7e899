# Sourced by the scripts: Open MPI refuses to run as root unless told, and must not bind to more cores
# than the machine has.
export OMPI_ALLOW_RUN_AS_ROOT=1
export OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
export OMPI_MCA_rmaps_base_oversubscribe=1
