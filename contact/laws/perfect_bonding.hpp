#pragma once
/// Perfectly bonded (tied) interface.

#include "contact/laws/interface_law.hpp"
#include "fem/core/parameter_schema.hpp"

namespace bipot::contact {

/// Perfect bonding: g = 0 (docs/formulation.md §3); the traction is whatever keeps the jump zero.
/// It is enforced exactly by the solver (constraint elimination of the jump), never by a
/// penalty, so the point-wise functions are not used (evaluate() refuses a tied law). RCCM with
/// huge w, C_n and C_t approaches it.
class PerfectBonding : public InterfaceLaw {
public:
  /// No keys.
  static ParamSchema schema();

  PerfectBonding() = default;
  /// From parameters validated against schema() (always empty).
  explicit PerfectBonding(const ParameterSet&) {}

  std::string name() const override { return "perfect_bonding"; }
  bool is_tied() const override { return true; }
  /// 0: unused, a tied interface has no friction cone.
  double friction_coefficient(double) const override { return 0.0; }
};

} // namespace bipot::contact
