#pragma once
/// Internal to fem/linalg: MUMPS' out-of-core factors (ICNTL(22)), set the same way for the
/// rooted LU and the distributed Schur complement.

#include <dmumps_c.h>

#include <cstdio>
#include <string>

namespace bipot::detail {

/// Factors written to files in `directory` (empty: kept in memory). MUMPS reads them back at
/// each solve (through the page cache when memory allows) and deletes them when the instance
/// is destroyed (JOB = -2). Set before the analysis: its memory estimates depend on it.
/// Out of core, the workspace's relaxation over MUMPS' estimate (ICNTL(14)) is 5 % instead of
/// its default: whoever asks for files asks for less memory (the pile at 936k DOFs: peak 882
/// -> 870 MiB), and a factorisation that runs short is retried with more (INFOG(1) = -8, -9).
inline void set_mumps_out_of_core(DMUMPS_STRUC_C& id, const std::string& directory) {
  id.icntl[21] = directory.empty() ? 0 : 1; // ICNTL(22)
  if (!directory.empty()) id.icntl[13] = 5;
  std::snprintf(id.ooc_tmpdir, sizeof id.ooc_tmpdir, "%s", directory.c_str());
  std::snprintf(id.ooc_prefix, sizeof id.ooc_prefix, "%s", "bipot_factors_");
}

} // namespace bipot::detail
