// pile_pullout: the pull-out of a pile from soil (axisymmetric), the seed paper's application,
// with any of the toolkit's interface laws. A thin layer over the toolkit: it lays out the
// problem (pile_problem.cpp), runs StaticAnalysis and writes the head curve and profiles.
#include "apps/catalogue/builtin_catalogue.hpp"
#include "apps/common/app_support.hpp"
#include "apps/common/checked_model.hpp"
#include "apps/common/checkpoints.hpp"
#include "apps/common/run_folder.hpp"
#include "apps/common/step_text.hpp"
#include "apps/pile_pullout/pile_input.hpp"
#include "apps/pile_pullout/pile_problem.hpp"
#include "apps/pile_pullout/pile_results.hpp"

#include "fem/analysis/model.hpp"
#include "fem/analysis/result_writer.hpp"
#include "fem/analysis/static_analysis.hpp"
#include "fem/core/error.hpp"
#include "fem/linalg/communicator.hpp"
#include "fem/linalg/parallel_environment.hpp"

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>

namespace {

using namespace bipot;

void usage() {
  std::cout
      << "pile_pullout - pull-out of a pile from soil with an adhesive/frictional interface\n\n"
         "usage:\n"
         "  pile_pullout run FILE.yaml [--output DIR] [--restart CHECKPOINT] [--quiet]\n"
         "        [--no-plot]\n"
         "        geostatic, installation and pull-out stages; writes DIR (default: the file's\n"
         "        output.directory) with head_force.csv, profiles.csv, solution.pvd,\n"
         "        interface_shaft.pvd, interface_toe.pvd, status.txt and, with\n"
         "        python3-matplotlib, pullout_curve.png and profiles.png. DIR is replaced\n"
         "        only when the run finishes: a failed run leaves it as it was and its\n"
         "        converged steps in DIR.failed. --restart continues from a checkpoint\n"
         "        (output.checkpoint) of the same input, where it was written; DIR starts\n"
         "        with the results up to there, copied from the checkpoint's folder\n"
         "  pile_pullout check FILE.yaml     validate the file, build and check the model\n"
         "  pile_pullout describe [--markdown]   the input file's keys\n\n"
         "Run in parallel with: mpiexec -n N pile_pullout run FILE.yaml\n"
         "Exit codes: 0 ok, 1 usage, 2 invalid input, 3 solver failure (converged steps are\n"
         "kept in DIR.failed), 4 other error.\n";
}

// Plots by the bundled matplotlib script; a missing Python or matplotlib costs the images,
// not the run.
void plot(const std::string& dir, const std::string& label) {
  const std::string script = BIPOT_PILE_PLOT_SCRIPT;
  if (!std::filesystem::exists(script)) {
    std::cout << "pile_pullout: plot script not found (" << script << "), no images\n";
    return;
  }
  const std::string q = "'";
  // The script runs by its #! line: Debian's python3 (/usr/bin/python3) has matplotlib; a
  // python3 earlier on PATH (pyenv, conda) may not.
  const std::string curves = q + script + q + " curves " + q + dir + "/pullout_curve.png" + q +
                             " " + q + label + "=" + dir + q;
  const std::string profiles =
      q + script + q + " profiles " + q + dir + "/profiles.png" + q + " " + q + dir + q;
  for (const auto& cmd : {curves, profiles})
    if (std::system((cmd + " > /dev/null").c_str()) != 0)
      std::cout << "pile_pullout: plotting failed (needs Debian's python3-matplotlib): " << cmd
                << "\n";
}

int run(const std::string& file, const std::string& output, const std::string& restart, bool quiet,
        bool plots) {
  const Catalogue catalogue = builtin_catalogue();
  pile::PileSpec spec = pile::read_pile_file(file, catalogue);
  if (!output.empty()) spec.output.directory = output;
  const Model model = app::checked_model(pile::make_problem(spec), catalogue);
  const bool root = mpi_rank() == 0;
  // A checkpoint of another input is refused before the results folder is touched.
  const StateArrays restored = restart.empty() ? StateArrays{} : app::read_restart(restart, model);
  app::RunFolder folder(spec.output.directory, model.spec, "pile_pullout");
  ResultWriter writer(model, mpi_rank(), mpi_size(), folder.working());
  pile::PileResults results(model, folder.working(), spec.profiles_at_mm, root);
  // Checkpoints carry the head curve's and profiles' own state too.
  const StaticAnalysis* running = nullptr;
  const app::AppState pile_state = [&results] { return results.save_state(); };
  AnalysisOptions options;
  options.on_stage_end = app::checkpoint_writer(model, &running, folder.working(), pile_state);
  options.on_increment_end =
      app::step_checkpoint_writer(model, &running, folder.working(), pile_state);
  StaticAnalysis analysis(model, options, &writer);
  running = &analysis;
  if (!restart.empty()) {
    const app::RestartPoint at = app::restore(restart, restored, analysis, writer, model);
    results.resume(at.folder, at.global_steps, restored);
    if (root && !quiet)
      std::printf("pile_pullout: restart from %s %s\n", restart.c_str(), at.text.c_str());
  }
  if (root && !quiet)
    std::printf("pile_pullout: %s: %s interface, %lld nodes, %lld cells, %lld DOFs, %d rank%s\n",
                file.c_str(), spec.law.c_str(), static_cast<long long>(model.mesh.num_nodes()),
                static_cast<long long>(model.mesh.num_cells()),
                static_cast<long long>(analysis.dofs().num_dofs()), mpi_size(),
                mpi_size() == 1 ? "" : "s");
  const RunSummary summary = analysis.run([&](const StepReport& r) {
    folder.converged(r);
    results.record(r, analysis);
    if (!root || quiet) return;
    const auto h = results.last();
    // Stage progress rather than "step k of n": sub-increments add steps to the plan.
    std::printf("  %-12s step %3d %4.0f%%  head %8.3f mm  force %9.2f kN  newton %3d  %.2f s%s\n",
                r.stage.c_str(), r.step, 100.0 * r.load_factor, 1e3 * h.displacement, h.force,
                r.iterations, r.seconds, app::step_flags(r).c_str());
    std::fflush(stdout);
  });
  const double peak_mib = max_all(app::peak_memory_mib());
  if (root && plots) plot(folder.working(), spec.name);
  folder.finish();
  if (!root) return 0;
  std::printf("pile_pullout: peak pull-out force %.2f kN at %.3f mm; final %.2f kN at %.3f mm\n",
              results.peak_force(), 1e3 * results.peak_displacement(), results.last().force,
              1e3 * results.last().displacement);
  std::printf("pile_pullout: %d increments, %d linear solves (%ld Krylov iterations), %d matrix "
              "set-ups; time %.2f s = assembly %.2f + set-up %.2f + solve %.2f + output %.2f + "
              "other; peak memory %.1f MiB per rank\n",
              summary.steps, summary.linear_solves, static_cast<long>(summary.linear_iterations),
              summary.matrix_setups, summary.seconds, summary.assembly_seconds,
              summary.setup_seconds, summary.solve_seconds, summary.output_seconds, peak_mib);
  std::cout << app::stepping_summary(summary, "pile_pullout") << "\n";
  if (const std::string e = app::energy_balance_summary(summary, "pile_pullout"); !e.empty())
    std::cout << e << "\n";
  // List what is there: a bonded shaft has no profiles to plot.
  const std::string& dir = folder.directory();
  std::string files = "head_force.csv, profiles.csv";
  for (const char* png : {"pullout_curve.png", "profiles.png"})
    if (plots && std::filesystem::exists(dir + "/" + png)) files += std::string(", ") + png;
  std::cout << "pile_pullout: results in " << dir << " (" << files << "; ParaView: " << dir
            << "/solution.pvd)\n";
  if (plots && std::filesystem::exists(dir + "/pullout_curve.png"))
    std::cout << "pile_pullout: plot of the pull-out curve: " << dir << "/pullout_curve.png\n";
  return 0;
}

template <class F> int guarded(F&& body) {
  return app::run_guarded("pile_pullout", std::forward<F>(body));
}

} // namespace

int main(int argc, char** argv) {
  std::vector<std::string> args;
  const auto env = app::start_parallel(argc, argv, "pile_pullout", args);
  if (!env) return app::kUsage;
  const bool root = env->rank() == 0;
  if (args.empty()) {
    if (root) usage();
    return 1;
  }
  std::string command = args[0], output, restart;
  bool quiet = false, plots = true, markdown = false;
  std::vector<std::string> files;
  for (std::size_t i = 1; i < args.size(); ++i) {
    const std::string& a = args[i];
    if (a == "--help" || a == "-h")
      command = "--help";
    else if (a == "--quiet" || a == "-q")
      quiet = true;
    else if (a == "--no-plot")
      plots = false;
    else if (a == "--markdown")
      markdown = true;
    else if (a == "--output" && i + 1 < args.size())
      output = args[++i];
    else if (a == "--restart" && i + 1 < args.size())
      restart = args[++i];
    else if (!a.empty() && a[0] == '-') {
      if (root) std::cerr << "pile_pullout: unknown option '" << a << "' (see --help)\n";
      return 1;
    } else
      files.push_back(a);
  }
  if (command == "--help" || command == "-h" || command == "help") {
    if (root) usage();
    return 0;
  }
  if (command == "describe") {
    if (root) std::cout << bipot::pile::describe_pile_input(markdown);
    return 0;
  }
  if ((command != "run" && command != "check") || files.size() != 1) {
    if (root) {
      if (command != "run" && command != "check")
        std::cerr << "pile_pullout: unknown command '" << command << "'\n";
      else
        std::cerr << "pile_pullout " << command << ": expected one input file\n";
      usage();
    }
    return 1;
  }
  if (command == "check")
    return guarded([&] {
      const bipot::Catalogue catalogue = bipot::builtin_catalogue();
      const bipot::Model model = app::checked_model_and_results_folder(
          bipot::pile::make_problem(bipot::pile::read_pile_file(files[0], catalogue)), catalogue);
      if (root)
        std::cout << files[0] << ": ok (" << model.mesh.num_nodes() << " nodes, "
                  << model.mesh.num_cells() << " cells)\n";
      return 0;
    });
  return guarded([&] { return run(files[0], output, restart, quiet, plots); });
}
