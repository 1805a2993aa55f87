// Restart from a checkpoint written at a stage end (StaticAnalysis::save_state, checkpoint
// files): the continued run gives the uninterrupted run's results to 1e-12 — every reaction,
// interface resultant and β of every later increment, and the final displacements — at this
// rank count, and from a checkpoint written at another rank count (BIPOT_RESTART_FROM names
// it; CTest runs 1 → 2 and 2 → 1). The model carries every kind of state: σ0 changed by a
// displacement reset, RCCM adhesion β, slips, multipliers, a law changed by a stage.
// Checkpoints of another input, of another format and non-checkpoint files are refused.
#include "fem/analysis/checkpoint.hpp"
#include "fem/analysis/model.hpp"
#include "fem/analysis/static_analysis.hpp"
#include "fem/core/error.hpp"
#include "fem/input/problem_reader.hpp"
#include "fem/linalg/communicator.hpp"
#include "tests/support/block_stage.hpp"
#include "tests/support/block_step_row.hpp"
#include "tests/support/model_from_text.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace bipot {
namespace {

using test::block_stage;

const std::string input =
    test::block_on_rccm_joint("{type: linear_elastic, youngs_modulus: 2.0e4, poissons_ratio: 0.25}",
                              "{type: generalized_newton, tolerance: 1.0e-13}") +
    // The planned increments (12 rows), no energy halvings (on by default).
    block_stage("press", 0, -1e-3, "    reset_displacements: true\n    energy_tolerance: 0\n") +
    block_stage("shear", 2e-3, 0, "    energy_tolerance: 0\n") +
    block_stage("shear_more", 6e-3, 0,
                "    energy_tolerance: 0\n"
                "    interfaces: {joint: {parameters: {friction_coefficient: 0.5}}}\n") +
    block_stage("lift", 6e-3, 2e-3, "    energy_tolerance: 0\n");

constexpr std::size_t saved_after = 2; // stages

struct Steps {
  std::vector<std::vector<double>> rows; ///< per increment: reactions, resultant, min β, energies
  std::vector<double> u;                 ///< final displacement
};

Steps record(StaticAnalysis& analysis) {
  Steps out;
  analysis.run([&](const StepReport& r) {
    // The energy balance continues too (its totals are cumulative since the start).
    out.rows.push_back(test::block_step_row(analysis, r));
  });
  out.u = analysis.displacement();
  return out;
}

// `continued` (the increments after the checkpoint) against the tail of `whole`, each column
// to 1e-12 of its largest magnitude over the whole run.
void expect_continues(const Steps& whole, const Steps& continued, const std::string& what) {
  ASSERT_LT(continued.rows.size(), whole.rows.size()) << what;
  ASSERT_GT(continued.rows.size(), 0u) << what;
  const std::size_t skip = whole.rows.size() - continued.rows.size();
  EXPECT_EQ(whole.rows[skip][0], double(saved_after)) << what; // the first stage after it
  for (std::size_t c = 0; c < whole.rows[0].size(); ++c) {
    double scale = 0;
    for (const auto& row : whole.rows)
      scale = std::max(scale, std::abs(row[c]));
    for (std::size_t k = 0; k < continued.rows.size(); ++k)
      EXPECT_NEAR(continued.rows[k][c], whole.rows[skip + k][c], 1e-12 * scale)
          << what << ": increment " << skip + k + 1 << ", column " << c;
  }
  double scale = 0, diff = 0;
  for (std::size_t i = 0; i < whole.u.size(); ++i) {
    scale = std::max(scale, std::abs(whole.u[i]));
    diff = std::max(diff, std::abs(continued.u[i] - whole.u[i]));
  }
  EXPECT_LE(diff, 1e-12 * scale) << what;
}

TEST(Restart, ContinuesLikeTheUninterruptedRun) {
  const Model model = bipot::test::model_from_text(input, "restart.yaml");
  const std::uint64_t hash = input_hash(model.spec, input);
  StateArrays saved;
  StaticAnalysis* whole_run = nullptr;
  AnalysisOptions options;
  options.on_stage_end = [&](std::size_t done, double time) {
    if (done == saved_after) saved = whole_run->save_state(done, time);
  };
  StaticAnalysis whole_analysis(model, options);
  whole_run = &whole_analysis;
  const Steps whole = record(whole_analysis);
  ASSERT_EQ(whole.rows.size(), 12u);
  // The model exercises what a checkpoint must carry: β fell during the shear.
  ASSERT_LT(whole.rows[5].back(), 1.0);

  // Through a file, as the apps do: rank 0 writes, every rank reads.
  const std::string file = "restart_test_np" + std::to_string(mpi_size()) + ".ckp";
  if (mpi_rank() == 0) write_checkpoint(file, hash, saved);
  barrier();
  StaticAnalysis restarted(model);
  restarted.load_state(read_checkpoint(file, hash));
  expect_continues(whole, record(restarted), "restart at " + std::to_string(mpi_size()) + " ranks");

  // From another rank count's checkpoint.
  if (const char* other = std::getenv("BIPOT_RESTART_FROM")) {
    StaticAnalysis across(model);
    across.load_state(read_checkpoint(other, hash));
    expect_continues(whole, record(across), std::string("restart from ") + other);
  }
}

// The reason of a refusal, or "" if the file is accepted.
std::string refusal(const std::string& file, std::uint64_t hash) {
  try {
    read_checkpoint(file, hash);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(Restart, RefusesAnotherInputAVersionOrANonCheckpointWithTheReason) {
  const std::string file = "refused_np" + std::to_string(mpi_size()) + ".ckp";
  const StateArrays state = {{"a", {1.0, 2.0}}};
  const std::uint64_t hash = content_hash("input");
  if (mpi_rank() == 0) write_checkpoint(file, hash, state);
  barrier();
  EXPECT_EQ(refusal(file, hash), "");
  EXPECT_EQ(read_checkpoint(file, hash), state);
  EXPECT_NE(refusal(file, content_hash("input changed")).find("written for another input"),
            std::string::npos);
  barrier();
  if (mpi_rank() == 0) {
    // Another format version (the u32 after the 8-byte magic) and another bipot version.
    std::fstream f(file, std::ios::in | std::ios::out | std::ios::binary);
    const std::uint32_t v = checkpoint_format_version + 1;
    f.seekp(8);
    f.write(reinterpret_cast<const char*>(&v), sizeof v);
  }
  barrier();
  EXPECT_NE(
      refusal(file, hash).find("format version " + std::to_string(checkpoint_format_version + 1)),
      std::string::npos);
  barrier();
  if (mpi_rank() == 0) {
    std::fstream f(file, std::ios::in | std::ios::out | std::ios::binary);
    const std::uint32_t v = checkpoint_format_version;
    f.seekp(8);
    f.write(reinterpret_cast<const char*>(&v), sizeof v);
    f.seekp(16); // first character of the version string
    f.put('9');
  }
  barrier();
  EXPECT_NE(refusal(file, hash).find("written by bipot 9"), std::string::npos);
  barrier();
  if (mpi_rank() == 0) std::ofstream(file) << "stage,step\n1,1\n";
  barrier();
  EXPECT_NE(refusal(file, hash).find("not a checkpoint file"), std::string::npos);
  barrier();
  if (mpi_rank() == 0) {
    write_checkpoint(file, hash, state);
    std::filesystem::resize_file(file, std::filesystem::file_size(file) - 4);
  }
  barrier();
  EXPECT_NE(refusal(file, hash).find("truncated"), std::string::npos);
}

} // namespace
} // namespace bipot
