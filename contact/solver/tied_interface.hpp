#pragma once
/// Exact tying: the bodies share the interface's nodes (perfect bonding in every stage between
/// two bodies). Nothing is added to the system, which is what makes the tie exact; the forces
/// the interface transmits are found after each increment from the bodies
/// (set_transmitted_forces()) for output. The other enforcement of the interface laws is
/// InterfaceAssembler (which also ties split pairs and bodies bonded to a rigid obstacle, by
/// the tie law: evaluate_tie()).

#include "contact/interface/interface_mesh.hpp"
#include "fem/assembly/dof_map.hpp"
#include "fem/assembly/interface_enforcement.hpp"

#include <Eigen/Core>

#include <vector>

namespace bipot::contact {

class TiedInterface final : public InterfaceEnforcement {
public:
  /// `iface` must share its nodes (shares_nodes()); `source` says where its forces come from.
  TiedInterface(const Interface& iface, const DofMap& dofs, TransmittedForce source);

  const std::string& name() const override { return iface_.name; }
  std::size_t num_pairs() const override { return iface_.pairs.size(); }
  bool acts_on_system() const override { return false; }
  void add_to_pattern(SparsityPattern&) const override {}
  void set_rigid_bodies(const RigidBodyConstraints*) override {}
  void set_augmentation(const std::vector<double>&) override {}
  void begin_increment(double) override {}
  void evaluate(const std::vector<double>&, double) override {}
  void add_to_system(const Constraints&, SparseMatrix*, DistributedVector&) const override {}
  double multiplier_change() const override { return 0.0; }
  void update_multipliers() override {}
  bool tangent_changed() const override { return false; }
  void mark_tangent_assembled() override {}
  void commit() override {}
  /// Largest A_i ‖t_i‖ (kN) of the transmitted forces.
  double force_scale() const override;
  double roundoff_force() const override { return 0.0; }

  bool adhesion_can_change() const override { return false; }
  /// β = 1 at every pair.
  std::vector<double> committed_adhesion() const override;
  std::vector<double> adhesion_at(const std::vector<double>&, double) const override {
    return committed_adhesion();
  }
  void freeze_adhesion(const std::vector<double>&) override {}
  void unfreeze_adhesion() override {}
  double adhesion_capacity() const override { return 0.0; }

  /// Tied in every stage (the model splits an interface that any stage unties).
  bool enter_stage(std::size_t) override { return false; }
  void set_gap_shift(double shift) override { gap_shift_ = shift; }
  double gap_shift() const override { return gap_shift_; }
  /// Pairs against an obstacle are never shared (node_b is the obstacle).
  bool has_obstacle() const override { return false; }
  void set_obstacle_displacement(const std::array<double, 3>& u) override { obstacle_u_ = u; }
  std::array<double, 3> obstacle_displacement() const override { return obstacle_u_; }
  /// Nothing to keep: the shared nodes' displacements are zeroed with the bodies'.
  void absorb_displacements() override { obstacle_u_ = {0, 0, 0}; }
  TransmittedForce transmitted_force() const override { return source_; }
  /// `force_all` holds, for every DOF, the force body 1 exerts on body 2 at the shared nodes.
  /// Sets each pair's traction Qᵀ F / A_i (kPa; r = traction, p = its normal part,
  /// compression positive), β = 1, status stick (reported as bonded), and the resultant.
  void set_transmitted_forces(const std::vector<double>& force_all) override;

  /// The gap shift only: the forces follow from the bodies after the next increment.
  StateArrays save_state() const override;
  void load_state(const StateArrays& state) override;

  /// Stores nothing and dissipates nothing: the bodies' work accounts for all.
  void start_energy_account() override {}
  void record_energy(InterfaceEnergy&) override {}
  std::vector<double> save_energy_account() const override { return {}; }
  void load_energy_account(const std::vector<double>& values) override;

  std::array<double, 3> resultant() const override;
  const std::vector<PairResult>& results() const override { return results_; }

private:
  const Interface& iface_;
  const DofMap& dofs_;
  int dim_;
  TransmittedForce source_;
  std::vector<PairResult> results_;
  std::vector<Eigen::Vector3d> force_; ///< A_i Q_i t_i, global components (padded to 3)
  double gap_shift_ = 0;
  std::array<double, 3> obstacle_u_{0, 0, 0};
};

} // namespace bipot::contact
