#pragma once
/// Abstract bulk material: pure point-wise code (no mesh, YAML, MPI or Trilinos), so each
/// material is unit-testable against closed forms.

#include "fem/core/types.hpp"

#include <string>

namespace bipot {

/// Stress update at one quadrature point. Strains and stresses use the Voigt order of
/// fem/core/types.hpp (engineering shear strains; stress tension positive).
/// Internal variables live in caller-owned arrays of size num_state_variables().
class Material {
public:
  virtual ~Material() = default;

  /// The YAML name (also the file stem).
  virtual std::string name() const = 0;

  /// Number of internal variables stored per quadrature point.
  virtual int num_state_variables() const { return 0; }

  /// Stress and consistent tangent dσ/dε for the total strain `strain` (size 4 in 2D, 6 in
  /// 3D) given the converged internal variables `old_state`; writes the updated internal
  /// variables to `new_state`. The stress excludes any initial (geostatic) stress, which the
  /// assembly adds.
  virtual void update(const Voigt& strain, const double* old_state, Voigt& stress,
                      VoigtMatrix& tangent, double* new_state) const = 0;

  /// True if the tangent does not depend on the strain or state: the analysis then keeps
  /// one matrix (and preconditioner) for as long as the constrained DOFs do not change.
  virtual bool is_linear() const { return false; }

  /// Weight per unit volume (kN/m³) used by gravity loads; 0 if not given.
  virtual double unit_weight() const { return 0.0; }
};

} // namespace bipot
