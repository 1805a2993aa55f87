// MUMPS on one process (MPI_COMM_SELF): the multifrontal method works on dense frontal
// matrices with BLAS-3 kernels and a nested-dissection-type ordering, which on our 2D meshes
// factorises 3 times faster than KLU2's column-by-column LU at 78k DOFs and 10 times at 306k
// (with OpenBLAS; docs/performance.md).
#include "fem/linalg/detail/mumps_diagnosis.hpp"
#include "fem/linalg/detail/mumps_out_of_core.hpp"
#include "fem/linalg/detail/root_factorization.hpp"
#include "fem/linalg/detail/symmetric_pairs.hpp"

#include <dmumps_c.h>
#include <mpi.h>

#include <algorithm>
#include <memory>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace bipot::detail {

namespace {

static_assert(std::is_same<MUMPS_INT, int>::value,
              "SymmetricPairs' lower triangle is handed to MUMPS as it is");

/// Asymmetry, relative to the rows' diagonals, up to which a matrix is factorised as
/// symmetric: a few hundred times the round-off of the element products that make an
/// assembled symmetric tangent differ from its transpose (B^T (D B), a return's Jacobian
/// times the elasticity). The solve is then that of (A + A^T)/2, which differs from A by
/// less than an LU's own backward error; a physical asymmetry (friction, non-associated
/// flow) is orders of magnitude above it.
constexpr double symmetry_tolerance = 1e-13;

/// MUMPS' matrix types (its SYM): LDL^T without pivoting, LDL^T with 1x1 and 2x2 pivots, LU.
enum class Kind { positive_definite = 1, symmetric = 2, general = 0 };

/// One MUMPS instance on this process (MPI_COMM_SELF) for one matrix kind.
class MumpsInstance {
public:
  MumpsInstance(Kind kind, const std::string& factor_directory) {
    id_.comm_fortran = static_cast<MUMPS_INT>(MPI_Comm_c2f(MPI_COMM_SELF));
    id_.par = 1; // this process works (there is only one)
    id_.sym = static_cast<MUMPS_INT>(kind);
    call(-1); // initialise
    // Silence all output: failures come back as INFOG codes and are thrown.
    id_.icntl[0] = -1;
    id_.icntl[1] = -1;
    id_.icntl[2] = -1;
    id_.icntl[3] = 0;
    id_.icntl[6] = 7; // ICNTL(7): ordering chosen by MUMPS from those it was built with
    set_mumps_out_of_core(id_, factor_directory);
  }
  ~MumpsInstance() {
    id_.job = -2; // free MUMPS' memory; errors here cannot be reported
    dmumps_c(&id_);
  }
  MumpsInstance(const MumpsInstance&) = delete;
  MumpsInstance& operator=(const MumpsInstance&) = delete;

  /// The structure: n rows, `nnz` entries at 1-based (rows1[k], cols1[k]) (a symmetric
  /// kind: one triangle). The arrays are the caller's and must outlive the instance: MUMPS
  /// reads them again at every factorisation.
  void analyse(std::size_t n, std::size_t nnz, const MUMPS_INT* rows1, const MUMPS_INT* cols1) {
    values_.assign(nnz, 0.0);
    id_.n = static_cast<MUMPS_INT>(n);
    id_.nnz = static_cast<MUMPS_INT8>(nnz);
    id_.irn = const_cast<MUMPS_INT*>(rows1); // MUMPS only reads them
    id_.jcn = const_cast<MUMPS_INT*>(cols1);
    id_.a = values_.data();
    call(1);
  }

  std::vector<double>& values() { return values_; }

  /// MUMPS' INFOG(1) after the factorisation of values(): ≥ 0 success, < 0 error.
  int factorize() {
    // Off-diagonal pivoting can need more workspace than the analysis estimated
    // (INFOG(1) = -8, -9): retry with a larger relaxation, as the MUMPS manual advises.
    for (int attempt = 0;; ++attempt) {
      id_.job = 2;
      dmumps_c(&id_);
      const int code = id_.infog[0];
      if ((code == -8 || code == -9) && attempt < 4) {
        id_.icntl[13] = std::max(40, 2 * id_.icntl[13]); // ICNTL(14): % extra workspace
        continue;
      }
      return code;
    }
  }
  /// INFOG(12) after a factorisation without pivoting: the number of negative pivots.
  int negative_pivots() const { return id_.infog[11]; }
  [[noreturn]] void throw_error() const {
    throw std::runtime_error(mumps_error(id_.infog[0], id_.infog[1], id_.icntl[21] != 0));
  }

  void solve(const double* b, double* x) {
    std::copy(b, b + id_.n, x);
    id_.rhs = x; // centralised right-hand side, overwritten by the solution
    call(3);
  }

private:
  void call(int job) {
    id_.job = job;
    dmumps_c(&id_);
    if (id_.infog[0] < 0) throw_error();
  }

  DMUMPS_STRUC_C id_{};
  std::vector<double> values_;
};

/// A symmetric matrix is factorised as LDL^T from its lower triangle: without pivoting while
/// every pivot comes out positive (the matrix is then positive definite, and the
/// factorisation stable), else with MUMPS' symmetric pivoting; an unsymmetric one as LU. On
/// the 100k-DOF strip footing's von Mises tangent one factorisation takes 0.16 s against
/// 0.26 s as LU (0.22 s with symmetric pivoting). The kind is decided on the values at each
/// factorisation but only moves down that list: once a matrix on this structure needed a
/// more general kind, later ones get it too (one MUMPS instance and analysis at a time, none
/// redone each time a tangent turns symmetric or definite for an iteration).
class MumpsFactorization final : public RootFactorization {
public:
  explicit MumpsFactorization(std::string factor_directory)
      : factor_directory_(std::move(factor_directory)) {}

  void analyse(const RootCsr& s) override {
    instance_.reset(); // it reads the arrays below
    n_ = s.size();
    rows1_.resize(s.cols.size());
    cols1_.resize(s.cols.size());
    for (std::size_t r = 0; r < n_; ++r)
      for (std::size_t k = s.row_ptr[r]; k < s.row_ptr[r + 1]; ++k) {
        rows1_[k] = static_cast<MUMPS_INT>(r + 1); // MUMPS counts from 1
        cols1_[k] = static_cast<MUMPS_INT>(s.cols[k] + 1);
      }
    pairs_ = std::make_unique<SymmetricPairs>(s, 1); // MUMPS counts from 1
    kind_ = pairs_->usable() ? Kind::positive_definite : Kind::general;
    if (kind_ == Kind::general) pairs_.reset();
  }

  void factorize(const std::vector<double>& values) override {
    if (kind_ != Kind::general && !pairs_->symmetric(values, symmetry_tolerance))
      move_to(Kind::general);
    for (;;) {
      if (!instance_) start();
      if (kind_ == Kind::general)
        std::copy(values.begin(), values.end(), instance_->values().begin());
      else
        pairs_->lower_values(values, instance_->values());
      const int code = instance_->factorize();
      // A zero or negative pivot without pivoting: not positive definite (or singular,
      // which the pivoting factorisation will then report).
      if (kind_ == Kind::positive_definite && (code == -10 || instance_->negative_pivots() > 0)) {
        move_to(Kind::symmetric);
        continue;
      }
      if (code < 0) instance_->throw_error();
      return;
    }
  }

  void solve(const double* b, double* x) override { instance_->solve(b, x); }

  const char* method() const override {
    return kind_ == Kind::positive_definite ? "Cholesky-type LDL^T"
           : kind_ == Kind::symmetric       ? "LDL^T"
                                            : "LU";
  }

private:
  void move_to(Kind kind) {
    kind_ = kind;
    instance_.reset(); // frees the other kind's factors
    if (kind == Kind::general) pairs_.reset();
  }

  /// A new instance of the current kind, analysed; instance_ is left as it was if that throws.
  void start() {
    auto instance = std::make_unique<MumpsInstance>(kind_, factor_directory_);
    const std::vector<MUMPS_INT>& rows = kind_ == Kind::general ? rows1_ : pairs_->lower_rows();
    const std::vector<MUMPS_INT>& cols = kind_ == Kind::general ? cols1_ : pairs_->lower_cols();
    instance->analyse(n_, rows.size(), rows.data(), cols.data());
    instance_ = std::move(instance);
  }

  std::string factor_directory_;
  std::size_t n_ = 0;
  std::vector<MUMPS_INT> rows1_, cols1_;  ///< the whole structure, 1-based
  std::unique_ptr<SymmetricPairs> pairs_; ///< while the kind is symmetric (MUMPS reads it)
  Kind kind_ = Kind::general;
  std::unique_ptr<MumpsInstance> instance_; ///< last: freed before the arrays it reads
};

} // namespace

std::unique_ptr<RootFactorization> make_mumps_factorization(const std::string& factor_directory) {
  return std::make_unique<MumpsFactorization>(factor_directory);
}

} // namespace bipot::detail
