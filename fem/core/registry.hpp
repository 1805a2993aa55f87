#pragma once
/// Explicit registry of named types (materials, interface laws, solvers). Each module has one
/// register_*() function with one line per type: static self-registration would be dropped
/// by the linker from static libraries.

#include "fem/core/error.hpp"
#include "fem/core/nearest_name.hpp"
#include "fem/core/parameter_schema.hpp"

#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace bipot {

template <class Base> class Registry {
public:
  using Factory = std::function<std::unique_ptr<Base>(const ParameterSet&)>;

  /// `what` names the kind of entry in messages ("material", "interface law").
  explicit Registry(std::string what) : what_(std::move(what)) {}

  void add(ParamSchema schema, Factory factory) {
    const std::string name = schema.name();
    entries_[name] = Entry{std::move(schema), std::move(factory)};
  }
  bool contains(const std::string& name) const { return entries_.count(name) != 0; }
  std::vector<std::string> names() const {
    std::vector<std::string> out;
    for (const auto& kv : entries_)
      out.push_back(kv.first);
    return out;
  }
  const std::string& what() const { return what_; }

  /// "unknown material 'x' (did you mean 'y'?); registered: a, b" — shared by all callers.
  std::string unknown_message(const std::string& name) const {
    std::string msg = "unknown " + what_ + " '" + name + "'";
    const auto near = nearest_name(name, names());
    if (!near.empty()) msg += " (did you mean '" + near + "'?)";
    return msg + "; registered: " + join_names(names());
  }

  const ParamSchema& schema(const std::string& name) const { return entry(name).schema; }

  /// Validates `params` (defaults filled in) and builds the object; throws InputError with
  /// every problem found.
  std::unique_ptr<Base> create(const std::string& name, ParameterSet params) const {
    const Entry& e = entry(name);
    validate_or_throw(e.schema, params);
    return e.factory(params);
  }

private:
  struct Entry {
    ParamSchema schema;
    Factory factory;
  };
  const Entry& entry(const std::string& name) const {
    auto it = entries_.find(name);
    if (it == entries_.end()) throw InputError(unknown_message(name));
    return it->second;
  }
  std::string what_;
  std::map<std::string, Entry> entries_;
};

} // namespace bipot
