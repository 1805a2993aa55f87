#pragma once
/// Internal to fem/analysis: when an increment has converged, one rule for both Newton
/// increment solvers (docs/theory.md, "Round-off floor").

#include <algorithm>

namespace bipot {

/// The force residual is met below `tolerance` × a reference force, or below the round-off
/// floor of the interface forces; the interface law (multiplier change or residual) is met
/// below `tolerance` × the same reference. Relative residuals (the history of an increment)
/// are measured against that reference too.
class ConvergenceTest {
public:
  /// Safety on the interfaces' round-off estimate.
  static constexpr double roundoff_factor = 10.0;

  explicit ConvergenceTest(double tolerance) : tolerance_(tolerance) {}

  /// At the increment's first residual: the reference is the largest of that residual, the
  /// applied load, the interfaces' largest force and the last converged reaction. Without the
  /// reaction, an increment the predictor already solves (a linear model under proportional
  /// loading) measured its residual against its own round-off and never converged.
  void set_reference(double first_residual, double load, double interface_force, double reaction) {
    reference_ = std::max({first_residual, load, interface_force, reaction});
  }
  bool has_reference() const { return reference_ >= 0; }
  /// The interface forces grew during the increment: the reference follows them.
  void raise_reference(double interface_force) {
    reference_ = std::max(reference_, interface_force);
  }
  double reference() const { return reference_; }
  double relative(double value) const { return value / reference_; }

  /// The interfaces' round-off force at the current iterate (their largest roundoff_force()).
  void set_roundoff(double roundoff) { roundoff_ = roundoff; }
  /// A tolerance below the interface forces' round-off (large ρ, tight tolerance) cannot be
  /// met; the residual then stalls at that level, which counts as converged.
  double force_floor() const {
    return std::max(tolerance_ * reference_, roundoff_factor * roundoff_);
  }
  bool forces_met(double norm) const { return norm <= force_floor(); }
  bool law_met(double residual) const { return residual <= tolerance_ * reference_; }

private:
  double tolerance_;
  double reference_ = -1.0; ///< < 0 until set_reference()
  double roundoff_ = 0.0;
};

} // namespace bipot
