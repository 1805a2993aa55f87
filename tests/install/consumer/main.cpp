// An outside project using an installed bipot through find_package. It adds its own interface
// law and its own material to bipot's built-in catalogue — without editing bipot — and solves
// a model that uses both, against a closed form:
//   two unit squares stacked (plane strain), the lower one's bottom on rollers, the upper
//   one's top pulled up by δ; between them `spring_joint` (this project's law: a linear
//   spring of stiffness k, no contact or friction in tension); both squares `lame_elastic`
//   (this project's material: isotropic elasticity given by its Lamé constants λ, μ).
//   In uniaxial stress σ (plane strain, sides free) each square stretches by (1 − ν²) σ / E
//   and the joint opens by σ / k, so the top reaction per unit width is
//       F = δ / (2 (1 − ν²) / E + 1 / k),   E = μ (3λ + 2μ) / (λ + μ), ν = λ / (2 (λ + μ)).
//   A direct solver and homogeneous fields: the only error is rounding, hence 1e-9.
#include "apps/catalogue/builtin_catalogue.hpp"
#include "contact/laws/interface_law.hpp"
#include "fem/analysis/model.hpp"
#include "fem/analysis/static_analysis.hpp"
#include "fem/core/error.hpp"
#include "fem/core/material.hpp"
#include "fem/element/element_values.hpp"
#include "fem/input/problem_reader.hpp"
#include "fem/linalg/parallel_environment.hpp"

#include <cmath>
#include <iostream>
#include <memory>

namespace {

using bipot::contact::LocalMatrix;
using bipot::contact::LocalVector;

// A joint that is a linear spring of stiffness k in every direction: β stays 1, the adhesive
// traction is −k g, and the Coulomb cone has μ = 0 (frictionless contact when it closes).
class SpringJoint : public bipot::contact::InterfaceLaw {
public:
  struct Parameters {
    double stiffness = 0;
  };
  static bipot::ParamSchemaOf<Parameters> schema() {
    bipot::ParamSchemaOf<Parameters> s("spring_joint",
                                       "a linear spring in every direction (consumer's law)");
    s.real("stiffness", &Parameters::stiffness, "kN/m^3", "spring stiffness k per unit area")
        .positive();
    return s;
  }
  explicit SpringJoint(bipot::Checked<Parameters> p) : k_(p->stiffness) {}
  std::string name() const override { return "spring_joint"; }
  double initial_adhesion() const override { return 1.0; }
  double update_adhesion(double beta_old, const LocalVector& jump, double,
                         LocalVector* dbeta_djump) const override {
    if (dbeta_djump) *dbeta_djump = LocalVector::Zero(jump.size());
    return beta_old;
  }
  LocalVector adhesive_traction(double beta, const LocalVector& jump,
                                LocalMatrix* dt_djump) const override {
    const double s = beta * beta * k_;
    if (dt_djump) *dt_djump = -s * LocalMatrix::Identity(jump.size(), jump.size());
    return -s * jump;
  }
  LocalVector adhesive_traction_dbeta(double beta, const LocalVector& jump) const override {
    return -2.0 * beta * k_ * jump;
  }
  double friction_coefficient(double) const override { return 0.0; }
  double stiffness_scale() const override { return k_; }

private:
  double k_;
};

// Isotropic linear elasticity from its Lamé constants (Voigt order of fem/core/types.hpp,
// engineering shear strains).
class LameElastic : public bipot::Material {
public:
  struct Parameters {
    double lambda = 0, mu = 0;
  };
  static bipot::ParamSchemaOf<Parameters> schema() {
    bipot::ParamSchemaOf<Parameters> s("lame_elastic",
                                       "isotropic elasticity from Lamé constants (consumer's)");
    s.real("lambda", &Parameters::lambda, "kPa", "first Lamé constant").non_negative();
    s.real("mu", &Parameters::mu, "kPa", "shear modulus").positive();
    return s;
  }
  explicit LameElastic(bipot::Checked<Parameters> p) : lambda_(p->lambda), mu_(p->mu) {}
  std::string name() const override { return "lame_elastic"; }
  bool is_linear() const override { return true; }
  void update(const bipot::Voigt& strain, const bipot::Voigt&, const double*, bipot::Voigt& stress,
              bipot::VoigtMatrix& tangent, double*) const override {
    const auto n = strain.size();
    tangent = bipot::VoigtMatrix::Zero(n, n);
    for (int i = 0; i < 3; ++i) {
      for (int j = 0; j < 3; ++j)
        tangent(i, j) = lambda_;
      tangent(i, i) += 2.0 * mu_;
    }
    for (int i = 3; i < n; ++i)
      tangent(i, i) = mu_;
    stress = tangent * strain;
  }

private:
  double lambda_, mu_;
};

constexpr double lambda = 4.0e3, mu = 6.0e3, k = 2.0e4, delta = 1.0e-3;

const char* input = R"(kinematics: plane_strain
mesh:
  blocks:
    cell: quad4
    x: {breaks: [0, 1], cells: [2]}
    y: {breaks: [0, 1, 2], cells: [2, 2]}
    regions: [base, block]
  sets:
    corner: {min: [0, 0], max: [0, 0]}
materials:
  base: {type: lame_elastic, lambda: 4.0e3, mu: 6.0e3}
  block: {type: lame_elastic, lambda: 4.0e3, mu: 6.0e3}
linear_solver: {method: direct}
interfaces:
  - {name: joint, between: [base, block], law: spring_joint, parameters: {stiffness: 2.0e4}}
stages:
  - name: pull
    increments: 2
    boundary_conditions:
      - {set: bottom, component: y, value: 0}
      - {set: corner, component: x, value: 0}
      - {set: top, component: y, value: 1.0e-3}
)";

} // namespace

int main(int argc, char** argv) {
  bipot::ParallelEnvironment env(argc, argv);
  bipot::Catalogue catalogue = bipot::builtin_catalogue();
  catalogue.interface_laws.add<SpringJoint>();
  catalogue.materials.add<LameElastic>();
  bool duplicate_refused = false;
  try {
    catalogue.materials.add<LameElastic>();
  } catch (const bipot::Error&) {
    duplicate_refused = true;
  }

  double F = 0;
  {
    const bipot::Model model =
        bipot::build_model(bipot::read_problem_text(input, "consumer.yaml", catalogue), catalogue);
    bipot::StaticAnalysis analysis(model);
    analysis.run();
    F = analysis.reaction("top")[1];
  }
  const double E = mu * (3 * lambda + 2 * mu) / (lambda + mu), nu = lambda / (2 * (lambda + mu));
  const double expected = delta / (2 * (1 - nu * nu) / E + 1 / k);

  // An element of the installed library, as before: the area of a 2 × 2 square.
  bipot::ElementValues ev(bipot::CellType::Quad4, bipot::Kinematics::PlaneStrain, 2);
  const double square[12] = {0, 0, 0, 2, 0, 0, 2, 2, 0, 0, 2, 0};
  ev.reinit(square);
  double area = 0;
  for (int q = 0; q < ev.num_points(); ++q)
    area += ev.JxW(q);

  const bool ok = std::abs(F - expected) <= 1e-9 * expected && std::abs(area - 4.0) < 1e-12 &&
                  duplicate_refused;
  if (env.rank() == 0)
    std::cout << "top reaction " << F << " kN/m (closed form " << expected << "), area " << area
              << ", duplicate name " << (duplicate_refused ? "refused" : "ACCEPTED")
              << (ok ? ": ok" : ": WRONG") << "\n";
  return ok ? 0 : 1;
}
