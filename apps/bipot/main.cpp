// bipot: run, check or describe finite-element models with contact interfaces.
#include "apps/bipot/commands.hpp"
#include "apps/catalogue/builtin_catalogue.hpp"
#include "apps/common/app_support.hpp"
#include "fem/linalg/parallel_environment.hpp"

#include <iostream>

int main(int argc, char** argv) {
  std::vector<std::string> args;
  const auto env = bipot::app::start_parallel(argc, argv, "bipot", args);
  if (!env) return bipot::app::kUsage;
  if (args.empty() || args[0] == "--help" || args[0] == "-h" || args[0] == "help") {
    if (env->rank() == 0) bipot::app::print_usage();
    return args.empty() ? 1 : 0;
  }
  const std::string command = args[0];
  args.erase(args.begin());
  // The one place bipot's own modules are wired in: everything below gets this catalogue.
  const bipot::Catalogue catalogue = bipot::builtin_catalogue();
  if (command == "run") return bipot::app::run_command(args, catalogue);
  if (command == "check") return bipot::app::check_command(args, catalogue);
  if (command == "describe") return bipot::app::describe_command(args, catalogue);
  if (env->rank() == 0) {
    std::cerr << "bipot: unknown command '" << command << "'\n";
    bipot::app::print_usage();
  }
  return 1;
}
