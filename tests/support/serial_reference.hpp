#pragma once
/// Test helpers for "1 and 2 ranks agree": the 1-rank run of a test (a CTest fixture set-up)
/// writes its solution to a file, the 2-rank run reads it back and compares.

#include "fem/linalg/communicator.hpp"

#include <cmath>
#include <fstream>
#include <iomanip>
#include <stdexcept>
#include <string>
#include <vector>

namespace bipot::test {

/// ‖a − b‖ / ‖b‖ (Euclidean).
inline double relative_difference(const std::vector<double>& a, const std::vector<double>& b) {
  double d = 0, n = 0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    d += (a[i] - b[i]) * (a[i] - b[i]);
    n += b[i] * b[i];
  }
  return std::sqrt(d / n);
}

/// On one rank: writes `values` to `file` (full precision) and returns an empty vector. On
/// several: returns the values the 1-rank run wrote; throws std::runtime_error naming the
/// file if it cannot be read (the 1-rank test did not run first).
inline std::vector<double> serial_reference(const std::string& file,
                                            const std::vector<double>& values) {
  if (mpi_size() == 1) {
    std::ofstream out(file);
    out << std::setprecision(17);
    for (double v : values)
      out << v << "\n";
    if (!out.good()) throw std::runtime_error("cannot write " + file);
    return {};
  }
  std::ifstream in(file);
  if (!in.good()) throw std::runtime_error("run the 1-rank test first (CTest fixture): " + file);
  std::vector<double> ref;
  for (double v; in >> v;)
    ref.push_back(v);
  return ref;
}

} // namespace bipot::test
