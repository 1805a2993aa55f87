#pragma once
/// Parameter schemas (MOOSE validParams / FEBio parameter tables): every material, interface
/// law and solver declares its keys with type, default, range, units and a one-line doc.
/// The same schema validates input, formats error messages and generates the docs.

#include <functional>
#include <limits>
#include <map>
#include <optional>
#include <string>
#include <variant>
#include <vector>

namespace bipot {

/// RealList: a list of reals (load factors, levels), each entry within the key's range.
enum class ParamType { Real, Integer, Boolean, String, RealList };

/// "real", "integer", "boolean", "string", "list of reals".
const char* to_string(ParamType type);

/// A parameter value as given by the user or a default.
using ParamValue = std::variant<double, long, bool, std::string, std::vector<double>>;

/// One key of a schema. Built fluently: `schema.real("youngs_modulus", "kPa", "...").positive()`.
struct ParamSpec {
  std::string name;
  ParamType type = ParamType::Real;
  std::string units; ///< "" for dimensionless
  std::string doc;
  bool required = true;
  std::optional<ParamValue> default_value;
  /// The initial value of the struct member a ParamSchemaOf key is bound to (empty for an
  /// unbound key or an optional member): what defaulted() makes the default.
  std::optional<ParamValue> member_initial;
  double lower = -std::numeric_limits<double>::infinity();
  double upper = std::numeric_limits<double>::infinity();
  bool lower_open = true; ///< the bound itself is excluded (always true for an infinite bound)
  bool upper_open = true;
  std::vector<std::string> choices; ///< allowed strings, empty = any
  std::string range_reason;         ///< why the range is what it is, for the message ("" = none)
  bool increasing = false;          ///< a list's entries must increase strictly

  ParamSpec& with_default(ParamValue v);
  /// The default is the bound member's initial value (ParamSchemaOf keys): written once, in
  /// the parameters struct. Throws std::logic_error for a key without one.
  ParamSpec& defaulted();
  /// Not required and without default: an absent key turns a feature off
  /// (ParameterSet::has tells).
  ParamSpec& optional();
  ParamSpec& positive();             ///< (0, inf)
  ParamSpec& non_negative();         ///< [0, inf)
  ParamSpec& at_least(double v);     ///< [v, ...
  ParamSpec& greater_than(double v); ///< (v, ...
  ParamSpec& at_most(double v);      ///< ..., v]
  ParamSpec& less_than(double v);    ///< ..., v)
  ParamSpec& one_of(std::vector<std::string> allowed);
  /// Appended to the out-of-range message, for a bound that is not obvious.
  ParamSpec& because(std::string reason);
  /// A list whose entries must increase strictly (each greater than the one before).
  ParamSpec& strictly_increasing();

  /// The bounds: "[0, 1]", "(0, inf)", "" when unbounded.
  std::string interval_text() const;
  /// The interval_text() of a scalar; a list's says what applies to each entry and to their
  /// order: "each in (0, 1], increasing".
  std::string range_text() const;
  /// The problem with a scalar value of the right type, if any, e.g.
  /// "value -3 is out of range (0, inf) kPa". Type mismatches are the caller's business; a
  /// list's entries are checked one by one (check_entry).
  std::optional<std::string> check(const ParamValue& value) const;
  /// The problem with entry `i` of a list, if any: out of range (as check()), or, for a
  /// strictly_increasing() key, not greater than the entry before it.
  std::optional<std::string> check_entry(const std::vector<double>& list, std::size_t i) const;
  /// "real, required, (0, inf) kPa: Young's modulus" — one line for --describe and docs.
  std::string summary() const;
};

class ParameterSet;

/// A condition between keys (e.g. dilatancy angle ≤ friction angle), checked once every key
/// is valid on its own — or, when `reads` names the keys it depends on, once those are valid,
/// so that an input with a problem elsewhere still hears of this one. `check` returns the
/// problem or nullopt; it is reported at `key`.
struct ParamRule {
  std::string key;
  std::string doc; ///< the condition in words, for --describe and the docs
  std::function<std::optional<std::string>(const ParameterSet&)> check;
  std::vector<std::string> reads = {}; ///< the keys `check` reads; empty: all of them
};

/// The ordered list of keys a named object accepts.
class ParamSchema {
public:
  ParamSchema() = default;
  ParamSchema(std::string name, std::string doc) : name_(std::move(name)), doc_(std::move(doc)) {}

  const std::string& name() const { return name_; }
  const std::string& doc() const { return doc_; }
  /// The same keys under another name: a law or material a project derives from a registered
  /// one registers under a name of its own.
  void rename(std::string name, std::string doc) {
    name_ = std::move(name);
    doc_ = std::move(doc);
  }
  const std::vector<ParamSpec>& specs() const { return specs_; }
  std::vector<std::string> keys() const;
  const ParamSpec* find(const std::string& key) const;

  ParamSpec& real(const std::string& key, const std::string& units, const std::string& doc);
  ParamSpec& integer(const std::string& key, const std::string& doc);
  ParamSpec& boolean(const std::string& key, const std::string& doc);
  ParamSpec& string(const std::string& key, const std::string& doc);
  /// A list of reals; the range set on it (positive(), at_most(), ...) applies to each entry.
  ParamSpec& real_list(const std::string& key, const std::string& units, const std::string& doc);
  /// Adds a cross-key rule (see ParamRule).
  void rule(ParamRule rule) { rules_.push_back(std::move(rule)); }
  const std::vector<ParamRule>& rules() const { return rules_; }

  /// Human-readable description: name, doc, then one line per key.
  std::string describe() const;
  /// A Markdown table of the keys (docs are generated from this so they cannot drift).
  std::string markdown_table() const;

private:
  ParamSpec& add(const std::string& key, ParamType type, const std::string& units,
                 const std::string& doc);
  std::string name_;
  std::string doc_;
  std::vector<ParamSpec> specs_;
  std::vector<ParamRule> rules_;
};

/// Validated parameter values by key. Typed getters throw bipot::Error on a missing key or
/// wrong type (a programming error once validation passed).
class ParameterSet {
public:
  void set(const std::string& key, ParamValue value) { values_[key] = std::move(value); }
  bool has(const std::string& key) const { return values_.count(key) != 0; }
  double real(const std::string& key) const;
  long integer(const std::string& key) const;
  bool boolean(const std::string& key) const;
  const std::string& string(const std::string& key) const;
  const std::vector<double>& real_list(const std::string& key) const;
  const std::map<std::string, ParamValue>& values() const { return values_; }

private:
  const ParamValue& at(const std::string& key) const;
  std::map<std::string, ParamValue> values_;
};

/// One problem found by validate(): the key it concerns and a message; for a list key, the
/// entry at fault (reported as key[entry], at that entry's line).
struct ParamProblem {
  std::string key;
  std::string message;
  std::optional<std::size_t> entry = std::nullopt;
};

/// Checks `given` against `schema` (unknown keys with the nearest valid one, missing required
/// keys with their doc, wrong types, out-of-range values and every bad entry of a list, then,
/// if all of that passed, the schema's cross-key rules) and fills in defaults.
/// An integer given where a real is expected is accepted and converted.
std::vector<ParamProblem> validate(const ParamSchema& schema, ParameterSet& given);

/// validate(), then throws InputError listing every problem as "<schema>.<key>: message"
/// ("<schema>.<key>[i]: message" for a list's entry i).
/// For objects built from code rather than from an input file.
void validate_or_throw(const ParamSchema& schema, ParameterSet& given);

/// Formats a value for messages ("1e+30", "true", "\"abc\"", "[0.5, 1]").
std::string format_value(const ParamValue& value);

} // namespace bipot
