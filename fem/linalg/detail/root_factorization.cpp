// Defaults of RootFactorization's Schur-complement interface: a package without it says so.
#include "fem/linalg/detail/root_factorization.hpp"

#include <stdexcept>

namespace bipot::detail {

namespace {
[[noreturn]] void no_schur() {
  throw std::runtime_error("this sparse LU package cannot compute a Schur complement "
                           "(use factorization: mumps)");
}
} // namespace

void RootFactorization::set_schur_variables(const std::vector<long long>&) {
  no_schur();
}
std::vector<double> RootFactorization::take_schur() {
  no_schur();
}
void RootFactorization::reduce(const double*, double*, double*) {
  no_schur();
}
void RootFactorization::expand(double*, const double*, double*) {
  no_schur();
}

} // namespace bipot::detail
