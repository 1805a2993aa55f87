#pragma once
/// Rigid bodies as exact multipoint constraints (master–slave elimination, docs/theory.md
/// "Rigid bodies"): every DOF of a body's nodes (the slaves) follows its reference node,
///   u_s = u_R + θ × (x_s − x_R)          (small rotations: linear in the masters),
/// i.e. u = T ũ with ũ the DOFs that stay. The masters are two extra nodes of the mesh, no
/// cell's, at the reference point: R carries the translations, Θ the rotations (component
/// k = rotation about axis k in 3D; component 0 = the rotation about z in 2D). Axisymmetric
/// bodies translate axially only (a rigid body of revolution cannot move radially nor turn):
/// slaves' r DOFs are held at 0, R's z is the only master.
///
/// Local systems are transformed before Dirichlet elimination: K̃ = Tᵀ K T, R̃ = Tᵀ R over the
/// local DOFs with the slaves replaced by their masters. The DOFs that carry no unknown (the
/// slaves, the masters' unused components) get an identity row and a zero right-hand side,
/// and a solution's slave entries are then set from the masters (follow()).

#include "fem/assembly/dof_map.hpp"
#include "fem/element/kinematics.hpp"
#include "fem/mesh/mesh.hpp"

#include <array>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

namespace bipot {

class DistributedVector;
class SparseMatrix;
class SparsityPattern;
class DofDistribution;

/// One rigid body: its nodes and its reference (master) nodes.
struct RigidBody {
  std::string name;
  std::vector<Index> nodes;             ///< slaves, sorted
  Index reference = -1, rotation = -1;  ///< the master nodes R and Θ
  std::array<double, 3> point{0, 0, 0}; ///< x_R (m)
};

/// The components of a rigid body's reference node by index: translations 0..d−1, then the
/// rotations (2D: one, "rz"; 3D: "rx", "ry", "rz"); axisymmetric: "z" only (index 1).
int rigid_body_components(Kinematics kin);
/// The master DOF of component `k` of `body` (see rigid_body_components()).
Index rigid_body_dof(const RigidBody& body, const DofMap& dofs, Kinematics kin, int k);

class RigidBodyConstraints {
public:
  RigidBodyConstraints(const Mesh& mesh, Kinematics kin, const DofMap& dofs,
                       const std::vector<RigidBody>& bodies);

  bool empty() const { return slaves_.empty(); }
  bool is_slave(Index dof) const { return slaves_.count(dof) != 0; }
  /// DOFs without an unknown of their own: slaves and the masters' unused components.
  const std::vector<Index>& inactive_dofs() const { return inactive_; }

  /// Replaces the slaves of a local system (DOFs `dofs`, right-hand side `R`, matrix `K`
  /// row-major or null) by their masters: on return `dofs` holds the local DOFs that are no
  /// slaves, in their order, then the masters they bring, and R, K the transformed system.
  void distribute(std::vector<Index>& dofs, std::vector<double>& R, std::vector<double>* K) const;
  /// Same for the DOFs of a sparsity block.
  void distribute(std::vector<Index>& dofs) const;
  /// Moves the slave entries of an assembled vector to their masters (f̃ = Tᵀ f, slaves 0);
  /// collective.
  void transfer(DistributedVector& f) const;
  /// Sets every slave entry of `u` (all DOFs) from its masters: u_s = Σ T_sm u_m.
  void follow(std::vector<double>& u) const;
  /// Identity rows of the owned inactive DOFs (see the class comment).
  void add_inactive_rows(const DofDistribution& dist, SparseMatrix& K) const;
  void add_inactive_rows(const DofDistribution& dist, SparsityPattern& pattern) const;

private:
  std::unordered_map<Index, std::vector<std::pair<Index, double>>> slaves_;
  std::vector<Index> slave_order_; ///< slaves_ keys, sorted (deterministic loops)
  std::vector<Index> inactive_;
};

} // namespace bipot
