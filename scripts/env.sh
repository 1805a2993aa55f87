# Sourced by the scripts: lets OpenMPI run as root (CI and these machines run as root) and
# keeps OpenMP threads from oversubscribing the MPI ranks.
export OMPI_ALLOW_RUN_AS_ROOT=1
export OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
export OMPI_MCA_rmaps_base_oversubscribe=1
# Parallel build and test jobs: every core this process may use. GNU nproc also honours
# OMP_NUM_THREADS and OMP_THREAD_LIMIT, so it would answer 1 once the line below is in force
# (or whenever the caller has set them); those are about threads per rank, not about jobs.
export BIPOT_JOBS="${BIPOT_JOBS:-$(env -u OMP_NUM_THREADS -u OMP_THREAD_LIMIT nproc)}"
export OMP_NUM_THREADS="${OMP_NUM_THREADS:-1}"
