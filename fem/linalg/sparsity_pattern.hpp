#pragma once
/// The nonzero structure a rank contributes to a SparseMatrix, kept in flat arrays.

#include "fem/core/types.hpp"

#include <vector>

namespace bipot {

/// Couplings this rank will assemble: cells (every DOF of a cell couples with every other,
/// an n x n block) and extra one-directional couplings `row <- cols` (contact pairs, tied
/// DOFs). Rows may belong to any rank. Negative DOF indices are skipped, so eliminated
/// (e.g. fixed) DOFs can stay in cell lists as -1. Storage is CSR-like (offsets + indices):
/// about 8 bytes per cell DOF, no per-cell allocation.
class SparsityPattern {
public:
  SparsityPattern() = default;
  /// One DOF list per cell.
  explicit SparsityPattern(const std::vector<std::vector<Index>>& cells) {
    for (const auto& c : cells)
      add_cell(c);
  }

  /// Pre-allocates for `num_cells` cells holding `num_cell_dofs` DOFs in all.
  void reserve(Index num_cells, Index num_cell_dofs) {
    cell_offsets_.reserve(static_cast<std::size_t>(num_cells) + 1);
    cell_dofs_.reserve(static_cast<std::size_t>(num_cell_dofs));
  }

  /// A cell with DOFs `dofs[0..n)`: all n x n couplings.
  void add_cell(const Index* dofs, int n) {
    cell_dofs_.insert(cell_dofs_.end(), dofs, dofs + n);
    cell_offsets_.push_back(static_cast<Index>(cell_dofs_.size()));
  }
  void add_cell(const std::vector<Index>& dofs) {
    add_cell(dofs.data(), static_cast<int>(dofs.size()));
  }

  /// Row `row` couples with columns `cols[0..n)` (only this direction; add the transpose
  /// coupling separately if the operator is symmetric).
  void add_coupling(Index row, const Index* cols, int n) {
    coupling_rows_.push_back(row);
    coupling_cols_.insert(coupling_cols_.end(), cols, cols + n);
    coupling_offsets_.push_back(static_cast<Index>(coupling_cols_.size()));
  }
  void add_coupling(Index row, const std::vector<Index>& cols) {
    add_coupling(row, cols.data(), static_cast<int>(cols.size()));
  }

  Index num_cells() const { return static_cast<Index>(cell_offsets_.size()) - 1; }
  /// Cell c has DOFs cell_dofs()[cell_offsets()[c] .. cell_offsets()[c+1]).
  const std::vector<Index>& cell_offsets() const { return cell_offsets_; }
  const std::vector<Index>& cell_dofs() const { return cell_dofs_; }

  Index num_couplings() const { return static_cast<Index>(coupling_rows_.size()); }
  /// Coupling k: row coupling_rows()[k], columns
  /// coupling_cols()[coupling_offsets()[k] .. coupling_offsets()[k+1]).
  const std::vector<Index>& coupling_rows() const { return coupling_rows_; }
  const std::vector<Index>& coupling_offsets() const { return coupling_offsets_; }
  const std::vector<Index>& coupling_cols() const { return coupling_cols_; }

private:
  std::vector<Index> cell_offsets_{0};
  std::vector<Index> cell_dofs_;
  std::vector<Index> coupling_rows_;
  std::vector<Index> coupling_offsets_{0};
  std::vector<Index> coupling_cols_;
};

} // namespace bipot
