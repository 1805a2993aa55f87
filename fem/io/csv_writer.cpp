#include "fem/io/csv_writer.hpp"

#include "fem/core/error.hpp"

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>

namespace bipot {

namespace {

std::string quoted(const std::string& name) {
  if (name.find_first_of(",\"\r\n") == std::string::npos) return name;
  std::string out = "\"";
  for (char c : name) {
    if (c == '"') out += '"';
    out += c;
  }
  return out + "\"";
}

} // namespace

CsvWriter::CsvWriter(std::string path, std::vector<std::string> columns)
    : path_(std::move(path)), columns_(std::move(columns)) {
  if (columns_.empty()) throw Error("CsvWriter '" + path_ + "': no columns");
  errno = 0;
  out_.open(path_, std::ios::out | std::ios::trunc);
  if (!out_)
    throw Error("CsvWriter: cannot open '" + path_ + "' for writing" +
                (errno ? std::string(": ") + std::strerror(errno) : std::string()));
  for (std::size_t i = 0; i < columns_.size(); ++i)
    out_ << (i ? "," : "") << quoted(columns_[i]);
  out_ << '\n' << std::flush;
  if (!out_) throw Error("CsvWriter: cannot write to '" + path_ + "'");
}

void CsvWriter::write_row(const std::vector<double>& values) {
  if (values.size() != columns_.size())
    throw Error("CsvWriter '" + path_ + "': row has " + std::to_string(values.size()) +
                " values, the header has " + std::to_string(columns_.size()) + " columns");
  char buf[32];
  for (std::size_t i = 0; i < values.size(); ++i) {
    std::snprintf(buf, sizeof buf, "%.17g", values[i]);
    out_ << (i ? "," : "") << buf;
  }
  out_ << '\n' << std::flush; // a crash keeps every completed row
  if (!out_) throw Error("CsvWriter: cannot write to '" + path_ + "'");
}

void CsvWriter::copy_rows(const std::string& path, double last_stage, int next_stage_steps) {
  std::ifstream in(path);
  if (!in) throw Error("CsvWriter: cannot read '" + path + "' to copy its rows");
  std::string header, line;
  std::getline(in, header);
  std::string expected;
  for (std::size_t i = 0; i < columns_.size(); ++i)
    expected += (i ? "," : "") + quoted(columns_[i]);
  if (header != expected)
    throw Error("CsvWriter: '" + path + "' has the header '" + header + "', expected '" + expected +
                "'");
  while (std::getline(in, line)) {
    if (line.empty()) continue;
    char* rest = nullptr;
    const double stage = std::strtod(line.c_str(), &rest);
    const double step = *rest == ',' ? std::strtod(rest + 1, nullptr) : 0.0;
    if (stage <= last_stage || (stage == last_stage + 1 && step <= next_stage_steps))
      out_ << line << '\n';
  }
  out_ << std::flush;
  if (!out_) throw Error("CsvWriter: cannot write to '" + path_ + "'");
}

} // namespace bipot
