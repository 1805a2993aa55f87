// Hertz contact, plane strain, frictionless: an elastic cylinder of radius R pressed onto an
// elastic flat. Closed form (Hertz 1882; K. L. Johnson, Contact Mechanics, 1985, ch. 4,
// cylinders in contact), load P per unit length:
//   a = sqrt(4 P R / (π E*)),  p(x) = p0 sqrt(1 − x²/a²),  p0 = 2 P / (π a),
//   1/E* = (1 − ν1²)/E1 + (1 − ν2²)/E2.
// Half model x ≥ 0. Body 1 = the flat [0, L] × [−L, 0]; body 2 = the "cylinder", a block
// [0, L] × [0, L] whose nodes are lifted by s(x) (1 − y/L), s(x) = R − sqrt(R² − x²), so that
// its bottom is the circle and its top stays flat. Both bodies use the same x node positions,
// so each flat node faces a cylinder node along the flat's normal (+y): the interface pairs
// them with `pairing: normal` and the initial gap s(x). The mesh is written as an MSH 4 file
// through the Gmsh API and read back through the YAML input, like a user's mesh.
// Also: both contact solvers agree; 1 and 2 ranks agree; a per-pair gap closes at the right
// displacement and survives a displacement reset.
//
// Size of the bodies: Hertz assumes half-spaces, here L = 20 a. Measured centre pressure
// against p0(P): +0.07% at L = 20 a; doubling L (same top displacement, so a = 0.046 m and
// L = 44 a) gives +0.04%, halving it (L = 9 a) +0.35%. At L = 20 a the domain effect is a
// few hundredths of a percent, below the discretisation error of h = a/16.
#include "apps/catalogue/builtin_catalogue.hpp"
#include "fem/analysis/model.hpp"
#include "fem/analysis/static_analysis.hpp"
#include "fem/core/error.hpp"
#include "fem/input/problem_reader.hpp"
#include "fem/linalg/communicator.hpp"
#include "fem/mesh/structured_mesh.hpp"
#include "tests/support/scratch_dir.hpp"
#include "tests/support/serial_reference.hpp"

#include <gmsh.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <functional>
#include <iomanip>
#include <map>
#include <sstream>

namespace bipot {
namespace {

constexpr double pi = 3.141592653589793238462643383279502884;

// kPa, m. E differs between the bodies so that E* combines two terms.
constexpr double E_flat = 2.0e5, E_cylinder = 1.0e5, nu = 0.3;
constexpr double R = 4.0;           ///< cylinder radius
constexpr double a_design = 0.05;   ///< half-width the load is chosen for (a/R = 1/80)
constexpr double h = a_design / 16; ///< cell size in the contact zone, both directions

double combined_modulus() {
  return 1.0 / ((1 - nu * nu) / E_flat + (1 - nu * nu) / E_cylinder);
}

/// Geometric ratio g > 1 of n cells over `length` whose first cell is `first`.
double grading_ratio(double length, int n, double first) {
  double lo = 1.0 + 1e-12, hi = 2.0;
  for (int k = 0; k < 200; ++k) {
    const double g = 0.5 * (lo + hi);
    ((std::pow(g, n) - 1) / (g - 1) * first < length ? lo : hi) = g;
  }
  return 0.5 * (lo + hi);
}

/// [0, size]: uniform cells of size h over [0, zone], then cells growing by about 1.2.
AxisSegments graded_axis(double zone, double size) {
  const int n_zone = static_cast<int>(std::lround(zone / h));
  const int n_far =
      static_cast<int>(std::ceil(std::log(1 + (size - zone) * 0.2 / h) / std::log(1.2)));
  return {{0.0, zone, size}, {n_zone, n_far}, {1.0, grading_ratio(size - zone, n_far, h)}};
}

/// `lift(x)` is the cylinder's initial gap profile (its bottom is y = lift(x)).
void write_mesh(const std::string& path, double size, const std::function<double(double)>& lift) {
  BlockMeshSpec spec;
  spec.x = graded_axis(1.5 * a_design, size);
  spec.y = graded_axis(a_design, size);
  spec.block_regions.assign(4, "cylinder");
  Mesh cylinder = make_block_mesh(spec);
  for (auto& x : cylinder.nodes)
    x[1] += lift(x[0]) * (1 - x[1] / size);
  // The flat: the same axis mirrored (fine cells at y = 0).
  spec.block_regions.assign(4, "flat");
  Mesh flat = make_block_mesh(spec);
  for (auto& x : flat.nodes)
    x[1] = -x[1];
  for (Index c = 0; c < flat.num_cells(); ++c) // mirrored cells are clockwise: reverse them
    std::reverse(flat.cell_nodes.begin() + flat.cell_offsets[c],
                 flat.cell_nodes.begin() + flat.cell_offsets[c + 1]);

  gmsh::initialize(0, nullptr, false);
  gmsh::option::setNumber("General.Terminal", 0);
  gmsh::model::add("hertz");
  std::size_t node_tag = 1, element_tag = 1;
  int curve = 0;
  std::map<std::string, std::vector<int>> curves_of;
  const std::pair<const Mesh*, std::string> bodies[2] = {{&flat, "flat"}, {&cylinder, "cylinder"}};
  for (int b = 0; b < 2; ++b) {
    const Mesh& m = *bodies[b].first;
    const std::string& name = bodies[b].second;
    const int surface = b + 1;
    gmsh::model::addDiscreteEntity(2, surface);
    const std::size_t first = node_tag;
    std::vector<std::size_t> tags, cell_tags, cell_nodes;
    std::vector<double> xyz;
    for (const auto& x : m.nodes) {
      tags.push_back(node_tag++);
      xyz.insert(xyz.end(), {x[0], x[1], 0.0});
    }
    gmsh::model::mesh::addNodes(2, surface, tags, xyz);
    for (Index c = 0; c < m.num_cells(); ++c) {
      cell_tags.push_back(element_tag++);
      for (int k = 0; k < 4; ++k)
        cell_nodes.push_back(first + m.cell(c)[k]);
    }
    gmsh::model::mesh::addElementsByType(surface, 3, cell_tags, cell_nodes); // 3 = quad4
    gmsh::model::addPhysicalGroup(2, {surface}, surface);
    gmsh::model::setPhysicalName(2, surface, name);
    // The generator's "bottom" is y = 0 for both bodies (the flat was mirrored); the reader
    // orients facets outward of their cell whatever their order here.
    for (const auto& [side, group] : std::vector<std::pair<std::string, std::string>>{
             {"top", name + "_far"}, {"bottom", name + "_contact"}, {"left", "symmetry"}}) {
      gmsh::model::addDiscreteEntity(1, ++curve);
      std::vector<std::size_t> line_tags, line_nodes;
      for (const Facet& f : m.facet_sets.at(side)) {
        line_tags.push_back(element_tag++);
        line_nodes.push_back(first + f.nodes[0]);
        line_nodes.push_back(first + f.nodes[1]);
      }
      gmsh::model::mesh::addElementsByType(curve, 1, line_tags, line_nodes); // 1 = line2
      curves_of[group].push_back(curve);
    }
  }
  int group_tag = 10;
  for (const auto& [group, curves] : curves_of) {
    gmsh::model::addPhysicalGroup(1, curves, ++group_tag);
    gmsh::model::setPhysicalName(1, group_tag, group);
  }
  gmsh::write(path);
  gmsh::finalize();
}

std::string input(const std::string& mesh, const std::string& solver, double poisson,
                  const std::string& stages) {
  std::ostringstream s;
  s << std::setprecision(17) << "kinematics: plane_strain\n"
    << "mesh: {file: " << mesh << "}\n"
    << "materials:\n"
    << "  flat: {type: linear_elastic, youngs_modulus: " << E_flat
    << ", poissons_ratio: " << poisson << "}\n"
    << "  cylinder: {type: linear_elastic, youngs_modulus: " << E_cylinder
    << ", poissons_ratio: " << poisson << "}\n"
    << "linear_solver: {method: direct}\n"
    << "interfaces:\n"
    << "  - {name: contact, facet_sets: [flat_contact, cylinder_contact], pairing: normal,\n"
    << "     law: coulomb_signorini, parameters: {friction_coefficient: 0}}\n"
    << "contact_solver: {type: " << solver << ", tolerance: 1.0e-12}\n"
    << "stages:\n"
    << stages;
  return s.str();
}

/// A stage moving the cylinder's top down by `depth` from the start of the run or the last
/// displacement reset.
std::string press(double depth, int increments, bool reset = false,
                  const std::string& name = "press") {
  std::ostringstream s;
  s << std::setprecision(17) << "  - name: " << name << "\n    increments: " << increments << "\n"
    << "    reset_displacements: " << (reset ? "true" : "false") << "\n"
    << "    boundary_conditions:\n"
    << "      - {set: flat_far, component: x, value: 0}\n"
    << "      - {set: flat_far, component: y, value: 0}\n"
    << "      - {set: symmetry, component: x, value: 0}\n"
    << "      - {set: cylinder_far, component: y, value: " << -depth << "}\n";
  return s.str();
}

struct Pressures {
  std::vector<double> x, p; ///< flat nodes of the interface by increasing x, pressure (kPa)
  double force = 0;         ///< P/2: the interface's vertical resultant on the cylinder (kN/m)
  double reaction = 0;      ///< vertical reaction of the cylinder's top (kN/m)
  std::vector<double> u;
  std::vector<std::vector<double>> history; ///< p after every increment
};

Pressures solve(const std::string& text) {
  const Model model = build_model(read_problem_text(text, "hertz.yaml", bipot::builtin_catalogue()),
                                  bipot::builtin_catalogue());
  StaticAnalysis analysis(model);
  const auto& pairs = model.interfaces.at(0).pairs;
  std::vector<std::size_t> order(pairs.size());
  for (std::size_t i = 0; i < order.size(); ++i)
    order[i] = i;
  const auto x_of = [&](std::size_t i) { return model.mesh.nodes[pairs[i].node_a][0]; };
  std::sort(order.begin(), order.end(),
            [&](std::size_t i, std::size_t j) { return x_of(i) < x_of(j); });
  Pressures out;
  for (std::size_t i : order)
    out.x.push_back(x_of(i));
  analysis.run([&](const StepReport&) {
    const auto& results = analysis.interfaces().at(0)->results();
    out.history.emplace_back();
    for (std::size_t i : order)
      out.history.back().push_back(results[i].r(0));
  });
  out.p = out.history.back();
  out.force = analysis.interfaces().at(0)->resultant()[1];
  out.reaction = analysis.reaction("cylinder_far")[1];
  out.u = analysis.displacement();
  return out;
}

// Top displacement giving a ≈ a_design with these bodies (found by trial; the test computes
// a from the measured load, so it only sets the resolution: about 16 cells across a).
constexpr double depth = 1.2e-3;

/// The Hertz solution of one solver, computed once per process.
const Pressures& hertz(const std::string& solver) {
  static std::map<std::string, Pressures> cache;
  auto it = cache.find(solver);
  if (it == cache.end()) {
    const test::ScratchDir scratch("hertz_" + solver);
    const std::string mesh = (scratch.path / "hertz.msh").string();
    write_mesh(mesh, 20 * a_design, [](double x) { return R - std::sqrt(R * R - x * x); });
    it = cache.emplace(solver, solve(input(mesh, solver, nu, press(depth, 2)))).first;
  }
  return it->second;
}

TEST(Hertz, HalfWidthAndPeakPressureMatchTheClosedForm) {
  const Pressures& res = hertz("semismooth_newton");
  // Equilibrium of the cylinder: its top carries what the interface carries (solver
  // tolerance 1e-12, relative).
  EXPECT_NEAR(-res.reaction, res.force, 1e-8 * res.force);
  const double P = 2 * res.force; // full cylinder, per unit length
  const double a = std::sqrt(4 * P * R / (pi * combined_modulus()));
  const double p0 = 2 * P / (pi * a);
  std::size_t last = 0;
  while (last + 1 < res.p.size() && res.p[last + 1] > 0)
    ++last;
  for (std::size_t i = last + 1; i < res.p.size(); ++i)
    EXPECT_EQ(res.p[i], 0.0) << "x = " << res.x[i]; // one contact zone
  if (mpi_rank() == 0)
    std::printf("[hertz] P = %.6g kN/m, a = %.6g m, last closed node x = %.6g m (h = %.3g), "
                "p0 = %.6g kPa, FE centre pressure %.6g kPa (%+.2f%%)\n",
                P, a, res.x[last], h, p0, res.p[0], 100 * (res.p[0] / p0 - 1));
  // The contact edge lies within one cell (h, the uniform contact-zone size) of a.
  EXPECT_NEAR(res.x[last], a, h);
  // The tolerance; measured +0.07% (see the domain-size note at the top).
  EXPECT_NEAR(res.p[0], p0, 0.03 * p0);
  // The whole profile away from the edge: within 1% of p0, ten times the largest deviation
  // measured there (0.1%); at the edge node the lumped weight smears the root singularity
  // of the slope (measured 0.7% at x = 0.93 a).
  for (std::size_t i = 0; i < res.x.size() && res.x[i] < 0.9 * a; ++i)
    EXPECT_NEAR(res.p[i], p0 * std::sqrt(1 - res.x[i] * res.x[i] / (a * a)), 0.01 * p0)
        << "x = " << res.x[i];
}

// Two solvers' results: displacements (relative L2) and pressures (max, relative to p0) both
// within 1e-8, printed. Both stop at 1e-12 relative; 1e-8 leaves room for the conditioning.
void expect_same_solution(const char* a_name, const char* b_name) {
  const Pressures& a = hertz(a_name);
  const Pressures& b = hertz(b_name);
  const double du = test::relative_difference(a.u, b.u);
  EXPECT_LT(du, 1e-8);
  ASSERT_EQ(a.p.size(), b.p.size());
  double dp = 0;
  for (std::size_t i = 0; i < b.p.size(); ++i)
    dp = std::max(dp, std::abs(a.p[i] - b.p[i]) / b.p[0]);
  EXPECT_LT(dp, 1e-8);
  if (mpi_rank() == 0)
    std::printf("[hertz] %s vs %s: displacements %.2e (relative L2), pressures %.2e p0 (max)\n",
                a_name, b_name, du, dp);
}

TEST(Hertz, UzawaAndNewtonAgree) {
  expect_same_solution("bipotential_uzawa", "semismooth_newton");
}

// The exact generalized Newton at the same tolerance, 1e-12, which the augmented Lagrangian
// reaches only through its round-off floor.
TEST(Hertz, GeneralizedNewtonAgrees) {
  expect_same_solution("generalized_newton", "semismooth_newton");
}

// The 1-rank run (CTest fixture setup) writes its solution; the 2-rank run compares. The
// pairs are evaluated on every rank and assembled by the owner of node a, so any difference
// is round-off in the linear solves: 1e-10 as for the other parallel checks.
TEST(Hertz, OneAndTwoRanksAgree) {
  const Pressures& res = hertz("semismooth_newton");
  std::vector<double> values = res.u;
  values.insert(values.end(), res.p.begin(), res.p.end());
  const auto ref = test::serial_reference("hertz_serial_solution.txt", values);
  if (mpi_size() == 1) return;
  ASSERT_EQ(ref.size(), values.size());
  const std::vector<double> ref_u(ref.begin(), ref.begin() + res.u.size());
  const double du = test::relative_difference(res.u, ref_u);
  EXPECT_LT(du, 1e-10);
  double dp = 0;
  for (std::size_t i = 0; i < res.p.size(); ++i)
    dp = std::max(dp, std::abs(res.p[i] - ref[res.u.size() + i]) / res.p[0]);
  EXPECT_LT(dp, 1e-10);
  if (mpi_rank() == 0)
    std::printf("[hertz] 2 vs 1 ranks: displacements %.2e (relative L2), pressures %.2e p0 "
                "(max)\n",
                du, dp);
}

// A per-pair gap, exactly: two blocks g0 apart (the upper one's bottom lifted uniformly),
// nu = 0 so the stress is uniaxial and uniform. The top moves down by delta: the interface
// stays open (p = 0) while delta < g0, then p = (delta − g0) / (L/E_flat + (L − g0)/E_cyl).
// A displacement reset keeps the pressure (the gap is not counted twice), and holding the
// top afterwards changes nothing.
TEST(NormalPairing, GapClosesAtItsSizeAndSurvivesAReset) {
  const double g0 = 1.0e-3, size = 20 * a_design, delta = 2.4 * g0;
  const test::ScratchDir scratch("hertz_gap");
  const std::string mesh = (scratch.path / "gap.msh").string();
  write_mesh(mesh, size, [g0](double) { return g0; });
  const Pressures res = solve(
      input(mesh, "semismooth_newton", 0.0, press(delta, 3, true) + press(0.0, 1, false, "hold")));
  ASSERT_EQ(res.history.size(), 4u);
  const double compliance = size / E_flat + (size - g0) / E_cylinder;
  for (int k = 0; k < 3; ++k) {
    const double d = delta * (k + 1) / 3; // 0.8 g0 (open), 1.6 g0, 2.4 g0
    const double p = std::max(0.0, d - g0) / compliance;
    // Solver tolerance 1e-12 on the residual; the pressures come out within 4e-9 of the
    // final one (measured), 1e-8 as in the RCCM pull test.
    for (double pk : res.history[k])
      EXPECT_NEAR(pk, p, 1e-8 * (delta - g0) / compliance) << "increment " << k;
  }
  // After the reset the hold stage re-converges the same state (a gap counted twice would
  // move p by g0/compliance, 70% of it).
  for (std::size_t i = 0; i < res.p.size(); ++i)
    EXPECT_NEAR(res.p[i], res.history[2][i], 1e-8 * res.history[2][i]);
  double largest = 0;
  for (double v : res.u)
    largest = std::max(largest, std::abs(v));
  EXPECT_LT(largest, 1e-9 * g0); // nothing moves in the hold stage
}

// The rigid-plane limit (issue 13): the same elastic cylinder pressed on a rigid plane y = 0
// (an obstacle, node to surface), E* = E_cylinder / (1 − ν²). The flat body stays in the mesh
// file, held and unloaded. The same checks and tolerances as above.
TEST(Hertz, RigidPlaneHalfWidthAndPeakPressure) {
  const test::ScratchDir scratch("hertz_rigid_plane");
  const std::string mesh = (scratch.path / "hertz.msh").string();
  write_mesh(mesh, 20 * a_design, [](double x) { return R - std::sqrt(R * R - x * x); });
  std::string text = input(mesh, "generalized_newton", nu, press(1.05e-3, 2));
  const std::string pairs = "  - {name: contact, facet_sets: [flat_contact, cylinder_contact], "
                            "pairing: normal,\n";
  const std::size_t at = text.find(pairs);
  ASSERT_NE(at, std::string::npos);
  text.replace(at, pairs.size(),
               "  - {name: contact, facet_sets: [cylinder_contact],\n"
               "     obstacle: {type: plane, point: [0, 0], normal: [0, 1]},\n");
  const Pressures res = solve(text);
  EXPECT_NEAR(res.reaction, res.force, 1e-8 * std::abs(res.force)); // force on the plane
  const double P = -2 * res.force; // the cylinder pushes the plane down
  const double E_star = E_cylinder / (1 - nu * nu);
  const double a = std::sqrt(4 * P * R / (pi * E_star));
  const double p0 = 2 * P / (pi * a);
  // Pairs sorted by x of the cylinder's nodes; the pressure is p = r_n (compression > 0).
  std::size_t last = 0;
  while (last + 1 < res.p.size() && res.p[last + 1] > 0)
    ++last;
  for (std::size_t i = last + 1; i < res.p.size(); ++i)
    EXPECT_EQ(res.p[i], 0.0) << "x = " << res.x[i];
  if (mpi_rank() == 0)
    std::printf("[hertz] rigid plane: P = %.6g kN/m, a = %.6g m, last closed node x = %.6g m, "
                "p0 = %.6g kPa, FE centre pressure %.6g kPa (%+.2f%%)\n",
                P, a, res.x[last], p0, res.p[0], 100 * (res.p[0] / p0 - 1));
  EXPECT_NEAR(res.x[last], a, h);
  EXPECT_NEAR(res.p[0], p0, 0.03 * p0);
  for (std::size_t i = 0; i < res.x.size() && res.x[i] < 0.9 * a; ++i)
    EXPECT_NEAR(res.p[i], p0 * std::sqrt(1 - res.x[i] * res.x[i] / (a * a)), 0.01 * p0)
        << "x = " << res.x[i];
}

TEST(NormalPairing, OnlyForFacetSetsAndTwoValues) {
  const std::string base =
      "kinematics: plane_strain\n"
      "mesh:\n  blocks:\n    cell: quad4\n"
      "    x: {breaks: [0, 1.0], cells: [2]}\n"
      "    y: {breaks: [-0.5, 0, 0.5], cells: [1, 1]}\n"
      "    regions: [base, block]\n"
      "materials:\n"
      "  base: {type: linear_elastic, youngs_modulus: 1.0e5, poissons_ratio: 0.3}\n"
      "  block: {type: linear_elastic, youngs_modulus: 1.0e5, poissons_ratio: 0.3}\n"
      "interfaces:\n  - name: joint\n";
  const std::string law = "    law: coulomb_signorini\n";
  const auto message = [](const std::string& text) -> std::string {
    try {
      read_problem_text(text, "pairing.yaml", bipot::builtin_catalogue());
    } catch (const InputError& e) {
      return e.what();
    }
    return "no error";
  };
  const std::string between =
      message(base + "    between: [base, block]\n" + law + "    pairing: normal\n");
  EXPECT_NE(between.find("pairing.yaml:15:14: interfaces[0].pairing: only facet_sets interfaces "
                         "are paired this way"),
            std::string::npos)
      << between;
  const std::string unknown =
      message(base + "    facet_sets: [top, bottom]\n" + law + "    pairing: sideways\n");
  EXPECT_NE(unknown.find("interfaces[0].pairing: unknown pairing 'sideways'; expected coincident "
                         "or normal"),
            std::string::npos)
      << unknown;
}

} // namespace
} // namespace bipot
