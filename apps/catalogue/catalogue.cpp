#include "apps/catalogue/catalogue.hpp"

#include "apps/catalogue/contact_module.hpp"

namespace bipot {

Model build_model(const ProblemSpec& spec, const Catalogue& catalogue) {
  return build_model(spec, catalogue.materials, contact_module(catalogue.interface_laws));
}

} // namespace bipot
