#!/usr/bin/env bash
# scripts/env.sh's job count for builds and ctest is every usable core, even when OpenMP
# variables (which GNU nproc honours, and which env.sh itself sets to 1) limit threads.
set -euo pipefail
cores="$(env -u OMP_NUM_THREADS -u OMP_THREAD_LIMIT nproc)"
jobs="$(env -u BIPOT_JOBS OMP_NUM_THREADS=1 OMP_THREAD_LIMIT=1 \
  bash -c 'source "$1/scripts/env.sh" && echo "$BIPOT_JOBS"' _ "$1")"
if [ "$jobs" != "$cores" ]; then
  echo "BIPOT_JOBS is '$jobs', expected the $cores usable cores" >&2
  exit 1
fi
echo "ok: $jobs jobs"
