#pragma once
/// How the apps say what the load stepping did: the flags of a progress line and the closing
/// summary, the same in every app.

#include "fem/analysis/static_analysis.hpp"

#include <string>

namespace bipot::app {

/// "" for a planned increment that converged at once; otherwise "  (" + what happened + ")",
/// e.g. "  (1/4 step, sub-increment, 0.41 s in failed attempts)", "  (jump: staggered)",
/// "  (unstable)", "  (traced, unstable)" (path-following, load factor falling), "  (1/4 step
/// for the energy, sub-increment, energy: 2 halvings)" (shortened by energy_tolerance alone),
/// "  (1/8 step, 1 of its 3 halvings for the energy)".
std::string step_flags(const StepReport& r);

/// "<program>: stepping: 83 increments (70 planned, 3 sub-increments, 10 traced), 2 cut-backs,
/// 1 jump; 0.52 s in failed attempts".
std::string stepping_summary(const RunSummary& s, const std::string& program);

/// "<program>: energy balance: worst error 9.5e-04 of the work put in (stage pullout, step 80;
/// energy.csv)", and above 1e-6 what makes it and what holds it; "" for a run with no step.
std::string energy_balance_summary(const RunSummary& s, const std::string& program);

} // namespace bipot::app
