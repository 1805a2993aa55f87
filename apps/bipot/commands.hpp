#pragma once
/// The subcommands of the `bipot` executable. Each returns the process exit code:
/// 0 success, 1 usage error, 2 invalid input, 3 solver failure, 4 other error.

#include <string>
#include <vector>

namespace bipot::app {

int run_command(const std::vector<std::string>& args);
int check_command(const std::vector<std::string>& args);
int describe_command(const std::vector<std::string>& args);
void print_usage();

} // namespace bipot::app
