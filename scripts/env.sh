# Sourced by the scripts: lets OpenMPI run as root (CI and these machines run as root) and
# keeps OpenMP threads from oversubscribing the MPI ranks.
export OMPI_ALLOW_RUN_AS_ROOT=1
export OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
export OMPI_MCA_rmaps_base_oversubscribe=1
export OMP_NUM_THREADS="${OMP_NUM_THREADS:-1}"
