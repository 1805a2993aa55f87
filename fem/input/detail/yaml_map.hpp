#pragma once
/// Internal to fem/input: one-pass validation helpers over yaml-cpp nodes. Every problem is
/// recorded (not thrown) as "file:line:col: key.path: message" so a user sees all of them at
/// once. Nodes are only read through const references: yaml-cpp's non-const operator[]
/// inserts keys. yaml-cpp marks are 0-based; messages are 1-based like compilers'.

#include <yaml-cpp/yaml.h>

#include <map>
#include <string>
#include <vector>

namespace bipot::input {

class Diagnostics {
public:
  explicit Diagnostics(std::string file) : file_(std::move(file)) {}
  /// "file:line:col: path" for a node.
  std::string where(const YAML::Node& node, const std::string& path) const;
  void error(const YAML::Node& node, const std::string& path, const std::string& message);
  /// A problem whose location is already formatted by where(). A problem already recorded
  /// (the same map read by two readers) is not repeated.
  void error_at(const std::string& where, const std::string& message);
  const std::vector<std::string>& problems() const { return problems_; }
  const std::string& file() const { return file_; }

private:
  std::string file_;
  std::vector<std::string> problems_;
};

/// "a.b" or "a[2]" path helpers.
std::string join_path(const std::string& parent, const std::string& key);
std::string index_path(const std::string& parent, std::size_t i);

/// Records every key of the map `node` given more than once, at each repetition: yaml-cpp
/// keeps them all and looks up the first, so the later values would be silently ignored.
void report_duplicate_keys(const YAML::Node& node, const std::string& path, Diagnostics& diag);

/// A YAML mapping with a fixed set of allowed keys. Construction reports a non-map node,
/// every unknown key (with the nearest allowed key) and every key given twice.
class YamlMap {
public:
  YamlMap(const YAML::Node& node, std::string path, Diagnostics& diag,
          const std::vector<std::string>& allowed);

  bool valid() const { return valid_; }
  bool has(const std::string& key) const;
  YAML::Node node(const std::string& key) const;
  const YAML::Node& self() const { return node_; }
  std::string path(const std::string& key) const { return join_path(path_, key); }
  const std::string& path() const { return path_; }
  /// "stages[0] (line 12)": how messages name this map when they are about another one.
  std::string path_and_line() const;
  std::string where(const std::string& key) const;
  /// "file:line:col: path" of the map itself.
  std::string where() const { return diag_.where(node_, path_); }
  Diagnostics& diag() const { return diag_; }

  /// Typed readers: return false (and record the problem) on a wrong type or when a required
  /// key is missing; leave `out` untouched when an optional key is absent. Integers must fit
  /// in an int: a larger one is out of range, never wrapped.
  bool real(const std::string& key, double& out, bool required = false) const;
  bool integer(const std::string& key, int& out, bool required = false) const;
  bool boolean(const std::string& key, bool& out, bool required = false) const;
  bool string(const std::string& key, std::string& out, bool required = false) const;
  bool reals(const std::string& key, std::vector<double>& out, bool required = false) const;
  bool integers(const std::string& key, std::vector<int>& out, bool required = false) const;
  bool strings(const std::string& key, std::vector<std::string>& out, bool required = false) const;
  /// Records "missing required key" at this map.
  void missing(const std::string& key, const std::string& doc = "") const;
  /// Records a problem at a key (or at the map if the key is absent).
  void error(const std::string& key, const std::string& message) const;

private:
  YAML::Node node_;
  std::string path_;
  Diagnostics& diag_;
  bool valid_ = false;
};

/// The entries of the list parent[key], each read as a map of the `allowed` keys (one that is
/// not a map is reported and not valid(), so that indices stay the list's). If parent[key] is
/// not a list, records `expected` there and returns none.
std::vector<YamlMap> list_entries(const YamlMap& parent, const std::string& key,
                                  const std::vector<std::string>& allowed,
                                  const std::string& expected);

/// The names of a list's entries (stages, interfaces), which must differ: a name given again
/// is reported at that entry's `name` key, with the entry that has it already.
class UniqueNames {
public:
  /// `what` ("stage") names the entries in messages; `why` says why names must differ.
  UniqueNames(std::string what, std::string why) : what_(std::move(what)), why_(std::move(why)) {}
  /// The `name` of the list's entry `index` (0-based), by default `what` and index + 1
  /// ("stage2"), checked against the names before it.
  std::string read(const YamlMap& entry, std::size_t index);

private:
  std::string what_, why_;
  std::map<std::string, std::string> first_; ///< name -> "stages[0] (line 11)"
};

/// Parses YAML text; throws InputError "file:line:col: YAML syntax error: ..." or
/// "file: the input file is empty".
YAML::Node load_yaml(const std::string& text, const std::string& file_name);

/// Input files larger than this are refused before they are parsed (64 MiB).
constexpr std::size_t max_input_bytes = std::size_t(64) << 20;
/// The whole content of a regular file of at most max_input_bytes, read with that bound (a
/// device such as /dev/zero, a pipe or a directory is refused before reading). Throws
/// InputError "path: cannot open the input file" or "path: ..." saying why it is refused.
std::string read_text_file(const std::string& path);

/// Decodes a scalar as a double / long / bool; false if it is not one.
bool decode_real(const YAML::Node& n, double& out);
bool decode_integer(const YAML::Node& n, long& out);
/// Decodes a scalar as an int: "" on success, else the problem: "expected an integer, got
/// 'x'", or for a whole number beyond an int (even beyond a long) "value 4294967297 is out of
/// range for an integer [-2147483648, 2147483647]".
std::string decode_int(const YAML::Node& n, int& out);
bool decode_boolean(const YAML::Node& n, bool& out);
/// The node's text for messages ("[...]" for a sequence, "{...}" for a map).
std::string describe_node(const YAML::Node& n);

} // namespace bipot::input
