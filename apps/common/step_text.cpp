#include "apps/common/step_text.hpp"

#include <cstdio>
#include <vector>

namespace bipot::app {

namespace {

std::string seconds_text(double s) {
  char text[32];
  std::snprintf(text, sizeof text, "%.2f s", s);
  return text;
}

std::string plural(int n, const std::string& one, const std::string& many) {
  return std::to_string(n) + " " + (n == 1 ? one : many);
}

// Only for a run whose energy control acted (every stage has it, 1e-6 by default; a run it
// never halved has its worst error on the energy balance line).
std::string energy_summary(const RunSummary& s) {
  if (s.energy_halvings == 0 && s.over_energy_budget == 0) return "";
  // Both worsts: energy.csv's (every error) and the controlled one, which leaves out the
  // errors of the increments kept over the budget; printing only the latter hid them.
  char worst[96];
  if (s.over_energy_budget > 0)
    std::snprintf(worst, sizeof worst, "%.2g (%.2g leaving out those increments' own errors)",
                  s.worst_energy_error, s.worst_controlled_energy_error);
  else
    std::snprintf(worst, sizeof worst, "%.2g", s.worst_energy_error);
  // Most increments kept over the budget stop at the smallest step contact_solver.max_cutbacks
  // allows: on rccm.yaml at 1e-6, 345 of them at 6 halvings, and every step within it at 8.
  const std::string advice = s.over_energy_budget > 0
                                 ? " (a larger contact_solver.max_cutbacks lets those at the "
                                   "smallest step halve further)"
                                 : "";
  return "; energy_tolerance: " + plural(s.energy_halvings, "halving", "halvings") + ", " +
         plural(s.over_energy_budget, "increment", "increments") +
         " kept over it, worst balance error " + worst + " of the work put in" + advice;
}

} // namespace

std::string step_flags(const StepReport& r) {
  std::vector<std::string> parts;
  // The halving level the step was solved at (it grows back one level per converged step),
  // and how much of it the energy budget asked for: a step shortened for the energy alone
  // is no convergence trouble. Failures show as time in failed attempts.
  const int level = r.cutbacks + r.energy_cutbacks;
  if (level > 0) {
    std::string step = "1/" + std::to_string(1L << level) + " step";
    if (r.energy_cutbacks == level)
      step += " for the energy";
    else if (r.energy_cutbacks > 0)
      step += ", " + std::to_string(r.energy_cutbacks) + " of its " + std::to_string(level) +
              " halvings for the energy";
    parts.push_back(step);
  }
  if (r.traced)
    parts.push_back("traced");
  else if (r.requested_output && r.planned_step == 0)
    parts.push_back("output level");
  else if (r.planned_step == 0)
    parts.push_back("sub-increment");
  if (r.path_abandoned) parts.push_back("path-following gave up: ramped");
  if (r.staggered > 0)
    parts.push_back("jump: staggered");
  else if (r.unstable && r.cutbacks == 0)
    parts.push_back("unstable");
  if (r.energy_halvings > 0)
    parts.push_back("energy: " + plural(r.energy_halvings, "halving", "halvings"));
  if (r.over_energy_budget) parts.push_back("kept over energy_tolerance");
  if (r.failed_seconds > 0) parts.push_back(seconds_text(r.failed_seconds) + " in failed attempts");
  if (parts.empty()) return "";
  std::string out = "  (";
  for (std::size_t i = 0; i < parts.size(); ++i)
    out += (i ? ", " : "") + parts[i];
  return out + ")";
}

std::string stepping_summary(const RunSummary& s, const std::string& program) {
  return program + ": stepping: " + plural(s.steps, "increment", "increments") + " (" +
         std::to_string(s.steps - s.sub_increments - s.traced_increments) + " planned, " +
         plural(s.sub_increments, "sub-increment", "sub-increments") + ", " +
         std::to_string(s.traced_increments) + " traced), " +
         plural(s.cutbacks, "cut-back", "cut-backs") + ", " +
         plural(s.staggered_increments, "jump", "jumps") + "; " + seconds_text(s.failed_seconds) +
         " in failed attempts" +
         (s.abandoned_paths > 0
              ? "; path-following gave up in " + plural(s.abandoned_paths, "stage", "stages") +
                    " (a traced step failed at every halving) and ramped on"
              : "") +
         energy_summary(s);
}

std::string energy_balance_summary(const RunSummary& s, const std::string& program) {
  if (s.worst_balance_step == 0) return "";
  char text[64];
  std::snprintf(text, sizeof text, "%.2g", s.worst_balance_error);
  std::string out = program + ": energy balance: worst error " + text +
                    " of the work put in (stage " + s.worst_balance_stage + ", step " +
                    std::to_string(s.worst_balance_step) + "; energy.csv)";
  // A linear bulk with bonded, frictional or rate-independent RCCM interfaces holds it to
  // round-off: a larger error is the steps' discretisation of what the ledger integrates by
  // quadrature.
  if (s.worst_balance_error > 1e-6)
    out += "; that is the steps' error on what the balance integrates by quadrature (viscous "
           "adhesion, a nonlinear bulk, a law without a closed form): shorter steps or a "
           "stage's energy_tolerance reduce it (docs/energy_quadrature.md)";
  return out;
}

} // namespace bipot::app
