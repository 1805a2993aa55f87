#include "contact/solver/tied_interface.hpp"

#include "contact/interface/pair_geometry.hpp"
#include "fem/core/error.hpp"

namespace bipot::contact {

TiedInterface::TiedInterface(const Interface& iface, const DofMap& dofs, TransmittedForce source)
    : iface_(iface), dofs_(dofs), dim_(dofs.dofs_per_node()), source_(source),
      results_(iface.pairs.size()), force_(iface.pairs.size(), Eigen::Vector3d::Zero()) {
  if (!shares_nodes(iface_))
    throw Error("interface '" + iface_.name + "': tying needs bodies that share its nodes");
  for (PairResult& r : results_) {
    r.beta = 1.0;
    r.jump = r.r = r.traction = LocalVector::Zero(dim_);
    r.status = ContactStatus::Stick;
  }
}

double TiedInterface::force_scale() const {
  double s = 0;
  for (std::size_t i = 0; i < iface_.pairs.size(); ++i)
    s = std::max(s, iface_.pairs[i].weight * results_[i].traction.norm());
  return s;
}

std::vector<double> TiedInterface::committed_adhesion() const {
  return std::vector<double>(iface_.pairs.size(), 1.0);
}

void TiedInterface::set_transmitted_forces(const std::vector<double>& force_all) {
  for (std::size_t i = 0; i < iface_.pairs.size(); ++i) {
    const InterfacePair& p = iface_.pairs[i];
    Eigen::Vector3d F = Eigen::Vector3d::Zero();
    for (int c = 0; c < dim_; ++c)
      F(c) = force_all[dofs_.dof(p.node_a, c)];
    force_[i] = F;
    const Eigen::Vector3d local = pair_frame(p, dim_).transpose() * F;
    PairResult& res = results_[i];
    res.traction = p.weight > 0 ? LocalVector(local.head(dim_) / p.weight)
                                : LocalVector(LocalVector::Zero(dim_));
    res.r = res.traction;
  }
}

StateArrays TiedInterface::save_state() const {
  return {{"gap_shift", {gap_shift_}}};
}

void TiedInterface::load_state(const StateArrays& state) {
  const auto it = state.find("gap_shift");
  if (it == state.end() || it->second.size() != 1)
    throw Error("interface '" + iface_.name + "': the state has no array 'gap_shift' of 1 value");
  gap_shift_ = it->second[0];
}

void TiedInterface::load_energy_account(const std::vector<double>& values) {
  if (!values.empty())
    throw Error("interface '" + iface_.name + "': a tied interface has no energy state, got " +
                std::to_string(values.size()) + " values");
}

std::array<double, 3> TiedInterface::resultant() const {
  std::array<double, 3> sum = {0, 0, 0};
  for (const auto& f : force_)
    for (int c = 0; c < 3; ++c)
      sum[c] += f(c);
  return sum;
}

} // namespace bipot::contact
