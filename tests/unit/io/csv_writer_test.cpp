#include "fem/io/csv_writer.hpp"

#include "fem/core/error.hpp"

#include "tests/support/scratch_dir.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <limits>
#include <unistd.h>

namespace bipot {
namespace {

namespace fs = std::filesystem;

using Scratch = test::ScratchDir;

std::vector<std::string> lines_of(const fs::path& p) {
  std::ifstream in(p);
  std::vector<std::string> lines;
  for (std::string line; std::getline(in, line);)
    lines.push_back(line);
  return lines;
}

std::vector<double> parse_row(const std::string& line) {
  std::vector<double> out;
  const char* p = line.c_str();
  while (*p) {
    char* end = nullptr;
    out.push_back(std::strtod(p, &end));
    p = *end == ',' ? end + 1 : end;
    if (end == p && *p) break;
  }
  return out;
}

TEST(CsvWriter, RowsReadBackBitIdentical) {
  const Scratch scratch("csv");
  const fs::path path = scratch.path / "history.csv";
  const std::vector<std::vector<double>> rows = {
      {0.1, 1.0 / 3.0, -2.5e17},
      {std::nextafter(1.0, 2.0), 1e-300, std::numeric_limits<double>::denorm_min()},
      {M_PI, -0.0, 123456789.123456789}};
  {
    CsvWriter w(path.string(), {"time", "force", "gap"});
    for (const auto& r : rows)
      w.write_row(r);
  }
  const auto lines = lines_of(path);
  ASSERT_EQ(lines.size(), 4u);
  EXPECT_EQ(lines[0], "time,force,gap");
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const auto back = parse_row(lines[i + 1]);
    ASSERT_EQ(back.size(), 3u);
    // 17 significant digits identify every double uniquely: the round trip is exact.
    for (int k = 0; k < 3; ++k)
      EXPECT_EQ(back[k], rows[i][k]) << lines[i + 1];
  }
  EXPECT_TRUE(std::signbit(parse_row(lines[3])[1])); // -0 keeps its sign
}

TEST(CsvWriter, EachRowIsOnDiskBeforeTheWriterCloses) {
  const Scratch scratch("csv");
  const fs::path path = scratch.path / "live.csv";
  CsvWriter w(path.string(), {"a", "b"});
  w.write_row({1.0, 2.0});
  EXPECT_EQ(lines_of(path).size(), 2u); // flushed: a crash now would keep this row
  w.write_row({3.0, 4.0});
  const auto lines = lines_of(path);
  ASSERT_EQ(lines.size(), 3u);
  EXPECT_EQ(lines[2], "3,4");
}

TEST(CsvWriter, QuotesAwkwardColumnNames) {
  const Scratch scratch("csv");
  const fs::path path = scratch.path / "names.csv";
  CsvWriter w(path.string(), {"u,x", "say \"hi\"", "plain"});
  EXPECT_EQ(lines_of(path)[0], "\"u,x\",\"say \"\"hi\"\"\",plain");
}

TEST(CsvWriter, ErrorsNameThePath) {
  const std::string bad = "/nonexistent_bipot_dir/sub/out.csv";
  try {
    CsvWriter w(bad, {"a"});
    FAIL() << "expected bipot::Error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("cannot open '" + bad + "' for writing"),
              std::string::npos)
        << e.what();
  }
  const Scratch scratch("csv");
  const fs::path path = scratch.path / "short.csv";
  CsvWriter w(path.string(), {"a", "b", "c"});
  try {
    w.write_row({1.0, 2.0});
    FAIL() << "expected bipot::Error";
  } catch (const Error& e) {
    EXPECT_EQ(std::string(e.what()),
              "CsvWriter '" + path.string() + "': row has 2 values, the header has 3 columns");
  }
  EXPECT_EQ(lines_of(path).size(), 1u); // the bad row wrote nothing
}

} // namespace
} // namespace bipot
