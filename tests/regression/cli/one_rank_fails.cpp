// A job in which the last rank fails alone while the others wait in a collective call: the
// apps' error handling (apps/common/app_support.hpp) must end every rank with the message and
// a non-zero exit code instead of leaving the others waiting (tests/regression/CMakeLists.txt).
#include "apps/common/app_support.hpp"

#include "fem/linalg/communicator.hpp"
#include "fem/linalg/parallel_environment.hpp"

int main(int argc, char** argv) {
  bipot::ParallelEnvironment env(argc, argv);
  return bipot::app::run_guarded("one_rank_fails", [&] {
    if (env.rank() == env.size() - 1) throw bipot::Error("a failure on the last rank only");
    bipot::barrier();
    return 0;
  });
}
