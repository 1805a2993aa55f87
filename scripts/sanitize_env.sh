# Sourced by scripts/test.sh --sanitize and scripts/fuzz.sh: run-time options of the
# sanitizers (docs/testing.md). Options already in the environment come last, so they win.
sanitize_dir="$(cd "$(dirname "${BASH_SOURCE[0]}")/../tests/sanitize" && pwd)"
# - detect_leaks: LeakSanitizer at every exit; third-party leaks (OpenMPI's MPI_Init, ...) are
#   suppressed by name in tests/sanitize/lsan.supp, so a leak in bipot's code still fails.
# - fast_unwind_on_malloc=0: Debian's libraries have no frame pointers, so the fast unwinder
#   stops at their first frame and a leak inside OpenMPI would show no OpenMPI frame to match.
#   It doubles the run time of allocation-heavy tests; without it the suppressions miss.
# - detect_stack_use_after_return, check_initialization_order, strict_init_order: more checks
#   on the project's own code, cheap here.
export ASAN_OPTIONS="halt_on_error=1:detect_leaks=1:fast_unwind_on_malloc=0:detect_stack_use_after_return=1:check_initialization_order=1:strict_init_order=1${ASAN_OPTIONS:+:$ASAN_OPTIONS}"
export LSAN_OPTIONS="suppressions=$sanitize_dir/lsan.supp:print_suppressions=0${LSAN_OPTIONS:+:$LSAN_OPTIONS}"
export UBSAN_OPTIONS="halt_on_error=1:print_stacktrace=1:report_error_type=1${UBSAN_OPTIONS:+:$UBSAN_OPTIONS}"
unset sanitize_dir
