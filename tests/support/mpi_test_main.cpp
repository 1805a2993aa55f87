// GoogleTest main for tests run under mpiexec: one ParallelEnvironment for the whole run,
// output from rank 0 only, and a failure on any rank fails every rank's exit code.
#include "fem/linalg/communicator.hpp"
#include "fem/linalg/parallel_environment.hpp"

#include <gtest/gtest.h>

int main(int argc, char** argv) {
  bipot::ParallelEnvironment env(argc, argv);
  ::testing::InitGoogleTest(&argc, argv);
  if (env.rank() != 0) {
    auto& listeners = ::testing::UnitTest::GetInstance()->listeners();
    delete listeners.Release(listeners.default_result_printer());
  }
  const int local = RUN_ALL_TESTS();
  const bipot::Index failed = bipot::sum_all(static_cast<bipot::Index>(local != 0));
  return failed > 0 ? 1 : 0;
}
