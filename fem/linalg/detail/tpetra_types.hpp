#pragma once
/// Internal to fem/linalg: Tpetra type names and the SparseMatrix implementation, shared by
/// the translation units that see Trilinos. Never include this from a public header.

#include "fem/linalg/detail/matrix_layout.hpp"
#include "fem/linalg/distributed_vector.hpp"
#include "fem/linalg/sparse_matrix.hpp"

#include <Teuchos_RCP.hpp>
#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_Map.hpp>
#include <Tpetra_MultiVector.hpp>
#include <Tpetra_Operator.hpp>
#include <Tpetra_Vector.hpp>

#include <algorithm>
#include <vector>

namespace bipot::detail {

using Map = Tpetra::Map<>;
using GO = Map::global_ordinal_type; // long long here; bipot::Index is long: same width
using CrsGraph = Tpetra::CrsGraph<>;
using CrsMatrix = Tpetra::CrsMatrix<double>;
using MultiVector = Tpetra::MultiVector<double>;
using Vector = Tpetra::Vector<double>;
using Operator = Tpetra::Operator<double>;

static_assert(sizeof(GO) == sizeof(Index), "Tpetra global ordinal must be 64-bit");

/// Copies a DistributedVector's owned block into a Tpetra vector on the same row map.
inline void copy_to_tpetra(const DistributedVector& from, Vector& to) {
  auto data = to.getDataNonConst(0);
  std::copy(from.owned_values(), from.owned_values() + from.num_owned(), data.getRawPtr());
}

/// Copies a Tpetra vector's owned block into a DistributedVector on the same distribution.
inline void copy_from_tpetra(const Vector& from, DistributedVector& to) {
  auto data = from.getData(0);
  std::copy(data.getRawPtr(), data.getRawPtr() + to.num_owned(), to.owned_values());
}

} // namespace bipot::detail

namespace bipot {

struct SparseMatrix::Impl {
  Impl(const DofDistribution& dist, const SparsityPattern& pattern);

  DofDistribution dist;
  detail::MatrixLayout layout;
  Teuchos::RCP<const detail::Map> row_map;
  Teuchos::RCP<const detail::Map> col_map;
  Teuchos::RCP<detail::CrsGraph> graph;
  Teuchos::RCP<detail::CrsMatrix> matrix;
  std::vector<double> ghost_values; ///< aligned with layout.ghost_cols()
  bool assembling = true;
  /// The owned rows' local structure (fixed by the graph) and, while assembling, the matrix
  /// values in the same order: add_block() adds into them directly. Tpetra's
  /// sumIntoLocalValues() builds Kokkos views for every row it is given, which took 16 % of
  /// the Mohr-Coulomb pile's run time.
  detail::CrsGraph::local_graph_host_type local_graph;
  double* values = nullptr;
  mutable Teuchos::RCP<detail::Vector> x_work, y_work; ///< multiply() buffers
};

} // namespace bipot
