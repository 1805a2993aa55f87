#include "apps/common/run_folder.hpp"
#include "tests/support/scratch_dir.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

namespace bipot::app {
namespace {

namespace fs = std::filesystem;
using test::ScratchDir;

ProblemSpec two_stages() {
  ProblemSpec spec;
  spec.file = "model.yaml";
  for (const char* name : {"rest", "shear"}) {
    StageSpec stage;
    stage.name = name;
    spec.stages.push_back(stage);
  }
  return spec;
}

StepReport step(int stage_index, const std::string& stage, int step, double load_factor,
                int global_step) {
  StepReport r;
  r.stage_index = stage_index;
  r.stage = stage;
  r.step = step;
  r.load_factor = load_factor;
  r.global_step = global_step;
  return r;
}

void write(const fs::path& path, const std::string& text) {
  std::ofstream(path) << text;
}

std::string read(const fs::path& path) {
  std::ifstream in(path);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// A finished run into `out` that wrote a.csv = `text`.
void finished_run(const std::string& out, const std::string& text) {
  RunFolder run(out, two_stages(), "test");
  write(fs::path(run.working()) / "a.csv", text);
  run.converged(step(1, "shear", 1, 1.0, 2));
  run.finish();
}

TEST(RunFolder, FinishedRunReplacesTheOldResultsWhole) {
  ScratchDir dir("run_folder");
  const std::string out = (dir.path / "results").string();
  finished_run(out, "old");
  write(fs::path(out) / "stale.csv", "from the old run only");

  RunFolder run(out, two_stages(), "test");
  EXPECT_NE(run.working(), out);
  EXPECT_NE(read(fs::path(run.working()) / "status.txt").find("status: running"),
            std::string::npos);
  EXPECT_EQ(read(fs::path(out) / "a.csv"), "old"); // untouched while the run goes on
  write(fs::path(run.working()) / "a.csv", "new");
  run.finish();

  EXPECT_EQ(read(fs::path(out) / "a.csv"), "new");
  EXPECT_FALSE(fs::exists(fs::path(out) / "stale.csv"));
  EXPECT_NE(read(fs::path(out) / "status.txt").find("status: finished"), std::string::npos);
  int entries = 0;
  for ([[maybe_unused]] const auto& e : fs::directory_iterator(dir.path))
    ++entries;
  EXPECT_EQ(entries, 1);                       // no working or old folder left beside
  EXPECT_EQ(fail_open_run_folder("late"), ""); // nothing open after finish()
}

TEST(RunFolder, FailedRunLeavesTheResultsAndKeepsItsStepsBeside) {
  ScratchDir dir("run_folder");
  const std::string out = (dir.path / "results").string();
  finished_run(out, "good");
  {
    RunFolder run(out, two_stages(), "test");
    write(fs::path(run.working()) / "a.csv", "partial");
    run.converged(step(0, "rest", 1, 1.0, 1));
  } // unwound by the exception, as in run_guarded
  const std::string where = fail_open_run_folder("no convergence\nresidual 0.2");

  EXPECT_EQ(read(fs::path(out) / "a.csv"), "good");
  EXPECT_NE(read(fs::path(out) / "status.txt").find("status: finished"), std::string::npos);
  const fs::path failed = out + ".failed";
  EXPECT_EQ(read(failed / "a.csv"), "partial");
  const std::string status = read(failed / "status.txt");
  EXPECT_NE(status.find("status: failed\n"), std::string::npos) << status;
  EXPECT_NE(status.find("stage: \"shear\"\nstep: 1\n"), std::string::npos) << status;
  EXPECT_NE(status.find("last_converged: \"stage rest, step 1\""), std::string::npos) << status;
  EXPECT_NE(status.find("message: |\n  no convergence\n  residual 0.2\n"), std::string::npos)
      << status;
  EXPECT_NE(where.find(failed.string()), std::string::npos) << where;
  EXPECT_EQ(fail_open_run_folder("again"), "");
}

TEST(RunFolder, FailureDetailsGoToFailureLog) {
  ScratchDir dir("run_folder");
  const std::string out = (dir.path / "results").string();
  {
    RunFolder run(out, two_stages(), "test");
    run.converged(step(0, "rest", 1, 1.0, 1));
  }
  const std::string where =
      fail_open_run_folder("no convergence; history (4 values): 1 ... 0.5", "1 1\n2 0.9\n3 0.7");
  const fs::path log = fs::path(out + ".failed") / "failure.log";
  EXPECT_EQ(read(log), "no convergence; history (4 values): 1 ... 0.5\n\n1 1\n2 0.9\n3 0.7\n");
  EXPECT_NE(where.find(log.string()), std::string::npos) << where;
  // Without details, no failure.log.
  { RunFolder run(out, two_stages(), "test"); }
  fail_open_run_folder("stopped");
  EXPECT_FALSE(fs::exists(log));
}

TEST(RunFolder, FailureWithinAStageNamesItsNextStep) {
  ScratchDir dir("run_folder");
  const std::string out = (dir.path / "results").string();
  {
    RunFolder run(out, two_stages(), "test");
    run.converged(step(1, "shear", 2, 0.5, 3));
  }
  fail_open_run_folder("stopped");
  const std::string status = read(fs::path(out + ".failed") / "status.txt");
  EXPECT_NE(status.find("stage: \"shear\"\nstep: 3\n"), std::string::npos) << status;
  EXPECT_FALSE(fs::exists(out)); // no finished run to keep
}

TEST(RunFolder, RefusesAFolderNoRunWrote) {
  ScratchDir dir("run_folder");
  const fs::path out = dir.path / "my_notes";
  fs::create_directory(out);
  write(out / "notes.txt", "precious");
  try {
    RunFolder run(out.string(), two_stages(), "test");
    FAIL() << "a folder of unrelated files was accepted";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("holds files that no bipot run wrote"), std::string::npos)
        << e.what();
  }
  EXPECT_EQ(read(out / "notes.txt"), "precious");
  int entries = 0;
  for ([[maybe_unused]] const auto& e : fs::directory_iterator(dir.path))
    ++entries;
  EXPECT_EQ(entries, 1); // no working folder was made
}

TEST(RunFolder, ReportsAFolderThatCannotBeCreatedBeforeTheRun) {
  ScratchDir dir("run_folder");
  write(dir.path / "a_file", "");
  try {
    RunFolder run((dir.path / "a_file" / "results").string(), two_stages(), "test");
    FAIL() << "a folder under a file was accepted";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("cannot write the results: cannot create '" +
                                         (dir.path / "a_file").string() + "'"),
              std::string::npos)
        << e.what();
  }
}

// What `bipot check` reports at output.directory: the constructor's refusals, found without
// creating anything (the same function decides both).
TEST(RunFolder, ProblemsAreFoundWithoutCreatingAnything) {
  ScratchDir dir("run_folder");
  write(dir.path / "a_file", "");
  EXPECT_EQ(results_folder_problem((dir.path / "new" / "deeper" / "results").string()), "");
  EXPECT_EQ(results_folder_problem((dir.path / "a_file" / "results").string()),
            "cannot create '" + (dir.path / "a_file").string() + "' (a file of that name exists)");
  EXPECT_EQ(results_folder_problem((dir.path / "a_file" / "sub" / "results").string()),
            "cannot create '" + (dir.path / "a_file" / "sub").string() + "' ('" +
                (dir.path / "a_file").string() + "' is a file)");
  fs::create_directory(dir.path / "my_notes");
  write(dir.path / "my_notes" / "notes.txt", "precious");
  EXPECT_NE(results_folder_problem((dir.path / "my_notes").string())
                .find("holds files that no bipot run wrote"),
            std::string::npos);
  EXPECT_NE(results_folder_problem(".").find("cannot be a results folder"), std::string::npos);
  int entries = 0;
  for ([[maybe_unused]] const auto& e : fs::directory_iterator(dir.path))
    ++entries;
  EXPECT_EQ(entries, 2); // a_file and my_notes: nothing was created
}

TEST(RunFolder, RefusesTheCurrentDirectory) {
  for (const char* out : {".", "./", ".."})
    EXPECT_THROW(RunFolder(out, two_stages(), "test"), Error) << out;
}

} // namespace
} // namespace bipot::app
