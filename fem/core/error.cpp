#include "fem/core/error.hpp"

namespace bipot {

namespace {
std::string join_lines(const std::vector<std::string>& lines) {
  std::string out;
  for (const auto& line : lines) {
    if (!out.empty()) out += '\n';
    out += line;
  }
  return out;
}
} // namespace

InputError::InputError(std::vector<std::string> problems)
    : Error(join_lines(problems)), problems_(std::move(problems)) {}

} // namespace bipot
