// Fuzz harness: the .msh reader (bipot's own MSH 4.1 parser, fem/gmsh). read_gmsh takes a
// path, so each input is written to a file of this process's own in the temporary directory.
// Invalid input must be reported as a bipot::Error; any other exception, a crash or a
// sanitizer report is a bug.
#include "harness.hpp"

#include "fem/core/error.hpp"
#include "fem/gmsh/gmsh_reader.hpp"

#include <filesystem>
#include <fstream>
#include <string>
#include <unistd.h>

namespace {

/// The scratch file, removed when the process exits normally.
struct ScratchFile {
  std::filesystem::path path = std::filesystem::temp_directory_path() /
                               ("bipot_fuzz_msh_" + std::to_string(::getpid()) + ".msh");
  ~ScratchFile() {
    std::error_code ec;
    std::filesystem::remove(path, ec);
  }
};

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static ScratchFile file;
  {
    std::ofstream out(file.path, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
  }
  try {
    bipot::read_gmsh(file.path.string());
  } catch (const bipot::Error&) {
    // Expected for most inputs.
  }
  return 0;
}
