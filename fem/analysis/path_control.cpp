#include "fem/analysis/path_control.hpp"

#include "fem/analysis/detail/path_step.hpp"
#include "fem/core/error.hpp"

#include <algorithm>
#include <sstream>

namespace bipot {

PathControl::PathControl(const StageSpec& stage, const CondensedInterfaceSystem* sys,
                         const std::vector<std::unique_ptr<InterfaceEnforcement>>& interfaces)
    : stage_(stage), sys_(sys), interfaces_(interfaces),
      max_increments_(stage.control.max_increments.value_or(20 * stage.increments)),
      planned_(1.0 / stage.increments), step_(std::make_unique<PathStep>()) {
  if (!stage.control.path_following()) return;
  if (!sys_)
    throw SolverError("stage '" + stage.name + "': control " + stage.control.type +
                      " needs contact_solver.type: generalized_newton and a contact interface");
  capacity_ = adhesion_capacity();
  if (stage.control.type == "dissipation") {
    if (!(capacity_ > 0))
      throw SolverError("stage '" + stage.name +
                        "': control dissipation follows the energy adhesion loss releases, and "
                        "no interface has adhesion left to lose (no rccm interface with beta > "
                        "0); use control: arc_length");
    dissipation_step_ = stage.control.dissipation_step.value_or(capacity_ / stage.increments);
    dissipation_ = dissipation_step_;
  }
}

PathControl::~PathControl() = default;

double PathControl::adhesion_capacity() const {
  double sum = 0;
  for (const auto& ia : interfaces_)
    sum += ia->adhesion_capacity();
  return sum;
}

Eigen::VectorXd PathControl::on_interface(const std::vector<double>& u) const {
  return on_interface_dofs(*sys_, u);
}

PathStep& PathControl::step(int level) {
  PathStep& ps = *step_;
  const double shrink = std::pow(0.5, level);
  ps.x_prev = x_prev_;
  ps.dlambda_prev = dlambda_prev_;
  if (mode_ == Mode::ArcLength) {
    ps.kind = PathStep::Kind::ArcLength;
    ps.length = shrink * length_;
    const double l_prev = x_prev_.norm();
    ps.predictor_scale = l_prev > 0 ? ps.length / l_prev : 0.0;
  } else {
    ps.kind = PathStep::Kind::Dissipation;
    ps.dissipation = shrink * dissipation_;
    // Along the last increment, scaled to the energy asked for (within reason: the last
    // increment may have been elastic, dissipating nothing: then as far as it went).
    ps.predictor_scale =
        dissipation_last_ > 0 ? std::clamp(ps.dissipation / dissipation_last_, 0.1, 1.0) : 1.0;
  }
  return ps;
}

bool PathControl::forward(const PathStep& step) const {
  return step.kind != PathStep::Kind::ArcLength || step.x.dot(x_prev_) > 0;
}

bool PathControl::can_switch() const {
  return stage_.control.type == "dissipation" && mode_ == Mode::Ramp && !finished_ && !declined_ &&
         capacity_ > 0 && x_prev_.size() != 0;
}

bool PathControl::switch_on_failure() {
  if (!can_switch()) return false;
  mode_ = Mode::Dissipation;
  return true;
}

void PathControl::end_increment(const std::vector<double>& u, const std::vector<double>& u_begin,
                                double dlambda, int iterations, bool may_grow) {
  traced_last_ = mode_ != Mode::Ramp;
  declined_ = false;
  dissipation_last_ = 0;
  if (!stage_.control.path_following()) return;
  const Eigen::VectorXd x = on_interface(u) - on_interface(u_begin);
  dissipation_last_ = sys_->released_adhesion_energy(nullptr); // before the commit
  // The step that converged sets the next one's length: a traced step's own, or a shorter
  // one after a cut-back (step() scaled it); then grown when Newton was quick (≤ 3
  // iterations), up to 4 times the first arc length (the dissipation step never grows beyond
  // the one asked for), and shrunk when it was slow (8 or more). Halved where the path turns:
  // the step needed more than 3 iterations and ended farther from its predictor (along the
  // last step) than its own length, so the predictor did worse than none. The next step
  // predicts along this one, still inside the turn; at full length it was slower still (on
  // rccm_traced.yaml at 80 increments the step where the snap-back turns took 4 and the next,
  // whose interface displacement grew 8 times, 6; halved it takes 5). Steps that are slow on
  // a straight stretch keep their length: halving those as well made the column's steps
  // uneven and cost the pile more steps.
  const bool turned = x_prev_.size() == x.size() && mode_ != Mode::Ramp &&
                      (x - step_->predictor_scale * x_prev_).norm() > x.norm();
  const double adapt = iterations > quick_iterations && turned      ? 0.5
                       : iterations >= slow_iterations              ? 0.6
                       : iterations <= quick_iterations && may_grow ? 1.5
                                                                    : 1.0;
  if (mode_ == Mode::ArcLength) {
    length_ = std::min(4.0 * length0_, adapt * step_->length);
  } else if (mode_ == Mode::Dissipation) {
    dissipation_ = std::min(dissipation_step_, adapt * step_->dissipation);
    // The interfaces no longer soften fast, the ramp can take over again: the load factor
    // rose and a planned increment at this step's rate would release no more than a traced
    // step (the ramp's own test for handing over, so it does not hand straight back). In a
    // Mohr-Coulomb soil the front creeps down the shaft after the snap-back while friction
    // holds the force: traced to the end, the pile took 569 increments (85 s), handed back
    // 309 (53 s). So too once adhesion can no longer release a step's energy: friction alone
    // would let the step run backwards (the pile pushed back in dissipates as well), and past
    // the snap-back the ramp is stable again.
    const bool gentle = dlambda > 0 && dissipation_last_ * planned_ <= dissipation_step_ * dlambda;
    if (dlambda >= planned_ || gentle || adhesion_capacity() < dissipation_step_)
      mode_ = Mode::Ramp;
  } else if (!finished_) {
    if (stage_.control.type == "arc_length" && x.size() > 0) {
      length0_ = stage_.control.arc_length.value_or(x.norm());
      length_ = length0_;
      mode_ = Mode::ArcLength;
    } else if (stage_.control.type == "dissipation" && dissipation_last_ > dissipation_step_) {
      // The ramp releases more than a traced step would: softening has set in.
      mode_ = Mode::Dissipation;
    }
  }
  x_prev_ = x;
  dlambda_prev_ = dlambda;
}

std::string PathControl::failure_message(std::size_t stage_index, int step, double lambda,
                                         int cutbacks, const std::vector<double>& history,
                                         const std::string& why) const {
  std::ostringstream msg;
  msg << "stage '" << stage_.name << "' (" << stage_index + 1 << "), traced step " << step << " ("
      << stage_.control.type << " control from load factor " << lambda << ", "
      << (mode_ == Mode::ArcLength ? "arc length " : "dissipation ")
      << (mode_ == Mode::ArcLength ? step_->length : step_->dissipation) << " after " << cutbacks
      << " cut-backs): " << why;
  if (!history.empty()) msg << "; last relative residual " << history.back();
  msg << ". To get through: more increments in this stage (shorter first steps), "
      << (mode_ == Mode::Dissipation ? "a smaller control.dissipation_step, "
                                     : "a smaller control.arc_length, ")
      << "or a larger max_cutbacks.";
  return msg.str();
}

} // namespace bipot
