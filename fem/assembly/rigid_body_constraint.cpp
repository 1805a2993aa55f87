#include "fem/assembly/rigid_body_constraint.hpp"

#include "fem/linalg/distributed_vector.hpp"
#include "fem/linalg/dof_distribution.hpp"
#include "fem/linalg/sparse_matrix.hpp"
#include "fem/linalg/sparsity_pattern.hpp"

#include <Eigen/Dense>

#include <algorithm>

namespace bipot {

int rigid_body_components(Kinematics kin) {
  switch (kin) {
  case Kinematics::PlaneStrain:
    return 3;
  case Kinematics::Axisymmetric:
    return 2; // r (held) and z
  case Kinematics::ThreeD:
    return 6;
  }
  return 0;
}

Index rigid_body_dof(const RigidBody& body, const DofMap& dofs, Kinematics kin, int k) {
  const int d = spatial_dim(kin);
  return k < d ? dofs.dof(body.reference, k) : dofs.dof(body.rotation, k - d);
}

RigidBodyConstraints::RigidBodyConstraints(const Mesh& mesh, Kinematics kin, const DofMap& dofs,
                                           const std::vector<RigidBody>& bodies) {
  const int d = spatial_dim(kin);
  for (const RigidBody& b : bodies) {
    auto R = [&](int c) { return dofs.dof(b.reference, c); };
    auto W = [&](int c) { return dofs.dof(b.rotation, c); };
    for (Index n : b.nodes) {
      double r[3];
      for (int i = 0; i < 3; ++i)
        r[i] = mesh.nodes[n][i] - b.point[i];
      auto& s = slaves_;
      switch (kin) {
      case Kinematics::PlaneStrain: // u = u_R + θ (−r_y, r_x)
        s[dofs.dof(n, 0)] = {{R(0), 1.0}, {W(0), -r[1]}};
        s[dofs.dof(n, 1)] = {{R(1), 1.0}, {W(0), r[0]}};
        break;
      case Kinematics::Axisymmetric: // axial translation only
        s[dofs.dof(n, 0)] = {};
        s[dofs.dof(n, 1)] = {{R(1), 1.0}};
        break;
      case Kinematics::ThreeD: // u = u_R + θ × r
        s[dofs.dof(n, 0)] = {{R(0), 1.0}, {W(1), r[2]}, {W(2), -r[1]}};
        s[dofs.dof(n, 1)] = {{R(1), 1.0}, {W(2), r[0]}, {W(0), -r[2]}};
        s[dofs.dof(n, 2)] = {{R(2), 1.0}, {W(0), r[1]}, {W(1), -r[0]}};
        break;
      }
    }
    // Masters' components without an unknown.
    if (kin == Kinematics::PlaneStrain) inactive_.push_back(W(1));
    if (kin == Kinematics::Axisymmetric) inactive_.insert(inactive_.end(), {R(0), W(0), W(1)});
    (void)d;
  }
  for (const auto& kv : slaves_)
    slave_order_.push_back(kv.first);
  std::sort(slave_order_.begin(), slave_order_.end());
  inactive_.insert(inactive_.end(), slave_order_.begin(), slave_order_.end());
  std::sort(inactive_.begin(), inactive_.end());
}

void RigidBodyConstraints::distribute(std::vector<Index>& dofs, std::vector<double>& R,
                                      std::vector<double>* K) const {
  if (slaves_.empty()) return;
  const int n = static_cast<int>(dofs.size());
  bool any = false;
  for (Index d : dofs)
    any = any || slaves_.count(d);
  if (!any) return;
  // New DOFs: the non-slaves in order, then the masters; T (n × m) maps new to old.
  std::vector<Index> out;
  std::vector<std::vector<std::pair<int, double>>> rows(n);
  auto column = [&](Index dof) {
    const auto it = std::find(out.begin(), out.end(), dof);
    if (it != out.end()) return static_cast<int>(it - out.begin());
    out.push_back(dof);
    return static_cast<int>(out.size()) - 1;
  };
  for (int i = 0; i < n; ++i)
    if (!slaves_.count(dofs[i])) rows[i].emplace_back(column(dofs[i]), 1.0);
  for (int i = 0; i < n; ++i) {
    const auto it = slaves_.find(dofs[i]);
    if (it == slaves_.end()) continue;
    for (const auto& [master, coefficient] : it->second)
      rows[i].emplace_back(column(master), coefficient);
  }
  const int m = static_cast<int>(out.size());
  Eigen::MatrixXd T = Eigen::MatrixXd::Zero(n, m);
  for (int i = 0; i < n; ++i)
    for (const auto& [j, v] : rows[i])
      T(i, j) += v;
  const Eigen::VectorXd Rt = T.transpose() * Eigen::Map<const Eigen::VectorXd>(R.data(), n);
  R.assign(Rt.data(), Rt.data() + m);
  if (K) {
    using RowMajor = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;
    const RowMajor Kt = T.transpose() * Eigen::Map<const RowMajor>(K->data(), n, n) * T;
    K->assign(Kt.data(), Kt.data() + static_cast<std::size_t>(m) * m);
  }
  dofs = std::move(out);
}

void RigidBodyConstraints::distribute(std::vector<Index>& dofs) const {
  if (slaves_.empty()) return;
  std::vector<Index> out;
  for (Index d : dofs) {
    const auto it = slaves_.find(d);
    if (it == slaves_.end()) {
      out.push_back(d);
      continue;
    }
    for (const auto& mc : it->second)
      out.push_back(mc.first);
  }
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  dofs = std::move(out);
}

void RigidBodyConstraints::transfer(DistributedVector& f) const {
  if (slaves_.empty()) return;
  const std::vector<double> all = f.gather_all();
  const bool root = f.distribution().rank() == 0; // each slave moved once
  for (Index s : slave_order_) {
    if (!root || all[s] == 0.0) continue;
    for (const auto& [master, coefficient] : slaves_.at(s))
      f.add(master, coefficient * all[s]);
    f.add(s, -all[s]);
  }
  f.finish_assembly();
}

void RigidBodyConstraints::follow(std::vector<double>& u) const {
  for (Index s : slave_order_) {
    double v = 0;
    for (const auto& [master, coefficient] : slaves_.at(s))
      v += coefficient * u[master];
    u[s] = v;
  }
}

void RigidBodyConstraints::add_inactive_rows(const DofDistribution& dist, SparseMatrix& K) const {
  for (Index d : inactive_)
    if (dist.owner_of_dof(d) == dist.rank()) K.add(d, d, 1.0);
}

void RigidBodyConstraints::add_inactive_rows(const DofDistribution& dist,
                                             SparsityPattern& pattern) const {
  for (Index d : inactive_)
    if (dist.owner_of_dof(d) == dist.rank()) pattern.add_cell({d});
}

} // namespace bipot
