// Amesos2 KLU2 on a one-process Tpetra matrix (see rooted_direct_solver.hpp for why the
// matrix is gathered by us rather than by Amesos2).
#include "fem/linalg/detail/root_factorization.hpp"
#include "fem/linalg/detail/tpetra_types.hpp"

#include <Amesos2.hpp>
#include <Teuchos_DefaultMpiComm.hpp>

#include <mpi.h>

namespace bipot::detail {

namespace {

class Klu2Factorization final : public RootFactorization {
public:
  void analyse(const RootCsr& s) override {
    structure_ = &s;
    solver_ = Teuchos::null;
    const std::size_t n = s.size();
    auto self = Teuchos::rcp(new Teuchos::MpiComm<int>(MPI_COMM_SELF));
    auto map = Teuchos::rcp(new Map(static_cast<Tpetra::global_size_t>(n), GO(0), self));
    std::vector<std::size_t> counts(n);
    for (std::size_t r = 0; r < n; ++r)
      counts[r] = s.row_ptr[r + 1] - s.row_ptr[r];
    auto graph = Teuchos::rcp(
        new CrsGraph(map, Teuchos::ArrayView<const std::size_t>(counts.data(), counts.size()),
                     Tpetra::StaticProfile));
    for (std::size_t r = 0; r < n; ++r)
      graph->insertGlobalIndices(static_cast<GO>(r), static_cast<int>(counts[r]),
                                 s.cols.data() + s.row_ptr[r]);
    graph->fillComplete();
    matrix_ = Teuchos::rcp(new CrsMatrix(graph));
    x_ = Teuchos::rcp(new MultiVector(map, 1));
    b_ = Teuchos::rcp(new MultiVector(map, 1));
  }

  void factorize(const std::vector<double>& values) override {
    const RootCsr& s = *structure_;
    if (matrix_->isFillComplete()) matrix_->resumeFill();
    for (std::size_t r = 0; r < s.size(); ++r) {
      const auto begin = s.row_ptr[r];
      matrix_->replaceGlobalValues(static_cast<GO>(r), static_cast<int>(s.row_ptr[r + 1] - begin),
                                   values.data() + begin, s.cols.data() + begin);
    }
    matrix_->fillComplete();
    if (solver_.is_null()) {
      solver_ = Amesos2::create<CrsMatrix, MultiVector>("KLU2", matrix_);
      solver_->symbolicFactorization(); // kept for every later factorisation
    }
    solver_->numericFactorization();
  }

  const char* method() const override { return "LU"; }

  void solve(const double* b, double* x) override {
    const std::size_t n = structure_->size();
    { // host views released before Amesos2 touches the vectors
      auto bv = b_->getDataNonConst(0);
      std::copy(b, b + n, bv.getRawPtr());
    }
    solver_->solve(x_.ptr(), b_.ptr());
    auto xv = x_->getData(0);
    std::copy(xv.getRawPtr(), xv.getRawPtr() + n, x);
  }

private:
  const RootCsr* structure_ = nullptr;
  Teuchos::RCP<CrsMatrix> matrix_;
  Teuchos::RCP<MultiVector> x_, b_;
  Teuchos::RCP<Amesos2::Solver<CrsMatrix, MultiVector>> solver_;
};

} // namespace

std::unique_ptr<RootFactorization> make_klu2_factorization() {
  return std::make_unique<Klu2Factorization>();
}

} // namespace bipot::detail
