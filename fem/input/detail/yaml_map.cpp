#include "fem/input/detail/yaml_map.hpp"

#include "fem/core/error.hpp"
#include "fem/core/nearest_name.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>

namespace bipot::input {

std::string Diagnostics::where(const YAML::Node& node, const std::string& path) const {
  const YAML::Mark m = node.Mark();
  std::string loc = file_;
  if (m.line >= 0) loc += ":" + std::to_string(m.line + 1) + ":" + std::to_string(m.column + 1);
  return loc + ": " + (path.empty() ? std::string("(top level)") : path);
}

void Diagnostics::error(const YAML::Node& node, const std::string& path,
                        const std::string& message) {
  error_at(where(node, path), message);
}

void Diagnostics::error_at(const std::string& where, const std::string& message) {
  const std::string problem = where + ": " + message;
  if (std::find(problems_.begin(), problems_.end(), problem) == problems_.end())
    problems_.push_back(problem);
}

std::string join_path(const std::string& parent, const std::string& key) {
  return parent.empty() ? key : parent + "." + key;
}
std::string index_path(const std::string& parent, std::size_t i) {
  return parent + "[" + std::to_string(i) + "]";
}

YAML::Node load_yaml(const std::string& text, const std::string& file_name) {
  YAML::Node root;
  try {
    root = YAML::Load(text);
  } catch (const YAML::ParserException& e) {
    throw InputError(file_name + ":" + std::to_string(e.mark.line + 1) + ":" +
                     std::to_string(e.mark.column + 1) + ": YAML syntax error: " + e.msg);
  }
  if (root.IsNull()) throw InputError(file_name + ": the input file is empty");
  return root;
}

namespace {
const char* file_kind(const std::filesystem::file_status& status) {
  namespace fs = std::filesystem;
  if (fs::is_directory(status)) return "a directory";
  if (fs::is_character_file(status)) return "a character device";
  if (fs::is_block_file(status)) return "a block device";
  if (fs::is_fifo(status)) return "a pipe";
  if (fs::is_socket(status)) return "a socket";
  return "not a regular file";
}
} // namespace

std::string read_text_file(const std::string& path) {
  namespace fs = std::filesystem;
  std::error_code ec;
  const fs::file_status status = fs::status(path, ec);
  if (ec || !fs::exists(status)) throw InputError(path + ": cannot open the input file");
  if (!fs::is_regular_file(status))
    throw InputError(path + ": is " + file_kind(status) +
                     ", not an input file (a regular YAML file is expected)");
  const std::string too_large = path + ": the input file is larger than " +
                                std::to_string(max_input_bytes >> 20) +
                                " MiB, the largest accepted";
  const auto size = fs::file_size(path, ec);
  if (!ec && size > max_input_bytes) throw InputError(too_large);
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path + ": cannot open the input file");
  // Bounded here too: the file may grow, and some (in /proc) report a size of 0.
  std::string text;
  std::string chunk(std::size_t(1) << 16, '\0');
  while (in.read(chunk.data(), static_cast<std::streamsize>(chunk.size())) || in.gcount() > 0) {
    text.append(chunk.data(), static_cast<std::size_t>(in.gcount()));
    if (text.size() > max_input_bytes) throw InputError(too_large);
  }
  return text;
}

bool decode_real(const YAML::Node& n, double& out) {
  if (!n.IsScalar()) return false;
  const std::string& s = n.Scalar();
  if (s == ".inf" || s == "-.inf" || s == ".nan") return false; // not meaningful inputs
  try {
    std::size_t used = 0;
    const double v = std::stod(s, &used);
    if (used != s.size() || !std::isfinite(v)) return false;
    out = v;
    return true;
  } catch (...) {
    return false;
  }
}

bool decode_integer(const YAML::Node& n, long& out) {
  if (!n.IsScalar()) return false;
  const std::string& s = n.Scalar();
  try {
    std::size_t used = 0;
    const long v = std::stol(s, &used);
    if (used != s.size()) return false;
    out = v;
    return true;
  } catch (...) {
    return false;
  }
}

namespace {
// "12", "-3", "+400000000000000000000": an integer literal, whatever its size.
bool is_whole_number(const std::string& s) {
  const std::size_t sign = !s.empty() && (s[0] == '+' || s[0] == '-') ? 1 : 0;
  return s.size() > sign && std::all_of(s.begin() + static_cast<std::ptrdiff_t>(sign), s.end(),
                                        [](unsigned char c) { return std::isdigit(c) != 0; });
}
} // namespace

std::string decode_int(const YAML::Node& n, int& out) {
  using limits = std::numeric_limits<int>;
  long v = 0;
  const bool decoded = decode_integer(n, v);
  if (!decoded && !(n.IsScalar() && is_whole_number(n.Scalar())))
    return "expected an integer, got " + describe_node(n);
  if (!decoded || v < limits::min() || v > limits::max())
    return "value " + n.Scalar() + " is out of range for an integer [" +
           std::to_string(limits::min()) + ", " + std::to_string(limits::max()) + "]";
  out = static_cast<int>(v);
  return "";
}

bool decode_boolean(const YAML::Node& n, bool& out) {
  if (!n.IsScalar()) return false;
  return YAML::convert<bool>::decode(n, out);
}

std::string describe_node(const YAML::Node& n) {
  if (n.IsSequence()) return "a list";
  if (n.IsMap()) return "a map";
  if (n.IsNull()) return "nothing";
  return "'" + n.Scalar() + "'";
}

void report_duplicate_keys(const YAML::Node& node, const std::string& path, Diagnostics& diag) {
  if (!node.IsMap()) return;
  std::map<std::string, YAML::Mark> first;
  for (const auto& kv : node) {
    if (!kv.first.IsScalar()) continue;
    const std::string& key = kv.first.Scalar();
    const auto [at, inserted] = first.emplace(key, kv.first.Mark());
    if (!inserted)
      diag.error(kv.first, join_path(path, key),
                 "key '" + key + "' given twice (first at line " +
                     std::to_string(at->second.line + 1) + ")");
  }
}

YamlMap::YamlMap(const YAML::Node& node, std::string path, Diagnostics& diag,
                 const std::vector<std::string>& allowed)
    : node_(node), path_(std::move(path)), diag_(diag) {
  if (!node_.IsMap()) {
    diag_.error(node_, path_, "expected a map of keys, got " + describe_node(node_));
    return;
  }
  valid_ = true;
  report_duplicate_keys(node_, path_, diag_);
  for (const auto& kv : node_) {
    const std::string key = kv.first.Scalar();
    if (std::find(allowed.begin(), allowed.end(), key) != allowed.end()) continue;
    std::string msg = "unknown key";
    const auto near = nearest_name(key, allowed);
    if (!near.empty()) msg += " (did you mean '" + near + "'?)";
    msg += "; allowed keys: " + join_names(allowed);
    diag_.error(kv.first, join_path(path_, key), msg);
  }
}

bool YamlMap::has(const std::string& key) const {
  if (!valid_) return false;
  const YAML::Node& n = node_;
  return static_cast<bool>(n[key]);
}

YAML::Node YamlMap::node(const std::string& key) const {
  const YAML::Node& n = node_;
  return n[key];
}

std::string YamlMap::where(const std::string& key) const {
  return has(key) ? diag_.where(node(key), path(key)) : diag_.where(node_, path(key));
}

std::string YamlMap::path_and_line() const {
  return path_ + " (line " + std::to_string(node_.Mark().line + 1) + ")";
}

void YamlMap::missing(const std::string& key, const std::string& doc) const {
  diag_.error(node_, path(key), "missing required key" + (doc.empty() ? "" : " (" + doc + ")"));
}

void YamlMap::error(const std::string& key, const std::string& message) const {
  diag_.error_at(where(key), message);
}

std::vector<YamlMap> list_entries(const YamlMap& parent, const std::string& key,
                                  const std::vector<std::string>& allowed,
                                  const std::string& expected) {
  std::vector<YamlMap> entries;
  const YAML::Node list = parent.node(key);
  if (!list.IsSequence()) {
    parent.error(key, expected);
    return entries;
  }
  for (std::size_t i = 0; i < list.size(); ++i)
    entries.emplace_back(list[i], index_path(parent.path(key), i), parent.diag(), allowed);
  return entries;
}

std::string UniqueNames::read(const YamlMap& entry, std::size_t index) {
  std::string name = what_ + std::to_string(index + 1);
  entry.string("name", name);
  const auto [at, inserted] = first_.emplace(name, entry.path_and_line());
  if (!inserted)
    entry.error("name",
                what_ + " name '" + name + "' is already the name of " + at->second + "; " + why_);
  return name;
}

namespace {
// Decoders return "" or what is wrong with the node.
template <class Decode, class T>
bool read_scalar(const YamlMap& m, const std::string& key, T& out, bool required, Decode decode) {
  if (!m.has(key)) {
    if (required && m.valid()) m.missing(key);
    return !required;
  }
  T v{};
  const std::string problem = decode(m.node(key), v);
  if (!problem.empty()) {
    m.error(key, problem);
    return false;
  }
  out = v;
  return true;
}

template <class Decode, class T>
bool read_list(const YamlMap& m, const std::string& key, std::vector<T>& out, bool required,
               const char* what, Decode decode) {
  if (!m.has(key)) {
    if (required && m.valid()) m.missing(key);
    return !required;
  }
  const YAML::Node n = m.node(key);
  if (!n.IsSequence()) {
    m.error(key, std::string("expected a list of ") + what + ", got " + describe_node(n));
    return false;
  }
  std::vector<T> values;
  bool ok = true;
  for (std::size_t i = 0; i < n.size(); ++i) {
    T v{};
    const std::string problem = decode(n[i], v);
    if (!problem.empty()) {
      m.diag().error(n[i], index_path(m.path(key), i), problem);
      ok = false;
    }
    values.push_back(v);
  }
  if (ok) out = values;
  return ok;
}

// A yes/no decoder as one that says what was expected.
template <class T> auto expecting(const char* what, bool (*decode)(const YAML::Node&, T&)) {
  return [what, decode](const YAML::Node& n, T& out) {
    return decode(n, out) ? std::string()
                          : std::string("expected ") + what + ", got " + describe_node(n);
  };
}

bool decode_string(const YAML::Node& n, std::string& out) {
  if (!n.IsScalar()) return false;
  out = n.Scalar();
  return true;
}
} // namespace

bool YamlMap::real(const std::string& key, double& out, bool required) const {
  return read_scalar(*this, key, out, required, expecting("a real number", decode_real));
}
bool YamlMap::integer(const std::string& key, int& out, bool required) const {
  return read_scalar(*this, key, out, required, decode_int);
}
bool YamlMap::boolean(const std::string& key, bool& out, bool required) const {
  return read_scalar(*this, key, out, required, expecting("true or false", decode_boolean));
}
bool YamlMap::string(const std::string& key, std::string& out, bool required) const {
  return read_scalar(*this, key, out, required, expecting("a string", decode_string));
}
bool YamlMap::reals(const std::string& key, std::vector<double>& out, bool required) const {
  return read_list(*this, key, out, required, "real numbers",
                   expecting("a real number", decode_real));
}
bool YamlMap::integers(const std::string& key, std::vector<int>& out, bool required) const {
  return read_list(*this, key, out, required, "integers", decode_int);
}
bool YamlMap::strings(const std::string& key, std::vector<std::string>& out, bool required) const {
  return read_list(*this, key, out, required, "strings", expecting("a string", decode_string));
}

} // namespace bipot::input
