#include "fem/linalg/detail/lu_preconditioner.hpp"

#include "fem/core/error.hpp"

#include <vector>

namespace bipot::detail {

void LuPreconditioner::factorize(const Teuchos::RCP<CrsMatrix>& A) {
  map_ = Teuchos::null; // not usable if the factorisation throws
  lu_.factorize(A);
  map_ = A->getRowMap();
}

void LuPreconditioner::apply(const MultiVector& X, MultiVector& Y, Teuchos::ETransp mode,
                             double alpha, double beta) const {
  if (mode != Teuchos::NO_TRANS) throw Error("LuPreconditioner: only A_old^{-1} x is available");
  if (map_.is_null()) throw Error("LuPreconditioner::apply before factorize()");
  const std::size_t n = X.getLocalLength();
  std::vector<double> x(n), y(n);
  for (std::size_t j = 0; j < X.getNumVectors(); ++j) {
    {
      auto xj = X.getData(j);
      std::copy(xj.getRawPtr(), xj.getRawPtr() + n, x.begin());
    }
    lu_.solve(x.data(), y.data());
    auto yj = Y.getDataNonConst(j);
    for (std::size_t i = 0; i < n; ++i)
      yj[i] = alpha * y[i] + (beta == 0.0 ? 0.0 : beta * yj[i]);
  }
}

} // namespace bipot::detail
