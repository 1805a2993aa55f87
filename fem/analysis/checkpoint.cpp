#include "fem/analysis/checkpoint.hpp"

#include "fem/core/error.hpp"

#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

#ifndef BIPOT_VERSION
#error "BIPOT_VERSION must be defined by the build (fem/analysis/CMakeLists.txt)"
#endif

namespace bipot {

namespace {

constexpr char magic[8] = {'B', 'I', 'P', 'O', 'T', 'C', 'K', 'P'};

bool little_endian() {
  const std::uint32_t one = 1;
  unsigned char first = 0;
  std::memcpy(&first, &one, 1);
  return first == 1;
}

// Integers and doubles are written in the host's byte order, which must be little-endian
// (checked on write and read), so that a file moves between machines unchanged.
template <class T> void put(std::ostream& out, T value) {
  out.write(reinterpret_cast<const char*>(&value), sizeof(T));
}
void put_string(std::ostream& out, const std::string& s) {
  put(out, static_cast<std::uint32_t>(s.size()));
  out.write(s.data(), static_cast<std::streamsize>(s.size()));
}

class Reader {
public:
  Reader(std::istream& in, std::string path) : in_(in), path_(std::move(path)) {}
  template <class T> T get() {
    T value{};
    read(reinterpret_cast<char*>(&value), sizeof(T));
    return value;
  }
  std::string get_string(std::size_t limit) {
    const auto n = get<std::uint32_t>();
    if (n > limit) fail("a name longer than " + std::to_string(limit) + " bytes");
    std::string s(n, '\0');
    read(s.data(), n);
    return s;
  }
  void read(char* to, std::size_t n) {
    if (!in_.read(to, static_cast<std::streamsize>(n))) fail("it ends early (truncated)");
  }
  [[noreturn]] void fail(const std::string& why) const {
    throw InputError(path_ + ": not a usable bipot checkpoint: " + why);
  }

private:
  std::istream& in_;
  std::string path_;
};

std::string hex(std::uint64_t h) {
  char buf[17];
  std::snprintf(buf, sizeof buf, "%016llx", static_cast<unsigned long long>(h));
  return buf;
}

std::string file_bytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw Error(path + ": cannot read it to hash the input of a checkpoint");
  std::ostringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

} // namespace

std::string bipot_version() {
  return BIPOT_VERSION;
}

std::uint64_t content_hash(const std::string& bytes, std::uint64_t hash) {
  for (unsigned char c : bytes) {
    hash ^= c;
    hash *= 1099511628211ull;
  }
  return hash;
}

std::uint64_t input_hash(const ProblemSpec& spec, const std::string& text) {
  std::uint64_t h = content_hash(text.empty() ? file_bytes(spec.file) : text);
  if (!spec.mesh.file.empty()) h = content_hash(file_bytes(spec.mesh.file), h);
  return h;
}

void write_checkpoint(const std::string& path, std::uint64_t input_hash, const StateArrays& state) {
  if (!little_endian()) throw Error(path + ": checkpoints are written on little-endian hosts only");
  const std::string tmp = path + ".partial";
  {
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    if (!out) throw Error(path + ": cannot write the checkpoint");
    out.write(magic, sizeof magic);
    put(out, checkpoint_format_version);
    put_string(out, bipot_version());
    put(out, input_hash);
    put(out, static_cast<std::uint64_t>(state.size()));
    for (const auto& [name, values] : state) {
      put_string(out, name);
      put(out, static_cast<std::uint64_t>(values.size()));
      out.write(reinterpret_cast<const char*>(values.data()),
                static_cast<std::streamsize>(values.size() * sizeof(double)));
    }
    out.flush();
    if (!out) throw Error(path + ": writing the checkpoint failed (disk full?)");
  }
  std::error_code ec;
  std::filesystem::rename(tmp, path, ec);
  if (ec) throw Error(path + ": cannot move the checkpoint into place: " + ec.message());
}

StateArrays read_checkpoint(const std::string& path, std::uint64_t input_hash) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path + ": cannot open the checkpoint");
  Reader r(in, path);
  if (!little_endian()) r.fail("this host is big-endian");
  char head[sizeof magic];
  r.read(head, sizeof head);
  if (std::memcmp(head, magic, sizeof magic) != 0)
    r.fail("it does not start with BIPOTCKP (not a checkpoint file)");
  const auto format = r.get<std::uint32_t>();
  if (format != checkpoint_format_version)
    throw InputError(path + ": the checkpoint has format version " + std::to_string(format) +
                     ", this bipot reads version " + std::to_string(checkpoint_format_version));
  const std::string version = r.get_string(256);
  if (version != bipot_version())
    throw InputError(path + ": the checkpoint was written by bipot " + version +
                     ", this is bipot " + bipot_version() +
                     " (its state may mean something else here)");
  const auto hash = r.get<std::uint64_t>();
  if (hash != input_hash)
    throw InputError(path + ": the checkpoint was written for another input (content hash " +
                     hex(hash) + ", this input and its mesh hash to " + hex(input_hash) +
                     "): the input file or its mesh changed since");
  const auto count = r.get<std::uint64_t>();
  StateArrays state;
  const auto size = std::filesystem::file_size(path);
  for (std::uint64_t i = 0; i < count; ++i) {
    const std::string name = r.get_string(4096);
    const auto n = r.get<std::uint64_t>();
    if (n > size / sizeof(double)) r.fail("array '" + name + "' is larger than the file");
    std::vector<double>& values = state[name];
    values.resize(n);
    r.read(reinterpret_cast<char*>(values.data()), n * sizeof(double));
  }
  return state;
}

} // namespace bipot
