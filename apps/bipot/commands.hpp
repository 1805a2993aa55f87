#pragma once
/// The subcommands of the `bipot` executable. Each returns the process exit code:
/// 0 success, 1 usage error, 2 invalid input, 3 solver failure, 4 other error.

#include "apps/catalogue/catalogue.hpp"

#include <string>
#include <vector>

namespace bipot::app {

int run_command(const std::vector<std::string>& args, const Catalogue& catalogue);
int check_command(const std::vector<std::string>& args, const Catalogue& catalogue);
int describe_command(const std::vector<std::string>& args, const Catalogue& catalogue);
void print_usage();

} // namespace bipot::app
