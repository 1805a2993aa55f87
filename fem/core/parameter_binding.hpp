#pragma once
/// Parameters declared once, bound to the member they fill. An object keeps its parameters
/// in a plain struct P and declares each key in a ParamSchemaOf<P> with a pointer to its
/// member:
///   ParamSchemaOf<Parameters> s("rccm", "...");
///   s.real("normal_stiffness", &Parameters::normal_stiffness, "kN/m^3", "...").positive();
///   s.real("friction_coefficient", &Parameters::friction_coefficient, "", "...").defaulted();
/// (defaulted(): the member's initializer is the default, so each value is written once.)
/// The untyped ParamSchema it derives from still serves the input checker, --describe and
/// the generated docs; the bindings fill P from a validated ParameterSet (fill) and write P
/// back as one (to_parameters), so no key string is written twice. Checked<P> is a P that
/// has passed through the schema exactly once: the input reader's validation (then fill) or
/// checked() for an object built from code, with the same messages either way.

#include "fem/core/parameter_schema.hpp"

#include <memory>
#include <optional>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace bipot {

template <class P> class ParamSchemaOf;

/// A P validated against its schema. Only ParamSchemaOf<P> makes one, so a constructor taking
/// Checked<P> need not validate again.
template <class P> class Checked {
public:
  const P& operator*() const { return value_; }
  const P* operator->() const { return &value_; }
  const P& value() const { return value_; }

private:
  friend class ParamSchemaOf<P>;
  struct Key {}; // two arguments, so a braced list never converts to a Checked
  Checked(P value, Key) : value_(std::move(value)) {}
  P value_;
};

namespace detail {
// The key type a member type maps to, and how a value crosses between them.
template <class T, class = void> struct ParamTraits;
template <> struct ParamTraits<double> {
  static constexpr ParamType type = ParamType::Real;
  static double read(const ParameterSet& s, const std::string& k) { return s.real(k); }
  static ParamValue write(double v) { return v; }
};
template <class T>
struct ParamTraits<T, std::enable_if_t<std::is_integral_v<T> && !std::is_same_v<T, bool>>> {
  static constexpr ParamType type = ParamType::Integer;
  static T read(const ParameterSet& s, const std::string& k) {
    return static_cast<T>(s.integer(k));
  }
  static ParamValue write(T v) { return static_cast<long>(v); }
};
template <> struct ParamTraits<bool> {
  static constexpr ParamType type = ParamType::Boolean;
  static bool read(const ParameterSet& s, const std::string& k) { return s.boolean(k); }
  static ParamValue write(bool v) { return v; }
};
template <> struct ParamTraits<std::string> {
  static constexpr ParamType type = ParamType::String;
  static std::string read(const ParameterSet& s, const std::string& k) { return s.string(k); }
  static ParamValue write(const std::string& v) { return v; }
};
template <> struct ParamTraits<std::vector<double>> {
  static constexpr ParamType type = ParamType::RealList;
  static std::vector<double> read(const ParameterSet& s, const std::string& k) {
    return s.real_list(k);
  }
  static ParamValue write(const std::vector<double>& v) { return v; }
};

template <class T> struct IsOptional : std::false_type {};
template <class T> struct IsOptional<std::optional<T>> : std::true_type { using value_type = T; };
} // namespace detail

/// The schema of the parameters struct P: every key bound to its member. The base's untyped
/// real()/integer()/... are hidden, so a key cannot be declared without its member. Declare
/// every key on one object: a copy shares the bindings of the schema it was copied from.
template <class P> class ParamSchemaOf : public ParamSchema {
public:
  ParamSchemaOf(std::string name, std::string doc)
      : ParamSchema(std::move(name), std::move(doc)),
        binders_(std::make_shared<std::vector<Binder>>()) {}

  /// A real key bound to a double or std::optional<double> member (optional: absent = empty).
  template <class T, class C>
  ParamSpec& real(const std::string& key, T C::*member, const std::string& units,
                  const std::string& doc) {
    return bind<ParamType::Real>(ParamSchema::real(key, units, doc), member);
  }
  /// An integer key bound to an int or long member, or an optional of one.
  template <class T, class C>
  ParamSpec& integer(const std::string& key, T C::*member, const std::string& doc) {
    return bind<ParamType::Integer>(ParamSchema::integer(key, doc), member);
  }
  /// A boolean key bound to a bool member.
  template <class T, class C>
  ParamSpec& boolean(const std::string& key, T C::*member, const std::string& doc) {
    return bind<ParamType::Boolean>(ParamSchema::boolean(key, doc), member);
  }
  /// A string key bound to a std::string member (`.one_of(...)` to restrict it).
  template <class T, class C>
  ParamSpec& string(const std::string& key, T C::*member, const std::string& doc) {
    return bind<ParamType::String>(ParamSchema::string(key, doc), member);
  }
  /// A list-of-reals key bound to a std::vector<double> member; its range applies to each
  /// entry (`.strictly_increasing()` to order them).
  template <class T, class C>
  ParamSpec& real_list(const std::string& key, T C::*member, const std::string& units,
                       const std::string& doc) {
    return bind<ParamType::RealList>(ParamSchema::real_list(key, units, doc), member);
  }
  /// A string key bound to an enum member: `names` gives the allowed strings (the key's
  /// one_of list, in that order) and the value each one stands for.
  template <class E, class C>
  ParamSpec& choice(const std::string& key, E C::*member,
                    std::vector<std::pair<std::string, E>> names, const std::string& doc) {
    static_assert(std::is_base_of_v<C, P>, "the member must belong to the parameters struct");
    E P::*m = member;
    std::vector<std::string> allowed;
    for (const auto& n : names)
      allowed.push_back(n.first);
    ParamSpec& spec = ParamSchema::string(key, doc).one_of(std::move(allowed));
    for (const auto& n : names)
      if (n.second == P{}.*m) spec.member_initial = n.first;
    binders_->push_back({key,
                         [key, m, names](const ParameterSet& s, P& p) {
                           if (!s.has(key)) return; // a rule's unread key
                           const std::string& v = s.string(key);
                           for (const auto& n : names)
                             if (n.first == v) p.*m = n.second;
                         },
                         [key, m, names](const P& p, ParameterSet& s) {
                           for (const auto& n : names)
                             if (n.second == p.*m) s.set(key, n.first);
                         }});
    return spec;
  }

  /// A condition between keys, written on the struct; reported at `key` (see ParamRule). With
  /// `reads` (the keys it depends on) it runs once those are valid, whatever the others; the
  /// struct's other members then hold what is valid, or their initial values.
  void rule(std::string key, std::string doc,
            std::function<std::optional<std::string>(const P&)> check,
            std::vector<std::string> reads = {}) {
    auto binders = binders_;
    ParamSchema::rule({std::move(key), std::move(doc),
                       [binders, check = std::move(check)](const ParameterSet& s) {
                         return check(read(*binders, s));
                       },
                       std::move(reads)});
  }

  /// P from parameters already validated against this schema (the input reader's): no second
  /// check. A key absent from `validated` takes its default; an optional one stays empty.
  Checked<P> fill(const ParameterSet& validated) const {
    ParameterSet all = validated;
    for (const auto& spec : specs())
      if (!all.has(spec.name) && spec.default_value) all.set(spec.name, *spec.default_value);
    return Checked<P>(read(*binders_, all), typename Checked<P>::Key{});
  }

  /// Validates `p` through this schema (ranges, choices, rules), for an object built from
  /// code; throws InputError with the messages an input file would get ("<schema>.<key>:").
  Checked<P> checked(const P& p) const {
    ParameterSet given = to_parameters(p);
    validate_or_throw(*this, given);
    return Checked<P>(p, typename Checked<P>::Key{});
  }

  /// The values of `p` by key; an empty optional member is left out.
  ParameterSet to_parameters(const P& p) const {
    ParameterSet s;
    for (const auto& b : *binders_)
      b.write(p, s);
    return s;
  }

  /// Whether `key` is bound to a member (every key of a ParamSchemaOf is; for tests).
  bool is_bound(const std::string& key) const {
    for (const auto& b : *binders_)
      if (b.key == key) return true;
    return false;
  }

private:
  struct Binder {
    std::string key;
    std::function<void(const ParameterSet&, P&)> read;
    std::function<void(const P&, ParameterSet&)> write;
  };

  static P read(const std::vector<Binder>& binders, const ParameterSet& s) {
    P p{};
    for (const auto& b : binders)
      b.read(s, p);
    return p;
  }

  template <ParamType K, class T, class C> ParamSpec& bind(ParamSpec& spec, T C::*member) {
    static_assert(std::is_base_of_v<C, P>, "the member must belong to the parameters struct");
    T P::*m = member;
    const std::string key = spec.name;
    if constexpr (detail::IsOptional<T>::value) {
      using V = typename detail::IsOptional<T>::value_type;
      using Traits = detail::ParamTraits<V>;
      static_assert(Traits::type == K, "the member's type does not match the key's");
      spec.optional();
      binders_->push_back({key,
                           [key, m](const ParameterSet& s, P& p) {
                             if (s.has(key))
                               p.*m = Traits::read(s, key);
                             else
                               p.*m = std::nullopt;
                           },
                           [key, m](const P& p, ParameterSet& s) {
                             if (p.*m) s.set(key, Traits::write(*(p.*m)));
                           }});
    } else {
      using Traits = detail::ParamTraits<T>;
      static_assert(Traits::type == K, "the member's type does not match the key's");
      spec.member_initial = Traits::write(P{}.*m);
      binders_->push_back(
          {key,
           [key, m](const ParameterSet& s, P& p) {
             if (s.has(key)) p.*m = Traits::read(s, key); // absent: a rule's unread key
           },
           [key, m](const P& p, ParameterSet& s) { s.set(key, Traits::write(p.*m)); }});
    }
    return spec;
  }

  // Shared with the closures of rule(), so that a copy of the schema (or the untyped
  // ParamSchema a registry keeps) still reads the struct.
  std::shared_ptr<std::vector<Binder>> binders_;
};

} // namespace bipot
