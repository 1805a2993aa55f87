#!/usr/bin/env bash
# Sets everything up (scripts/setup.sh) and runs the main job: the pile pull-out with the
# RCCM interface (inputs/pile_pullout/rccm.yaml), results in results/pile_rccm/.
# Usage: scripts/run.sh [INPUT.yaml] [NUMBER_OF_RANKS]
#   inputs/pile_pullout/*.yaml run with the pile_pullout app, other inputs with bipot.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
source "$root/scripts/env.sh"
"$root/scripts/setup.sh"
input="${1:-$root/inputs/pile_pullout/rccm.yaml}"
ranks="${2:-1}"
build="${BUILD_DIR:-$root/build}"
case "$input" in
  *pile_pullout/*) app=("$build/apps/pile_pullout/pile_pullout" run "$input") ;;
  *) app=("$build/apps/bipot/bipot" run "$input") ;;
esac
cd "$root"
if [ "$ranks" -gt 1 ]; then
  mpiexec -n "$ranks" --allow-run-as-root --oversubscribe "${app[@]}"
else
  "${app[@]}"
fi
