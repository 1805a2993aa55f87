#pragma once
/// The catalogue of everything bipot ships: the wiring of materials/ and contact/ into the
/// registries the reader and the model builder are given.

#include "apps/catalogue/catalogue.hpp"

namespace bipot {

/// A fresh catalogue with every built-in material and interface law. A value: an
/// application may add its own entries before using it, e.g.
///   Catalogue catalogue = builtin_catalogue();
///   catalogue.interface_laws.add<MyLaw>(); // MyLaw::schema(), MyLaw(Checked<Parameters>)
///   Model model = build_model(read_problem_file(path, catalogue), catalogue);
Catalogue builtin_catalogue();

} // namespace bipot
