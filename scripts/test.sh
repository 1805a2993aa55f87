#!/usr/bin/env bash
# Sets everything up (scripts/setup.sh) and runs the whole test suite with CTest.
# Usage: scripts/test.sh [--sanitize] [ctest arguments]      e.g. scripts/test.sh -R contact
#   --sanitize  the suite built with AddressSanitizer + UndefinedBehaviorSanitizer (Debug at
#               -O1) in build-sanitize/ (or SANITIZE_BUILD_DIR), run with the options of
#               scripts/sanitize_env.sh (docs/testing.md)
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
source "$root/scripts/env.sh"
if [ "${1:-}" = "--sanitize" ]; then
  shift
  export BUILD_DIR="${SANITIZE_BUILD_DIR:-$root/build-sanitize}" BUILD_TYPE=Debug
  export BIPOT_SANITIZE=address,undefined
  source "$root/scripts/sanitize_env.sh"
fi
"$root/scripts/setup.sh"
cd "${BUILD_DIR:-$root/build}"
ctest --output-on-failure -j "$BIPOT_JOBS" "$@"
