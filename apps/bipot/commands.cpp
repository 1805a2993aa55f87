#include "apps/bipot/commands.hpp"
#include "apps/common/app_support.hpp"
#include "apps/common/checked_model.hpp"
#include "apps/common/checkpoints.hpp"
#include "apps/common/run_folder.hpp"
#include "apps/common/step_text.hpp"

#include "fem/analysis/model.hpp"
#include "fem/analysis/result_writer.hpp"
#include "fem/analysis/static_analysis.hpp"
#include "fem/core/error.hpp"
#include "fem/core/nearest_name.hpp"
#include "fem/input/problem_reader.hpp"
#include "fem/input/stage_schema.hpp"
#include "fem/linalg/communicator.hpp"
#include "fem/linalg/linear_solver.hpp"

#include <cstdio>
#include <fstream>
#include <iostream>

namespace bipot::app {

namespace {

bool root() {
  return mpi_rank() == 0;
}

bool wants_help(const std::vector<std::string>& args) {
  for (const auto& a : args)
    if (a == "--help" || a == "-h") return true;
  return false;
}

template <class F> int guarded(F&& body) {
  return run_guarded("bipot", std::forward<F>(body));
}

std::string one_file(const std::vector<std::string>& args, const char* usage) {
  std::vector<std::string> files;
  for (const auto& a : args)
    if (a.empty() || a[0] != '-') files.push_back(a);
  if (files.size() != 1) {
    if (root()) std::cerr << "usage: " << usage << "\n";
    return "";
  }
  return files[0];
}

} // namespace

void print_usage() {
  std::cout << "bipot - finite elements with adhesive, frictional and unilateral interfaces\n\n"
               "usage:\n"
               "  bipot run FILE.yaml        solve the problem, results in output.directory\n"
               "                             (status.txt says finished or failed)\n"
               "  bipot check FILE.yaml      validate the input and the mesh, solve nothing\n"
               "  bipot describe [NAME]      parameters of a material, an interface law, a\n"
               "                             contact solver or linear_solver; 'input' for the\n"
               "                             file's top-level keys\n"
               "  bipot COMMAND --help       help on a command\n\n"
               "Run in parallel with: mpiexec -n N bipot run FILE.yaml\n"
               "Kokkos options (--kokkos-threads=N, --kokkos-help, ...) are passed on to Kokkos.\n"
               "Exit codes: 0 ok, 1 usage, 2 invalid input, 3 solver failure, 4 other error.\n";
}

int check_command(const std::vector<std::string>& args, const Catalogue& catalogue) {
  if (wants_help(args)) {
    if (root())
      std::cout << "bipot check FILE.yaml\n  Reads FILE.yaml, builds its mesh and materials, "
                   "checks the mesh (non-finite\n  coordinates, inverted cells, coincident or "
                   "unused nodes), that every stage holds\n  every body and that the results "
                   "folder can be written, and reports every problem\n  as file:line:col: "
                   "key.path: message. Warns (exit code 0) of a prescribed displacement\n  step "
                   "larger than the model.\n";
    return 0;
  }
  const std::string file = one_file(args, "bipot check FILE.yaml");
  if (file.empty()) return 1;
  return guarded([&] {
    // Every problem `run` would stop at before solving: the model's and the results folder's.
    const Model model =
        checked_model_and_results_folder(read_problem_file(file, catalogue), catalogue);
    print_model_warnings(model, "bipot");
    if (root())
      std::cout << file << ": ok (" << model.mesh.num_nodes() << " nodes, "
                << model.mesh.num_cells() << " cells, " << model.spec.stages.size() << " stage"
                << (model.spec.stages.size() == 1 ? "" : "s") << ")\n";
    return 0;
  });
}

int run_command(const std::vector<std::string>& args, const Catalogue& catalogue) {
  if (wants_help(args)) {
    if (root())
      std::cout << "bipot run FILE.yaml [--output DIR] [--restart CHECKPOINT] [--quiet]\n"
                   "  Solves the problem stage by stage and writes DIR (default: "
                   "output.directory):\n"
                   "  solution.pvd (open it in ParaView), reactions.csv and status.txt. The "
                   "results are\n"
                   "  written into DIR.running-<pid> and replace DIR only when the run "
                   "finishes; a failed\n"
                   "  run leaves DIR as it was and its converged increments in DIR.failed.\n"
                   "  Prints one progress line per converged increment unless --quiet.\n"
                   "  --restart continues from a checkpoint (output.checkpoint) of the same "
                   "input,\n"
                   "  where it was written (a stage end or a step within a stage); DIR starts "
                   "with the results up to there,\n"
                   "  copied from the checkpoint's folder.\n";
    return 0;
  }
  bool quiet = false;
  std::string output, restart;
  std::vector<std::string> files;
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string& a = args[i];
    if (a == "--quiet" || a == "-q")
      quiet = true;
    else if (a == "--output" && i + 1 < args.size())
      output = args[++i];
    else if (a == "--restart" && i + 1 < args.size())
      restart = args[++i];
    else if (!a.empty() && a[0] == '-') {
      if (root()) std::cerr << "bipot run: unknown option '" << a << "'\n";
      return 1;
    } else
      files.push_back(a);
  }
  const std::string file =
      one_file(files, "bipot run FILE.yaml [--output DIR] [--restart CHECKPOINT] [--quiet]");
  if (file.empty()) return 1;
  return guarded([&] {
    const Model model = checked_model(read_problem_file(file, catalogue), catalogue);
    print_model_warnings(model, "bipot");
    // A checkpoint of another input is refused before the results folder is touched.
    const StateArrays restored = restart.empty() ? StateArrays{} : read_restart(restart, model);
    RunFolder folder(output.empty() ? model.spec.output.directory : output, model.spec, "bipot");
    RunSummary summary;
    {
      ResultWriter writer(model, mpi_rank(), mpi_size(), folder.working());
      const StaticAnalysis* running = nullptr;
      AnalysisOptions options;
      options.on_stage_end = checkpoint_writer(model, &running, folder.working());
      options.on_increment_end = step_checkpoint_writer(model, &running, folder.working());
      StaticAnalysis analysis(model, options, &writer);
      running = &analysis;
      if (!restart.empty()) {
        const RestartPoint at = restore(restart, restored, analysis, writer, model);
        if (root() && !quiet)
          std::cout << "bipot: restart from " << restart << " " << at.text << "\n";
      }
      if (root() && !quiet)
        std::cout << "bipot: " << file << ": " << model.mesh.num_nodes() << " nodes, "
                  << model.mesh.num_cells() << " cells, " << analysis.dofs().num_dofs()
                  << " DOFs on " << mpi_size() << " rank" << (mpi_size() == 1 ? "" : "s") << "\n";
      summary = analysis.run([&](const StepReport& r) {
        folder.converged(r);
        if (!root() || quiet) return;
        // Stage progress rather than "step k of n": sub-increments add steps to the plan.
        std::printf("  stage %-12s step %3d %4.0f%%  t = %-9.4g  newton %2d  linear %4d  "
                    "residual %.2e  %.2f s%s\n",
                    r.stage.c_str(), r.step, 100.0 * r.load_factor, r.time, r.iterations,
                    r.linear_iterations, r.residual, r.seconds, app::step_flags(r).c_str());
        std::fflush(stdout);
      });
    }
    folder.finish();
    const double peak_mib = max_all(peak_memory_mib());
    if (root()) {
      std::printf("bipot: done: %d increments, %d linear solves (%d iterations), %d matrix "
                  "set-ups\n"
                  "bipot: time %.3f s = assembly %.3f + set-up %.3f + solve %.3f + output %.3f "
                  "+ other; peak memory %.1f MiB per rank\n",
                  summary.steps, summary.linear_solves, summary.linear_iterations,
                  summary.matrix_setups, summary.seconds, summary.assembly_seconds,
                  summary.setup_seconds, summary.solve_seconds, summary.output_seconds, peak_mib);
      std::cout << app::stepping_summary(summary, "bipot") << "\n";
      if (const std::string e = app::energy_balance_summary(summary, "bipot"); !e.empty())
        std::cout << e << "\n";
      std::cout << "bipot: results in " << folder.directory()
                << " (ParaView: " << folder.directory() << "/solution.pvd)\n";
    }
    return 0;
  });
}

int describe_command(const std::vector<std::string>& args, const Catalogue& catalogue) {
  if (wants_help(args)) {
    if (root())
      std::cout << "bipot describe [NAME] [--markdown]\n  Without NAME: lists what can be "
                   "described. With NAME: its parameters (type, default, range, units, "
                   "meaning);\n  --markdown prints them as the table used in the docs.\n";
    return 0;
  }
  if (!root()) return 0;
  const auto& mats = catalogue.materials;
  const auto& laws = catalogue.interface_laws;
  const auto& solvers = catalogue.contact_solvers;
  std::vector<std::string> names;
  bool markdown = false;
  for (const auto& a : args)
    if (a == "--markdown")
      markdown = true;
    else
      names.push_back(a);
  if (names.empty()) {
    std::cout << "materials: " << join_names(mats.names()) << "\n"
              << "interface laws: " << join_names(laws.names()) << "\n"
              << "contact solvers: " << join_names(solvers.names()) << "\n"
              << "linear solver: linear_solver\n"
              << "input file: input, stage, control\n"
              << "Use: bipot describe NAME [--markdown]\n";
    return 0;
  }
  const std::string& name = names[0];
  auto print = [&](const ParamSchema& s) {
    std::cout << (markdown ? s.markdown_table() : s.describe());
  };
  if (mats.contains(name))
    print(mats.schema(name));
  else if (laws.contains(name))
    print(laws.schema(name));
  else if (solvers.contains(name))
    print(solvers.schema(name));
  else if (name == "linear_solver")
    print(LinearSolver::schema());
  else if (name == "input")
    std::cout << describe_input_format();
  else if (name == "stage")
    print(stage_schema());
  else if (name == "control")
    print(control_schema());
  else {
    std::vector<std::string> all = mats.names();
    for (const auto& n : laws.names())
      all.push_back(n);
    for (const auto& n : solvers.names())
      all.push_back(n);
    all.push_back("linear_solver");
    for (const char* n : {"input", "stage", "control"})
      all.push_back(n);
    std::string msg = "bipot describe: nothing is called '" + name + "'";
    const auto near = nearest_name(name, all);
    if (!near.empty()) msg += " (did you mean '" + near + "'?)";
    std::cerr << msg << "; available: " << join_names(all) << "\n";
    return 1;
  }
  return 0;
}

} // namespace bipot::app
