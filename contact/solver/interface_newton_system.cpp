#include "contact/solver/interface_newton_system.hpp"

#include <algorithm>

namespace bipot::contact {

CondensedSize condensed_size(const std::vector<const Interface*>& interfaces, int dim) {
  std::vector<Index> nodes;
  CondensedSize size;
  for (const Interface* iface : interfaces)
    for (const InterfacePair& p : iface->pairs) {
      nodes.push_back(p.node_a);
      if (p.node_b != rigid_obstacle) nodes.push_back(p.node_b);
      size.multipliers += dim;
    }
  std::sort(nodes.begin(), nodes.end());
  size.dofs = dim * static_cast<Index>(std::unique(nodes.begin(), nodes.end()) - nodes.begin());
  return size;
}

std::string condensed_size_problem(const CondensedSize& size, const std::string& where) {
  if (size.total() <= max_condensed_unknowns) return "";
  return (where.empty() ? std::string() : where + ": ") +
         "generalized_newton condenses the model onto its " + std::to_string(size.dofs) +
         " interface DOFs and " + std::to_string(size.multipliers) +
         " multipliers, a dense system of more than " + std::to_string(max_condensed_unknowns) +
         " unknowns; use type: semismooth_newton for interfaces this large";
}

InterfaceNewtonSystem::InterfaceNewtonSystem(const std::vector<InterfaceAssembler*>& interfaces,
                                             const DofMap& dofs)
    : dim_(dofs.dofs_per_node()) {
  interfaces_ = interfaces;
  // A node may belong to two interfaces (the corner of a pile's shaft and toe): one x each.
  for (InterfaceAssembler* ia : interfaces_)
    for (const InterfacePair& p : ia->interface().pairs)
      for (int c = 0; c < dim_; ++c) {
        dofs_.push_back(dofs.dof(p.node_a, c));
        if (p.node_b != rigid_obstacle) dofs_.push_back(dofs.dof(p.node_b, c));
      }
  std::sort(dofs_.begin(), dofs_.end());
  dofs_.erase(std::unique(dofs_.begin(), dofs_.end()), dofs_.end());
  auto position = [&](Index dof) {
    return static_cast<Index>(std::lower_bound(dofs_.begin(), dofs_.end(), dof) - dofs_.begin());
  };
  Index next = num_dofs();
  for (InterfaceAssembler* ia : interfaces_)
    for (std::size_t i = 0; i < ia->num_pairs(); ++i) {
      const InterfacePair& p = ia->interface().pairs[i];
      // DOFs are node-major (dof = node × dim + c), so a node's components are consecutive.
      const Index b = p.node_b == rigid_obstacle ? Index(-1) : position(dofs.dof(p.node_b, 0));
      pairs_.push_back({ia, i, position(dofs.dof(p.node_a, 0)), b, next});
      next += dim_;
    }
  num_multipliers_ = next - num_dofs();
}

Eigen::VectorXd InterfaceNewtonSystem::multipliers() const {
  Eigen::VectorXd lambda(num_multipliers_);
  for (const PairSlots& s : pairs_) {
    const double A = s.iface->interface().pairs[s.pair].weight;
    lambda.segment(s.multiplier - num_dofs(), dim_) = A * s.iface->multipliers()[s.pair];
  }
  return lambda;
}

void InterfaceNewtonSystem::set_multipliers(const Eigen::VectorXd& lambda) const {
  for (InterfaceAssembler* ia : interfaces_) {
    std::vector<LocalVector> r = ia->multipliers();
    for (const PairSlots& s : pairs_) {
      if (s.iface != ia) continue;
      const double A = ia->interface().pairs[s.pair].weight;
      r[s.pair] = A > 0 ? LocalVector(lambda.segment(s.multiplier - num_dofs(), dim_) / A)
                        : LocalVector(LocalVector::Zero(dim_));
    }
    ia->set_multipliers(r);
  }
}

template <class AddEntry>
void InterfaceNewtonSystem::add_terms(const std::vector<bool>& constrained, Eigen::VectorXd& F,
                                      AddEntry* jac) const {
  const int d = dim_;
  for (const PairSlots& s : pairs_) {
    const double A = s.iface->interface().pairs[s.pair].weight;
    const Index m = s.multiplier;
    if (!(A > 0)) { // a pair without area carries no force: λ stays at A r̂ = 0
      F.segment(m, d).setZero();
      if (jac)
        for (int c = 0; c < d; ++c)
          (*jac)(m + c, m + c, 1.0);
      continue;
    }
    const PairResult& res = s.iface->results()[s.pair];
    const InterfaceResponseDerivatives& der = s.iface->derivatives(s.pair);
    const Eigen::MatrixXd Q = s.iface->frame(s.pair);
    const Eigen::VectorXd r_in = s.iface->multipliers()[s.pair];
    const Eigen::VectorXd adhesive = res.traction - res.r;
    // Interface force on b (global components): Q (λ + A a).
    const Eigen::VectorXd force = Q * (A * r_in + A * adhesive);
    F.segment(m, d) = A * (r_in - res.r);
    // Against an obstacle (s.b < 0) body 2's side is data: no row, no column.
    const bool has_b = s.b >= 0;
    auto held_b = [&](int c) { return !has_b || constrained[s.b + c]; };
    for (int c = 0; c < d; ++c) {
      if (!held_b(c)) F(s.b + c) += force(c);
      if (!constrained[s.a + c]) F(s.a + c) -= force(c);
    }
    if (!jac) continue;
    // d(adhesive)/d(jump), β's dependence on the jump included.
    const Eigen::MatrixXd D = der.dt_djump - der.dr_djump;
    const Eigen::MatrixXd Kc = A * Q * D * Q.transpose();         // ∂(force on b)/∂x_b
    const Eigen::MatrixXd Cx = -A * der.dr_djump * Q.transpose(); // ∂F_λ/∂x_b
    for (int r = 0; r < d; ++r) {
      const bool free_b = !held_b(r), free_a = !constrained[s.a + r];
      for (int c = 0; c < d; ++c) {
        if (free_b) {
          (*jac)(s.b + r, s.b + c, Kc(r, c));
          (*jac)(s.b + r, s.a + c, -Kc(r, c));
          (*jac)(s.b + r, m + c, Q(r, c));
        }
        if (free_a) {
          if (has_b) (*jac)(s.a + r, s.b + c, -Kc(r, c));
          (*jac)(s.a + r, s.a + c, Kc(r, c));
          (*jac)(s.a + r, m + c, -Q(r, c));
        }
        if (has_b) (*jac)(m + r, s.b + c, Cx(r, c));
        (*jac)(m + r, s.a + c, -Cx(r, c));
      }
    }
    const Eigen::MatrixXd dF_dlambda = Eigen::MatrixXd::Identity(d, d) - der.dr_dr;
    for (int r = 0; r < d; ++r)
      for (int c = 0; c < d; ++c)
        (*jac)(m + r, m + c, dF_dlambda(r, c));
    // A component that the law leaves free (stick: ∂F_λ/∂λ = 0) and that acts only on
    // prescribed DOFs (both nodes held in its direction, e.g. a pile head pair whose two copies
    // are pulled together) is undetermined: any value satisfies the equations and the
    // reactions take the force. Fix its step by its own row (a zero column otherwise makes J
    // singular).
    // A stuck component elsewhere gets stick_regularisation (two pairs on one node pair).
    for (int c = 0; c < d; ++c) {
      const bool free_in_law = dF_dlambda.col(c).norm() == 0.0;
      bool acts = !free_in_law;
      for (int r = 0; r < d && !acts; ++r)
        acts = Q(r, c) != 0.0 && (!held_b(r) || !constrained[s.a + r]);
      if (!acts)
        (*jac)(m + c, m + c, 1.0);
      else if (free_in_law)
        (*jac)(m + c, m + c, stick_regularisation);
    }
  }
}

void InterfaceNewtonSystem::add(const std::vector<bool>& constrained, Eigen::VectorXd& F,
                                Eigen::MatrixXd* J) const {
  auto entry = [J](Index r, Index c, double v) { (*J)(r, c) += v; };
  add_terms(constrained, F, J ? &entry : nullptr);
}

void InterfaceNewtonSystem::add(const std::vector<bool>& constrained, Eigen::VectorXd& F,
                                std::vector<Eigen::Triplet<double>>& J) const {
  auto entry = [&J](Index r, Index c, double v) { J.emplace_back(r, c, v); };
  add_terms(constrained, F, &entry);
}

double InterfaceNewtonSystem::multiplier_residual(const Eigen::VectorXd& F) const {
  double worst = 0;
  for (const PairSlots& s : pairs_)
    worst = std::max(worst, F.segment(s.multiplier, dim_).norm());
  return worst;
}

std::vector<ContactStatus> InterfaceNewtonSystem::branches() const {
  std::vector<ContactStatus> out;
  out.reserve(pairs_.size());
  for (const PairSlots& s : pairs_)
    out.push_back(s.iface->results()[s.pair].status);
  return out;
}

bool InterfaceNewtonSystem::set_tie_hints(const Eigen::VectorXd& Fx,
                                          const std::vector<bool>& constrained) const {
  bool changed = false;
  for (InterfaceAssembler* ia : interfaces_) {
    // With a predictor (multipliers extrapolated along the last increment) the residual at
    // the start is the predictor's error, whose direction says nothing of the coming slip:
    // hinted from it, the Coulomb pile took 111 linear solves, 83 with round-off deciding and
    // 79 hinting only increments without a predictor (a stage's first).
    if (ia->predicted()) continue;
    std::vector<ConeTie> hints(ia->num_pairs(), ConeTie::ByValue);
    for (const PairSlots& s : pairs_) {
      if (s.iface != ia) continue;
      // How the residual pushes the jump u_b − u_a, from the forces on the pair's own free
      // DOFs (a local estimate: the condensed bulk also couples the nodes): its tangential
      // part against r_t continues the slip, along r_t reverses it, which the cone's interior
      // takes.
      Eigen::VectorXd push = Eigen::VectorXd::Zero(dim_);
      for (int c = 0; c < dim_; ++c) {
        if (s.b >= 0 && !constrained[s.b + c]) push(c) += Fx(s.b + c);
        if (!constrained[s.a + c]) push(c) -= Fx(s.a + c);
      }
      const Eigen::VectorXd local = ia->frame(s.pair).transpose() * push;
      const double along = local.tail(dim_ - 1).dot(ia->multipliers()[s.pair].tail(dim_ - 1));
      if (along != 0.0) hints[s.pair] = along < 0.0 ? ConeTie::Slip : ConeTie::Stick;
    }
    changed = ia->set_tie_hints(std::move(hints)) || changed;
  }
  return changed;
}

double InterfaceNewtonSystem::released_adhesion_energy(Eigen::VectorXd* grad) const {
  double released = 0;
  for (InterfaceAssembler* ia : interfaces_) {
    const double per_beta = ia->law().adhesion_energy(1.0) - ia->law().adhesion_energy(0.0);
    if (per_beta == 0.0) continue;
    const std::vector<double> committed = ia->committed_adhesion();
    for (const PairSlots& s : pairs_) {
      if (s.iface != ia) continue;
      const double A = ia->interface().pairs[s.pair].weight;
      released += A * per_beta * (committed[s.pair] - ia->results()[s.pair].beta);
      if (!grad) continue;
      // jump = Qᵀ(u_b − u_a): ∂β/∂x_b = Q ∂β/∂jump, ∂β/∂x_a its opposite.
      const Eigen::VectorXd g =
          -A * per_beta * (ia->frame(s.pair) * ia->derivatives(s.pair).dbeta_djump);
      grad->segment(s.b, dim_) += g;
      grad->segment(s.a, dim_) -= g;
    }
  }
  return released;
}

} // namespace bipot::contact
