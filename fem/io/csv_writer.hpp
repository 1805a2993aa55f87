#pragma once
/// Comma-separated output of time histories (one row per step), safe against crashes.

#include <fstream>
#include <string>
#include <vector>

namespace bipot {

/// Writes a CSV file: a header line of column names, then rows of numbers at full double
/// precision (%.17g, so values read back bit-identical). Each row is flushed, so a crash
/// leaves every completed row in the file. Column names containing a comma, a quote or a
/// line break are quoted (RFC 4180). The file is truncated on construction.
class CsvWriter {
public:
  /// Opens `path` and writes the header. Throws bipot::Error naming the path if the file
  /// cannot be opened or there are no columns.
  CsvWriter(std::string path, std::vector<std::string> columns);

  /// Appends one row; throws bipot::Error if its size differs from the number of columns or
  /// the write fails.
  void write_row(const std::vector<double>& values);

  /// Appends the rows of an earlier file at `path` with this header whose first value (the
  /// stage, 1-based) is at most `last_stage`, or is the next stage with a second value (the
  /// step within it) of at most `next_stage_steps`, as they are (a restart's earlier
  /// increments). Throws bipot::Error if the file cannot be read or its header differs.
  void copy_rows(const std::string& path, double last_stage, int next_stage_steps = 0);

  const std::string& path() const { return path_; }
  const std::vector<std::string>& columns() const { return columns_; }

private:
  std::string path_;
  std::vector<std::string> columns_;
  std::ofstream out_;
};

} // namespace bipot
