// MUMPS on one process (MPI_COMM_SELF): the multifrontal method works on dense frontal
// matrices with BLAS-3 kernels and a nested-dissection-type ordering, which on our 2D meshes
// factorises 3 times faster than KLU2's column-by-column LU at 78k DOFs and 10 times at 306k
// (with OpenBLAS; docs/performance.md).
#include "fem/linalg/detail/root_factorization.hpp"

#include <dmumps_c.h>
#include <mpi.h>

#include <algorithm>
#include <stdexcept>
#include <string>

namespace bipot::detail {

namespace {

// INFOG(1) codes that users can act on; the rest are reported by number (MUMPS manual §8).
std::string mumps_error(int code, int detail) {
  switch (code) {
  case -10:
    return "numerically singular matrix (MUMPS INFOG(1) = -10)";
  case -13:
    return "memory allocation failed (MUMPS INFOG(1) = -13, " + std::to_string(detail) + " items)";
  default:
    return "MUMPS error INFOG(1) = " + std::to_string(code) +
           ", INFOG(2) = " + std::to_string(detail);
  }
}

class MumpsFactorization final : public RootFactorization {
public:
  explicit MumpsFactorization(bool symmetric) : symmetric_(symmetric) {
    id_.comm_fortran = static_cast<MUMPS_INT>(MPI_Comm_c2f(MPI_COMM_SELF));
    id_.par = 1; // this process works (there is only one)
    // General unsymmetric by default: friction makes the contact tangent unsymmetric. A
    // symmetric matrix (a linear elastic bulk) is factorised LDLᵀ (SYM = 2, indefinite:
    // constrained rows and rigid-body rows need not keep it positive definite).
    id_.sym = symmetric ? 2 : 0;
    call(-1); // initialise
    // Silence all output: failures come back as INFOG codes and are thrown.
    id_.icntl[0] = -1;
    id_.icntl[1] = -1;
    id_.icntl[2] = -1;
    id_.icntl[3] = 0;
    id_.icntl[6] = 7; // ICNTL(7): ordering chosen by MUMPS from those it was built with
  }
  ~MumpsFactorization() override {
    id_.job = -2; // free MUMPS' memory; errors here cannot be reported
    dmumps_c(&id_);
  }
  MumpsFactorization(const MumpsFactorization&) = delete;
  MumpsFactorization& operator=(const MumpsFactorization&) = delete;

  void analyse(const RootCsr& s) override {
    const std::size_t n = s.size();
    // A symmetric matrix is given by its lower triangle: MUMPS sums (i, j) and (j, i).
    std::size_t entries = s.cols.size();
    if (symmetric_) {
      entries = 0;
      for (std::size_t r = 0; r < n; ++r)
        for (std::size_t k = s.row_ptr[r]; k < s.row_ptr[r + 1]; ++k)
          entries += static_cast<std::size_t>(s.cols[k]) <= r;
    }
    // Exact sizes: growing by push_back could hold up to twice these arrays (100s of MB).
    kept_.clear();
    irn_.clear();
    jcn_.clear();
    kept_.reserve(symmetric_ ? entries : 0);
    irn_.reserve(entries);
    jcn_.reserve(entries);
    for (std::size_t r = 0; r < n; ++r)
      for (std::size_t k = s.row_ptr[r]; k < s.row_ptr[r + 1]; ++k) {
        if (symmetric_ && static_cast<std::size_t>(s.cols[k]) > r) continue;
        if (symmetric_) kept_.push_back(k);
        irn_.push_back(static_cast<MUMPS_INT>(r + 1)); // MUMPS counts from 1
        jcn_.push_back(static_cast<MUMPS_INT>(s.cols[k] + 1));
      }
    values_.assign(irn_.size(), 0.0);
    id_.n = static_cast<MUMPS_INT>(n);
    id_.nnz = static_cast<MUMPS_INT8>(irn_.size());
    id_.irn = irn_.data();
    id_.jcn = jcn_.data();
    id_.a = values_.data();
    call(1);
  }

  void factorize(const std::vector<double>& values) override {
    if (symmetric_)
      for (std::size_t t = 0; t < kept_.size(); ++t)
        values_[t] = values[kept_[t]];
    else
      std::copy(values.begin(), values.end(), values_.begin());
    // S is written here and handed over by take_schur() (no copy kept: 77 MB at |I| = 3100);
    // the solves after the factorisation do not read it.
    const std::size_t m = schur_vars_.size();
    schur_.assign(m * m, 0.0);
    id_.schur = schur_.data();
    // Off-diagonal pivoting can need more workspace than the analysis estimated
    // (INFOG(1) = -8, -9): retry with a larger relaxation, as the MUMPS manual advises.
    for (int attempt = 0;; ++attempt) {
      id_.job = 2;
      dmumps_c(&id_);
      const int code = id_.infog[0];
      if (code >= 0 && !schur_vars_.empty() && id_.infog[27] > 0)
        throw std::runtime_error("numerically singular matrix outside the Schur variables (" +
                                 std::to_string(id_.infog[27]) + " null pivots, MUMPS INFOG(28))");
      if (code >= 0) return;
      if ((code == -8 || code == -9) && attempt < 4) {
        id_.icntl[13] = std::max(40, 2 * id_.icntl[13]); // ICNTL(14): % extra workspace
        continue;
      }
      throw std::runtime_error(mumps_error(code, id_.infog[1]));
    }
  }

  void solve(const double* b, double* x) override {
    if (!schur_vars_.empty())
      throw std::runtime_error("a Schur factorisation solves through reduce() and expand()");
    std::copy(b, b + id_.n, x);
    id_.rhs = x; // centralised right-hand side, overwritten by the solution
    call(3);
  }

  void set_schur_variables(const std::vector<long long>& variables) override {
    schur_vars_.resize(variables.size());
    for (std::size_t i = 0; i < variables.size(); ++i)
      schur_vars_[i] = static_cast<MUMPS_INT>(variables[i] + 1);
    const std::size_t m = variables.size();
    reduced_.assign(m, 0.0);
    id_.size_schur = static_cast<MUMPS_INT>(m);
    id_.listvar_schur = schur_vars_.data();
    id_.schur_lld = static_cast<MUMPS_INT>(m);
    // ICNTL(19) = 1: the whole Schur complement, centralised on this (host) process, by rows
    // for an unsymmetric matrix. 0 when empty: MUMPS refuses a Schur set of size 0.
    id_.icntl[18] = m > 0 ? 1 : 0;
    // ICNTL(24) = 1: count null pivots (INFOG(28)). Without it a Schur factorisation of a
    // singular A_BB returned no error (checked on a zero matrix), unlike the plain one.
    id_.icntl[23] = m > 0 ? 1 : 0;
  }

  std::vector<double> take_schur() override {
    id_.schur = nullptr;
    if (symmetric_) {
      // MUMPS returns the lower triangle by rows (ICNTL(19) = 1, SYM = 2) and writes the
      // other triangle too, from workspace it did not initialise: mirror the lower one.
      const std::size_t m = schur_vars_.size();
      for (std::size_t i = 0; i < m; ++i)
        for (std::size_t j = 0; j < i; ++j)
          schur_[j * m + i] = schur_[i * m + j];
    }
    return std::move(schur_);
  }

  void reduce(const double* b, double* work, double* reduced) override {
    std::copy(b, b + id_.n, work);
    if (schur_vars_.empty()) { // plain solve: nothing to reduce
      id_.rhs = work;
      call(3);
      return;
    }
    id_.rhs = work;
    id_.redrhs = reduced_.data();
    id_.lredrhs = id_.size_schur;
    id_.icntl[25] = 1; // ICNTL(26) = 1: condensation (forward elimination) only
    call_then_reset(3);
    std::copy(reduced_.begin(), reduced_.end(), reduced);
  }

  void expand(double* work, const double* x_schur, double* x) override {
    if (!schur_vars_.empty()) {
      std::copy(x_schur, x_schur + reduced_.size(), reduced_.begin());
      id_.rhs = work;
      id_.redrhs = reduced_.data();
      id_.lredrhs = id_.size_schur;
      id_.icntl[25] = 2; // ICNTL(26) = 2: expansion from the Schur variables' solution
      call_then_reset(3);
    }
    std::copy(work, work + id_.n, x);
  }

private:
  void call(int job) {
    id_.job = job;
    dmumps_c(&id_);
    if (id_.infog[0] < 0) throw std::runtime_error(mumps_error(id_.infog[0], id_.infog[1]));
  }

  void call_then_reset(int job) {
    id_.job = job;
    dmumps_c(&id_);
    id_.icntl[25] = 0; // ICNTL(26): back to ordinary solves
    if (id_.infog[0] < 0) throw std::runtime_error(mumps_error(id_.infog[0], id_.infog[1]));
  }

  bool symmetric_;
  std::vector<std::size_t> kept_; ///< symmetric: positions of the lower triangle's entries
  DMUMPS_STRUC_C id_{};
  std::vector<MUMPS_INT> schur_vars_; ///< 1-based, as MUMPS counts
  std::vector<double> schur_, reduced_;
  std::vector<MUMPS_INT> irn_, jcn_;
  std::vector<double> values_;
};

} // namespace

std::unique_ptr<RootFactorization> make_mumps_factorization(bool symmetric) {
  return std::make_unique<MumpsFactorization>(symmetric);
}

} // namespace bipot::detail
