// Fuzz harness: the YAML input reader, from text. Invalid input must be reported as a
// bipot::Error (an InputError listing the problems); any other exception, a crash or a
// sanitizer report is a bug.
#include "harness.hpp"

#include "apps/catalogue/builtin_catalogue.hpp"
#include "fem/core/error.hpp"
#include "fem/input/problem_reader.hpp"

#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const bipot::Catalogue catalogue = bipot::builtin_catalogue();
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    bipot::read_problem_text(text, "fuzz.yaml", catalogue);
  } catch (const bipot::Error&) {
    // Expected for nearly every input.
  }
  return 0;
}
