// The analysis with a material that has internal variables (von_mises with linear hardening):
// drained triaxial compression against its closed form, a failed increment leaving the committed
// state untouched, a cut-back run equal to the run planned with the sub-increments, and Newton's
// quadratic convergence with the consistent tangent, with and without the condensed generalized
// Newton. With mohr_coulomb: the two contact solvers agree, and a singular tangent (apex) is cut
// back.
#include "fem/analysis/model.hpp"
#include "fem/analysis/result_writer.hpp"
#include "fem/analysis/static_analysis.hpp"
#include "fem/assembly/solid_assembler.hpp"
#include "fem/input/problem_reader.hpp"
#include "fem/linalg/distributed_vector.hpp"
#include "fem/linalg/dof_distribution.hpp"
#include "tests/support/model_from_text.hpp"

#include "../support/scratch_dir.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <iterator>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>

namespace bipot {
namespace {

constexpr double E = 1.0e4, nu = 0.3, sy = 20.0, H = 500.0;

std::string exact(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.17g", v);
  return buf;
}

// The von Mises material of these tests (yield stress 20 kPa) with hardening modulus H.
std::string von_mises(double hardening) {
  return "{type: von_mises, youngs_modulus: 1.0e4, poissons_ratio: 0.3, yield_stress: 20.0, "
         "hardening_modulus: " +
         exact(hardening) + "}";
}

// One axisymmetric quad4 cell, r in [0, R], z in [0, 1]: confined by p on its side and top,
// then compressed axially by a prescribed top displacement with the side pressure held, then
// unloaded axially to `unload` (elastic: the committed plastic strain must be remembered).
std::string triaxial_input(double p, double top, int increments, double unload, bool reset = false,
                           const std::string& material = von_mises(H)) {
  return "kinematics: axisymmetric\nmesh:\n  blocks:\n    cell: quad4\n"
         "    x: {breaks: [0.0, 0.5], cells: [1]}\n    y: {breaks: [0.0, 1.0], cells: [1]}\n"
         "    regions: [sample]\n"
         "materials:\n  sample: " +
         material +
         "\n"
         "linear_solver: {method: direct}\n"
         "stages:\n"
         "  - name: confine\n    boundary_conditions:\n"
         "      - {set: bottom, component: z, value: 0}\n"
         "      - {set: left, component: r, value: 0}\n"
         "    loads:\n      - {type: pressure, set: right, value: " +
         std::to_string(p) + "}\n      - {type: pressure, set: top, value: " + std::to_string(p) +
         "}\n  - name: shear\n    increments: " + std::to_string(increments) +
         (reset ? "\n    reset_displacements: true" : "") +
         "\n    boundary_conditions:\n"
         "      - {set: bottom, component: z, value: 0}\n"
         "      - {set: left, component: r, value: 0}\n"
         "      - {set: top, component: z, value: " +
         std::to_string(top) +
         "}\n    loads:\n      - {type: pressure, set: right, value: " + std::to_string(p) +
         "}\n  - name: unload\n    increments: 2\n" +
         "    boundary_conditions:\n"
         "      - {set: bottom, component: z, value: 0}\n"
         "      - {set: left, component: r, value: 0}\n"
         "      - {set: top, component: z, value: " +
         exact(unload) +
         "}\n    loads:\n      - {type: pressure, set: right, value: " + std::to_string(p) + "}\n";
}

// Axial stress of drained triaxial compression of the J2 material at axial strain eps_a
// (negative) under confining pressure p, from zero stress: σ_r = −p, σ_a = −p − q, elastic
// axial strain (σ_a − 2ν σ_r)/E, plastic axial strain −ē, q = σ_y + H ē once yielding.
double triaxial_axial_stress(double eps_a, double p) {
  const double elastic_limit = -((1 - 2 * nu) * p + sy) / E;
  const double ebar = std::max(0.0, (elastic_limit - eps_a) / (1 + H / E));
  return -p - (sy + H * ebar);
}

// Equivalent plastic strain of the same test.
double triaxial_ebar(double eps_a, double p) {
  const double elastic_limit = -((1 - 2 * nu) * p + sy) / E;
  return std::max(0.0, (elastic_limit - eps_a) / (1 + H / E));
}

TEST(PlasticTriaxial, AxialStressMatchesClosedForm) {
  const double p = 50.0, R = 0.5, top = -0.02;
  const double sa = triaxial_axial_stress(top, p), q = -p - sa;
  const double ebar = triaxial_ebar(top, p);
  ASSERT_GT(ebar, 5 * sy / E); // well into the plastic range
  // Unloading by q/E axial strain is elastic and brings σ_a back to −p.
  const double unload = top + q / E;
  const Model model =
      bipot::test::model_from_text(triaxial_input(p, top, 4, unload), "triaxial.yaml");
  StaticAnalysis analysis(model);
  // Lateral strain: elastic (σ_r − ν(σ_a + σ_θ))/E plus the plastic ē/2 (isochoric flow).
  const double eps_r = (-p - nu * (sa - p)) / E + 0.5 * ebar;
  auto side_ur = [&] {
    for (Index n = 0; n < model.mesh.num_nodes(); ++n)
      if (std::abs(model.mesh.nodes[n][0] - R) < 1e-12) return analysis.displacement()[n * 2];
    return 0.0;
  };
  int checked = 0;
  // The material's output fields (cell averages): ē and the plastic flag.
  auto output = [&](const std::string& name) {
    const auto names = analysis.output_field_names();
    const auto values = analysis.cell_output_fields();
    const auto it = std::find(names.begin(), names.end(), name);
    return it == names.end() ? -1.0 : values[it - names.begin()];
  };
  analysis.run([&](const StepReport& r) {
    if (!r.stage_end) return;
    const double force = analysis.reaction("top")[1];
    EXPECT_NEAR(output("equivalent_plastic_strain"), r.stage == "confine" ? 0.0 : ebar, 1e-8 * ebar)
        << r.stage;
    EXPECT_EQ(output("plastic"), r.stage == "shear" ? 1.0 : 0.0) << r.stage;
    if (r.stage == "shear") {
      const double expected = sa * M_PI * R * R;
      std::printf("triaxial peak: top reaction %.12g, closed form %.12g\n", force, expected);
      EXPECT_NEAR(force, expected, 1e-8 * std::abs(expected));
      EXPECT_NEAR(side_ur(), eps_r * R, 1e-8 * std::abs(eps_r * R));
      ++checked;
    } else if (r.stage == "unload") {
      const double expected = -p * M_PI * R * R;
      std::printf("triaxial unloaded: top reaction %.12g, closed form %.12g\n", force, expected);
      EXPECT_NEAR(force, expected, 1e-8 * std::abs(expected));
      // Elastic unloading: the radius shrinks by ν q/E (Poisson), the plastic ē/2 stays.
      EXPECT_NEAR(side_ur(), (eps_r - nu * q / E) * R, 1e-8 * std::abs(eps_r * R));
      ++checked;
    }
  });
  EXPECT_EQ(checked, 2);
}

// A displacement reset (geostatic stage) after plastic loading changes only the displacement
// reference: the material keeps its plastic strain, so the unloading that follows gives the
// same stresses, ē and reaction as without the reset, and the displacements differ by those
// at the reset (the unloading target moves by the same amount).
TEST(PlasticState, DisplacementResetKeepsThePlasticHistory) {
  const double p = 50.0, top = -0.02, unload = top + 0.5 * (-p - triaxial_axial_stress(top, p)) / E;
  struct Result {
    std::vector<double> u_shear, u, stress, fields;
    double force;
  };
  auto run = [&](bool reset) {
    const Model model = bipot::test::model_from_text(
        triaxial_input(p, top, 2, reset ? unload - top : unload, reset), "triaxial.yaml");
    StaticAnalysis analysis(model);
    Result r;
    analysis.run([&](const StepReport& s) {
      if (s.stage == "shear" && s.stage_end) r.u_shear = analysis.displacement();
    });
    r.u = analysis.displacement();
    std::vector<Index> cells;
    std::vector<double> strain;
    analysis.cell_results(cells, strain, r.stress);
    r.fields = analysis.cell_output_fields();
    r.force = analysis.reaction("top")[1];
    return r;
  };
  const Result plain = run(false), reset = run(true);
  std::printf("reset: force %.12g (without reset %.12g)\n", reset.force, plain.force);
  EXPECT_NEAR(reset.force, plain.force, 1e-10 * std::abs(plain.force));
  for (std::size_t i = 0; i < plain.stress.size(); ++i)
    EXPECT_NEAR(reset.stress[i], plain.stress[i], 1e-10 * p) << i;
  ASSERT_EQ(reset.fields.size(), plain.fields.size());
  for (std::size_t i = 0; i < plain.fields.size(); ++i)
    EXPECT_NEAR(reset.fields[i], plain.fields[i], 1e-12) << i;
  for (std::size_t i = 0; i < plain.u.size(); ++i)
    EXPECT_NEAR(reset.u[i], plain.u[i] - plain.u_shear[i], 1e-12) << i;
}

// Drained triaxial compression of Mohr–Coulomb soil (c = 10 kPa, φ = 30°, ψ = 10°) under
// the confining pressure p: the axial stress at failure is −(N p + 2 c √N), N = (1 + sin φ) /
// (1 − sin φ), and once failing the strain increments are plastic with the triaxial edge's
// flow: Δε_v / Δε_a = −2 sin ψ / (1 − sin ψ) (dilation under axial compression).
TEST(PlasticTriaxial, MohrCoulombStrengthAndDilatancy) {
  const double p = 50.0, R = 0.5, c = 10.0, phi = 30.0 * M_PI / 180, psi = 10.0 * M_PI / 180;
  const double N = (1 + std::sin(phi)) / (1 - std::sin(phi));
  const std::string mc = "{type: mohr_coulomb, youngs_modulus: 1.0e4, poissons_ratio: 0.3, "
                         "cohesion: 10.0, friction_angle: 30.0, dilatancy_angle: 10.0}";
  const Model model = bipot::test::model_from_text(triaxial_input(p, -0.05, 5, -0.05, false, mc),
                                                   "mc_triaxial.yaml");
  StaticAnalysis analysis(model);
  Index side = -1, top = -1;
  for (Index n = 0; n < model.mesh.num_nodes(); ++n) {
    if (std::abs(model.mesh.nodes[n][0] - R) < 1e-12) side = n;
    if (std::abs(model.mesh.nodes[n][1] - 1.0) < 1e-12) top = n;
  }
  std::vector<std::array<double, 2>> strains; // (ε_a, ε_v) at the end of each shear step
  analysis.run([&](const StepReport& r) {
    if (r.stage != "shear") return;
    const auto& u = analysis.displacement();
    const double ea = u[top * 2 + 1], er = u[side * 2] / R;
    strains.push_back({ea, ea + 2 * er});
    const double sa = analysis.reaction("top")[1] / (M_PI * R * R);
    std::printf("MC triaxial step %d: eps_a %.5f, sigma_a %.10g (failure %.10g)\n", r.step, ea, sa,
                -(N * p + 2 * c * std::sqrt(N)));
  });
  ASSERT_EQ(strains.size(), 5u);
  const double sa = analysis.reaction("top")[1] / (M_PI * R * R);
  EXPECT_NEAR(sa, -(N * p + 2 * c * std::sqrt(N)), 1e-8 * (N * p));
  // The last two steps are on the failure plateau (failure at ε_a ≈ −0.012).
  const double dea = strains[4][0] - strains[3][0], dev = strains[4][1] - strains[3][1];
  const double ratio = -2 * std::sin(psi) / (1 - std::sin(psi));
  std::printf("MC dilatancy: dev/dea %.10g, closed form %.10g\n", dev / dea, ratio);
  EXPECT_NEAR(dev / dea, ratio, 1e-8 * std::abs(ratio));
}

// The VTK series carries the materials' output fields as cell data.
TEST(PlasticOutput, VtkHasMaterialFields) {
  test::ScratchDir dir("plastic_output");
  const Model model =
      bipot::test::model_from_text(triaxial_input(50.0, -0.02, 2, -0.01), "triaxial.yaml");
  ResultWriter writer(model, 0, 1, dir.path.string());
  StaticAnalysis analysis(model, {}, &writer);
  analysis.run();
  std::ifstream in(dir.path / "solution_0003_0.vtu");
  ASSERT_TRUE(in.good());
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  for (const std::string name : {"equivalent_plastic_strain", "plastic", "stress"})
    EXPECT_NE(text.find("Name=\"" + name + "\""), std::string::npos) << name;
}

} // namespace
} // namespace bipot

namespace bipot {
namespace {

// Plane strain soil [0, 2] x [0, 1] (two layers, y < 0.5 and above) under a rough rigid
// footing on x ≤ 0.5 of its top (symmetry at x = 0), pushed down by `settlement`. With an
// interface between the layers (`interface` not empty) the increments go through the contact
// solver `solver`.
std::string footing_input(const std::string& interface, const std::string& solver,
                          double settlement, int increments,
                          const std::string& material = von_mises(100.0)) {
  return "kinematics: plane_strain\nmesh:\n  blocks:\n    cell: quad4\n"
         "    x: {breaks: [0.0, 0.5, 2.0], cells: [6, 8]}\n"
         "    y: {breaks: [0.0, 0.5, 1.0], cells: [4, 6]}\n"
         "    regions: [lower, lower, upper, upper]\n"
         "  sets:\n    footing: {min: [0.0, 1.0], max: [0.5, 1.0]}\n"
         "materials:\n"
         "  lower: " +
         material + "\n  upper: " + material +
         "\n"
         "linear_solver: {method: direct}\n" +
         interface + solver +
         "stages:\n  - name: load\n    increments: " + std::to_string(increments) +
         "\n    boundary_conditions:\n"
         "      - {set: bottom, component: x, value: 0}\n"
         "      - {set: bottom, component: y, value: 0}\n"
         "      - {set: left, component: x, value: 0}\n"
         "      - {set: right, component: x, value: 0}\n"
         "      - {set: footing, component: x, value: 0}\n"
         "      - {set: footing, component: y, value: " +
         exact(-settlement) + "}\n";
}

const std::string joint =
    "interfaces:\n  - name: joint\n    between: [lower, upper]\n"
    "    law: coulomb_signorini\n    parameters: {friction_coefficient: 0.5}\n";

struct Histories {
  std::vector<std::vector<double>> residuals; ///< per increment
  std::vector<int> iterations;                ///< per increment
  std::vector<double> u, stress;              ///< final; committed cell stresses
  double force = 0;                           ///< footing reaction, y
  int cutbacks = 0;
};

Histories run_footing(const std::string& text, AnalysisOptions options = {}) {
  const Model model = bipot::test::model_from_text(text, "footing.yaml");
  StaticAnalysis analysis(model, options);
  Histories h;
  analysis.run([&](const StepReport& r) {
    h.residuals.push_back(r.residual_history);
    h.iterations.push_back(r.iterations);
    h.cutbacks += r.cutbacks;
  });
  h.u = analysis.displacement();
  std::vector<Index> cells;
  std::vector<double> strain;
  analysis.cell_results(cells, strain, h.stress);
  h.force = analysis.reaction("footing")[1];
  return h;
}

// Quadratic convergence on the smooth part: r_{k+1} ≤ C r_k² once r_k ≤ 1e-3 (and while
// r_{k+1} is above round-off). Returns how many pairs were checked.
int check_quadratic(const Histories& h, const std::string& what, bool expect = true) {
  constexpr double C = 100.0; // measured ≤ 41 (the printed histories)
  int pairs = 0;
  for (std::size_t i = 0; i < h.residuals.size(); ++i) {
    const auto& r = h.residuals[i];
    std::printf("%s increment %zu:", what.c_str(), i + 1);
    for (double v : r)
      std::printf(" %.3e", v);
    std::printf("\n");
    for (std::size_t k = 0; k + 1 < r.size(); ++k) {
      if (r[k] > 1e-3 || r[k + 1] < 1e-13) continue;
      if (expect) {
        EXPECT_LE(r[k + 1], C * r[k] * r[k])
            << what << " increment " << i + 1 << " iteration " << k;
      }
      ++pairs;
    }
  }
  return pairs;
}

TEST(PlasticNewton, QuadraticWithoutContact) {
  const Histories h = run_footing(footing_input("", "", 0.02, 4));
  EXPECT_GT(check_quadratic(h, "newton"), 2);
}

TEST(PlasticNewton, QuadraticGeneralizedNewtonOuterLoop) {
  const Histories h = run_footing(footing_input(
      joint, "contact_solver: {type: generalized_newton, tolerance: 1.0e-11}\n", 0.02, 4));
  EXPECT_GT(check_quadratic(h, "generalized_newton"), 2);
  // The same problem by the semi-smooth Newton on the whole mesh: the same solution. Its
  // history interleaves multiplier updates (an augmented Lagrangian), so it is printed, not
  // held to the quadratic rate.
  const Histories s = run_footing(footing_input(
      joint, "contact_solver: {type: semismooth_newton, tolerance: 1.0e-11}\n", 0.02, 4));
  check_quadratic(s, "semismooth_newton", false);
  std::printf("footing force: generalized %.12g, semismooth %.12g\n", h.force, s.force);
  EXPECT_NEAR(h.force, s.force, 1e-8 * std::abs(s.force));
}

// A frictional, dilatant soil (Mohr-Coulomb, c = 3 kPa, phi = 35 deg, psi = 5 deg) under the
// footing pushed 5 cm in 4 increments. Its return is only piecewise smooth (plane, edges,
// apex, whose tangent is zero), on which the undamped outer loop of generalized_newton cut
// an increment back (and cycled on the Mohr-Coulomb pile); damped on the whole residual it
// needs no cut-back, and both solvers, each converged to 1e-10, give the same solution.
TEST(PlasticNewton, MohrCoulombGeneralizedNewtonMatchesSemismooth) {
  const std::string soil = "{type: mohr_coulomb, youngs_modulus: 1.0e4, poissons_ratio: 0.3, "
                           "cohesion: 3.0, friction_angle: 35.0, dilatancy_angle: 5.0}";
  const Histories g = run_footing(footing_input(
      joint, "contact_solver: {type: generalized_newton, tolerance: 1.0e-10}\n", 0.05, 4, soil));
  const Histories s = run_footing(footing_input(
      joint, "contact_solver: {type: semismooth_newton, tolerance: 1.0e-10}\n", 0.05, 4, soil));
  for (std::size_t i = 0; i < g.residuals.size(); ++i) {
    std::printf("generalized_newton increment %zu:", i + 1);
    for (double v : g.residuals[i])
      std::printf(" %.3e", v);
    std::printf("\n");
  }
  EXPECT_EQ(g.cutbacks, 0);
  EXPECT_EQ(s.cutbacks, 0); // the same increments, so the same plastic path
  ASSERT_EQ(g.u.size(), s.u.size());
  double du = 0;
  for (std::size_t i = 0; i < g.u.size(); ++i)
    du = std::max(du, std::abs(g.u[i] - s.u[i]));
  std::printf("footing force: generalized %.12g, semismooth %.12g; max |du| %.3e m\n", g.force,
              s.force, du);
  EXPECT_NEAR(g.force, s.force, 1e-8 * std::abs(s.force));
  EXPECT_LE(du, 1e-8 * 0.05);
}

// A failed factorisation is a failed increment, cut back like the others. Mohr-Coulomb soil
// with almost no cohesion (c = 1 kPa, phi = 35 deg, psi = 5 deg) under the footing with the
// frictional joint, semismooth_newton, 8 increments: in the first, a Newton iterate puts
// points at the apex, whose tangent is zero, and MUMPS finds the matrix numerically singular
// (shown with max_cutbacks = 0: the run stops there, naming the factorisation; counted once
// by hand: 143 of the 560 points at the apex then, 4-62 at the matrices that factorised). With the
// default cut-backs the run gets through and ends in equilibrium, on the solution that
// generalized_newton (no cut-back) finds with the 8 planned increments: within 1e-4, since
// the sub-increments change the plastic path a little (8 against 16 increments: 2.4e-3).
TEST(PlasticState, SingularTangentIsCutBack) {
  const std::string soil = "{type: mohr_coulomb, youngs_modulus: 1.0e4, poissons_ratio: 0.3, "
                           "cohesion: 1.0, friction_angle: 35.0, dilatancy_angle: 5.0}";
  auto input = [&](const std::string& solver) {
    return footing_input(joint, "contact_solver: {" + solver + ", tolerance: 1.0e-10}\n", 0.05, 8,
                         soil);
  };
  try {
    run_footing(input("type: semismooth_newton, max_cutbacks: 0"));
    ADD_FAILURE() << "the first increment converged without a cut-back: nothing is tested";
  } catch (const SolverError& e) {
    const std::string what = e.what();
    std::printf("without cut-backs: %.160s\n", what.c_str());
    EXPECT_NE(what.find("step 1 of 8"), std::string::npos);
    EXPECT_NE(what.find("factorisation failed"), std::string::npos);
  }
  const Model model = test::model_from_text(input("type: semismooth_newton"), "f.yaml");
  StaticAnalysis analysis(model, AnalysisOptions{});
  int first_cutbacks = -1;
  analysis.run([&](const StepReport& r) {
    if (r.global_step == 1) first_cutbacks = r.cutbacks;
  });
  EXPECT_GE(first_cutbacks, 1);
  const double footing = analysis.reaction("footing")[1], bottom = analysis.reaction("bottom")[1];
  const Histories g = run_footing(input("type: generalized_newton"));
  std::printf("footing force %.12g, bottom %.12g; generalized_newton %.12g (%d cut-backs)\n",
              footing, bottom, g.force, g.cutbacks);
  EXPECT_NEAR(footing + bottom, 0.0, 1e-8 * std::abs(footing)); // the body's equilibrium
  EXPECT_EQ(g.cutbacks, 0);
  EXPECT_NEAR(footing, g.force, 1e-4 * std::abs(g.force));
}

// A failed increment leaves the committed state untouched: the footing pushed in one
// increment with too few Newton iterations allowed fails, is halved, and must then give
// exactly the run planned with two increments (same starting points, same iterations).
TEST(PlasticState, CutBackEqualsPlannedSubIncrements) {
  const Histories planned = run_footing(footing_input("", "", 0.02, 2));
  const Histories whole = run_footing(footing_input("", "", 0.02, 1));
  const int needed = *std::max_element(planned.iterations.begin(), planned.iterations.end());
  std::printf("iterations: one increment %d, two increments at most %d\n", whole.iterations[0],
              needed);
  ASSERT_GT(whole.iterations[0], needed); // otherwise nothing would be cut back
  AnalysisOptions options;
  options.max_iterations = needed;
  const Histories cut = run_footing(footing_input("", "", 0.02, 1), options);
  EXPECT_EQ(cut.cutbacks, 1);
  ASSERT_EQ(cut.u.size(), planned.u.size());
  double du = 0, ds = 0;
  for (std::size_t i = 0; i < cut.u.size(); ++i)
    du = std::max(du, std::abs(cut.u[i] - planned.u[i]));
  for (std::size_t i = 0; i < cut.stress.size(); ++i)
    ds = std::max(ds, std::abs(cut.stress[i] - planned.stress[i]));
  std::printf("cut-back vs planned: max |du| %.3e, max |dstress| %.3e\n", du, ds);
  EXPECT_LE(du, 1e-12 * 0.02);
  EXPECT_LE(ds, 1e-12 * sy);
}

} // namespace
} // namespace bipot

namespace bipot {
namespace {

// Geostatic stress (γ = 20 kN/m³, K0 = 0.3) of a column 2 m deep: at its base σ_v = −40,
// σ_h = σ_zz = −12 kPa, a von Mises stress of 28 kPa.
std::string geostatic_input(double yield_stress) {
  return "kinematics: plane_strain\nmesh:\n  blocks:\n    cell: quad4\n"
         "    x: {breaks: [0.0, 1.0], cells: [2]}\n    y: {breaks: [0.0, 2.0], cells: [4]}\n"
         "    regions: [soil]\n"
         "materials:\n  soil: {type: von_mises, youngs_modulus: 1.0e4, poissons_ratio: 0.3, "
         "yield_stress: " +
         exact(yield_stress) +
         "}\n"
         "initial_stress:\n  - {region: soil, type: geostatic, unit_weight: 20.0, "
         "lateral_coefficient: 0.3, surface: 2.0}\n"
         "stages:\n  - name: rest\n    boundary_conditions:\n"
         "      - {set: bottom, component: y, value: 0}\n"
         "      - {set: left, component: x, value: 0}\n"
         "      - {set: right, component: x, value: 0}\n";
}

TEST(InitialStress, OutsideTheYieldSurfaceIsAnInputError) {
  EXPECT_NO_THROW(bipot::test::model_from_text(geostatic_input(28.5), "column.yaml"));
  try {
    bipot::test::model_from_text(geostatic_input(20.0), "column.yaml");
    FAIL() << "no error";
  } catch (const InputError& e) {
    const std::string what = e.what();
    std::printf("%s\n", what.c_str());
    EXPECT_NE(what.find("column.yaml:"), std::string::npos);
    EXPECT_NE(what.find("initial_stress[0]"), std::string::npos);
    EXPECT_NE(what.find("region 'soil'"), std::string::npos);
    EXPECT_NE(what.find("(0, 0)"), std::string::npos); // the first node of the base
    EXPECT_NE(what.find("yield function is 8 kPa"), std::string::npos); // 28 − 20
  }
}

} // namespace
} // namespace bipot
