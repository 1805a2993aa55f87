#include "apps/common/app_support.hpp"

#include "fem/linalg/communicator.hpp"

#include <fstream>
#include <iostream>

namespace bipot::app {

int report_error(const std::exception& e, int code, const std::string& program) {
  if (mpi_rank() != 0) return code;
  if (auto input = dynamic_cast<const InputError*>(&e)) {
    const auto n = input->problems().size();
    std::cerr << program << ": invalid input (" << n << " problem" << (n == 1 ? "" : "s") << "):\n";
    for (const auto& p : input->problems())
      std::cerr << "  " << p << "\n";
  } else {
    std::cerr << program << ": " << e.what() << "\n";
  }
  return code;
}

double peak_memory_mb() {
  std::ifstream status("/proc/self/status");
  for (std::string line; std::getline(status, line);)
    if (line.rfind("VmHWM:", 0) == 0) return std::stod(line.substr(6)) / 1024.0;
  return 0.0;
}

} // namespace bipot::app
