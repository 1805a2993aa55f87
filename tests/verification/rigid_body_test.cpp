// Rigid bodies (fem/assembly/rigid_body_constraint.hpp): a region whose nodes follow a
// reference node exactly (master–slave elimination).
// - every node of the body moves as u_R + θ × (x − x_R) to round-off;
// - a rigid cap on a bar with nu = 0 (uniaxial stress): u = F L / (E A), exact for linear
//   elements; in axisymmetry with A = π (R_o² − R_i²);
// - equilibrium: the supports' reactions balance the force and moment the reference node
//   transmits (1e-10);
// - prescribed rotation in 2D, a moment in 3D;
// - with a contact interface, every solver agrees; 1 and 2 ranks agree.
#include "apps/catalogue/builtin_catalogue.hpp"
#include "fem/analysis/model.hpp"
#include "fem/analysis/static_analysis.hpp"
#include "fem/input/problem_reader.hpp"
#include "fem/linalg/communicator.hpp"

#include "tests/support/serial_reference.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

namespace bipot {
namespace {

constexpr double pi = 3.141592653589793;

struct Result {
  std::vector<double> state;         ///< StaticAnalysis::rigid_body_state(0)
  std::vector<double> u;             ///< all DOFs
  double follow_error = 0;           ///< max |u_s − (u_R + θ × r)| over the body's nodes
  std::vector<double> base;          ///< reaction of set `base`
  std::array<double, 3> resultant{}; ///< of the first interface, if any
};

Result solve(const std::string& text, const std::string& base) {
  const Model model = build_model(read_problem_text(text, "rigid.yaml", bipot::builtin_catalogue()),
                                  bipot::builtin_catalogue());
  StaticAnalysis analysis(model);
  analysis.run();
  Result r;
  r.state = analysis.rigid_body_state(0);
  r.u = analysis.displacement();
  const int d = spatial_dim(model.kinematics);
  const RigidBody& b = model.rigid_bodies[0];
  const auto& dofs = analysis.dofs();
  double theta[3] = {0, 0, 0};
  if (d == 2 && model.kinematics == Kinematics::PlaneStrain)
    theta[2] = r.u[dofs.dof(b.rotation, 0)];
  if (d == 3)
    for (int i = 0; i < 3; ++i)
      theta[i] = r.u[dofs.dof(b.rotation, i)];
  for (Index n : b.nodes) {
    double x[3];
    for (int i = 0; i < 3; ++i)
      x[i] = model.mesh.nodes[n][i] - b.point[i];
    const double rot[3] = {theta[1] * x[2] - theta[2] * x[1], theta[2] * x[0] - theta[0] * x[2],
                           theta[0] * x[1] - theta[1] * x[0]};
    for (int c = 0; c < d; ++c) {
      double expected = r.u[dofs.dof(b.reference, c)] + rot[c];
      if (model.kinematics == Kinematics::Axisymmetric) expected = c == 0 ? 0.0 : expected;
      r.follow_error = std::max(r.follow_error, std::abs(r.u[dofs.dof(n, c)] - expected));
    }
  }
  r.base = analysis.reaction(base);
  if (!analysis.interfaces().empty()) r.resultant = analysis.interfaces()[0]->resultant();
  return r;
}

const std::string elastic =
    "  soil: {type: linear_elastic, youngs_modulus: 1.0e4, poissons_ratio: 0.0}\n"
    "  cap: {type: linear_elastic, youngs_modulus: 1.0e4, poissons_ratio: 0.0}\n";

std::string bar(const std::string& kinematics, const std::string& x, const std::string& stage) {
  return "kinematics: " + kinematics +
         "\nmesh:\n  blocks:\n    cell: quad4\n"
         "    x: " +
         x +
         "\n    y: {breaks: [0, 1.0, 1.2], cells: [4, 1]}\n"
         "    regions: [soil, cap]\n"
         "materials:\n" +
         elastic +
         "linear_solver: {method: direct}\n"
         "rigid_bodies:\n  - {name: cap, region: cap}\n"
         "stages:\n  - name: push\n    increments: 2\n    boundary_conditions:\n" +
         stage;
}

// ν = 0: uniform uniaxial stress under the rigid cap, u = F L / (E A) exactly; the cap
// moves as one and the base carries the force.
TEST(RigidBody, CapOnABarMovesByFLOverEA) {
  const double F = -100, E = 1.0e4, L = 1.0, width = 2.0;
  const Result r = solve(bar("plane_strain", "{breaks: [0, 2.0], cells: [4]}",
                             "      - {set: bottom, component: x, value: 0}\n"
                             "      - {set: bottom, component: y, value: 0}\n"
                             "    rigid_bodies:\n"
                             "      - {body: cap, component: y, force: -100}\n"
                             "      - {body: cap, component: x, force: 0}\n"
                             "      - {body: cap, component: rz, force: 0}\n"),
                         "bottom");
  ASSERT_EQ(r.state.size(), 6u);
  EXPECT_NEAR(r.state[1], F * L / (E * width), 1e-12 * std::abs(F * L / (E * width)));
  EXPECT_NEAR(r.state[0], 0.0, 1e-15);
  EXPECT_NEAR(r.state[2], 0.0, 1e-15);
  EXPECT_LT(r.follow_error, 1e-16);
  EXPECT_NEAR(r.state[4], F, 1e-10 * std::abs(F)); // what the reference node transmits
  EXPECT_NEAR(r.base[1], -F, 1e-10 * std::abs(F));
}

TEST(RigidBody, AxisymmetricCapMovesAxially) {
  const double F = -100, E = 1.0e4, L = 1.0, ri = 0.5, ro = 1.5;
  const Result r = solve(bar("axisymmetric", "{breaks: [0.5, 1.5], cells: [4]}",
                             "      - {set: bottom, component: z, value: 0}\n"
                             "    rigid_bodies:\n"
                             "      - {body: cap, component: z, force: -100}\n"),
                         "bottom");
  const double area = pi * (ro * ro - ri * ri);
  ASSERT_EQ(r.state.size(), 4u);
  EXPECT_NEAR(r.state[1], F * L / (E * area), 1e-12 * std::abs(F * L / (E * area)));
  EXPECT_LT(r.follow_error, 1e-16); // radial 0, axial the reference node's
  EXPECT_NEAR(r.base[1], -F, 1e-10 * std::abs(F));
}

// A prescribed rotation and translation of a footing on an elastic block (ν = 0.3): the
// footing turns exactly, and the base's reactions balance what its reference node transmits.
TEST(RigidBody, PrescribedRotationIn2d) {
  const std::string text =
      "kinematics: plane_strain\n"
      "mesh:\n  blocks:\n    cell: quad8\n"
      "    x: {breaks: [0, 2.0], cells: [6]}\n"
      "    y: {breaks: [0, 1.0, 1.2], cells: [4, 1]}\n"
      "    regions: [soil, cap]\n"
      "materials:\n"
      "  soil: {type: linear_elastic, youngs_modulus: 1.0e4, poissons_ratio: 0.3}\n"
      "  cap: {type: linear_elastic, youngs_modulus: 1.0e4, poissons_ratio: 0.3}\n"
      "linear_solver: {method: direct}\n"
      "rigid_bodies:\n  - {name: cap, region: cap, reference_point: [1.0, 1.2]}\n"
      "stages:\n  - name: tilt\n    increments: 2\n    boundary_conditions:\n"
      "      - {set: bottom, component: x, value: 0}\n"
      "      - {set: bottom, component: y, value: 0}\n"
      "    rigid_bodies:\n"
      "      - {body: cap, component: x, value: 1.0e-3}\n"
      "      - {body: cap, component: y, value: -2.0e-3}\n"
      "      - {body: cap, component: rz, value: 1.0e-3}\n";
  const Result r = solve(text, "bottom");
  EXPECT_NEAR(r.state[0], 1.0e-3, 1e-18);
  EXPECT_NEAR(r.state[1], -2.0e-3, 1e-18);
  EXPECT_NEAR(r.state[2], 1.0e-3, 1e-18);
  EXPECT_LT(r.follow_error, 1e-17);
  const double scale = std::abs(r.state[4]);
  ASSERT_GT(scale, 1.0);
  EXPECT_NEAR(r.base[0], -r.state[3], 1e-10 * scale); // force equilibrium
  EXPECT_NEAR(r.base[1], -r.state[4], 1e-10 * scale);
  EXPECT_GT(std::abs(r.state[5]), 0.0); // turning it takes a moment
}

// Applying the moment a prescribed rotation took gives back that rotation (the moment is
// the rotation's work conjugate), with the same translations held.
TEST(RigidBody, AppliedMomentGivesBackThePrescribedRotation) {
  const auto text = [](const std::string& rz) {
    return "kinematics: plane_strain\n"
           "mesh:\n  blocks:\n    cell: quad4\n"
           "    x: {breaks: [0, 2.0], cells: [6]}\n"
           "    y: {breaks: [0, 1.0, 1.2], cells: [4, 1]}\n"
           "    regions: [soil, cap]\n"
           "materials:\n"
           "  soil: {type: linear_elastic, youngs_modulus: 1.0e4, poissons_ratio: 0.3}\n"
           "  cap: {type: linear_elastic, youngs_modulus: 1.0e4, poissons_ratio: 0.3}\n"
           "linear_solver: {method: direct}\n"
           "rigid_bodies:\n  - {name: cap, region: cap, reference_point: [0.7, 1.3]}\n"
           "stages:\n  - name: tilt\n    boundary_conditions:\n"
           "      - {set: bottom, component: x, value: 0}\n"
           "      - {set: bottom, component: y, value: 0}\n"
           "    rigid_bodies:\n"
           "      - {body: cap, component: x, value: 0}\n"
           "      - {body: cap, component: y, value: 0}\n"
           "      - {body: cap, component: rz, " +
           rz + "}\n";
  };
  const Result turned = solve(text("value: 1.0e-3"), "bottom");
  char moment[64];
  std::snprintf(moment, sizeof moment, "force: %.17g", turned.state[5]);
  const Result pushed = solve(text(moment), "bottom");
  EXPECT_NEAR(pushed.state[2], 1.0e-3, 1e-10 * 1.0e-3);
  EXPECT_LT(test::relative_difference(pushed.u, turned.u), 1e-10);
}

// 3D: a moment about x on a rigid top layer of a hex block turns it about x only; its
// nodes follow exactly and the base carries the forces.
TEST(RigidBody, MomentIn3d) {
  const std::string text =
      "kinematics: three_d\n"
      "mesh:\n  blocks:\n    cell: hex8\n"
      "    x: {breaks: [0, 1.0], cells: [2]}\n"
      "    y: {breaks: [0, 1.0], cells: [2]}\n"
      "    z: {breaks: [0, 1.0, 1.2], cells: [2, 1]}\n"
      "    regions: [soil, cap]\n"
      "materials:\n" +
      elastic +
      "linear_solver: {method: direct}\n"
      "rigid_bodies:\n  - {name: cap, region: cap, reference_point: [0.5, 0.5, 1.2]}\n"
      "stages:\n  - name: turn\n    boundary_conditions:\n"
      "      - {set: back, component: x, value: 0}\n"
      "      - {set: back, component: y, value: 0}\n"
      "      - {set: back, component: z, value: 0}\n"
      "    rigid_bodies:\n"
      "      - {body: cap, component: rx, force: 5}\n"
      "      - {body: cap, component: z, force: -20}\n";
  const Result r = solve(text, "back");
  ASSERT_EQ(r.state.size(), 12u);
  EXPECT_GT(r.state[3], 0.0); // turns about +x
  EXPECT_NEAR(r.state[4], 0.0, 1e-12 * r.state[3]);
  EXPECT_NEAR(r.state[5], 0.0, 1e-12 * r.state[3]);
  EXPECT_LT(r.follow_error, 1e-16);
  EXPECT_NEAR(r.state[9], 5.0, 1e-10 * 5.0);
  EXPECT_NEAR(r.base[2], 20.0, 1e-10 * 20.0);
  EXPECT_NEAR(r.base[0], 0.0, 1e-10 * 20.0);
  EXPECT_NEAR(r.base[1], 0.0, 1e-10 * 20.0);
}

// A rigid cap pressing a block onto a rigid plane with friction, then pushed sideways by a
// force below mu N: the contact solvers agree (1e-8) and, with the cap's rotation held,
// the plane carries exactly the cap's force (equilibrium, 1e-9); 1 and 2 ranks agree.
// An elastic block under a rigid cap of the same width.
const std::string soil_and_cap =
    "kinematics: plane_strain\n"
    "mesh:\n  blocks:\n    cell: quad4\n"
    "    x: {breaks: [0, 1.0], cells: [4]}\n"
    "    y: {breaks: [0, 0.5, 0.6], cells: [3, 1]}\n"
    "    regions: [soil, cap]\n"
    "materials:\n"
    "  soil: {type: linear_elastic, youngs_modulus: 2.0e4, poissons_ratio: 0.25}\n"
    "  cap: {type: linear_elastic, youngs_modulus: 2.0e4, poissons_ratio: 0.25}\n"
    "linear_solver: {method: direct}\n"
    "rigid_bodies:\n  - {name: cap, region: cap}\n";

std::string capped_block(const std::string& solver) {
  return soil_and_cap +

         "interfaces:\n  - name: floor\n    facet_sets: [bottom]\n"
         "    obstacle: {type: plane, point: [0, 0], normal: [0, 1]}\n"
         "    law: coulomb_signorini\n    parameters: {friction_coefficient: 0.3}\n"
         "contact_solver: {type: " +
         solver +
         ", tolerance: 1.0e-11}\n"
         "stages:\n"
         "  - name: press\n    increments: 2\n    rigid_bodies:\n"
         "      - {body: cap, component: y, force: -50}\n"
         "      - {body: cap, component: x, value: 0}\n"
         "      - {body: cap, component: rz, value: 0}\n"
         "  - name: push\n    increments: 2\n    rigid_bodies:\n"
         "      - {body: cap, component: y, force: -50}\n"
         "      - {body: cap, component: x, force: 5}\n"
         "      - {body: cap, component: rz, value: 0}\n";
}

TEST(RigidBody, WithContactEverySolverAgrees) {
  const Result reference = solve(capped_block("generalized_newton"), "top");
  // The plane carries the cap's force: the block pushes it down by 50 and drags it by 5.
  EXPECT_NEAR(reference.resultant[1], -50.0, 1e-9 * 50);
  EXPECT_NEAR(reference.resultant[0], 5.0, 1e-9 * 50);
  EXPECT_LT(reference.follow_error, 1e-16);
  for (const std::string type : {"semismooth_newton", "bipotential_uzawa"}) {
    const Result other = solve(capped_block(type), "top");
    const double d = test::relative_difference(other.u, reference.u);
    if (mpi_rank() == 0)
      std::printf("[rigid body] %s vs generalized_newton: %.2e\n", type.c_str(), d);
    EXPECT_LT(d, 1e-8) << type;
  }
  std::vector<double> values = reference.u;
  values.insert(values.end(), reference.state.begin(), reference.state.end());
  const auto ref = test::serial_reference("rigid_body_solution.txt", values);
  if (mpi_size() == 1) return;
  ASSERT_EQ(ref.size(), values.size());
  const double d = test::relative_difference(values, ref);
  if (mpi_rank() == 0) std::printf("[rigid body] 2 vs 1 ranks: %.2e\n", d);
  EXPECT_LT(d, 1e-10);
}

// A rigid block on a rigid plane (its bottom nodes are the interface's: the pairs' blocks go
// to the reference node), pressed by N and pushed sideways until it slides: the plane carries
// (μ N, −N) exactly. How N spreads over the pairs is not determined (rigid on rigid):
// bipotential_uzawa settles on one, semismooth_newton's multipliers keep drifting (measured:
// no convergence in 200 updates), so only the former is run here. generalized_newton, which
// condenses on the interface DOFs, refuses it with a located error.
std::string rigid_block(const std::string& solver) {
  return "kinematics: plane_strain\n"
         "mesh:\n  blocks:\n    cell: quad4\n"
         "    x: {breaks: [0, 1.0], cells: [4]}\n"
         "    y: {breaks: [0, 0.5], cells: [2]}\n"
         "    regions: [block]\n"
         "materials:\n"
         "  block: {type: linear_elastic, youngs_modulus: 2.0e4, poissons_ratio: 0.25}\n"
         "linear_solver: {method: direct}\n"
         "rigid_bodies:\n  - {name: block, region: block, reference_point: [0.5, 0]}\n"
         "interfaces:\n  - name: floor\n    facet_sets: [bottom]\n"
         "    obstacle: {type: plane, point: [0, 0], normal: [0, 1]}\n"
         "    law: coulomb_signorini\n    parameters: {friction_coefficient: 0.3}\n"
         "contact_solver: {type: " +
         solver +
         ", tolerance: 1.0e-11}\n"
         "stages:\n"
         "  - name: press\n    rigid_bodies:\n"
         "      - {body: block, component: y, force: -100}\n"
         "      - {body: block, component: x, value: 0}\n"
         "      - {body: block, component: rz, value: 0}\n"
         "  - name: push\n    increments: 2\n    rigid_bodies:\n"
         "      - {body: block, component: y, force: -100}\n"
         "      - {body: block, component: x, value: 1.0e-3}\n"
         "      - {body: block, component: rz, value: 0}\n";
}

TEST(RigidBody, RigidBlockSlidesOnARigidPlane) {
  for (const std::string type : {"bipotential_uzawa"}) {
    const Result r = solve(rigid_block(type), "top");
    EXPECT_NEAR(r.resultant[1], -100.0, 1e-9 * 100) << type;
    EXPECT_NEAR(r.resultant[0], 30.0, 1e-9 * 100) << type; // μ N, along the push
    EXPECT_NEAR(r.state[3], 30.0, 1e-9 * 100) << type;     // the push's reaction
    EXPECT_NEAR(r.state[0], 1.0e-3, 1e-18) << type;
    EXPECT_LT(r.follow_error, 1e-16) << type;
  }
  std::string message;
  try {
    build_model(read_problem_text(rigid_block("generalized_newton"), "rigid.yaml",
                                  bipot::builtin_catalogue()),
                bipot::builtin_catalogue());
  } catch (const InputError& e) {
    message = e.what();
  }
  EXPECT_NE(message.find("rigid.yaml:19:17: contact_solver: contact_solver.type: "
                         "generalized_newton condenses the model on its interface nodes, and "
                         "node 0 at (0, 0) of interface 'floor' belongs to rigid body 'block'"),
            std::string::npos)
      << message;
}

// A rigid cap on an elastic block, joined by a Coulomb interface between the regions (the
// cap's side of the pairs are its slaves), pressed by a force and pushed until it slides:
// the interface passes (μ N, −N) to the block; both augmented-Lagrangian solvers agree.
TEST(RigidBody, RigidCapSlidesOnAnElasticBlock) {
  const auto text = [](const std::string& solver) {
    return soil_and_cap +

           "interfaces:\n  - name: joint\n    between: [cap, soil]\n"
           "    law: coulomb_signorini\n    parameters: {friction_coefficient: 0.3}\n"
           "contact_solver: {type: " +
           solver +
           ", tolerance: 1.0e-11}\n"
           "stages:\n"
           "  - name: press\n    increments: 2\n    boundary_conditions:\n"
           "      - {set: bottom, component: x, value: 0}\n"
           "      - {set: bottom, component: y, value: 0}\n"
           "    rigid_bodies:\n"
           "      - {body: cap, component: y, force: -50}\n"
           "      - {body: cap, component: x, value: 0}\n"
           "      - {body: cap, component: rz, value: 0}\n"
           "  - name: push\n    increments: 4\n    boundary_conditions:\n"
           "      - {set: bottom, component: x, value: 0}\n"
           "      - {set: bottom, component: y, value: 0}\n"
           "    rigid_bodies:\n"
           "      - {body: cap, component: y, force: -50}\n"
           "      - {body: cap, component: x, value: 4.0e-3}\n"
           "      - {body: cap, component: rz, value: 0}\n";
  };
  const Result newton = solve(text("semismooth_newton"), "bottom");
  const Result uzawa = solve(text("bipotential_uzawa"), "bottom");
  for (const Result* r : {&newton, &uzawa}) {
    EXPECT_NEAR(r->resultant[1], -50.0, 1e-9 * 50);
    EXPECT_NEAR(r->resultant[0], 15.0, 1e-9 * 50); // μ N along the push
    EXPECT_NEAR(r->base[0], -15.0, 1e-9 * 50);     // the block's support takes it
    EXPECT_NEAR(r->base[1], 50.0, 1e-9 * 50);
    EXPECT_LT(r->follow_error, 1e-16);
  }
  EXPECT_LT(test::relative_difference(uzawa.u, newton.u), 1e-8);
}

// The pile head as a rigid cap (axisymmetric): the pile's top nodes, the shaft interface's
// top node among them, move axially as one; pulled by F, the pile hands F to the soil
// through its RCCM interface (still bonded), and the soil's base holds it (1e-9).
TEST(RigidBody, PileHeadAsARigidCap) {
  const std::string text =
      "kinematics: axisymmetric\n"
      "mesh:\n  blocks:\n    cell: quad8\n"
      "    x: {breaks: [0, 0.135, 2.0], cells: [2, 8], grading: [1, 1.3]}\n"
      "    y: {breaks: [-6.0, -4.0, 0], cells: [4, 8]}\n"
      "    regions: [soil, soil, pile, soil]\n"
      "  sets:\n"
      "    head: {min: [0, 0], max: [0.135, 0], region: pile}\n"
      "    far: {min: [2.0, -6.0], max: [2.0, 0]}\n"
      "materials:\n"
      "  soil: {type: linear_elastic, youngs_modulus: 2.0e4, poissons_ratio: 0.3}\n"
      "  pile: {type: linear_elastic, youngs_modulus: 3.0e7, poissons_ratio: 0.2}\n"
      "linear_solver: {method: direct}\n"
      "rigid_bodies:\n  - {name: cap, set: head}\n"
      "interfaces:\n  - name: skin\n    between: [pile, soil]\n    law: rccm\n"
      "    parameters: {normal_stiffness: 1.0e6, tangential_stiffness: 1.0e6, "
      "decohesion_energy: 0.5, friction_coefficient: 0.5}\n"
      "contact_solver: {type: semismooth_newton, tolerance: 1.0e-11}\n"
      "stages:\n  - name: pull\n    increments: 2\n    boundary_conditions:\n"
      "      - {set: bottom, component: z, value: 0}\n"
      "      - {set: far, component: r, value: 0}\n"
      "    rigid_bodies:\n      - {body: cap, component: z, force: 20}\n";
  const Result r = solve(text, "bottom");
  ASSERT_EQ(r.state.size(), 4u);
  EXPECT_GT(r.state[1], 0.0); // pulled up
  EXPECT_LT(r.follow_error, 1e-16);
  EXPECT_NEAR(r.state[3], 20.0, 1e-10 * 20);
  EXPECT_NEAR(r.resultant[1], 20.0, 1e-9 * 20); // the pile pulls the soil up
  EXPECT_NEAR(r.base[1], -20.0, 1e-9 * 20);
}

} // namespace
} // namespace bipot
