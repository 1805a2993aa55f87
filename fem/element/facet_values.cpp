#include "fem/element/facet_values.hpp"

#include "fem/core/error.hpp"
#include "fem/mesh/mesh.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

namespace bipot {
namespace {

constexpr double two_pi = 6.283185307179586476925286766559005768;

std::string num(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.6g", v);
  return buf;
}

} // namespace

FacetValues::FacetValues(CellType type, Kinematics kin, int degree)
    : FacetValues(type, kin, gauss_rule(type, degree)) {}

FacetValues::FacetValues(CellType type, Kinematics kin, QuadratureRule rule)
    : type_(type), kin_(kin), rule_(std::move(rule)) {
  dim_ = spatial_dim(kin);
  if (type == CellType::Point1 || cell_dim(type) != dim_ - 1)
    throw Error("FacetValues: facet type " + to_string(type) + " cannot be used with " +
                to_string(kin) + " kinematics (facet dimension " + std::to_string(cell_dim(type)) +
                ", spatial dimension " + std::to_string(dim_) + ")");
  nq_ = rule_.size();
  nn_ = bipot::num_nodes(type);
  const int rdim = dim_ - 1;
  N_.resize(nq_ * nn_);
  dNref_.resize(nq_ * nn_ * rdim);
  x_.assign(nq_, {0, 0, 0});
  n_.assign(nq_, {0, 0, 0});
  JxW_.assign(nq_, 0.0);
  for (int q = 0; q < nq_; ++q) {
    shape_values(type, rule_.points[q].data(), &N_[q * nn_]);
    shape_gradients(type, rule_.points[q].data(), &dNref_[q * nn_ * rdim]);
  }
}

void FacetValues::reinit(const double* coords, Index facet) {
  compute(coords, facet, false);
}

void FacetValues::reinit(const Mesh& mesh, const Facet& facet) {
  if (facet.type != type_ || static_cast<int>(facet.nodes.size()) != nn_)
    throw Error("FacetValues for " + to_string(type_) + " given a " + to_string(facet.type) +
                " facet of cell " + std::to_string(facet.cell));
  for (int a = 0; a < nn_; ++a)
    for (int i = 0; i < 3; ++i)
      coords_[3 * a + i] = mesh.nodes[facet.nodes[a]][i];
  compute(coords_.data(), facet.cell, true);
}

void FacetValues::compute(const double* coords, Index id, bool id_is_cell) {
  auto label = [&] {
    const std::string what = id_is_cell ? "facet of cell " : "facet ";
    return (id >= 0 ? what + std::to_string(id) : what + "(id unknown)") + " (" + to_string(type_) +
           ")";
  };
  // Size of the facet, for a scale-free degeneracy test.
  double h = 0;
  for (int a = 1; a < nn_; ++a) {
    double d2 = 0;
    for (int i = 0; i < 3; ++i)
      d2 += std::pow(coords[3 * a + i] - coords[i], 2);
    h = std::max(h, std::sqrt(d2));
  }
  const int rdim = dim_ - 1;
  for (int q = 0; q < nq_; ++q) {
    const double* N = &N_[q * nn_];
    const double* dN = &dNref_[q * nn_ * rdim];
    std::array<double, 3> x{0, 0, 0}, t1{0, 0, 0}, t2{0, 0, 0}; // t_j = ∂x/∂ξ_j
    for (int a = 0; a < nn_; ++a)
      for (int i = 0; i < dim_; ++i) {
        x[i] += N[a] * coords[3 * a + i];
        t1[i] += dN[a * rdim] * coords[3 * a + i];
        if (rdim == 2) t2[i] += dN[a * rdim + 1] * coords[3 * a + i];
      }
    std::array<double, 3> n{0, 0, 0};
    if (dim_ == 2) {
      n = {t1[1], -t1[0], 0};
    } else {
      n = {t1[1] * t2[2] - t1[2] * t2[1], t1[2] * t2[0] - t1[0] * t2[2],
           t1[0] * t2[1] - t1[1] * t2[0]};
    }
    const double jac = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    if (!(jac > 1e-12 * std::pow(h, rdim)))
      throw Error(label() + " is degenerate: " + (dim_ == 2 ? "length" : "area") + " element " +
                  num(jac) + " at quadrature point " + std::to_string(q));
    for (double& c : n)
      c /= jac;
    double w = rule_.weights[q] * jac;
    if (kin_ == Kinematics::Axisymmetric) {
      // r = 0 is allowed: a facet on the axis has zero revolved area.
      if (x[0] < 0)
        throw Error(label() + " has a quadrature point at r = " + num(x[0]) +
                    " < 0; axisymmetric meshes must lie in r >= 0");
      w *= two_pi * x[0];
    }
    x_[q] = x;
    n_[q] = n;
    JxW_[q] = w;
  }
}

} // namespace bipot
