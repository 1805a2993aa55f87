#include "fem/core/parameter_schema.hpp"

#include <algorithm>
#include <set>
#include <stdexcept>

#include "fem/core/error.hpp"
#include "fem/core/nearest_name.hpp"

#include <cmath>
#include <sstream>

namespace bipot {

const char* to_string(ParamType type) {
  switch (type) {
  case ParamType::Real:
    return "real";
  case ParamType::Integer:
    return "integer";
  case ParamType::Boolean:
    return "boolean";
  case ParamType::String:
    return "string";
  case ParamType::RealList:
    return "list of reals";
  }
  return "?";
}

std::string format_value(const ParamValue& value) {
  std::ostringstream os;
  if (auto d = std::get_if<double>(&value))
    os << *d;
  else if (auto i = std::get_if<long>(&value))
    os << *i;
  else if (auto b = std::get_if<bool>(&value))
    os << (*b ? "true" : "false");
  else if (auto list = std::get_if<std::vector<double>>(&value)) {
    os << '[';
    for (std::size_t k = 0; k < list->size(); ++k)
      os << (k ? ", " : "") << (*list)[k];
    os << ']';
  } else
    os << '"' << std::get<std::string>(value) << '"';
  return os.str();
}

ParamSpec& ParamSpec::with_default(ParamValue v) {
  required = false;
  default_value = std::move(v);
  return *this;
}
ParamSpec& ParamSpec::defaulted() {
  if (!member_initial)
    throw std::logic_error("parameter '" + name +
                           "': defaulted() needs a bound, non-optional member");
  return with_default(*member_initial);
}
ParamSpec& ParamSpec::optional() {
  required = false;
  default_value.reset();
  return *this;
}
ParamSpec& ParamSpec::positive() {
  return greater_than(0.0);
}
ParamSpec& ParamSpec::non_negative() {
  return at_least(0.0);
}
ParamSpec& ParamSpec::at_least(double v) {
  lower = v;
  lower_open = false;
  return *this;
}
ParamSpec& ParamSpec::greater_than(double v) {
  lower = v;
  lower_open = true;
  return *this;
}
ParamSpec& ParamSpec::at_most(double v) {
  upper = v;
  upper_open = false;
  return *this;
}
ParamSpec& ParamSpec::less_than(double v) {
  upper = v;
  upper_open = true;
  return *this;
}
ParamSpec& ParamSpec::one_of(std::vector<std::string> allowed) {
  choices = std::move(allowed);
  return *this;
}

ParamSpec& ParamSpec::strictly_increasing() {
  increasing = true;
  return *this;
}

std::string ParamSpec::range_text() const {
  if (type != ParamType::RealList) return interval_text();
  const std::string each = interval_text();
  if (each.empty()) return increasing ? "increasing" : "";
  return "each in " + each + (increasing ? ", increasing" : "");
}

std::string ParamSpec::interval_text() const {
  if (std::isinf(lower) && std::isinf(upper)) return "";
  std::ostringstream os;
  // An integer key's bounds in full: [1, 1000000], not [1, 1e+06].
  const auto bound = [&](double b) {
    if (type == ParamType::Integer)
      os << static_cast<long long>(b);
    else
      os << b;
  };
  os << (lower_open ? '(' : '[');
  if (std::isinf(lower))
    os << "-inf";
  else
    bound(lower);
  os << ", ";
  if (std::isinf(upper))
    os << "inf";
  else
    bound(upper);
  os << (upper_open ? ')' : ']');
  return os.str();
}

std::optional<std::string> ParamSpec::check(const ParamValue& value) const {
  double x = 0;
  if (auto d = std::get_if<double>(&value))
    x = *d;
  else if (auto i = std::get_if<long>(&value))
    x = static_cast<double>(*i);
  else if (auto s = std::get_if<std::string>(&value)) {
    if (choices.empty()) return std::nullopt;
    for (const auto& c : choices)
      if (c == *s) return std::nullopt;
    std::string msg = "value \"" + *s + "\" is not one of: " + join_names(choices);
    const auto near = nearest_name(*s, choices);
    if (!near.empty()) msg += " (did you mean \"" + near + "\"?)";
    return msg;
  } else {
    return std::nullopt;
  }
  const bool below = lower_open ? !(x > lower) : !(x >= lower);
  const bool above = upper_open ? !(x < upper) : !(x <= upper);
  if (std::isnan(x) || below || above) {
    std::string msg = "value " + format_value(value) + " is out of range " + interval_text();
    if (!units.empty()) msg += " " + units;
    if (!range_reason.empty()) msg += ": " + range_reason;
    return msg;
  }
  return std::nullopt;
}

std::optional<std::string> ParamSpec::check_entry(const std::vector<double>& list,
                                                  std::size_t i) const {
  if (auto msg = check(list[i])) return msg;
  if (increasing && i > 0 && !(list[i] > list[i - 1]))
    return "value " + format_value(list[i]) + " does not exceed the entry before it (" +
           format_value(list[i - 1]) + "): the entries must increase";
  return std::nullopt;
}

ParamSpec& ParamSpec::because(std::string reason) {
  range_reason = std::move(reason);
  return *this;
}

std::string ParamSpec::summary() const {
  std::ostringstream os;
  os << to_string(type);
  if (required)
    os << ", required";
  else if (default_value)
    os << ", default " << format_value(*default_value);
  else
    os << ", optional";
  const auto range = range_text();
  if (!range.empty()) os << ", " << range;
  if (!choices.empty()) os << ", one of {" << join_names(choices) << "}";
  if (!units.empty()) os << ", " << units;
  os << ": " << doc;
  return os.str();
}

std::vector<std::string> ParamSchema::keys() const {
  std::vector<std::string> out;
  for (const auto& s : specs_)
    out.push_back(s.name);
  return out;
}

const ParamSpec* ParamSchema::find(const std::string& key) const {
  for (const auto& s : specs_)
    if (s.name == key) return &s;
  return nullptr;
}

ParamSpec& ParamSchema::add(const std::string& key, ParamType type, const std::string& units,
                            const std::string& doc) {
  ParamSpec s;
  s.name = key;
  s.type = type;
  s.units = units;
  s.doc = doc;
  specs_.push_back(std::move(s));
  return specs_.back();
}

ParamSpec& ParamSchema::real(const std::string& key, const std::string& units,
                             const std::string& doc) {
  return add(key, ParamType::Real, units, doc);
}
ParamSpec& ParamSchema::integer(const std::string& key, const std::string& doc) {
  return add(key, ParamType::Integer, "", doc);
}
ParamSpec& ParamSchema::boolean(const std::string& key, const std::string& doc) {
  return add(key, ParamType::Boolean, "", doc);
}
ParamSpec& ParamSchema::string(const std::string& key, const std::string& doc) {
  return add(key, ParamType::String, "", doc);
}
ParamSpec& ParamSchema::real_list(const std::string& key, const std::string& units,
                                  const std::string& doc) {
  return add(key, ParamType::RealList, units, doc);
}

std::string ParamSchema::describe() const {
  std::ostringstream os;
  os << name_ << ": " << doc_ << "\n";
  if (specs_.empty()) os << "  (no parameters)\n";
  for (const auto& s : specs_)
    os << "  " << s.name << " (" << s.summary() << ")\n";
  for (const auto& r : rules_)
    os << "  rule: " << r.doc << "\n";
  return os.str();
}

std::string ParamSchema::markdown_table() const {
  std::ostringstream os;
  if (specs_.empty()) return "No parameters.\n";
  os << "| key | type | default | range | units | description |\n";
  os << "|---|---|---|---|---|---|\n";
  for (const auto& s : specs_) {
    std::string range = s.range_text();
    if (!s.choices.empty()) range = "one of " + join_names(s.choices, ", ");
    os << "| `" << s.name << "` | " << to_string(s.type) << " | "
       << (s.required ? std::string("required")
                      : (s.default_value ? format_value(*s.default_value) : std::string("-")))
       << " | " << range << " | " << s.units << " | " << s.doc << " |\n";
  }
  if (!rules_.empty()) os << "\nRules between keys:\n";
  for (const auto& r : rules_)
    os << "- " << r.doc << "\n";
  return os.str();
}

const ParamValue& ParameterSet::at(const std::string& key) const {
  auto it = values_.find(key);
  if (it == values_.end()) throw Error("parameter '" + key + "' is not set");
  return it->second;
}
double ParameterSet::real(const std::string& key) const {
  const auto& v = at(key);
  if (auto d = std::get_if<double>(&v)) return *d;
  if (auto i = std::get_if<long>(&v)) return static_cast<double>(*i);
  throw Error("parameter '" + key + "' is not a real number");
}
long ParameterSet::integer(const std::string& key) const {
  if (auto i = std::get_if<long>(&at(key))) return *i;
  throw Error("parameter '" + key + "' is not an integer");
}
bool ParameterSet::boolean(const std::string& key) const {
  if (auto b = std::get_if<bool>(&at(key))) return *b;
  throw Error("parameter '" + key + "' is not a boolean");
}
const std::string& ParameterSet::string(const std::string& key) const {
  if (auto s = std::get_if<std::string>(&at(key))) return *s;
  throw Error("parameter '" + key + "' is not a string");
}
const std::vector<double>& ParameterSet::real_list(const std::string& key) const {
  if (auto l = std::get_if<std::vector<double>>(&at(key))) return *l;
  throw Error("parameter '" + key + "' is not a list of reals");
}

namespace {
bool type_matches(ParamType type, ParamValue& value) {
  switch (type) {
  case ParamType::Real:
    if (auto i = std::get_if<long>(&value)) value = static_cast<double>(*i);
    return std::holds_alternative<double>(value);
  case ParamType::Integer:
    return std::holds_alternative<long>(value);
  case ParamType::Boolean:
    return std::holds_alternative<bool>(value);
  case ParamType::String:
    return std::holds_alternative<std::string>(value);
  case ParamType::RealList:
    return std::holds_alternative<std::vector<double>>(value);
  }
  return false;
}
} // namespace

std::vector<ParamProblem> validate(const ParamSchema& schema, ParameterSet& given) {
  std::vector<ParamProblem> problems;
  ParameterSet out;
  for (const auto& [key, value] : given.values()) {
    const ParamSpec* spec = schema.find(key);
    if (!spec) {
      std::string msg = "unknown key for '" + schema.name() + "'";
      const auto near = nearest_name(key, schema.keys());
      if (!near.empty()) msg += " (did you mean '" + near + "'?)";
      msg += "; allowed keys: " + (schema.keys().empty() ? "none" : join_names(schema.keys()));
      problems.push_back({key, msg});
      continue;
    }
    ParamValue v = value;
    if (!type_matches(spec->type, v)) {
      const char* article = spec->type == ParamType::Integer ? "an " : "a ";
      problems.push_back({key, "expected " + std::string(article) + to_string(spec->type) +
                                   ", got " + format_value(value)});
      continue;
    }
    if (auto list = std::get_if<std::vector<double>>(&v)) {
      // Every bad entry is reported, each at its own place; one makes the key invalid.
      const std::size_t before = problems.size();
      for (std::size_t k = 0; k < list->size(); ++k)
        if (auto msg = spec->check_entry(*list, k)) problems.push_back({key, *msg, k});
      if (problems.size() > before) continue;
    } else if (auto msg = spec->check(v)) {
      problems.push_back({key, *msg});
      continue;
    }
    out.set(key, v);
  }
  for (const auto& spec : schema.specs()) {
    if (given.has(spec.name)) continue;
    if (spec.required)
      problems.push_back({spec.name, "missing required key (" + spec.summary() + ")"});
    else if (spec.default_value)
      out.set(spec.name, *spec.default_value);
  }
  given = out;
  // A rule runs once the keys it reads are valid: all of them, unless it names its own.
  std::set<std::string> invalid;
  for (const auto& p : problems)
    invalid.insert(p.key);
  std::vector<ParamProblem> broken;
  for (const auto& rule : schema.rules()) {
    const bool ready =
        rule.reads.empty()
            ? problems.empty()
            : std::all_of(rule.reads.begin(), rule.reads.end(),
                          [&](const std::string& k) { return !invalid.count(k) && given.has(k); });
    if (!ready) continue;
    if (auto msg = rule.check(given)) broken.push_back({rule.key, *msg});
  }
  problems.insert(problems.end(), broken.begin(), broken.end());
  return problems;
}

void validate_or_throw(const ParamSchema& schema, ParameterSet& given) {
  const auto problems = validate(schema, given);
  if (problems.empty()) return;
  std::vector<std::string> lines;
  for (const auto& p : problems)
    lines.push_back(schema.name() + "." + p.key +
                    (p.entry ? "[" + std::to_string(*p.entry) + "]" : "") + ": " + p.message);
  throw InputError(lines);
}

} // namespace bipot
