// VtkSeriesWriter::resume: a restarted run's series starts with the earlier run's steps.
#include "fem/core/error.hpp"
#include "fem/io/vtk_writer.hpp"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace bipot {

namespace {

// The values of attribute `name` in every `<tag ...>` of the XML text, in order (the files
// this writer produces: one element per line, attributes in double quotes).
std::vector<std::string> attributes(const std::string& text, const std::string& tag,
                                    const std::string& name) {
  std::vector<std::string> out;
  const std::string open = "<" + tag + " ", key = " " + name + "=\"";
  for (std::size_t at = text.find(open); at != std::string::npos; at = text.find(open, at + 1)) {
    const std::size_t end = text.find('>', at);
    const std::size_t k = text.find(key, at);
    if (k == std::string::npos || k > end) continue;
    const std::size_t v = k + key.size();
    out.push_back(text.substr(v, text.find('"', v) - v));
  }
  return out;
}

std::string text_of(const std::string& file) {
  std::ifstream in(file);
  if (!in) throw Error("VtkSeriesWriter: cannot read '" + file + "' to continue its series");
  std::ostringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

void copy_step_file(const std::filesystem::path& from, const std::filesystem::path& to) {
  std::error_code ec;
  std::filesystem::copy_file(from, to, std::filesystem::copy_options::overwrite_existing, ec);
  if (ec)
    throw Error("VtkSeriesWriter: cannot copy '" + from.string() + "' to '" + to.string() +
                "': " + ec.message());
}

} // namespace

void VtkSeriesWriter::resume(const std::string& directory, double time) {
  const std::filesystem::path old(directory);
  const std::string pvd = text_of((old / (basename_ + ".pvd")).string());
  const auto times = attributes(pvd, "DataSet", "timestep");
  const auto files = attributes(pvd, "DataSet", "file");
  for (std::size_t s = 0; s < times.size() && s < files.size(); ++s) {
    const double t = std::stod(times[s]);
    if (t > time + 1e-12 * std::max(1.0, std::abs(time))) break;
    times_.push_back(t);
    files_.push_back(files[s]);
    if (rank_ != 0) continue;
    copy_step_file(old / files[s], std::filesystem::path(directory_) / files[s]);
    if (files[s].size() > 5 && files[s].compare(files[s].size() - 5, 5, ".pvtu") == 0)
      for (const auto& piece : attributes(text_of((old / files[s]).string()), "Piece", "Source"))
        copy_step_file(old / piece, std::filesystem::path(directory_) / piece);
  }
  if (rank_ == 0 && !times_.empty()) write_pvd();
}

} // namespace bipot
