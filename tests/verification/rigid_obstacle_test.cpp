// Interfaces against rigid obstacles (contact/interface/rigid_obstacle.hpp): a body's facet
// set paired node to surface with an analytical plane or circle whose motion is data.
// - a block pressed on a rigid plane, sheared until it slides: tangential force = mu × normal
//   force; lifted, nothing; the same forces as the block on a foundation whose every node is
//   fixed (node-to-node pairs with u_b = 0, what a rigid plane at rest is);
// - the obstacle moving instead of the block gives the same forces (a rigid translation);
// - every contact solver agrees; 1 and 2 ranks agree;
// - RCCM: a bar bonded to a rigid plane pulled off follows the 1D closed form of
//   rccm_pull_test with a rigid base;
// - perfect bonding to a moving plane equals prescribing the same displacement, and the force
//   on the obstacle balances the reaction at the other end;
// - Hertz: a rigid cylinder (circle) pressed into an elastic half-plane;
// - 3D: a block sliding on a plane, a sphere and a cylinder pressed into a block.
#include "apps/catalogue/builtin_catalogue.hpp"
#include "fem/analysis/model.hpp"
#include "fem/analysis/static_analysis.hpp"
#include "fem/input/problem_reader.hpp"
#include "fem/linalg/communicator.hpp"

#include "tests/support/serial_reference.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <sstream>

namespace bipot {
namespace {

constexpr double mu = 0.3;

std::string block_mesh(bool with_base) {
  return std::string("kinematics: plane_strain\n"
                     "mesh:\n  blocks:\n    cell: quad4\n"
                     "    x: {breaks: [0, 1.0], cells: [4]}\n") +
         (with_base ? "    y: {breaks: [-0.5, 0, 0.5], cells: [2, 3]}\n"
                      "    regions: [base, block]\n"
                      "  sets: {base_nodes: {min: [0, -0.5], max: [1, 0], region: base}}\n"
                      "materials:\n"
                      "  base: {type: linear_elastic, youngs_modulus: 1.0e5, poissons_ratio: 0.3}\n"
                    : "    y: {breaks: [0, 0.5], cells: [3]}\n"
                      "    regions: [block]\n"
                      "materials:\n") +
         "  block: {type: linear_elastic, youngs_modulus: 2.0e4, poissons_ratio: 0.25}\n"
         "linear_solver: {method: direct}\n";
}

std::string floor_interface(const std::string& law, const std::string& parameters) {
  return "interfaces:\n  - name: floor\n    facet_sets: [bottom]\n"
         "    obstacle: {type: plane, point: [0, 0], normal: [0, 1]}\n"
         "    law: " +
         law + "\n    parameters: " + parameters + "\n";
}

std::string solver(const std::string& type) {
  return "contact_solver: {type: " + type + ", tolerance: 1.0e-11}\n";
}

/// Stages moving the top of the block by (x, y) at the end of each; `base` fixes every node
/// of the foundation, `floor` moves the obstacle by (fx, fy) instead (top held there).
std::string stage(const std::string& name, int increments, double x, double y,
                  const std::string& extra = "") {
  std::ostringstream s;
  s << "  - name: " << name << "\n    increments: " << increments << "\n"
    << "    boundary_conditions:\n"
    << "      - {set: top, component: x, value: " << x << "}\n"
    << "      - {set: top, component: y, value: " << y << "}\n"
    << extra;
  return s.str();
}
const std::string fixed_base = "      - {set: base_nodes, component: x, value: 0}\n"
                               "      - {set: base_nodes, component: y, value: 0}\n";
std::string press_shear_lift(const std::string& extra = "") {
  return "stages:\n" + stage("press", 2, 0, -1e-3, extra) + stage("shear", 4, 4e-3, -1e-3, extra) +
         stage("lift", 2, 4e-3, 1e-3, extra);
}

struct Outcome {
  std::vector<std::array<double, 3>> resultant; ///< interface force after each increment
  std::vector<std::vector<double>> top;         ///< reaction of the top after each increment
  std::vector<int> sticking;
  std::vector<double> u;
};

Outcome run(const std::string& text) {
  const Model model =
      build_model(read_problem_text(text, "obstacle.yaml", bipot::builtin_catalogue()),
                  bipot::builtin_catalogue());
  StaticAnalysis analysis(model);
  Outcome out;
  analysis.run([&](const StepReport&) {
    out.top.push_back(analysis.reaction("top"));
    if (analysis.interfaces().empty()) return;
    const auto& ia = *analysis.interfaces()[0];
    out.resultant.push_back(ia.resultant());
    int stick = 0;
    for (const auto& r : ia.results())
      stick += r.status == contact::ContactStatus::Stick;
    out.sticking.push_back(stick);
  });
  out.u = analysis.displacement();
  return out;
}

const Outcome& sliding(const std::string& type) {
  static std::map<std::string, Outcome> cache;
  auto it = cache.find(type);
  if (it == cache.end())
    it =
        cache
            .emplace(type, run(block_mesh(false) +
                               floor_interface("coulomb_signorini", "{friction_coefficient: 0.3}") +
                               solver(type) + press_shear_lift()))
            .first;
  return it->second;
}

class RigidPlane : public testing::TestWithParam<std::string> {};

TEST_P(RigidPlane, BlockSlidesAtMuTimesNormalForceAndOpensWhenLifted) {
  const Outcome& r = sliding(GetParam());
  ASSERT_EQ(r.resultant.size(), 8u);
  // Pressed: the block pushes the plane down (force on the obstacle), no shear.
  EXPECT_LT(r.resultant[1][1], 0.0);
  EXPECT_NEAR(r.resultant[1][0], 0.0, 1e-9 * std::abs(r.resultant[1][1]));
  // Sheared by 4 mm over 1 mm of compression: every pair slips, and the plane is dragged
  // along +x with mu times the normal force (solver tolerance 1e-11).
  const auto& f = r.resultant[5];
  EXPECT_EQ(r.sticking[5], 0);
  EXPECT_GT(f[0], 0.0);
  EXPECT_NEAR(f[0], -mu * f[1], 1e-9 * mu * std::abs(f[1]));
  // Equilibrium of the block: the top's reaction is the force passed to the plane.
  for (int c = 0; c < 2; ++c)
    EXPECT_NEAR(r.top[5][c], f[c], 1e-9 * std::abs(f[1]));
  // Lifted: open, nothing carried.
  EXPECT_EQ(r.resultant[7][0], 0.0);
  EXPECT_EQ(r.resultant[7][1], 0.0);
}

INSTANTIATE_TEST_SUITE_P(Solvers, RigidPlane,
                         testing::Values("generalized_newton", "semismooth_newton",
                                         "bipotential_uzawa"));

// A plane at rest is a foundation whose every node is fixed: the node-to-node pairs then see
// u_b = 0 exactly as the obstacle's pairs do, so the forces agree to the solver tolerance.
TEST(RigidPlane, SameForcesAsAFullyFixedFoundation) {
  const Outcome& obstacle = sliding("semismooth_newton");
  const Outcome base =
      run(block_mesh(true) +
          "interfaces:\n  - name: joint\n    between: [base, block]\n"
          "    law: coulomb_signorini\n    parameters: {friction_coefficient: 0.3}\n" +
          solver("semismooth_newton") + press_shear_lift(fixed_base));
  ASSERT_EQ(base.resultant.size(), obstacle.resultant.size());
  const double scale = std::abs(obstacle.resultant[1][1]);
  double worst = 0;
  for (std::size_t k = 0; k < base.resultant.size(); ++k)
    for (int c = 0; c < 2; ++c) {
      // The foundation's interface reports the force on the block, the obstacle's the force
      // on the plane: opposite.
      worst = std::max(worst, std::abs(base.resultant[k][c] + obstacle.resultant[k][c]));
      worst = std::max(worst, std::abs(base.top[k][c] - obstacle.top[k][c]));
    }
  std::printf("[obstacle] vs fixed foundation: largest force difference %.2e of %.4g kN\n", worst,
              scale);
  EXPECT_LT(worst, 1e-9 * scale);
}

// Every solver reaches the same displacements (1e-8, as for the deformable block).
TEST(RigidPlane, SolversAgree) {
  const Outcome& reference = sliding("semismooth_newton");
  for (const std::string type : {"generalized_newton", "bipotential_uzawa"}) {
    const double d = test::relative_difference(sliding(type).u, reference.u);
    std::printf("[obstacle] %s vs semismooth_newton: %.2e\n", type.c_str(), d);
    EXPECT_LT(d, 1e-8) << type;
  }
}

// Pressing by moving the plane up under a held top is the same as pressing the top down on
// a plane at rest: a rigid translation of the whole problem, the same forces.
TEST(RigidPlane, MovingThePlaneEqualsMovingTheBlock) {
  const std::string moves = "    obstacle_displacements:\n"
                            "      - {interface: floor, value: [0, 1.0e-3]}\n";
  const Outcome moved =
      run(block_mesh(false) + floor_interface("coulomb_signorini", "{friction_coefficient: 0.3}") +
          solver("generalized_newton") + "stages:\n" + stage("press", 2, 0, 0, moves) +
          stage("shear", 4, 4e-3, 0));
  const Outcome& pressed = sliding("generalized_newton");
  ASSERT_EQ(moved.resultant.size(), 6u);
  const double scale = std::abs(pressed.resultant[1][1]);
  for (std::size_t k = 0; k < 6; ++k)
    for (int c = 0; c < 2; ++c)
      EXPECT_NEAR(moved.resultant[k][c], pressed.resultant[k][c], 1e-9 * scale)
          << "increment " << k + 1;
}

// The 1-rank run (CTest fixture set-up) writes its solution, the 2-rank run compares: pairs
// are evaluated on every rank and assembled by node a's owner, so only the linear solves'
// round-off differs (1e-10 as for the other parallel checks).
TEST(RigidPlane, OneAndTwoRanksAgree) {
  for (const std::string type : {"generalized_newton", "semismooth_newton"}) {
    const Outcome& r = sliding(type);
    std::vector<double> values = r.u;
    for (const auto& f : r.resultant)
      values.insert(values.end(), f.begin(), f.begin() + 2);
    const auto ref = test::serial_reference("rigid_obstacle_" + type + ".txt", values);
    if (mpi_size() == 1) continue;
    ASSERT_EQ(ref.size(), values.size());
    const double d = test::relative_difference(values, ref);
    if (mpi_rank() == 0) std::printf("[obstacle] %s, 2 vs 1 ranks: %.2e\n", type.c_str(), d);
    EXPECT_LT(d, 1e-10) << type;
  }
}

// RCCM: a bar (nu = 0, uniaxial) bonded to a rigid plane and pulled off. With the base rigid,
// rccm_pull_test's 1D closed form becomes
//   sigma = C beta^2 g,  beta = min(1, w / (C g^2)),  delta = g + sigma L / E.
TEST(RigidPlane, RccmBarPulledOffFollowsTheClosedForm) {
  constexpr double C = 1.0e5, w = 0.02, E = 1.0e6, L = 1.0;
  const std::string text =
      "kinematics: plane_strain\n"
      "mesh:\n  blocks:\n    cell: quad4\n"
      "    x: {breaks: [0, 1.0], cells: [3]}\n"
      "    y: {breaks: [0, 1.0], cells: [3]}\n"
      "    regions: [column]\n"
      "materials:\n"
      "  column: {type: linear_elastic, youngs_modulus: 1.0e6, poissons_ratio: 0.0}\n"
      "linear_solver: {method: direct}\n" +
      floor_interface("rccm", "{normal_stiffness: 1.0e5, tangential_stiffness: 1.0e5, "
                              "decohesion_energy: 0.02, friction_coefficient: 0.5}") +
      "contact_solver: {type: generalized_newton, tolerance: 1.0e-12}\n"
      "stages:\n  - name: pull\n    increments: 12\n    boundary_conditions:\n"
      "      - {set: top, component: x, value: 0}\n"
      "      - {set: top, component: y, value: 3.0e-3}\n";
  const Model model = build_model(read_problem_text(text, "pull.yaml", bipot::builtin_catalogue()),
                                  bipot::builtin_catalogue());
  StaticAnalysis analysis(model);
  int steps = 0, softening = 0;
  analysis.run([&](const StepReport& rep) {
    ++steps;
    const auto& ia = *analysis.interfaces()[0];
    const double delta = 3.0e-3 * rep.load_factor;
    const double sigma = ia.resultant()[1]; // force the bar pulls the plane up with, per width
    const double g = ia.results()[0].jump(0);
    const double beta = std::min(1.0, w / (C * g * g));
    for (const auto& p : ia.results()) { // uniform opening and adhesion
      EXPECT_NEAR(p.jump(0), g, 1e-9 * std::abs(g) + 1e-15);
      EXPECT_NEAR(p.beta, beta, 1e-8);
    }
    EXPECT_NEAR(sigma, C * beta * beta * g, 1e-8 * std::sqrt(w * C)) << "step " << steps;
    EXPECT_NEAR(delta, g + sigma * L / E, 1e-8 * 3.0e-3) << "step " << steps;
    EXPECT_LE(sigma, std::sqrt(w * C) * (1 + 1e-12));
    softening += g > std::sqrt(w / C);
  });
  EXPECT_EQ(steps, 12);
  EXPECT_GT(softening, 3); // the pull reaches the softening branch
}

// Perfect bonding holds the facet's nodes to the plane: moving the plane by (dx, dy) under a
// held top is prescribing (dx, dy) on the bottom, to round-off; the force on the plane is the
// top's reaction (equilibrium of the block).
TEST(RigidPlane, PerfectBondingEqualsPrescribedDisplacements) {
  const std::string tail = "contact_solver: {type: generalized_newton}\nstages:\n";
  const Outcome bonded = run(block_mesh(false) + floor_interface("perfect_bonding", "{}") + tail +
                             stage("move", 2, 0, 0,
                                   "    obstacle_displacements:\n"
                                   "      - {interface: floor, value: [2.0e-3, 1.0e-3]}\n"));
  const Outcome fixed = run(block_mesh(false) + tail +
                            stage("move", 2, 0, 0,
                                  "      - {set: bottom, component: x, value: 2.0e-3}\n"
                                  "      - {set: bottom, component: y, value: 1.0e-3}\n"));
  EXPECT_LT(test::relative_difference(bonded.u, fixed.u), 1e-12);
  const auto& f = bonded.resultant.back();
  ASSERT_GT(std::abs(f[1]), 1.0);
  for (int c = 0; c < 2; ++c) {
    EXPECT_NEAR(f[c], bonded.top.back()[c], 1e-10 * std::abs(f[1]));
    EXPECT_NEAR(bonded.top.back()[c], fixed.top.back()[c], 1e-10 * std::abs(f[1]));
  }
}

// Hertz (Johnson 1985, ch. 4), a rigid cylinder of radius R pressed into an elastic
// half-plane, per unit length: a = sqrt(4 P R / (pi E*)), p0 = 2 P / (pi a),
// E* = E / (1 - nu^2) (the rigid limit of hertz_test's combined modulus). Half model x >= 0,
// the circle centred on x = 0 and lowered by `depth`; fine cells h = a/16 near the contact.
TEST(RigidCircle, HertzHalfWidthAndPeakPressure) {
  constexpr double pi = 3.141592653589793, R = 4.0, E = 1.0e5, nu = 0.3, h = 0.05 / 16;
  const std::string text =
      "kinematics: plane_strain\n"
      "mesh:\n  blocks:\n    cell: quad4\n"
      "    x: {breaks: [0, 0.075, 1.0], cells: [24, 20], grading: [1, 1.12]}\n"
      "    y: {breaks: [-1.0, -0.05, 0], cells: [20, 16], grading: [0.893, 1]}\n"
      "    regions: [flat, flat, flat, flat]\n"
      "materials:\n"
      "  flat: {type: linear_elastic, youngs_modulus: 1.0e5, poissons_ratio: 0.3}\n"
      "linear_solver: {method: direct}\n"
      "interfaces:\n  - name: indenter\n    facet_sets: [top]\n"
      "    obstacle: {type: circle, point: [0, 4.0], radius: 4.0}\n"
      "    law: coulomb_signorini\n    parameters: {friction_coefficient: 0}\n"
      "contact_solver: {type: semismooth_newton, tolerance: 1.0e-12}\n"
      "stages:\n  - name: press\n    increments: 2\n    boundary_conditions:\n"
      "      - {set: bottom, component: x, value: 0}\n"
      "      - {set: bottom, component: y, value: 0}\n"
      "      - {set: left, component: x, value: 0}\n"
      "    obstacle_displacements:\n      - {interface: indenter, value: [0, -1.0e-3]}\n";
  const Model model =
      build_model(read_problem_text(text, "hertz_circle.yaml", bipot::builtin_catalogue()),
                  bipot::builtin_catalogue());
  StaticAnalysis analysis(model);
  analysis.run();
  const auto& ia = *analysis.interfaces()[0];
  const auto& pairs = model.interfaces[0].pairs;
  // Pressures by increasing x.
  std::vector<std::pair<double, double>> p;
  for (std::size_t i = 0; i < pairs.size(); ++i)
    p.emplace_back(model.mesh.nodes[pairs[i].node_a][0], ia.results()[i].r(0));
  std::sort(p.begin(), p.end());
  const double P = 2 * ia.resultant()[1]; // the flat pushes the circle up (+y)
  const double a = std::sqrt(4 * P * R * (1 - nu * nu) / (pi * E));
  const double p0 = 2 * P / (pi * a);
  std::size_t last = 0;
  while (last + 1 < p.size() && p[last + 1].second > 0)
    ++last;
  for (std::size_t i = last + 1; i < p.size(); ++i)
    EXPECT_EQ(p[i].second, 0.0) << "x = " << p[i].first; // one contact zone
  if (mpi_rank() == 0)
    std::printf("[obstacle] circle: P = %.6g kN/m, a = %.6g m, last closed node x = %.6g m, "
                "p0 = %.6g kPa, FE centre pressure %.6g kPa (%+.2f%%)\n",
                P, a, p[last].first, p0, p[0].second, 100 * (p[0].second / p0 - 1));
  // hertz_test's tolerances: the contact edge within a cell of a, the centre pressure 3%.
  EXPECT_NEAR(p[last].first, a, h);
  EXPECT_NEAR(p[0].second, p0, 0.03 * p0);
}

// 3D (the generator's z faces are back and front): a hex block pressed on a rigid plane
// and sheared along (0.6, 0.8) slides on the Coulomb cone at every pair, along the shear.
TEST(RigidObstacle3d, BlockSlidesOnAPlaneOnTheCone) {
  const std::string text =
      "kinematics: three_d\n"
      "mesh:\n  blocks:\n    cell: hex8\n"
      "    x: {breaks: [0, 1.0], cells: [2]}\n"
      "    y: {breaks: [0, 1.0], cells: [2]}\n"
      "    z: {breaks: [0, 0.5], cells: [2]}\n"
      "    regions: [block]\n"
      "materials:\n"
      "  block: {type: linear_elastic, youngs_modulus: 2.0e4, poissons_ratio: 0.25}\n"
      "linear_solver: {method: direct}\n"
      "interfaces:\n  - name: floor\n    facet_sets: [back]\n"
      "    obstacle: {type: plane, point: [0, 0, 0], normal: [0, 0, 2]}\n"
      "    law: coulomb_signorini\n    parameters: {friction_coefficient: 0.3}\n"
      "contact_solver: {type: generalized_newton, tolerance: 1.0e-11}\n"
      "stages:\n"
      "  - name: press\n    boundary_conditions:\n"
      "      - {set: front, component: x, value: 0}\n"
      "      - {set: front, component: y, value: 0}\n"
      "      - {set: front, component: z, value: -1.0e-3}\n"
      "  - name: shear\n    increments: 2\n    boundary_conditions:\n"
      "      - {set: front, component: x, value: 3.0e-3}\n"
      "      - {set: front, component: y, value: 4.0e-3}\n"
      "      - {set: front, component: z, value: -1.0e-3}\n";
  const Model model =
      build_model(read_problem_text(text, "block3d.yaml", bipot::builtin_catalogue()),
                  bipot::builtin_catalogue());
  StaticAnalysis analysis(model);
  analysis.run();
  const auto& ia = *analysis.interfaces()[0];
  // Every pair slips and sits on the cone, |r_t| = mu r_n (solver tolerance 1e-11); the
  // slip directions differ a little from node to node (Poisson), so the resultant's
  // tangential part is a little under mu N, along the shear.
  for (const auto& p : ia.results()) {
    ASSERT_EQ(p.status, contact::ContactStatus::Slip);
    EXPECT_NEAR(p.r.tail(2).norm(), mu * p.r(0), 1e-9 * mu * p.r(0));
  }
  const auto f = ia.resultant();
  EXPECT_LT(f[2], 0.0);
  const double tangential = std::hypot(f[0], f[1]);
  EXPECT_NEAR(tangential, -mu * f[2], 1e-3 * std::abs(f[2]));
  EXPECT_NEAR(f[0] / tangential, 0.6, 1e-4); // dragged along the shear
  const auto front = analysis.reaction("front");
  for (int c = 0; c < 3; ++c)
    EXPECT_NEAR(front[c], f[c], 1e-9 * std::abs(f[2]));
}

// A rigid sphere and a rigid cylinder pressed 1 mm into a block's front (z = max), every solver:
// the block carries the force to its support (equilibrium) and the solvers agree (1e-8).
class RoundObstacle3d : public testing::TestWithParam<std::string> {};

TEST_P(RoundObstacle3d, EquilibriumAndSolversAgree) {
  const auto text = [&](const std::string& type) {
    return "kinematics: three_d\n"
           "mesh:\n  blocks:\n    cell: hex8\n"
           "    x: {breaks: [0, 1.0], cells: [4]}\n"
           "    y: {breaks: [0, 1.0], cells: [4]}\n"
           "    z: {breaks: [0, 0.5], cells: [2]}\n"
           "    regions: [block]\n"
           "materials:\n"
           "  block: {type: linear_elastic, youngs_modulus: 2.0e4, poissons_ratio: 0.25}\n"
           "linear_solver: {method: direct}\n"
           "interfaces:\n  - name: indenter\n    facet_sets: [front]\n    obstacle: " +
           GetParam() +
           "\n    law: coulomb_signorini\n    parameters: {friction_coefficient: 0.2}\n"
           "contact_solver: {type: " +
           type +
           ", tolerance: 1.0e-11}\n"
           "stages:\n"
           "  - name: press\n    increments: 2\n    boundary_conditions:\n"
           "      - {set: back, component: x, value: 0}\n"
           "      - {set: back, component: y, value: 0}\n"
           "      - {set: back, component: z, value: 0}\n"
           "    obstacle_displacements:\n"
           "      - {interface: indenter, value: [0, 0, -2.0e-3]}\n";
  };
  const auto outcome = [&](const std::string& type) {
    const Model model =
        build_model(read_problem_text(text(type), "indenter.yaml", bipot::builtin_catalogue()),
                    bipot::builtin_catalogue());
    StaticAnalysis analysis(model);
    analysis.run();
    std::array<double, 3> f = analysis.interfaces()[0]->resultant();
    const auto bottom = analysis.reaction("back");
    for (int c = 0; c < 3; ++c) // the block pushes the indenter as its support pushes it
      EXPECT_NEAR(f[c], bottom[c], 1e-9 * std::abs(f[2])) << type << " component " << c;
    EXPECT_GT(f[2], 1.0) << type; // in contact, pushed up
    return analysis.displacement();
  };
  const std::vector<double> reference = outcome("generalized_newton");
  for (const std::string type : {"semismooth_newton", "bipotential_uzawa"})
    EXPECT_LT(test::relative_difference(outcome(type), reference), 1e-8) << type;
}

INSTANTIATE_TEST_SUITE_P(
    Shapes, RoundObstacle3d,
    testing::Values("{type: sphere, point: [0.5, 0.5, 1.499], radius: 1.0}",
                    "{type: cylinder, point: [0.5, 0, 1.499], axis: [0, 1, 0], radius: 1.0}"));

} // namespace
} // namespace bipot
