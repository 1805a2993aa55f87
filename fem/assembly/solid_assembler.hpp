#pragma once
/// Cell loop of small-strain solid mechanics: tangent stiffness and internal forces
/// f_int = ∫ Bᵀ (σ0 + σ(ε)) dV over the cells this rank owns, with quadrature-point state.

#include "fem/assembly/constraints.hpp"
#include "fem/assembly/dof_map.hpp"
#include "fem/core/material.hpp"
#include "fem/core/state_arrays.hpp"
#include "fem/element/element_values.hpp"
#include "fem/mesh/mesh.hpp"

#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace bipot {

class RigidBodyConstraints;
class SparseMatrix;
class SparsityPattern;
class DistributedVector;

class SolidAssembler {
public:
  /// `material_of_region[id]` is the material of mesh region id (not owned; may be null for
  /// regions without cells). `owned_cells` are the cells this rank integrates.
  SolidAssembler(const Mesh& mesh, Kinematics kin, const DofMap& dofs,
                 std::vector<const Material*> material_of_region, std::vector<Index> owned_cells);
  ~SolidAssembler();

  /// Sets σ0 at every quadrature point from a function of position and region id.
  void set_initial_stress(const std::function<Voigt(const std::array<double, 3>&, int)>& sigma0);

  /// For the total displacement `u` (all global DOFs, replicated): adds the condensed local
  /// systems K_e du = −f_int,e to `K` (if not null) and `R`. `removed` (if not null) receives the
  /// entries of the local matrices that the elimination takes out, those in a constrained row or
  /// column (LinearBulkResidual rebuilds the residual from them and K). `ahead` (if not null,
  /// with `R_ahead`) is a second set of values on the same constrained DOFs: `R_ahead` gets the
  /// residual condensed with those, from the same local systems (a path's residual at the
  /// next load factor, without evaluating the materials again).
  void assemble(const std::vector<double>& u, const Constraints& constraints, SparseMatrix* K,
                DistributedVector& R, SparseMatrix* removed = nullptr,
                const Constraints* ahead = nullptr, DistributedVector* R_ahead = nullptr);
  /// What assemble() adds to `R` when every constrained value is zero (`held`: DOFs that keep
  /// their value, a line search's trial): their rows zeroed. Without the tangent's products,
  /// which a residual does not need.
  void residual(const std::vector<double>& u, const Constraints& held, DistributedVector& R);
  /// Adds the unconstrained internal force f_int(u) to `f` (reactions); with `region` ≥ 0,
  /// only that region's cells (the force a body's cells exert on shared nodes).
  void internal_force(const std::vector<double>& u, DistributedVector& f, int region = -1);
  /// Accepts the last trial state (end of a converged increment): the materials' internal
  /// variables. Until then every assembly starts again from the
  /// committed internal variables, so a failed (cut-back) increment leaves no trace.
  void commit();

  /// Displacement reset that keeps stresses (geostatic stage); the caller then zeroes `u`.
  /// Materials without internal variables: the stress of `u` at every quadrature point is
  /// added to the initial stress. Materials with internal variables keep their whole history
  /// instead: the strain of `u` becomes a per-point offset added to the strain they are
  /// given, so their plastic strain, hardening and stress carry over unchanged while the
  /// displacements and the output strains restart from zero (docs/theory.md).
  void absorb_stress_into_initial(const std::vector<double>& u);

  /// The committed state of the owned cells for a checkpoint (solid_state.cpp): "cells" (global
  /// ids), "points" (quadrature points of each), and every per-point and per-cell array
  /// (today σ0 as "point.initial_stress", the internal variables and the strain offsets), cell
  /// after cell, each with its values per cell ("<name>.count"). Keyed by
  /// global cell id, so that the arrays gathered from every rank restore the state at any
  /// rank count. A new array is one line in state_array_refs().
  StateArrays save_state() const;
  /// Restores the owned cells' state from the arrays of every cell (gathered save_state()s, in
  /// any order). Throws bipot::Error if an owned cell or an array is missing or sized wrongly.
  void load_state(const StateArrays& state);

  const std::vector<Index>& owned_cells() const { return owned_cells_; }
  /// Rigid bodies (not owned; null for none): every cell system, pattern and internal force
  /// is transformed onto their masters, and assemble() adds the inactive DOFs' identity rows.
  void set_rigid_bodies(const RigidBodyConstraints* rigid) { rigid_ = rigid; }
  /// Adds the DOFs of every owned cell (with `touching`: of those with a constrained DOF) to
  /// a sparsity pattern.
  void add_to_pattern(SparsityPattern& pattern, const Constraints* touching = nullptr) const;
  /// Whether an initial stress is set (f_int(0) ≠ 0).
  bool has_initial_stress() const { return !sigma0_.empty(); }
  /// Cell averages (over quadrature points) of strain and stress of the owned cells at the
  /// committed displacement `u` (the internal variables as committed), Voigt components
  /// interleaved. Computed when asked (for output), not kept: at 1M DOFs stored committed and
  /// trial averages cost ~120 MB.
  void cell_averages(const std::vector<double>& u, std::vector<double>& strain,
                     std::vector<double>& stress) const;
  int voigt_size() const { return nv_; }
  /// Names of the materials' output fields (plastic strain, yield indicator, ...): the union
  /// over every material of the model, in region order, so that all ranks agree.
  std::vector<std::string> output_field_names() const;
  /// Committed cell averages of the output fields, one value per owned cell and field
  /// (fields interleaved, in the order of output_field_names()); 0 in cells whose material
  /// does not have the field.
  std::vector<double> cell_output_fields() const;
  /// Committed internal variables of every quadrature point of the owned cells, in cell then
  /// point order, num_state_variables() of its material each; empty if no material has any.
  const std::vector<double>& committed_state() const { return state_; }

private:
  /// An array of the state for save_state()/load_state(): owned cell k holds
  /// values[offsets[k], offsets[k + 1]) (the array may be empty until first used: σ0).
  struct StateArrayRef {
    const char* name;
    std::vector<double>* values;
    std::vector<Index> offsets;
  };
  /// Every per-point and per-cell array of the committed state (solid_state.cpp).
  std::vector<StateArrayRef> state_array_refs();

  ElementValues& values_for(CellType type) const;
  template <class CellKernel>
  void loop(const std::vector<double>& u, bool tangent, CellKernel&& kernel,
            const std::function<void(Index, const Voigt&, const Voigt&, bool)>& point_stress = {});

  const Mesh& mesh_;
  Kinematics kin_;
  const DofMap& dofs_;
  std::vector<const Material*> materials_;
  std::vector<Index> owned_cells_;
  const RigidBodyConstraints* rigid_ = nullptr;
  int region_filter_ = -1; ///< loop() skips cells of other regions when ≥ 0
  int nv_;
  /// Shape values per cell type, made when first needed (a cache: const loops use it too).
  mutable std::map<CellType, std::unique_ptr<ElementValues>> values_;
  // Per quadrature point only what the physics needs (σ0); strain and stress are averaged
  // per cell when output asks (cell_averages()): at 1M DOFs per-point copies cost ~300 MB.
  std::vector<Index> qp_offset_; ///< per owned cell, first quadrature point
  std::vector<double> sigma0_;   ///< initial stress per point (nv each); empty = zero
  // Internal variables, only for materials that have some (a linear model stores nothing):
  // state_offset_[k] is the first value of owned cell k, its points following each other.
  std::vector<Index> state_offset_;
  std::vector<double> state_, trial_state_; ///< committed; of the last assembly
  /// Per point (nv each), points of materials with internal variables only: the strain at
  /// the last displacement reset, added to what those materials see. Empty until a reset.
  std::vector<double> strain_offset_;
};

} // namespace bipot
