#pragma once
/// Internal to fem/linalg: MUMPS' failure codes as the user reads them, the same for the
/// rooted LU and the distributed Schur complement.

#include <string>

namespace bipot::detail {

/// INFOG(1) = `code` < 0 and INFOG(2) = `detail` in words: the codes a user can act on by
/// name and with what to change, the rest by number (MUMPS manual, §8). `out_of_core`: the
/// factors were already in files.
inline std::string mumps_error(int code, int detail, bool out_of_core) {
  const std::string codes =
      "MUMPS INFOG(1) = " + std::to_string(code) + ", INFOG(2) = " + std::to_string(detail);
  switch (code) {
  case -10:
    return "numerically singular matrix (" + codes + ")";
  case -13:
    return "memory allocation failed (" + codes + ")" +
           (out_of_core ? std::string("; the factors are in files already: more memory is needed "
                                      "(with generalized_newton, more ranks share them)")
                        : std::string("; `linear_solver: {out_of_core: true}` keeps the factors "
                                      "in files instead of memory"));
  default:
    return codes;
  }
}

} // namespace bipot::detail
