#include "contact/solver/interface_assembler.hpp"

#include "contact/interface/pair_geometry.hpp"
#include "fem/core/error.hpp"
#include "fem/linalg/distributed_vector.hpp"
#include "fem/linalg/dof_distribution.hpp"
#include "fem/linalg/sparse_matrix.hpp"
#include "fem/linalg/sparsity_pattern.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

namespace bipot::contact {

InterfaceAssembler::InterfaceAssembler(const Interface& iface, const InterfaceLaw& law,
                                       const DofMap& dofs, const DofDistribution& dist,
                                       ContactSolverOptions options,
                                       std::vector<StageLaw> stage_laws)
    : iface_(iface), law_(&law), options_(std::move(options)), stage_laws_(std::move(stage_laws)),
      dofs_(dofs), dim_(dofs.dofs_per_node()), frozen_law_(law) {
  if (!iface_.pairs.empty() && shares_nodes(iface_))
    throw Error("interface '" + iface_.name +
                "': its bodies share nodes, which only tying enforces (TiedInterface)");
  const std::size_t n = iface_.pairs.size();
  owned_.resize(n);
  for (std::size_t i = 0; i < n; ++i)
    owned_[i] = dist.owner_of_node(iface_.pairs[i].node_a) == dist.rank();
  rho_.assign(n, 1.0);
  committed_.assign(n, initial_state(law, dim_));
  for (std::size_t i = 0; i < n; ++i) {
    // The jump at rest, which a tied law on split pairs holds: the gaps only.
    committed_[i].jump(0) = iface_.initial_gap + iface_.pairs[i].gap;
    if (law.is_tied()) committed_[i].beta = 1.0;
  }
  multiplier_.assign(n, LocalVector::Zero(dim_));
  previous_r_.resize(n);
  for (std::size_t i = 0; i < n; ++i)
    previous_r_[i] = committed_[i].r;
  results_.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    results_[i].beta = committed_[i].beta;
    results_[i].jump = results_[i].r = results_[i].traction = LocalVector::Zero(dim_);
  }
  tangent_.assign(n, LocalMatrix::Zero(dim_, dim_));
  derivatives_.resize(n);
  offset_.assign(n, LocalVector::Zero(dim_));
  assembled_tangent_ = tangent_;
}

void InterfaceAssembler::add_to_pattern(SparsityPattern& pattern) const {
  std::vector<Index> block;
  for (std::size_t i = 0; i < iface_.pairs.size(); ++i) {
    if (!owned_[i]) continue;
    const Index nodes[2] = {iface_.pairs[i].node_a, iface_.pairs[i].node_b};
    dofs_.node_dofs(nodes, nodes[1] == rigid_obstacle ? 1 : 2, block);
    if (rigid_) rigid_->distribute(block);
    pattern.add_cell(block);
  }
}

void InterfaceAssembler::set_augmentation(const std::vector<double>& diagonal_all) {
  const ContactSolverOptions& options = options_;
  for (std::size_t i = 0; i < iface_.pairs.size(); ++i) {
    const InterfacePair& p = iface_.pairs[i];
    if (options.augmentation > 0) {
      rho_[i] = options.augmentation;
      continue;
    }
    // 1/W_ii with W_ii ≈ 1/k_a + 1/k_b: the local flexibility of the two bodies at the pair,
    // per unit area (k from the bulk diagonal, smallest over the components).
    double ka = INFINITY, kb = INFINITY;
    // A rigid body's slave (identity row) is infinitely stiff, like an obstacle.
    auto stiff = [&](Index dof) { return rigid_ && rigid_->is_slave(dof); };
    for (int c = 0; c < dim_; ++c) {
      if (!stiff(dofs_.dof(p.node_a, c))) ka = std::min(ka, diagonal_all[dofs_.dof(p.node_a, c)]);
      if (p.node_b != rigid_obstacle && !stiff(dofs_.dof(p.node_b, c)))
        kb = std::min(kb, diagonal_all[dofs_.dof(p.node_b, c)]);
    }
    const double k = (ka > 0 && kb > 0) ? 1.0 / (1.0 / ka + 1.0 / kb) : std::max(ka, kb);
    const double bulk = p.weight > 0 ? k / p.weight : k;
    // The multipliers converge like ρ/(ρ + bulk stiffness) per update: ρ must dominate the
    // bodies' stiffness at the pair, not only the law's (a soft adhesive joint between stiff
    // bodies needed 110 updates per increment with ρ = 10 C_n in the pile model, 13 with this).
    double rho = std::max(law_->stiffness_scale(), std::isfinite(bulk) ? bulk : 0.0);
    if (!(rho > 0)) rho = 1.0;
    rho_[i] = options.augmentation_factor * rho;
  }
}

void InterfaceAssembler::begin_increment(double extrapolation) {
  tie_hint_.clear();
  predicted_ = extrapolation != 0.0;
  for (std::size_t i = 0; i < multiplier_.size(); ++i)
    multiplier_[i] = committed_[i].r + extrapolation * (committed_[i].r - previous_r_[i]);
}

bool InterfaceAssembler::set_tie_hints(std::vector<ConeTie> hints) {
  bool changed = false;
  for (std::size_t i = 0; i < at_tie_.size() && i < hints.size(); ++i) {
    if (!at_tie_[i] || hints[i] == ConeTie::ByValue) continue;
    const ContactStatus wanted =
        hints[i] == ConeTie::Stick ? ContactStatus::Stick : ContactStatus::Slip;
    changed = changed || results_[i].status != wanted;
  }
  tie_hint_ = std::move(hints);
  return changed;
}

void InterfaceAssembler::absorb_displacements() {
  for (std::size_t i = 0; i < offset_.size(); ++i) {
    offset_[i] = committed_[i].jump;
    offset_[i](0) -= iface_.initial_gap + iface_.pairs[i].gap + gap_shift_;
  }
  obstacle_u_ = {0, 0, 0}; // part of the jumps just kept, like the bodies' displacements
}

double InterfaceAssembler::u_b(const InterfacePair& p, int c, const std::vector<double>& u) const {
  return p.node_b == rigid_obstacle ? obstacle_u_[c] : u[dofs_.dof(p.node_b, c)];
}

LocalVector InterfaceAssembler::local_jump(std::size_t i, const std::vector<double>& u) const {
  const InterfacePair& p = iface_.pairs[i];
  Eigen::Vector3d g = Eigen::Vector3d::Zero();
  for (int c = 0; c < dim_; ++c)
    g(c) = u_b(p, c, u) - u[dofs_.dof(p.node_a, c)];
  const Eigen::Vector3d local = pair_frame(p, dim_).transpose() * g;
  LocalVector out = local.head(dim_) + offset_[i];
  out(0) += iface_.initial_gap + p.gap + gap_shift_;
  return out;
}

void InterfaceAssembler::evaluate(const std::vector<double>& u, double dtau) {
  multiplier_change_ = 0;
  roundoff_force_ = 0;
  tangent_changed_ = false;
  InterfaceResponseDerivatives d;
  force_.resize(iface_.pairs.size());
  at_tie_.assign(iface_.pairs.size(), 0);
  for (std::size_t i = 0; i < iface_.pairs.size(); ++i) {
    const InterfacePair& p = iface_.pairs[i];
    const LocalVector jump = local_jump(i, u);
    InterfaceState old = committed_[i];
    if (frozen_) old.beta = frozen_beta_[i];
    const ConeTie tie = tie_hint_.empty() ? ConeTie::ByValue : tie_hint_[i];
    const InterfaceResponse resp = contact::evaluate(frozen_ ? *frozen_law_ : *law_, old, jump,
                                                     multiplier_[i], dtau, rho_[i], &d, tie);
    at_tie_[i] = resp.tie;
    PairResult& res = results_[i];
    res.beta = resp.beta;
    res.jump = jump;
    res.r = resp.r;
    res.traction = resp.traction;
    res.status = resp.status;
    multiplier_change_ = std::max(multiplier_change_, p.weight * (resp.r - multiplier_[i]).norm());
    double u_size = 0;
    for (int c = 0; c < dim_; ++c)
      u_size = std::max({u_size, std::abs(u[dofs_.dof(p.node_a, c)]), std::abs(u_b(p, c, u))});
    const double err = std::numeric_limits<double>::epsilon() * p.weight * rho_[i] * u_size;
    roundoff_force_ += err * err;
    tangent_[i] = d.dt_djump;
    derivatives_[i] = d;
    if (!(tangent_[i] == assembled_tangent_[i])) tangent_changed_ = true;
    Eigen::Vector3d t = Eigen::Vector3d::Zero();
    t.head(dim_) = resp.traction;
    force_[i] = p.weight * (pair_frame(p, dim_) * t);
  }
  roundoff_force_ = std::sqrt(roundoff_force_);
}

void InterfaceAssembler::add_to_system(const Constraints& constraints, SparseMatrix* K,
                                       DistributedVector& R) const {
  const int n = 2 * dim_;
  std::vector<Index> block;
  std::vector<double> Kl(static_cast<std::size_t>(n) * n), Rl(n);
  for (std::size_t i = 0; i < iface_.pairs.size(); ++i) {
    if (!owned_[i]) continue;
    const InterfacePair& p = iface_.pairs[i];
    const Eigen::MatrixXd Q = pair_frame(p, dim_).topLeftCorner(dim_, dim_);
    // K = −∂R/∂u; R_b = +A Q t(ĝ), ĝ = Qᵀ(u_b − u_a): ∂R_b/∂u_b = A Q (∂t/∂ĝ) Qᵀ.
    const Eigen::MatrixXd Kt = -p.weight * (Q * Eigen::MatrixXd(tangent_[i]) * Q.transpose());
    for (int r = 0; r < dim_; ++r) {
      Rl[r] = -force_[i](r);       // node a receives −A Q t
      Rl[dim_ + r] = force_[i](r); // node b receives +A Q t
      for (int c = 0; c < dim_; ++c) {
        Kl[r * n + c] = Kt(r, c);
        Kl[r * n + dim_ + c] = -Kt(r, c);
        Kl[(dim_ + r) * n + c] = -Kt(r, c);
        Kl[(dim_ + r) * n + dim_ + c] = Kt(r, c);
      }
    }
    const Index nodes[2] = {p.node_a, p.node_b};
    if (p.node_b == rigid_obstacle) {
      // Node a's block only: the obstacle has no DOFs (Kl and Rl keep it first, row stride n).
      for (int r = 0; r < dim_; ++r)
        for (int c = 0; c < dim_; ++c)
          Kl[r * dim_ + c] = Kt(r, c);
    }
    int m = p.node_b == rigid_obstacle ? dim_ : n;
    dofs_.node_dofs(nodes, m / dim_, block);
    if (rigid_ && (rigid_->is_slave(block.front()) || rigid_->is_slave(block.back()))) {
      // Onto the rigid body's reference node; Kl and Rl compacted to the m × m system first.
      std::vector<double> Km(static_cast<std::size_t>(m) * m), Rm(Rl.begin(), Rl.begin() + m);
      for (int r = 0; r < m; ++r)
        for (int c = 0; c < m; ++c)
          Km[r * m + c] = Kl[r * (m == n ? n : dim_) + c];
      rigid_->distribute(block, Rm, K ? &Km : nullptr);
      m = static_cast<int>(block.size());
      Rl = Rm;
      Kl = Km;
    }
    if (K) {
      constraints.condense(block.data(), m, Kl.data(), Rl.data());
      K->add_dense(block.data(), m, Kl.data());
    } else {
      constraints.condense(block.data(), m, Rl.data());
    }
    R.add(block.data(), m, Rl.data());
  }
}

LocalMatrix InterfaceAssembler::frame(std::size_t i) const {
  return pair_frame(iface_.pairs[i], dim_).topLeftCorner(dim_, dim_);
}

void InterfaceAssembler::update_multipliers() {
  for (std::size_t i = 0; i < multiplier_.size(); ++i)
    multiplier_[i] = results_[i].r;
}

void InterfaceAssembler::mark_tangent_assembled() {
  assembled_tangent_ = tangent_;
  tangent_changed_ = false;
}

void InterfaceAssembler::commit() {
  for (std::size_t i = 0; i < committed_.size(); ++i) {
    previous_r_[i] = committed_[i].r;
    committed_[i].beta = results_[i].beta;
    committed_[i].jump = results_[i].jump;
    committed_[i].r = results_[i].r;
    multiplier_[i] = results_[i].r;
  }
}

bool InterfaceAssembler::enter_stage(std::size_t stage) {
  bool changed = false;
  for (const StageLaw& sl : stage_laws_)
    if (sl.stage == stage) set_law(*sl.law), changed = true;
  return changed;
}

void InterfaceAssembler::set_law(const InterfaceLaw& law) {
  law_ = &law;
  frozen_law_.emplace(law);
  frozen_ = false;
  for (std::size_t i = 0; i < committed_.size(); ++i) {
    double& beta = committed_[i].beta;
    beta = law.is_tied() ? 1.0 : std::min(beta, law.initial_adhesion());
    results_[i].beta = beta;
  }
  rebase_energy_account();
  tangent_changed_ = true;
}

void InterfaceAssembler::freeze_adhesion(const std::vector<double>& beta) {
  if (beta.size() != committed_.size())
    throw Error("interface '" + iface_.name + "': freeze_adhesion needs one beta per pair");
  frozen_beta_ = beta;
  frozen_ = true;
}

std::vector<double> InterfaceAssembler::committed_adhesion() const {
  std::vector<double> beta(committed_.size());
  for (std::size_t i = 0; i < committed_.size(); ++i)
    beta[i] = committed_[i].beta;
  return beta;
}

std::vector<double> InterfaceAssembler::adhesion_at(const std::vector<double>& u,
                                                    double dtau) const {
  std::vector<double> beta(committed_.size());
  for (std::size_t i = 0; i < committed_.size(); ++i)
    beta[i] = law_->update_adhesion(committed_[i].beta, local_jump(i, u), dtau);
  return beta;
}

bool InterfaceAssembler::adhesion_can_change() const {
  if (law_->is_tied()) return false;
  return std::any_of(committed_.begin(), committed_.end(),
                     [](const InterfaceState& s) { return s.beta > 0.0; });
}

double InterfaceAssembler::adhesion_capacity() const {
  double sum = 0;
  for (std::size_t i = 0; i < committed_.size(); ++i)
    sum += iface_.pairs[i].weight * law_->adhesion_energy(committed_[i].beta);
  return sum;
}

std::array<double, 3> InterfaceAssembler::resultant() const {
  std::array<double, 3> sum = {0, 0, 0};
  for (const auto& f : force_)
    for (int c = 0; c < 3; ++c)
      sum[c] += f(c);
  return sum;
}

double InterfaceAssembler::force_scale() const {
  double s = 0;
  for (std::size_t i = 0; i < iface_.pairs.size(); ++i)
    s = std::max(s, iface_.pairs[i].weight * results_[i].traction.norm());
  return s;
}

} // namespace bipot::contact
