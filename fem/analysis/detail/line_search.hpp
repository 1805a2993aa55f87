#pragma once
/// Internal to fem/analysis: the line search both Newton increment solvers damp their steps
/// with.

namespace bipot::analysis_detail {

// Backtracking (Armijo) on a merit function along a Newton direction: halves the step from 1
// up to 8 times until merit(step) < (1 − 1e-4 step) merit0. Without such a decrease, the best
// step tried, or the full one if none helped (at a kink of the contact law the Newton
// direction need not be a descent direction). `merit_at_full` ≥ 0: merit(1), evaluated
// already by the caller.
template <class Merit>
double backtracking_step(double merit0, Merit merit, double merit_at_full = -1.0) {
  double step = 1.0, best = merit0, best_step = 1.0;
  for (int k = 0; k < 8; ++k) {
    const double m = k == 0 && merit_at_full >= 0.0 ? merit_at_full : merit(step);
    if (m < (1.0 - 1e-4 * step) * merit0) return step;
    if (m < best) best = m, best_step = step;
    step *= 0.5;
  }
  return best < merit0 ? best_step : 1.0;
}

} // namespace bipot::analysis_detail
