#pragma once
/// Perfectly bonded (tied) interface.

#include "contact/laws/interface_law.hpp"
#include "fem/core/parameter_binding.hpp"

namespace bipot::contact {

/// Perfect bonding: g = 0 (docs/formulation.md §3); the traction is whatever keeps the jump zero.
/// Enforced exactly, never by a penalty: an interface bonded in every stage keeps shared nodes
/// (no jump exists); one bonded in some stages only is split and its pairs are held by
/// evaluate_tie() (an equality multiplier, exact to the solver's tolerance), so the
/// point-wise functions below are not used. RCCM with huge w, C_n and C_t approaches it.
class PerfectBonding : public InterfaceLaw {
public:
  struct Parameters {}; ///< no keys
  static ParamSchemaOf<Parameters> schema();

  PerfectBonding() = default;
  explicit PerfectBonding(const Parameters& p) : PerfectBonding(schema().checked(p)) {}
  explicit PerfectBonding(Checked<Parameters>) {}

  std::string name() const override { return "perfect_bonding"; }
  bool is_tied() const override { return true; }
  /// 0: unused, a tied interface has no friction cone.
  double friction_coefficient(double) const override { return 0.0; }
};

} // namespace bipot::contact
