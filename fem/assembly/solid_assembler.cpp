#include "fem/assembly/solid_assembler.hpp"

#include "fem/assembly/rigid_body_constraint.hpp"

#include "fem/core/error.hpp"
#include "fem/element/quadrature.hpp"
#include "fem/linalg/distributed_vector.hpp"
#include "fem/linalg/sparse_matrix.hpp"
#include "fem/linalg/sparsity_pattern.hpp"

#include <algorithm>

namespace bipot {

SolidAssembler::SolidAssembler(const Mesh& mesh, Kinematics kin, const DofMap& dofs,
                               std::vector<const Material*> material_of_region,
                               std::vector<Index> owned_cells)
    : mesh_(mesh), kin_(kin), dofs_(dofs), materials_(std::move(material_of_region)),
      owned_cells_(std::move(owned_cells)), nv_(bipot::voigt_size(spatial_dim(kin))) {
  qp_offset_.reserve(owned_cells_.size() + 1);
  qp_offset_.push_back(0);
  for (Index c : owned_cells_) {
    const int region = mesh_.cell_regions[c];
    if (region < 0 || region >= static_cast<int>(materials_.size()) || !materials_[region])
      throw InputError("no material for region '" + mesh_.region_name(region) + "' (cell " +
                       std::to_string(c) + ")");
    qp_offset_.push_back(qp_offset_.back() + values_for(mesh_.cell_types[c]).num_points());
  }
  Index num_state = 0;
  std::vector<Index> offsets = {0};
  for (std::size_t k = 0; k < owned_cells_.size(); ++k) {
    const Index c = owned_cells_[k];
    num_state += (qp_offset_[k + 1] - qp_offset_[k]) *
                 materials_[mesh_.cell_regions[c]]->num_state_variables();
    offsets.push_back(num_state);
  }
  if (num_state > 0) {
    state_offset_ = std::move(offsets);
    state_.assign(num_state, 0.0);
    trial_state_ = state_;
  }
}

SolidAssembler::~SolidAssembler() = default;

ElementValues& SolidAssembler::values_for(CellType type) const {
  auto it = values_.find(type);
  if (it == values_.end())
    it = values_
             .emplace(type,
                      std::make_unique<ElementValues>(type, kin_, stiffness_degree(type, kin_)))
             .first;
  return *it->second;
}

void SolidAssembler::set_initial_stress(
    const std::function<Voigt(const std::array<double, 3>&, int)>& sigma0) {
  sigma0_.assign(static_cast<std::size_t>(qp_offset_.back()) * nv_, 0.0);
  for (std::size_t k = 0; k < owned_cells_.size(); ++k) {
    const Index c = owned_cells_[k];
    if (region_filter_ >= 0 && mesh_.cell_regions[c] != region_filter_) continue;
    ElementValues& ev = values_for(mesh_.cell_types[c]);
    ev.reinit(mesh_, c);
    for (int q = 0; q < ev.num_points(); ++q) {
      const Voigt s = sigma0(ev.point(q), mesh_.cell_regions[c]);
      for (int i = 0; i < nv_; ++i)
        sigma0_[(qp_offset_[k] + q) * nv_ + i] = s(i);
    }
  }
}

// Integrates each owned cell at `u`, then runs `kernel(dofs, f_e, K_e)`: f_e = f_int,e and,
// if `tangent`, K_e = the tangent (row-major), both sized num_dofs; otherwise K_e stays empty
// (internal forces alone skip the B^T D B products). If `point_stress` is given, also calls it with
// (point index, strain of `u`, material stress, whether the material has internal variables) at
// every point.
template <class CellKernel>
void SolidAssembler::loop(
    const std::vector<double>& u, bool tangent, CellKernel&& kernel,
    const std::function<void(Index, const Voigt&, const Voigt&, bool)>& point_stress) {
  std::vector<Index> cell_dofs;
  std::vector<double> u_e, f_e, K_e;
  Eigen::MatrixXd B, DB;
  Voigt eps, eps_material, sig, sig0;
  VoigtMatrix D;
  for (std::size_t k = 0; k < owned_cells_.size(); ++k) {
    const Index c = owned_cells_[k];
    if (region_filter_ >= 0 && mesh_.cell_regions[c] != region_filter_) continue;
    ElementValues& ev = values_for(mesh_.cell_types[c]);
    ev.reinit(mesh_, c);
    dofs_.cell_dofs(mesh_, c, cell_dofs);
    const int nd = ev.num_dofs();
    u_e.resize(nd);
    for (int a = 0; a < nd; ++a)
      u_e[a] = u[cell_dofs[a]];
    f_e.assign(nd, 0.0);
    K_e.assign(tangent ? static_cast<std::size_t>(nd) * nd : 0, 0.0);
    B.resize(nv_, nd);
    const Material& mat = *materials_[mesh_.cell_regions[c]];
    const int ns = mat.num_state_variables();
    const double* old_state = ns > 0 ? &state_[state_offset_[k]] : nullptr;
    double* new_state = ns > 0 ? &trial_state_[state_offset_[k]] : nullptr;
    Eigen::Map<Eigen::VectorXd> f(f_e.data(), nd);
    const int nk = tangent ? nd : 0;
    Eigen::Map<Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>> Km(
        K_e.data(), nk, nk);
    for (int q = 0; q < ev.num_points(); ++q) {
      const Index p = qp_offset_[k] + q;
      ev.strain_displacement(q, B);
      eps = B * Eigen::Map<const Eigen::VectorXd>(u_e.data(), nd);
      if (sigma0_.empty())
        sig0.setZero(nv_);
      else
        sig0 = Eigen::Map<const Eigen::VectorXd>(&sigma0_[p * nv_], nv_);
      eps_material = eps;
      if (ns > 0 && !strain_offset_.empty())
        eps_material += Eigen::Map<const Eigen::VectorXd>(&strain_offset_[p * nv_], nv_);
      mat.update(eps_material, sig0, old_state ? old_state + q * ns : nullptr, sig, D,
                 new_state ? new_state + q * ns : nullptr);
      if (point_stress) point_stress(p, eps, sig, ns > 0);
      const Voigt total = sig + sig0;
      const double w = ev.JxW(q);
      f.noalias() += w * (B.transpose() * total);
      if (!tangent) continue;
      DB.noalias() = D * B;
      Km.noalias() += w * (B.transpose() * DB);
    }
    kernel(cell_dofs, f_e, K_e);
  }
}

void SolidAssembler::assemble(const std::vector<double>& u, const Constraints& constraints,
                              SparseMatrix* K, DistributedVector& R, SparseMatrix* removed,
                              const Constraints* ahead, DistributedVector* R_ahead) {
  std::vector<double> kept, K_ahead, f_ahead;
  std::vector<char> held;
  loop(u, true,
       [&](std::vector<Index>& cell_dofs, std::vector<double>& f_e, std::vector<double>& K_e) {
         for (auto& v : f_e)
           v = -v;                                             // residual contribution −f_int
         if (rigid_) rigid_->distribute(cell_dofs, f_e, &K_e); // before Dirichlet: on the masters
         const int nd = static_cast<int>(cell_dofs.size());
         if (removed) {
           // What the elimination takes out of K_e: entries in a constrained row or column.
           held.resize(nd);
           bool any = false;
           for (int a = 0; a < nd; ++a) {
             held[a] = constraints.is_constrained(cell_dofs[a]);
             any = any || held[a];
           }
           if (any) {
             kept.assign(K_e.size(), 0.0);
             for (int a = 0; a < nd; ++a)
               for (int b = 0; b < nd; ++b)
                 if (held[a] || held[b]) kept[a * nd + b] = K_e[a * nd + b];
             removed->add_dense(cell_dofs.data(), nd, kept.data());
           }
         }
         if (ahead && R_ahead) {
           // Condensing changes K_e: the second set works on copies.
           K_ahead.assign(K_e.begin(), K_e.end());
           f_ahead.assign(f_e.begin(), f_e.end());
           ahead->condense(cell_dofs.data(), nd, K_ahead.data(), f_ahead.data());
           for (int a = 0; a < nd; ++a)
             R_ahead->add(cell_dofs[a], f_ahead[a]);
         }
         constraints.condense(cell_dofs.data(), nd, K_e.data(), f_e.data());
         if (K) K->add_dense(cell_dofs.data(), nd, K_e.data());
         for (int a = 0; a < nd; ++a)
           R.add(cell_dofs[a], f_e[a]);
       });
  if (rigid_ && K) rigid_->add_inactive_rows(R.distribution(), *K);
}

void SolidAssembler::residual(const std::vector<double>& u, const Constraints& held,
                              DistributedVector& R) {
  loop(u, false,
       [&](std::vector<Index>& cell_dofs, std::vector<double>& f_e, std::vector<double>&) {
         for (auto& v : f_e)
           v = -v;
         if (rigid_) rigid_->distribute(cell_dofs, f_e, nullptr);
         const int nd = static_cast<int>(cell_dofs.size());
         held.condense(cell_dofs.data(), nd, f_e.data());
         for (int a = 0; a < nd; ++a)
           R.add(cell_dofs[a], f_e[a]);
       });
}

void SolidAssembler::internal_force(const std::vector<double>& u, DistributedVector& f,
                                    int region) {
  region_filter_ = region;
  loop(u, false,
       [&](std::vector<Index>& cell_dofs, std::vector<double>& f_e, std::vector<double>&) {
         if (rigid_) rigid_->distribute(cell_dofs, f_e, nullptr);
         for (std::size_t a = 0; a < cell_dofs.size(); ++a)
           f.add(cell_dofs[a], f_e[a]);
       });
  region_filter_ = -1;
}

void SolidAssembler::commit() {
  state_ = trial_state_;
}

void SolidAssembler::absorb_stress_into_initial(const std::vector<double>& u) {
  const std::size_t n = static_cast<std::size_t>(qp_offset_.back()) * nv_;
  if (sigma0_.empty()) sigma0_.assign(n, 0.0);
  if (!state_.empty() && strain_offset_.empty()) strain_offset_.assign(n, 0.0);
  std::vector<double> added(n, 0.0), strain(state_.empty() ? 0 : n, 0.0);
  std::vector<bool> history(qp_offset_.back(), false);
  loop(
      u, false, [](std::vector<Index>&, std::vector<double>&, std::vector<double>&) {},
      [&](Index p, const Voigt& eps, const Voigt& sig, bool has_state) {
        history[p] = has_state;
        for (int i = 0; i < nv_; ++i)
          (has_state ? strain : added)[p * nv_ + i] = has_state ? eps(i) : sig(i);
      });
  // Added after the loop, which reads both.
  for (std::size_t p = 0; p < history.size(); ++p)
    for (int i = 0; i < nv_; ++i) {
      if (history[p])
        strain_offset_[p * nv_ + i] += strain[p * nv_ + i];
      else
        sigma0_[p * nv_ + i] += added[p * nv_ + i];
    }
}

std::vector<std::string> SolidAssembler::output_field_names() const {
  std::vector<std::string> names;
  for (const Material* m : materials_)
    for (int i = 0; m && i < m->num_output_fields(); ++i)
      if (std::find(names.begin(), names.end(), m->output_field_name(i)) == names.end())
        names.push_back(m->output_field_name(i));
  return names;
}

std::vector<double> SolidAssembler::cell_output_fields() const {
  const std::vector<std::string> names = output_field_names();
  const std::size_t nf = names.size();
  std::vector<double> out(owned_cells_.size() * nf, 0.0), point;
  if (nf == 0 || state_.empty()) return out;
  for (std::size_t k = 0; k < owned_cells_.size(); ++k) {
    const Material& mat = *materials_[mesh_.cell_regions[owned_cells_[k]]];
    const int ns = mat.num_state_variables(), no = mat.num_output_fields();
    if (ns == 0 || no == 0) continue;
    std::vector<std::size_t> column(no);
    for (int i = 0; i < no; ++i)
      column[i] = std::find(names.begin(), names.end(), mat.output_field_name(i)) - names.begin();
    const Index points = qp_offset_[k + 1] - qp_offset_[k];
    point.resize(no);
    for (Index q = 0; q < points; ++q) {
      mat.output(&state_[state_offset_[k] + q * ns], point.data());
      for (int i = 0; i < no; ++i)
        out[k * nf + column[i]] += point[i] / points;
    }
  }
  return out;
}

void SolidAssembler::add_to_pattern(SparsityPattern& pattern, const Constraints* touching) const {
  std::vector<Index> cell_dofs;
  for (Index c : owned_cells_) {
    dofs_.cell_dofs(mesh_, c, cell_dofs);
    if (rigid_) rigid_->distribute(cell_dofs);
    if (touching && std::none_of(cell_dofs.begin(), cell_dofs.end(),
                                 [&](Index d) { return touching->is_constrained(d); }))
      continue;
    pattern.add_cell(cell_dofs);
  }
}

void SolidAssembler::cell_averages(const std::vector<double>& u, std::vector<double>& strain,
                                   std::vector<double>& stress) const {
  strain.assign(owned_cells_.size() * nv_, 0.0);
  stress.assign(owned_cells_.size() * nv_, 0.0);
  std::vector<Index> cell_dofs;
  std::vector<double> scratch;
  Eigen::VectorXd u_e;
  Eigen::MatrixXd B;
  Voigt eps, eps_material, sig, sig0 = Voigt::Zero(nv_);
  VoigtMatrix D;
  for (std::size_t k = 0; k < owned_cells_.size(); ++k) {
    const Index c = owned_cells_[k];
    ElementValues& ev = values_for(mesh_.cell_types[c]);
    ev.reinit(mesh_, c);
    dofs_.cell_dofs(mesh_, c, cell_dofs);
    u_e.resize(ev.num_dofs());
    B.resize(nv_, ev.num_dofs());
    for (int a = 0; a < ev.num_dofs(); ++a)
      u_e[a] = u[cell_dofs[a]];
    const Material& mat = *materials_[mesh_.cell_regions[c]];
    const int ns = mat.num_state_variables();
    scratch.resize(ns);
    const double share = 1.0 / ev.num_points();
    for (int q = 0; q < ev.num_points(); ++q) {
      const Index p = qp_offset_[k] + q;
      ev.strain_displacement(q, B);
      eps = B * u_e;
      if (!sigma0_.empty()) sig0 = Eigen::Map<const Eigen::VectorXd>(&sigma0_[p * nv_], nv_);
      eps_material = eps;
      if (ns > 0 && !strain_offset_.empty())
        eps_material += Eigen::Map<const Eigen::VectorXd>(&strain_offset_[p * nv_], nv_);
      // From the committed internal variables the converged strain is an elastic trial that
      // returns the converged stress (to round-off); the scratch state is not kept.
      mat.update(eps_material, sig0, ns > 0 ? &state_[state_offset_[k] + q * ns] : nullptr, sig, D,
                 ns > 0 ? scratch.data() : nullptr);
      Eigen::Map<Eigen::VectorXd>(&strain[k * nv_], nv_) += share * eps;
      Eigen::Map<Eigen::VectorXd>(&stress[k * nv_], nv_) += share * (sig + sig0);
    }
  }
}

} // namespace bipot
