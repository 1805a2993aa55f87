// `linear_solver: {out_of_core: true}` in the sparse solvers: the rooted MUMPS LU's factors
// in files, and the temporary directory they need (the Schur complement's in
// schur_complement_solver_test.cpp, a whole run in tests/verification/out_of_core_run_test.cpp).
#include "chain_problem.hpp"
#include "fem/core/error.hpp"
#include "fem/linalg/communicator.hpp"
#include "fem/linalg/linear_solver.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

namespace bipot {
namespace {

using test::Chain;
using test::relative_error;

LinearSolverOptions direct_options() {
  LinearSolverOptions o;
  o.method = "direct";
  o.preconditioner = "none";
  return o;
}

// `out_of_core`: the rooted MUMPS LU keeps its factors in files in TMPDIR while the solver
// lives, and solves as the in-memory factors do.
TEST(LinearSolver, OutOfCoreDirectSolveMatchesInMemoryAndRemovesItsFiles) {
  namespace fs = std::filesystem;
  Chain chain;
  const auto dist = chain.distribution();
  SparseMatrix A(dist, chain.pattern(dist));
  chain.assemble(A);
  DistributedVector b(dist), x_memory(dist), x_disk(dist);
  chain.assemble_rhs(b);
  LinearSolver memory(direct_options());
  memory.setup(A);
  memory.solve(b, x_memory);

  const char* old = std::getenv("TMPDIR");
  const std::string saved = old ? old : "";
  const fs::path dir = fs::temp_directory_path() / ("bipot_ooc_direct_" + std::to_string(getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  setenv("TMPDIR", dir.c_str(), 1);
  auto files = [&] { return std::distance(fs::directory_iterator(dir), fs::directory_iterator()); };
  {
    LinearSolverOptions o = direct_options();
    o.out_of_core = true;
    EXPECT_EQ(factor_directory(o), dir.string());
    LinearSolver disk(o);
    disk.setup(A);
    // The matrix is gathered and factorised on rank 0.
    if (mpi_rank() == 0) {
      EXPECT_GT(files(), 0) << "no factor file in " << dir;
    }
    disk.solve(b, x_disk);
  }
  if (saved.empty())
    unsetenv("TMPDIR");
  else
    setenv("TMPDIR", saved.c_str(), 1);
  EXPECT_EQ(files(), 0) << "factor files left in " << dir;
  fs::remove_all(dir);
  EXPECT_LT(relative_error(x_disk, [&](Index i) { return chain.exact(i); }), 1e-12);
  x_disk.axpy(-1.0, x_memory);
  EXPECT_LE(x_disk.norm2(), 1e-14 * x_memory.norm2());
}

// A TMPDIR out_of_core cannot use is reported by name, not left to MUMPS (which would write
// the factors elsewhere or fail later without saying why).
TEST(LinearSolver, OutOfCoreNeedsAUsableTemporaryDirectory) {
  namespace fs = std::filesystem;
  const char* old = std::getenv("TMPDIR");
  const std::string saved = old ? old : "";
  const fs::path base = fs::temp_directory_path() / ("bipot_tmpdir_" + std::to_string(getpid()));
  fs::remove_all(base);
  fs::create_directories(base);
  LinearSolverOptions o;
  o.out_of_core = true;
  auto message = [&] {
    try {
      factor_directory(o);
    } catch (const Error& e) {
      return std::string(e.what());
    }
    return std::string("no exception");
  };
  const fs::path file = base / "a_file";
  std::ofstream(file) << "not a directory";
  setenv("TMPDIR", file.c_str(), 1);
  const std::string not_a_directory = message();
  fs::path deep = base;
  for (int i = 0; i < 3; ++i)
    deep /= std::string(90, 'd');
  fs::create_directories(deep);
  setenv("TMPDIR", deep.c_str(), 1);
  const std::string too_long = message();
  if (saved.empty())
    unsetenv("TMPDIR");
  else
    setenv("TMPDIR", saved.c_str(), 1);
  fs::remove_all(base);
  EXPECT_NE(not_a_directory.find("set TMPDIR to a writable directory"), std::string::npos)
      << not_a_directory;
  EXPECT_NE(too_long.find("longer than the 255 characters"), std::string::npos) << too_long;
  o.out_of_core = false;
  EXPECT_EQ(factor_directory(o), "");
}

} // namespace
} // namespace bipot
