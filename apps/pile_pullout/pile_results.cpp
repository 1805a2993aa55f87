#include "apps/pile_pullout/pile_results.hpp"

#include "apps/pile_pullout/pile_problem.hpp"
#include "fem/core/error.hpp"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <numeric>

namespace bipot::pile {

namespace {

std::size_t interface_index(const Model& model, const std::string& name) {
  for (std::size_t k = 0; k < model.interfaces.size(); ++k)
    if (model.interfaces[k].name == name) return k;
  throw Error("pile model: no interface named '" + name + "'");
}

} // namespace

HeadState head_state(const Model& model, const StaticAnalysis& analysis) {
  const auto& nodes = model.mesh.node_sets.at(kHead);
  const auto& u = analysis.displacement();
  HeadState h;
  for (Index n : nodes)
    h.displacement += u[analysis.dofs().dof(n, 1)];
  h.displacement /= static_cast<double>(nodes.size());
  h.force = analysis.reaction(kHead)[1];
  return h;
}

PileResults::PileResults(const Model& model, const std::string& directory,
                         std::vector<double> profiles_at_mm, bool write)
    : model_(model), directory_(directory), profiles_at_mm_(std::move(profiles_at_mm)),
      write_(write) {
  if (!write_) return;
  head_.open(head_force_path());
  profiles_.open(profiles_path());
  if (!head_ || !profiles_) throw Error("cannot write the pile results in '" + directory_ + "'");
  head_ << "step,stage,time,head_displacement_mm,head_force_kN,newton_iterations,cutbacks,"
           "unstable,traced\n";
  profiles_ << "step,head_displacement_mm,depth_m,skin_friction_kPa,contact_pressure_kPa,beta,"
               "slip_mm,opening_mm,status,stage\n";
  head_.flush();
  profiles_.flush();
}

void PileResults::record(const StepReport& report, const StaticAnalysis& analysis) {
  last_ = head_state(model_, analysis);
  const double head_mm = 1e3 * last_.displacement;
  const bool pullout = report.stage == "pullout";
  if (pullout && last_.force > peak_force_) {
    peak_force_ = last_.force;
    peak_displacement_ = last_.displacement;
  }
  if (!write_) return;
  char line[256];
  std::snprintf(line, sizeof line, "%d,%s,%.9g,%.9g,%.9g,%d,%d,%d,%d\n", report.global_step,
                report.stage.c_str(), report.time, head_mm, last_.force, report.iterations,
                report.cutbacks, report.unstable ? 1 : 0, report.traced ? 1 : 0);
  head_ << line;
  head_.flush();

  // Profiles: the end of the geostatic and installation stages, the pull-out steps that first
  // reach each requested head displacement, and the last step.
  bool due = !pullout && report.stage_end;
  if (pullout) {
    while (next_profile_ < profiles_at_mm_.size() &&
           head_mm >= profiles_at_mm_[next_profile_] * (1 - 1e-9)) {
      due = true;
      ++next_profile_;
    }
    due = due || report.stage_end;
  }
  if (due) write_profile(report, analysis, head_mm);
}

void PileResults::write_profile(const StepReport& report, const StaticAnalysis& analysis,
                                double head_mm) {
  const std::size_t k = interface_index(model_, kShaft);
  const auto& ia = *analysis.interfaces()[k];
  const auto& pairs = model_.interfaces[k].pairs;
  const auto& results = ia.results();
  std::vector<std::size_t> order(pairs.size());
  std::iota(order.begin(), order.end(), 0);
  auto z = [&](std::size_t i) { return model_.mesh.nodes[pairs[i].node_a][1]; };
  std::sort(order.begin(), order.end(), [&](std::size_t i, std::size_t j) { return z(i) > z(j); });
  char line[256];
  for (std::size_t i : order) {
    const auto& r = results[i];
    // Local frame: n = +r (pile into soil), t1 = +z. t is the traction the pile exerts on the
    // soil, so t_t > 0 is the soil held back as the pile rises: the skin friction. The slip
    // of the pile relative to the soil, upward positive, is −g_t.
    std::snprintf(line, sizeof line, "%d,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%s,%s\n",
                  report.global_step, head_mm, -z(i), r.traction(1), r.r(0), r.beta,
                  -1e3 * r.jump(1), 1e3 * r.jump(0), to_string(reported_status(r)),
                  report.stage.c_str());
    profiles_ << line;
  }
  profiles_.flush();
}

} // namespace bipot::pile

namespace bipot::pile {

namespace {

// Appends the data rows of `from` whose first value (the global step) is at most `steps`;
// its header must be `to`'s (written by the constructor).
void copy_rows(const std::string& from, std::ofstream& to, int steps) {
  std::ifstream in(from);
  if (!in) throw Error("cannot read '" + from + "' to continue its rows after the restart");
  std::string line;
  std::getline(in, line); // the header, already written
  while (std::getline(in, line))
    if (!line.empty() && std::atoi(line.c_str()) <= steps) to << line << '\n';
  to.flush();
  if (!to) throw Error("cannot write the pile results copied from '" + from + "'");
}

} // namespace

StateArrays PileResults::save_state() const {
  return {{"app.pile_results",
           {static_cast<double>(next_profile_), peak_force_, peak_displacement_, last_.displacement,
            last_.force}}};
}

void PileResults::resume(const std::string& from, int steps, const StateArrays& state) {
  const auto it = state.find("app.pile_results");
  if (it == state.end() || it->second.size() != 5)
    throw InputError(from + ": the checkpoint holds no pile_pullout results state (written by "
                            "another program?)");
  const std::vector<double>& v = it->second;
  next_profile_ = static_cast<std::size_t>(v[0]);
  peak_force_ = v[1];
  peak_displacement_ = v[2];
  last_ = {v[3], v[4]};
  if (!write_) return;
  copy_rows(from + "/head_force.csv", head_, steps);
  copy_rows(from + "/profiles.csv", profiles_, steps);
}

} // namespace bipot::pile
