#include "contact/laws/rccm.hpp"

#include "fem/core/error.hpp"

#include <algorithm>
#include <cassert>

namespace bipot::contact {

ParamSchemaOf<Rccm::Parameters> Rccm::schema() {
  using P = Parameters;
  ParamSchemaOf<P> s("rccm", "RCCM interface: unilateral contact, Coulomb friction and adhesion "
                             "(Raous, Cangemi, Cocu 1999)");
  s.real("normal_stiffness", &P::normal_stiffness, "kN/m^3",
         "initial normal stiffness C_n of the sound interface")
      .positive();
  s.real("tangential_stiffness", &P::tangential_stiffness, "kN/m^3",
         "initial tangential stiffness C_t of the sound interface")
      .positive();
  s.real("decohesion_energy", &P::decohesion_energy, "kJ/m^2",
         "decohesion energy w, dissipated per area by debonding")
      .positive();
  s.real("friction_coefficient", &P::friction_coefficient, "",
         "Coulomb friction coefficient mu once debonded (mu_bar = mu (1 - beta))")
      .non_negative()
      .defaulted();
  s.real("adhesion_viscosity", &P::adhesion_viscosity, "kN*s/m",
         "adhesion viscosity alpha (0 = quasi-static limit)")
      .non_negative()
      .defaulted();
  s.real("initial_adhesion", &P::initial_adhesion, "",
         "initial adhesion intensity beta0 (1 = sound, 0 = debonded)")
      .at_least(0.0)
      .at_most(1.0)
      .defaulted();
  return s;
}

Rccm::Rccm(Checked<Parameters> p)
    : cn_(p->normal_stiffness), ct_(p->tangential_stiffness), w_(p->decohesion_energy),
      mu_(p->friction_coefficient), alpha_(p->adhesion_viscosity), beta0_(p->initial_adhesion) {}

double Rccm::driving_energy(const LocalVector& jump) const {
  const double g_n_plus = std::max(jump(0), 0.0);
  return cn_ * g_n_plus * g_n_plus + ct_ * jump.tail(jump.size() - 1).squaredNorm();
}

double Rccm::update_adhesion(double beta_old, const LocalVector& jump, double dtau,
                             LocalVector* dbeta_djump) const {
  const Eigen::Index d = jump.size();
  assert((d == 2 || d == 3) && beta_old >= 0.0 && beta_old <= 1.0 && dtau >= 0.0);
  const double g_n_plus = std::max(jump(0), 0.0);
  const double energy = driving_energy(jump);
  if (dbeta_djump) *dbeta_djump = LocalVector::Zero(d);

  double beta = beta_old;
  double dbeta_denergy = 0.0;
  if (alpha_ > 0.0) {
    const double h = dtau / alpha_;
    const double candidate = (beta_old + w_ * h) / (1.0 + energy * h);
    if (candidate < beta_old) {
      beta = candidate;
      dbeta_denergy = -candidate * h / (1.0 + energy * h);
    }
  } else if (energy * beta_old > w_) { // w/E < β_old without dividing by E = 0
    beta = w_ / energy;
    dbeta_denergy = -beta / energy;
  }
  if (dbeta_djump && dbeta_denergy != 0.0) {
    (*dbeta_djump)(0) = dbeta_denergy * 2.0 * cn_ * g_n_plus;
    dbeta_djump->tail(d - 1) = dbeta_denergy * 2.0 * ct_ * jump.tail(d - 1);
  }
  return beta;
}

std::optional<double> Rccm::spring_work(double beta_old, const LocalVector& from,
                                        const LocalVector& to) const {
  // With a viscosity β depends on how fast Ẽ rose within the step, which the ends do not say.
  if (alpha_ > 0.0) return std::nullopt;
  const Eigen::Index d = from.size();
  // ½ C_n ⟨g_n⟩₋²: the normal spring's energy in penetration, which does not drive β.
  const auto compressed = [&](const LocalVector& g) {
    const double g_n = std::min(g(0), 0.0);
    return 0.5 * cn_ * g_n * g_n;
  };
  const double e0 = driving_energy(from), e1 = driving_energy(to);
  if (e0 * beta_old > w_ * (1.0 + 1e-12)) return std::nullopt;
  const double b0 = beta_old * beta_old;
  const double dp = compressed(to) - compressed(from);
  // Below the threshold β stays: a linear spring, the whole path's work from its ends.
  if (e1 * beta_old <= w_) return 0.5 * b0 * (e1 - e0) + b0 * dp;
  // Past Ẽ* = w/β_old, β = w/Ẽ and ½ β² dẼ = ½ w² dẼ/Ẽ² integrates to ½ w (β_old − β_1).
  const double beta1 = w_ / e1;
  const double springs = 0.5 * b0 * (w_ / beta_old - e0) + 0.5 * w_ * (beta_old - beta1);
  if (dp == 0.0) return springs;
  // The penetration's share: exact where the pair leaves it at β_old (Ẽ, convex along the
  // segment, at most Ẽ* where g_n crosses 0), else, with g_n < 0 at the end (within the
  // contact tolerance), by the trapezoid in β².
  if (to(0) >= 0.0) {
    const double s = from(0) / (from(0) - to(0));
    if (ct_ * (from.tail(d - 1) + s * (to - from).tail(d - 1)).squaredNorm() * beta_old <= w_)
      return springs + b0 * dp;
  }
  return springs + 0.5 * (b0 + beta1 * beta1) * dp;
}

LocalVector Rccm::adhesive_traction(double beta, const LocalVector& jump,
                                    LocalMatrix* dt_djump) const {
  const Eigen::Index d = jump.size();
  const double b2 = beta * beta;
  LocalVector t(d);
  t(0) = -b2 * cn_ * jump(0);
  t.tail(d - 1) = -b2 * ct_ * jump.tail(d - 1);
  if (dt_djump) {
    *dt_djump = LocalMatrix::Zero(d, d);
    (*dt_djump)(0, 0) = -b2 * cn_;
    for (Eigen::Index i = 1; i < d; ++i)
      (*dt_djump)(i, i) = -b2 * ct_;
  }
  return t;
}

LocalVector Rccm::adhesive_traction_dbeta(double beta, const LocalVector& jump) const {
  const Eigen::Index d = jump.size();
  LocalVector t(d);
  t(0) = -2.0 * beta * cn_ * jump(0);
  t.tail(d - 1) = -2.0 * beta * ct_ * jump.tail(d - 1);
  return t;
}

double Rccm::stiffness_scale() const {
  return std::max(cn_, ct_);
}

} // namespace bipot::contact
