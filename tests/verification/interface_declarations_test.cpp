// Every way of declaring an interface × every interface law, on one closed-form problem: two
// unit squares stacked (ν = 0, plane strain, so each is a bar in uniaxial stress), the base's
// bottom fixed, the top of the upper square pulled up or pushed down by δ. The interface is
//   - `between: [base, block]` on a mesh whose squares share their nodes (split by bipot),
//   - `facet_sets: [base_top, block_bottom]` on separately meshed squares (coincident pairs),
//   - the same facet sets with `pairing: normal`.
// The stress σ (top reaction per unit width) is, with E the Young's modulus of both squares:
//   perfect_bonding               E δ / 2 in tension and compression (one bar of length 2);
//   rccm (sound, w never reached) δ / (2/E + 1/C_n) in tension (the joint a spring in series),
//                                 E δ / 2 in compression (unilateral contact is rigid);
//   coulomb_signorini             0 in tension (the joint opens), E δ / 2 in compression.
// A direct solver and homogeneous fields: the only error is rounding, hence 1e-9.
// (Regression: perfect_bonding on facet sets used to glue nothing: reaction 1.6e-14.)
#include "apps/catalogue/builtin_catalogue.hpp"
#include "fem/analysis/model.hpp"
#include "fem/analysis/static_analysis.hpp"
#include "fem/core/error.hpp"
#include "fem/input/problem_reader.hpp"

#include "tests/support/scratch_dir.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace bipot {
namespace {

constexpr double E = 1.0e4;   // kPa, both squares
constexpr double C_n = 1.0e4; // kN/m³, the RCCM joint
constexpr int n = 3;          // cells per side of each square

// Writes the two squares as a Gmsh MSH 4.1 file: regions base (y ∈ [0, 1]) and block
// (y ∈ [1, 2], raised by `lift`); facet sets bottom, top and, for separate squares, base_top
// and block_bottom.
void write_mesh(const std::string& path, bool shared, double lift = 0) {
  const int row = n + 1;
  // Node tags: base (n+1)² from 1; the block's own rows follow (all n+1 of them if separate).
  auto base = [&](int i, int j) { return 1 + j * row + i; };
  const int block_first = 1 + row * row - (shared ? row : 0);
  auto block = [&](int i, int j) { return block_first + j * row + i; };
  std::ostringstream nodes, elements;
  const int num_nodes = row * row + row * (shared ? n : row);
  nodes << "2 1 0 " << num_nodes << "\n";
  for (int t = 1; t <= num_nodes; ++t)
    nodes << t << "\n";
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i)
      nodes << double(i) / n << " " << double(j) / n << " 0\n";
  for (int j = shared ? 1 : 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i)
      nodes << double(i) / n << " " << 1.0 + lift + double(j) / n << " 0\n";
  int tag = 1, blocks = 0, count = 0;
  auto quads = [&](int surface, auto node) {
    elements << "2 " << surface << " 3 " << n * n << "\n";
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i)
        elements << tag++ << " " << node(i, j) << " " << node(i + 1, j) << " " << node(i + 1, j + 1)
                 << " " << node(i, j + 1) << "\n";
    ++blocks, count += n * n;
  };
  auto lines = [&](int curve, auto node, int j) {
    elements << "1 " << curve << " 1 " << n << "\n";
    for (int i = 0; i < n; ++i)
      elements << tag++ << " " << node(i, j) << " " << node(i + 1, j) << "\n";
    ++blocks, count += n;
  };
  quads(1, base);
  quads(2, block);
  lines(1, base, 0);
  lines(2, block, n);
  if (!shared) {
    lines(3, base, n);
    lines(4, block, 0);
  }
  const int curves = shared ? 2 : 4;
  std::ofstream out(path);
  out << "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n$PhysicalNames\n"
      << curves + 2 << "\n"
      << "1 1 \"bottom\"\n1 2 \"top\"\n";
  if (!shared) out << "1 3 \"base_top\"\n1 4 \"block_bottom\"\n";
  out << "2 5 \"base\"\n2 6 \"block\"\n$EndPhysicalNames\n$Entities\n0 " << curves << " 2 0\n"
      << "1 0 0 0 1 0 0 1 1 0\n2 0 2 0 1 2 0 1 2 0\n";
  if (!shared) out << "3 0 1 0 1 1 0 1 3 0\n4 0 1 0 1 1 0 1 4 0\n";
  out << "1 0 0 0 1 1 0 1 5 0\n2 0 1 0 1 2 0 1 6 0\n$EndEntities\n"
      << "$Nodes\n1 " << num_nodes << " 1 " << num_nodes << "\n"
      << nodes.str() << "$EndNodes\n"
      << "$Elements\n"
      << blocks << " " << count << " 1 " << tag - 1 << "\n"
      << elements.str() << "$EndElements\n";
}

struct Declaration {
  const char* name;
  bool shared_nodes;
  const char* keys;
};
const Declaration declarations[] = {
    {"between", true, "between: [base, block]"},
    {"facet_sets", false, "facet_sets: [base_top, block_bottom]"},
    {"facet_sets_normal", false, "facet_sets: [base_top, block_bottom], pairing: normal"},
};

struct Law {
  const char* name;
  const char* yaml;
  double tension; ///< σ / δ in tension
};
const Law laws[] = {
    {"perfect_bonding", "law: perfect_bonding", E / 2},
    {"rccm",
     "law: rccm, parameters: {normal_stiffness: 1.0e4, tangential_stiffness: 1.0e4, "
     "decohesion_energy: 1.0e3, friction_coefficient: 0.5}",
     1.0 / (2.0 / E + 1.0 / C_n)},
    {"coulomb_signorini", "law: coulomb_signorini, parameters: {friction_coefficient: 0.5}", 0.0},
};

double top_reaction(const std::string& mesh, const Declaration& d, const Law& law, double delta) {
  std::ostringstream s;
  s << "kinematics: plane_strain\nmesh: {file: " << mesh << "}\nmaterials:\n"
    << "  base: {type: linear_elastic, youngs_modulus: " << E << ", poissons_ratio: 0.0}\n"
    << "  block: {type: linear_elastic, youngs_modulus: " << E << ", poissons_ratio: 0.0}\n"
    << "linear_solver: {method: direct}\n"
    << "interfaces:\n  - {name: joint, " << d.keys << ", " << law.yaml << "}\n"
    << "contact_solver: {type: generalized_newton, tolerance: 1.0e-12}\n"
    << "stages:\n  - name: load\n    boundary_conditions:\n"
    << "      - {set: bottom, component: x, value: 0}\n"
    << "      - {set: bottom, component: y, value: 0}\n"
    << "      - {set: top, component: x, value: 0}\n"
    << "      - {set: top, component: y, value: " << delta << "}\n";
  const Model model =
      build_model(read_problem_text(s.str(), "declarations.yaml", bipot::builtin_catalogue()),
                  bipot::builtin_catalogue());
  StaticAnalysis analysis(model);
  analysis.run();
  return analysis.reaction("top")[1];
}

TEST(InterfaceDeclarations, EveryWayTimesEveryLawMatchesTheBarInSeries) {
  test::ScratchDir dir("declarations");
  const std::string shared = (dir.path / "shared.msh").string();
  const std::string separate = (dir.path / "separate.msh").string();
  write_mesh(shared, true);
  write_mesh(separate, false);
  const double delta = 1.0e-3;
  for (const Declaration& d : declarations)
    for (const Law& law : laws) {
      const std::string& mesh = d.shared_nodes ? shared : separate;
      const double pull = top_reaction(mesh, d, law, delta);
      const double push = top_reaction(mesh, d, law, -delta);
      const double scale = E * delta / 2;
      EXPECT_NEAR(pull, law.tension * delta, 1e-9 * scale) << d.name << " × " << law.name;
      EXPECT_NEAR(push, -E * delta / 2, 1e-9 * scale) << d.name << " × " << law.name;
    }
}

// Gluing moves no node: perfect bonding of facet sets paired across a gap is refused, naming
// the interface and the gap.
TEST(InterfaceDeclarations, PerfectBondingAcrossAGapIsRefused) {
  test::ScratchDir dir("declarations");
  const std::string path = (dir.path / "gap.msh").string();
  write_mesh(path, false, 1.0e-3);
  try {
    top_reaction(path, declarations[2], laws[0], 1.0e-3);
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("interface 'joint': perfect bonding joins coincident nodes"),
              std::string::npos)
        << what;
    EXPECT_NE(what.find("0.001 apart along the normal"), std::string::npos) << what;
  }
}

} // namespace
} // namespace bipot
