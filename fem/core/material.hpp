#pragma once
/// Abstract bulk material: pure point-wise code (no mesh, YAML, MPI or Trilinos), so each
/// material is unit-testable against closed forms.

#include "fem/core/types.hpp"

#include <optional>
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

  /// Number of internal variables stored per quadrature point (the same for 2D and 3D).
  virtual int num_state_variables() const { return 0; }

  /// Stress and consistent tangent dσ/dε for the total strain `strain` (size 4 in 2D, 6 in
  /// 3D) given the converged internal variables `old_state`; writes the updated internal
  /// variables to `new_state` and never writes `old_state`, so the caller commits an
  /// increment by copying new_state over old_state (and cuts back by not doing so).
  /// `initial_stress` σ0 (same size as `strain`, zero when there is none) is the stress at
  /// zero strain, e.g. geostatic: a yield criterion must see the total stress σ0 + σ.
  /// The returned stress still EXCLUDES σ0, which the assembly adds.
  virtual void update(const Voigt& strain, const Voigt& initial_stress, const double* old_state,
                      Voigt& stress, VoigtMatrix& tangent, double* new_state) const = 0;

  /// Number of point-wise diagnostics (for VTK output) derived from the internal variables.
  virtual int num_output_fields() const { return 0; }
  /// Name of diagnostic `i` in [0, num_output_fields()), snake_case.
  virtual std::string output_field_name(int /*i*/) const { return {}; }
  /// Writes the num_output_fields() diagnostics of the internal variables `state` to `values`.
  virtual void output(const double* /*state*/, double* /*values*/) const {}

  /// True if the tangent does not depend on the strain or state: the analysis then keeps
  /// one matrix (and preconditioner) for as long as the constrained DOFs do not change.
  virtual bool is_linear() const { return false; }

  /// The yield function at total stress `stress` of a virgin point (≤ 0 admissible, kPa), or
  /// nothing for a material without a yield surface: the check that initial (geostatic)
  /// stresses are admissible needs no more than this.
  virtual std::optional<double> initial_yield_value(const Voigt& /*stress*/) const {
    return std::nullopt;
  }

  /// Weight per unit volume (kN/m³) used by gravity loads; 0 if not given.
  virtual double unit_weight() const { return 0.0; }
};

} // namespace bipot
