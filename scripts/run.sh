#!/usr/bin/env bash
# Sets everything up (scripts/setup.sh) and runs the main job.
# Usage: scripts/run.sh [INPUT.yaml] [NUMBER_OF_RANKS]
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
source "$root/scripts/env.sh"
"$root/scripts/setup.sh"
input="${1:-$root/inputs/examples/thick_cylinder.yaml}"
ranks="${2:-1}"
bipot="${BUILD_DIR:-$root/build}/apps/bipot/bipot"
cd "$root"
if [ "$ranks" -gt 1 ]; then
  mpiexec -n "$ranks" "$bipot" run "$input"
else
  "$bipot" run "$input"
fi
