// Runs under the energy step control (stage `energy_tolerance`).
//
// Counting: the halvings the energy budget asks for are reported apart from the convergence
// cut-backs (StepReport::energy_cutbacks beside cutbacks, the CSV flag `cutbacks`, the run
// summary's cut-backs and halvings). On a plastic block sheared and lifted off an RCCM joint
// with at most 6 Newton iterations per attempt (convergence cut-backs) and energy_tolerance
// 1e-4 (energy halvings), every increment's load step is the planned one halved cutbacks +
// energy_cutbacks times (exactly, where it does not stop at a planned level), the energy's
// part grows only by the increment's own energy halvings, and the convergence part's rises
// add up to no more than the run's failed attempts (summary cut-backs). Before, the energy
// halvings counted as cut-backs: the rises of `cutbacks` added up to 15 against 5 failures.
//
// Restarts: continued from a checkpoint file written after an increment the control kept over
// its budget (and so excused), the run gives the uninterrupted run's energy.csv — every
// energy total to 1e-12 of its column's largest magnitude, energy_halvings and
// over_energy_budget exactly — and the same step flags (cutbacks, energy_cutbacks, unstable).
// The model makes the excused error visible: a block sheared off an RCCM joint (α small)
// under a loose energy_tolerance (1e-3, max_cutbacks 1) debonds in a jump, kept over the
// budget, after increments whose within-budget errors are not excused; then it slides on
// (β = 0: no error of its own) under a tight tolerance (1e-6). Its increments are flagged
// over the budget only because of the error carried from the shear, which the control
// must still count after a restart. Before checkpoints saved the control's state, a restart
// excused the whole error it carried: the sliding increments were not flagged, and the
// energy's part of the cut-back level was lost (a restarted step shortened for the energy
// alone was reported cut back and unstable).
//
// Output: `output.every` counts the plan, not the halvings. With every: 2 the VTK series holds
// the even planned levels and the stage ends, and none of the many sub-increments (before, the
// viscous pile at energy_tolerance 1e-6 wrote 600 VTK files, 253 MB, for its 80 planned steps).
#include "apps/catalogue/builtin_catalogue.hpp"
#include "fem/analysis/checkpoint.hpp"
#include "fem/analysis/model.hpp"
#include "fem/analysis/result_writer.hpp"
#include "fem/analysis/static_analysis.hpp"
#include "fem/input/problem_reader.hpp"
#include "tests/support/block_stage.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

namespace bipot {
namespace {

using test::block_stage;

TEST(EnergyControlRun, CountsEnergyHalvingsApartFromCutBacks) {
  const std::string text =
      test::block_on_rccm_joint(
          "{type: von_mises, youngs_modulus: 2.0e4, poissons_ratio: 0.25, yield_stress: 30.0, "
          "hardening_modulus: 2.0e3}",
          "{type: generalized_newton, tolerance: 1.0e-11, max_iterations: 6}") +
      block_stage("press", 0, -2e-3) +
      block_stage("shear", 6e-3, -2e-3, "    energy_tolerance: 1.0e-4\n", 4) +
      block_stage("lift", 8e-3, 1e-3, "    energy_tolerance: 1.0e-4\n", 4) +
      "output: {directory: energy_counts, every: 2}\n";
  std::filesystem::remove_all("energy_counts");
  const Model model = build_model(
      read_problem_text(text, "energy_counts.yaml", builtin_catalogue()), builtin_catalogue());
  ResultWriter writer(model, 0, 1);
  StaticAnalysis analysis(model, {}, &writer);
  int due = 0, planned_due = 0, sub_increments = 0;
  std::string stage;
  double lambda = 0;
  int cutbacks = 0, energy_cutbacks = 0, rises = 0, halvings = 0;
  const RunSummary summary = analysis.run([&](const StepReport& r) {
    if (r.stage != stage) stage = r.stage, lambda = 0, cutbacks = 0, energy_cutbacks = 0;
    const double step = 1.0 / r.steps / std::pow(2.0, r.cutbacks + r.energy_cutbacks);
    const bool stop = r.planned_step > 0 || r.requested_output || r.stage_end;
    if (!stop) {
      EXPECT_NEAR(r.load_factor - lambda, step, 1e-12) << r.stage << " step " << r.step;
    } else {
      EXPECT_LE(r.load_factor - lambda, step + 1e-12) << r.stage << " step " << r.step;
    }
    EXPECT_LE(r.energy_cutbacks - energy_cutbacks, r.energy_halvings)
        << r.stage << " step " << r.step;
    due += r.stage_end || (r.planned_step > 0 && r.planned_step % 2 == 0);
    sub_increments += r.planned_step == 0;
    if (r.stage_end) planned_due += r.steps / 2 + r.steps % 2; // even levels, and the end
    rises += std::max(r.cutbacks - cutbacks, 0);
    halvings += r.energy_halvings;
    lambda = r.load_factor, cutbacks = r.cutbacks, energy_cutbacks = r.energy_cutbacks;
  });
  // Both kinds happened, each counted once.
  EXPECT_GT(summary.cutbacks, 0);
  EXPECT_GT(summary.energy_halvings, summary.cutbacks);
  EXPECT_EQ(halvings, summary.energy_halvings);
  EXPECT_LE(rises, summary.cutbacks);
  std::printf("%d cut-backs (level rises %d), %d energy halvings\n", summary.cutbacks, rises,
              summary.energy_halvings);
  // The VTK series: the even planned levels and the stage ends (press has one increment).
  int vtk_files = 0;
  for (const auto& entry : std::filesystem::directory_iterator("energy_counts")) {
    const std::string name = entry.path().filename().string();
    vtk_files += name.rfind("solution_", 0) == 0 && entry.path().extension() == ".vtu";
  }
  EXPECT_GT(sub_increments, 10); // the halvings made many
  EXPECT_EQ(due, planned_due);   // every planned level reported
  EXPECT_EQ(due, 6);             // press 2/3 and 3/3, shear and lift 2/4 and 4/4
  EXPECT_EQ(vtk_files, due);
}

const std::string input =
    test::block_on_rccm_joint(
        "{type: linear_elastic, youngs_modulus: 2.0e4, poissons_ratio: 0.25}",
        "{type: generalized_newton, tolerance: 1.0e-11, max_iterations: 25, max_cutbacks: 1}") +
    block_stage("press", 0, -2e-3, "", 2) +
    block_stage("shear", 12e-3, -2e-3, "    energy_tolerance: 1.0e-3\n", 12) +
    block_stage("slide", 14e-3, -2e-3, "    energy_tolerance: 1.0e-6\n", 2);

// One increment as energy.csv and the step flags hold it.
struct Row {
  std::string stage;
  std::vector<double> energy; ///< the totals, balance_error, relative_error
  int energy_halvings = 0, cutbacks = 0, energy_cutbacks = 0;
  bool over_energy_budget = false, unstable = false;
};

std::vector<Row> record(StaticAnalysis& analysis) {
  std::vector<Row> rows;
  analysis.run([&](const StepReport& r) {
    const EnergyTotals& e = r.energy;
    rows.push_back({r.stage,
                    {e.external_work, e.interference_work, e.bulk_energy, e.interface_energy,
                     e.adhesion_dissipation, e.viscous_dissipation, e.contact_work,
                     e.balance_error(), e.relative_error()},
                    r.energy_halvings,
                    r.cutbacks,
                    r.energy_cutbacks,
                    r.over_energy_budget,
                    r.unstable});
  });
  return rows;
}

void expect_continues(const std::vector<Row>& whole, const std::vector<Row>& continued,
                      std::size_t skip, const std::string& what) {
  ASSERT_EQ(continued.size(), whole.size() - skip) << what;
  for (std::size_t c = 0; c < whole[0].energy.size(); ++c) {
    double scale = 0;
    for (const Row& row : whole)
      scale = std::max(scale, std::abs(row.energy[c]));
    for (std::size_t k = 0; k < continued.size(); ++k)
      EXPECT_NEAR(continued[k].energy[c], whole[skip + k].energy[c], 1e-12 * scale)
          << what << ": increment " << skip + k + 1 << ", energy column " << c;
  }
  for (std::size_t k = 0; k < continued.size(); ++k) {
    const Row &a = continued[k], &b = whole[skip + k];
    const std::string at = what + ": increment " + std::to_string(skip + k + 1);
    EXPECT_EQ(a.over_energy_budget, b.over_energy_budget) << at;
    EXPECT_EQ(a.energy_halvings, b.energy_halvings) << at;
    EXPECT_EQ(a.cutbacks, b.cutbacks) << at;
    EXPECT_EQ(a.energy_cutbacks, b.energy_cutbacks) << at;
    EXPECT_EQ(a.unstable, b.unstable) << at;
  }
}

TEST(EnergyControlRun, RestartsWithTheExcusedErrorAndTheEnergysCutBackLevel) {
  const Model model = build_model(
      read_problem_text(input, "energy_restart.yaml", builtin_catalogue()), builtin_catalogue());
  struct Saved {
    std::size_t increments; ///< converged before it
    std::string what;
    StateArrays state;
  };
  std::vector<Saved> saved;
  StaticAnalysis* whole_run = nullptr;
  std::size_t increments = 0;
  AnalysisOptions options;
  // Within the shear at every planned level after the first increment kept over the budget
  // (where some still carry the energy's halving), and at its end.
  bool kept_over = false;
  options.on_increment_end = [&](const StepReport& r) {
    ++increments;
    kept_over = kept_over || r.over_energy_budget;
    if (r.stage == "shear" && kept_over && r.planned_step > 0 && !r.stage_end)
      saved.push_back({increments, "shear step " + std::to_string(r.planned_step),
                       whole_run->save_step_state()});
  };
  options.on_stage_end = [&](std::size_t done, double time) {
    if (done == 2)
      saved.push_back({increments, "the end of shear", whole_run->save_state(done, time)});
  };
  StaticAnalysis whole_analysis(model, options);
  whole_run = &whole_analysis;
  const std::vector<Row> whole = record(whole_analysis);

  // What the checkpoints must carry: an excused error, and a step still shortened for the
  // energy alone.
  ASSERT_GE(saved.size(), 2u);
  EXPECT_TRUE(std::any_of(saved.begin(), saved.end(), [&](const Saved& s) {
    return whole[s.increments].energy_cutbacks > 0 && whole[s.increments].stage == "shear";
  }));
  // The sliding increments: inside their own share (|Δ balance_error| ≤ 1e-6 × the work they
  // put in), yet over the budget for the error the shear left unexcused.
  int slide = 0;
  for (std::size_t k = 1; k < whole.size(); ++k) {
    if (whole[k].stage != "slide") continue;
    ++slide;
    const double own = whole[k].energy[7] - whole[k - 1].energy[7];
    const double put_in = whole[k].energy[0] - whole[k - 1].energy[0];
    EXPECT_LE(std::abs(own), 1e-6 * std::abs(put_in)) << "increment " << k + 1;
    EXPECT_TRUE(whole[k].over_energy_budget) << "increment " << k + 1;
  }
  EXPECT_EQ(slide, 2);

  // Through a checkpoint file, as the apps restart.
  const std::string file = "energy_control_run_test.ckp";
  for (const Saved& s : saved) {
    write_checkpoint(file, 0, s.state);
    StaticAnalysis restarted(model);
    restarted.load_state(read_checkpoint(file, 0));
    expect_continues(whole, record(restarted), s.increments, "restart at " + s.what);
  }
  std::remove(file.c_str());
}

} // namespace
} // namespace bipot
