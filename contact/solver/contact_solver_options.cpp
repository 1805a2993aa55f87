#include "contact/solver/contact_solver_options.hpp"

namespace bipot::contact {

namespace {

using Options = ContactSolverOptions;

void common_keys(ParamSchemaOf<Options>& s, double default_factor) {
  s.real("augmentation", &Options::augmentation, "kN/m^3",
         "augmentation parameter rho of the projection; 0 = automatic per pair: the larger of "
         "the law's stiffness and the bodies' local stiffness 1/W_ii at the pair")
      .non_negative()
      .defaulted();
  s.real("augmentation_factor", &Options::augmentation_factor, "", "multiplies the automatic rho")
      .positive()
      .with_default(default_factor);
  // Below 1e-14 (about 50 ε) a relative residual is round-off of the sums that form it, not a
  // measure of equilibrium: such a tolerance could only stall or pass by chance.
  s.real("tolerance", &Options::tolerance, "",
         "relative tolerance on the force residual and the multiplier change; at least 1e-14, "
         "what double precision can verify")
      .at_least(1e-14)
      .less_than(1.0)
      .because("below 1e-14 (about 50 machine epsilons) a relative residual is the round-off of "
               "the sums that form it, which no solver can reduce")
      .defaulted();
  s.integer("max_cutbacks", &Options::max_cutbacks,
            "halvings of a non-converging increment before the run stops")
      .at_least(0)
      .defaulted();
  s.boolean("line_search", &Options::line_search,
            "backtracking line search on the residual norm (globalisation)")
      .defaulted();
}

// max_iterations, and max_outer_iterations for the solvers with a multiplier loop
// (`outer_doc` non-empty): their meaning and defaults differ by solver.
void iteration_keys(ParamSchemaOf<Options>& s, const std::string& doc, long max,
                    const std::string& outer_doc = "", long max_outer = 0) {
  s.integer("max_iterations", &Options::max_iterations, doc).at_least(1).with_default(max);
  if (outer_doc.empty()) return;
  s.integer("max_outer_iterations", &Options::max_outer_iterations, outer_doc)
      .at_least(1)
      .with_default(max_outer);
}

// The registry's factory: the options of solver `schema.name()` from its validated keys; a
// key the solver does not have (max_outer_iterations of generalized_newton) keeps the
// struct's value.
Registry<Options>::Factory factory(const ParamSchemaOf<Options>& schema) {
  return [schema](const ParameterSet& p) {
    auto o = std::make_unique<Options>(*schema.fill(p));
    o->type = schema.name();
    return o;
  };
}

} // namespace

std::vector<ParamSchemaOf<ContactSolverOptions>> contact_solver_schemas() {
  ParamSchemaOf<Options> newton(
      "semismooth_newton", "semi-smooth Newton on equilibrium with the multipliers moved as soon "
                           "as the residual dropped tenfold (inexact augmented Lagrangian)");
  // Factor 30, measured with the increment predictor (bench/contact.py, 10k DOFs): linear
  // solves per increment 5.0 / 3.9 / 3.8 at factor 10 / 30 / 100; default pile run 296 /
  // 274 / 235 solves. At 100 the sliding-block test needs a cut-back and the Hertz test's
  // hold stage fails, so 30 keeps the gain without the harsher stick/slip switches.
  common_keys(newton, 30.0);
  iteration_keys(newton, "Newton iterations between multiplier updates", 50,
                 "multiplier updates per increment", 200);
  ParamSchemaOf<Options> uzawa(
      "bipotential_uzawa", "the seed's Uzawa predictor-corrector on the bipotential projection, "
                           "alternated with equilibrium solves at fixed multipliers");
  // The equilibrium solves include rho (augmented Lagrangian), so no explicit-Uzawa bound
  // rho < 2/lambda_max(W) applies; larger rho means fewer multiplier updates. Sliding-block
  // test: factor 1 / 10 / 100 took 141 / 62 / 41 linear solves for 6 increments (before the
  // increment predictor). Same default as semismooth_newton so that both reach the same
  // solution by default.
  common_keys(uzawa, 30.0);
  iteration_keys(uzawa, "Newton iterations per equilibrium solve", 100,
                 "Uzawa multiplier updates per increment", 2000);
  ParamSchemaOf<Options> exact(
      "generalized_newton",
      "exact generalized Newton (Alart-Curnier): displacements and interface "
      "multipliers are the unknowns of one Newton step, the bulk condensed onto "
      "the interface DOFs by a MUMPS Schur complement");
  // rho only weighs the jump against the force inside the projection (which pairs are
  // stuck, sliding or open at the next iterate); it no longer sets a convergence rate.
  common_keys(exact, 1.0);
  iteration_keys(exact, "Newton iterations per increment", 50);
  return {newton, uzawa, exact};
}

const Registry<ContactSolverOptions>& contact_solvers() {
  static const Registry<ContactSolverOptions> registry = [] {
    Registry<ContactSolverOptions> r("contact solver");
    for (const auto& schema : contact_solver_schemas())
      r.add(schema, factory(schema));
    return r;
  }();
  return registry;
}

ContactSolverOptions default_contact_solver() {
  return *contact_solvers().create_validated("generalized_newton", ParameterSet{});
}

} // namespace bipot::contact
