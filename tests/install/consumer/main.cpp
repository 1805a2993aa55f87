// Uses installed headers and libraries: a material from the registry and an element.
#include "fem/element/element_values.hpp"
#include "materials/material_registry.hpp"

#include <cmath>
#include <iostream>

int main() {
  bipot::ParameterSet p;
  p.set("youngs_modulus", 2.0e8);
  p.set("poissons_ratio", 0.25);
  auto steel = bipot::materials().create("linear_elastic", p);
  bipot::Voigt eps = bipot::Voigt::Zero(6), sig;
  eps(0) = 1e-3;
  bipot::VoigtMatrix D;
  steel->update(eps, bipot::Voigt::Zero(eps.size()), nullptr, sig, D, nullptr);
  // sigma_xx = (lambda + 2G) eps_xx with lambda = G = 8e7 for nu = 0.25: 2.4e5.
  bipot::ElementValues ev(bipot::CellType::Quad4, bipot::Kinematics::PlaneStrain, 2);
  const double square[12] = {0, 0, 0, 2, 0, 0, 2, 2, 0, 0, 2, 0};
  ev.reinit(square);
  double area = 0;
  for (int q = 0; q < ev.num_points(); ++q)
    area += ev.JxW(q);
  const bool ok = std::abs(sig(0) - 2.4e5) < 1e-6 && std::abs(area - 4.0) < 1e-12;
  std::cout << "sigma_xx = " << sig(0) << ", area = " << area << (ok ? " ok" : " WRONG") << "\n";
  return ok ? 0 : 1;
}
