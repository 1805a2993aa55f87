#pragma once
/// Explicit registry of named types (materials, interface laws, solvers). Each module has one
/// register_*() function with one line per type: static self-registration would be dropped
/// by the linker from static libraries.

#include "fem/core/error.hpp"
#include "fem/core/nearest_name.hpp"
#include "fem/core/parameter_binding.hpp"

#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace bipot {

/// What the input reader needs of a registry: its names and their parameter schemas, without
/// the type of the objects it builds (fem/input validates laws and materials it cannot name).
class SchemaIndex {
public:
  virtual ~SchemaIndex() = default;
  /// The kind of entry in messages ("material", "interface law").
  virtual const std::string& what() const = 0;
  virtual bool contains(const std::string& name) const = 0;
  virtual std::vector<std::string> names() const = 0;
  /// Throws InputError with unknown_message() for a name not registered.
  virtual const ParamSchema& schema(const std::string& name) const = 0;

  /// "unknown material 'x' (did you mean 'y'?); registered: a, b" — shared by all callers.
  std::string unknown_message(const std::string& name) const {
    std::string msg = "unknown " + what() + " '" + name + "'";
    const auto near = nearest_name(name, names());
    if (!near.empty()) msg += " (did you mean '" + near + "'?)";
    return msg + "; registered: " + join_names(names());
  }
};

/// Names → (schema, factory). A value type: an application starts from the built-in
/// entries (apps/catalogue) and adds its own before handing the registry to the reader and
/// the model builder; nothing registers itself globally.
template <class Base> class Registry : public SchemaIndex {
public:
  using Factory = std::function<std::unique_ptr<Base>(const ParameterSet&)>;

  /// `what` names the kind of entry in messages ("material", "interface law").
  explicit Registry(std::string what) : what_(std::move(what)) {}

  /// Throws bipot::Error if the name is taken: a project adding a law of the same name as a
  /// built-in one must not replace it silently.
  void add(ParamSchema schema, Factory factory) {
    const std::string name = schema.name();
    if (contains(name)) throw Error(what_ + " '" + name + "' is registered twice");
    entries_[name] = Entry{std::move(schema), std::move(factory)};
  }
  /// Registers T under T::schema() (a ParamSchemaOf<T::Parameters>), built by its constructor
  /// from Checked<T::Parameters>: the one-line registration of a law or material.
  template <class T> void add() {
    auto schema = T::schema();
    add(schema, [schema](const ParameterSet& p) -> std::unique_ptr<Base> {
      return std::make_unique<T>(schema.fill(p));
    });
  }
  bool contains(const std::string& name) const override { return entries_.count(name) != 0; }
  std::vector<std::string> names() const override {
    std::vector<std::string> out;
    for (const auto& kv : entries_)
      out.push_back(kv.first);
    return out;
  }
  const std::string& what() const override { return what_; }

  const ParamSchema& schema(const std::string& name) const override { return entry(name).schema; }

  /// Validates `params` (defaults filled in) and builds the object; throws InputError with
  /// every problem found.
  std::unique_ptr<Base> create(const std::string& name, ParameterSet params) const {
    const Entry& e = entry(name);
    validate_or_throw(e.schema, params);
    return e.factory(params);
  }

  /// Builds the object from parameters the input reader has already validated against
  /// schema(name) (file:line:col messages): no second validation.
  std::unique_ptr<Base> create_validated(const std::string& name,
                                         const ParameterSet& validated) const {
    return entry(name).factory(validated);
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
