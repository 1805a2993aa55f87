#!/usr/bin/env bash
# Sets everything up (scripts/setup.sh) and runs the whole test suite with CTest.
# Usage: scripts/test.sh [--sanitize | --ci] [ctest arguments]    e.g. scripts/test.sh -R contact
#   --sanitize  the suite built with AddressSanitizer + UndefinedBehaviorSanitizer (Debug at
#               -O1) in build-sanitize/ (or SANITIZE_BUILD_DIR), run with the options of
#               scripts/sanitize_env.sh (docs/testing.md)
#   --ci        what .ci/run does (docs/testing.md, "CI"): the format check, the Release build
#               with warnings as errors and the whole suite, then a Debug + ASan + UBSan build
#               of the unit tests and a few verification and CLI tests, which it runs
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
source "$root/scripts/env.sh"

# The sanitized subset of --ci: every unit test at 1 rank, the fuzz corpora, the CLI's input
# checks, the patch test at 1 and 2 ranks and the verification tests that cover the contact
# solvers at 1 rank (docs/testing.md has the times). linalg_tests_np2 is left out: 190 s of
# the 600 the subset took under ASan, for code the np1 run already covers.
ci_sanitize_targets="core_tests materials_tests element_tests contact_laws_tests mesh_tests
  io_tests io_mpi_tests linalg_tests input_tests docs_tables_match_schemas app_support_tests
  contact_interface_tests contact_solver_tests patch_test contact_block_test rccm_pull_test
  interface_declarations_test path_following_test analysis_unit_tests bipot yaml_replay msh_replay
  leak_is_reported"
ci_sanitize_tests='^([a-z_]+_tests(_np1)?|docs_tables_match_schemas|patch_test_np[12]|'
ci_sanitize_tests+='(contact_block|rccm_pull|interface_declarations|path_following)_test_np1|'
ci_sanitize_tests+='fuzz_corpus_(yaml|msh)|cli_check_.*|sanitize_leak_is_reported_np1)$'

sanitized() {
  export BUILD_DIR="${SANITIZE_BUILD_DIR:-$root/build-sanitize}" BUILD_TYPE=Debug
  export BIPOT_SANITIZE=address,undefined
  source "$root/scripts/sanitize_env.sh"
}

if [ "${1:-}" = "--ci" ]; then
  shift
  SECONDS=0
  EXTRA_PACKAGES=clang-format-14 "$root/scripts/setup.sh" --packages-only
  "$root/scripts/check_format.sh" "$root"
  export BIPOT_WERROR=ON
  "$root/scripts/setup.sh"
  (cd "${BUILD_DIR:-$root/build}" && ctest --output-on-failure -j "$BIPOT_JOBS" "$@")
  echo "ci: format check, Release build and suite: $SECONDS s"
  SECONDS=0
  (
    sanitized
    BUILD_TARGETS="$ci_sanitize_targets" "$root/scripts/setup.sh"
    cd "$BUILD_DIR"
    ctest --output-on-failure -j "$BIPOT_JOBS" -R "$ci_sanitize_tests"
  )
  echo "ci: sanitized Debug build and subset: $SECONDS s"
  exit 0
fi
if [ "${1:-}" = "--sanitize" ]; then
  shift
  sanitized
fi
"$root/scripts/setup.sh"
cd "${BUILD_DIR:-$root/build}"
ctest --output-on-failure -j "$BIPOT_JOBS" "$@"
