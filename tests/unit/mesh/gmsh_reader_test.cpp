#include "fem/gmsh/gmsh_reader.hpp"

#include "fem/core/error.hpp"
#include "fem/mesh/cell_facets.hpp"
#include "mesh_test_utils.hpp"

#include "tests/support/scratch_dir.hpp"
#include <gmsh.h>

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <functional>
#include <set>
#include <unistd.h>

namespace bipot {
namespace {

namespace fs = std::filesystem;

const std::string kGeo = std::string(BIPOT_SOURCE_DIR) + "/inputs/meshes/square_with_regions.geo";
const std::string kMsh = std::string(BIPOT_SOURCE_DIR) + "/inputs/meshes/square_with_regions.msh";

using Scratch = test::ScratchDir;

/// Runs `build` in a Gmsh session of the test's own and writes the mesh to `out`.
void gmsh_write(const std::function<void()>& build, const fs::path& out) {
  gmsh::initialize(0, nullptr, false);
  gmsh::option::setNumber("General.Terminal", 0);
  build();
  gmsh::write(out.string());
  gmsh::finalize();
}

std::string input_error(const std::string& path) {
  try {
    read_gmsh(path);
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

double region_area(const Mesh& m, const std::string& region) {
  double a = 0.0;
  for (Index c = 0; c < m.num_cells(); ++c)
    if (m.cell_regions[c] == m.regions.at(region)) a += test::cell_measure(m, c);
  return a;
}

TEST(GmshReader, ShippedMeshRegionsAndSets) {
  const Mesh m = read_gmsh(kMsh);
  EXPECT_EQ(m.dim, 2);
  EXPECT_EQ(m.regions.size(), 2u);
  EXPECT_EQ(m.regions.count("left_part"), 1u);
  EXPECT_EQ(m.regions.count("right_part"), 1u);
  for (const char* name : {"left", "right", "bottom", "top", "middle"}) {
    EXPECT_FALSE(m.facet_sets.at(name).empty()) << name;
    EXPECT_EQ(m.node_sets.at(name), m.facet_set_nodes(name)) << name;
  }
  ASSERT_EQ(m.node_sets.at("origin").size(), 1u); // the physical point
  const auto& origin = m.nodes[m.node_sets.at("origin")[0]];
  EXPECT_EQ(origin[0], 0.0);
  EXPECT_EQ(origin[1], 0.0);
  // The .geo meshes the left part with triangles and recombines the right part into quads.
  for (Index c = 0; c < m.num_cells(); ++c)
    EXPECT_EQ(m.cell_types[c],
              m.cell_regions[c] == m.regions.at("left_part") ? CellType::Tri3 : CellType::Quad4);
  // Compact numbering: every node is used by a cell.
  std::vector<char> used(m.num_nodes(), 0);
  for (Index n : m.cell_nodes)
    used[n] = 1;
  EXPECT_EQ(std::count(used.begin(), used.end(), 0), 0);
  EXPECT_NO_THROW(m.check_consistency());
}

TEST(GmshReader, ShippedMeshAreasAndOrientation) {
  const Mesh m = read_gmsh(kMsh);
  // Exact geometry (straight edges of a unit square split at 0.5): round-off only.
  EXPECT_NEAR(region_area(m, "left_part") + region_area(m, "right_part"), 1.0, 1e-12);
  EXPECT_NEAR(region_area(m, "left_part"), 0.5, 1e-12);
  EXPECT_NEAR(region_area(m, "right_part"), 0.5, 1e-12);
  for (Index c = 0; c < m.num_cells(); ++c)
    EXPECT_TRUE(test::positively_oriented(m, c)) << "cell " << c;
}

TEST(GmshReader, ShippedFileHasClockwiseQuadsToReorient) {
  // Guards the orientation test above: the file itself stores the right part clockwise.
  gmsh::initialize(0, nullptr, false);
  gmsh::option::setNumber("General.Terminal", 0);
  gmsh::open(kMsh);
  std::vector<int> types;
  std::vector<std::vector<std::size_t>> tags, nodes;
  gmsh::model::mesh::getElements(types, tags, nodes, 2, 2);
  ASSERT_EQ(types, std::vector<int>{3});
  std::vector<double> x(4), y(4), xyz, uvw;
  for (int a = 0; a < 4; ++a) {
    gmsh::model::mesh::getNode(nodes[0][a], xyz, uvw);
    x[a] = xyz[0];
    y[a] = xyz[1];
  }
  gmsh::finalize();
  double s = 0.0;
  for (int a = 0; a < 4; ++a)
    s += x[a] * y[(a + 1) % 4] - x[(a + 1) % 4] * y[a];
  EXPECT_LT(s, 0.0);
}

TEST(GmshReader, ShippedFacetSetsOutwardAndInterfaceShared) {
  const Mesh m = read_gmsh(kMsh);
  const std::map<std::string, std::array<double, 2>> normals = {
      {"left", {-1, 0}},
      {"right", {1, 0}},
      {"bottom", {0, -1}},
      {"top", {0, 1}},
      {"middle", {1, 0}}}; // middle: outward of left_part, the region with the smaller id
  for (const auto& [name, normal] : normals) {
    double length = 0.0;
    for (const Facet& f : m.facet_sets.at(name)) {
      ASSERT_GE(f.cell, 0);
      const auto cn = test::cell_node_list(m, f.cell);
      for (Index n : f.nodes)
        EXPECT_NE(std::find(cn.begin(), cn.end(), n), cn.end());
      const auto n = facet_normal(m, f);
      EXPECT_NEAR(n[0], normal[0], 1e-14) << name; // straight axis-parallel edges
      EXPECT_NEAR(n[1], normal[1], 1e-14) << name;
      const auto& p = m.nodes[f.nodes[0]];
      const auto& q = m.nodes[f.nodes[1]];
      length += std::hypot(q[0] - p[0], q[1] - p[1]);
    }
    EXPECT_NEAR(length, 1.0, 1e-12) << name; // every side (and the middle) has length 1
  }
  for (const Facet& f : m.facet_sets.at("middle"))
    EXPECT_EQ(m.cell_regions[f.cell], m.regions.at("left_part"));

  // The interface nodes belong to cells of both regions (conforming, not duplicated).
  const int left = m.regions.at("left_part"), right = m.regions.at("right_part");
  for (Index n : m.node_sets.at("middle")) {
    EXPECT_NEAR(m.nodes[n][0], 0.5, 1e-15);
    bool in_left = false, in_right = false;
    for (Index c = 0; c < m.num_cells(); ++c) {
      const auto cn = test::cell_node_list(m, c);
      if (std::find(cn.begin(), cn.end(), n) == cn.end()) continue;
      in_left |= m.cell_regions[c] == left;
      in_right |= m.cell_regions[c] == right;
    }
    EXPECT_TRUE(in_left && in_right) << "node " << n;
  }
  EXPECT_EQ(region_interface_facets(m, left, right).size(), m.facet_sets.at("middle").size());
}

TEST(GmshReader, SecondOrderIncompleteMesh) {
  const Scratch scratch("gmsh");
  const fs::path out = scratch.path / "order2.msh";
  gmsh_write(
      [] {
        gmsh::open(kGeo);
        gmsh::option::setNumber("Mesh.ElementOrder", 2);
        gmsh::option::setNumber("Mesh.SecondOrderIncomplete", 1); // Quad8, not Quad9
        gmsh::model::mesh::generate(2);
      },
      out);
  const Mesh m = read_gmsh(out.string());
  std::set<CellType> types(m.cell_types.begin(), m.cell_types.end());
  EXPECT_EQ(types, (std::set<CellType>{CellType::Tri6, CellType::Quad8}));
  EXPECT_NEAR(region_area(m, "left_part"), 0.5, 1e-12);
  EXPECT_NEAR(region_area(m, "right_part"), 0.5, 1e-12);
  for (Index c = 0; c < m.num_cells(); ++c) {
    EXPECT_TRUE(test::positively_oriented(m, c));
    // Mid-nodes sit at the middle of their edge after re-ordering: straight edges, so Gmsh
    // places them at the midpoint up to round-off.
    const int nc = num_corners(m.cell_types[c]);
    for (int e = 0; e < nc; ++e)
      for (int k = 0; k < 2; ++k)
        EXPECT_NEAR(m.nodes[m.cell(c)[nc + e]][k],
                    0.5 * (m.nodes[m.cell(c)[e]][k] + m.nodes[m.cell(c)[(e + 1) % nc]][k]), 1e-12);
  }
  for (const Facet& f : m.facet_sets.at("top")) {
    EXPECT_EQ(f.type, CellType::Line3);
    EXPECT_NEAR(facet_normal(m, f)[1], 1.0, 1e-14);
  }
}

TEST(GmshReader, TetrahedralBox) {
  const Scratch scratch("gmsh");
  const fs::path out = scratch.path / "box.msh";
  gmsh_write(
      [] {
        gmsh::model::occ::addBox(0, 0, 0, 1, 1, 1);
        gmsh::model::occ::synchronize();
        gmsh::vectorpair faces;
        gmsh::model::getEntities(faces, 2);
        std::vector<int> face_tags;
        for (const auto& f : faces)
          face_tags.push_back(f.second);
        gmsh::model::setPhysicalName(3, gmsh::model::addPhysicalGroup(3, {1}), "solid");
        gmsh::model::setPhysicalName(2, gmsh::model::addPhysicalGroup(2, face_tags), "skin");
        gmsh::option::setNumber("Mesh.MeshSizeMax", 0.4);
        gmsh::model::mesh::generate(3);
      },
      out);
  const Mesh m = read_gmsh(out.string());
  EXPECT_EQ(m.dim, 3);
  double volume = 0.0;
  for (Index c = 0; c < m.num_cells(); ++c) {
    ASSERT_EQ(m.cell_types[c], CellType::Tet4);
    EXPECT_TRUE(test::positively_oriented(m, c));
    volume += test::cell_measure(m, c);
  }
  EXPECT_NEAR(volume, 1.0, 1e-12); // unit cube, flat faces: round-off only
  double area = 0.0;
  for (const Facet& f : m.facet_sets.at("skin")) {
    const auto n = facet_normal(m, f);
    const auto xf = test::centroid(m, f.nodes);
    double out_dot = 0.0;
    for (int k = 0; k < 3; ++k)
      out_dot += n[k] * (xf[k] - 0.5); // convex: outward from centre
    EXPECT_GT(out_dot, 0.0);
    const auto& a = m.nodes[f.nodes[0]];
    const auto& b = m.nodes[f.nodes[1]];
    const auto& c = m.nodes[f.nodes[2]];
    const double u[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
    const double v[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
    area += 0.5 * std::sqrt(std::pow(u[1] * v[2] - u[2] * v[1], 2) +
                            std::pow(u[2] * v[0] - u[0] * v[2], 2) +
                            std::pow(u[0] * v[1] - u[1] * v[0], 2));
  }
  EXPECT_NEAR(area, 6.0, 1e-12);
  EXPECT_EQ(boundary_facets(m).size(), m.facet_sets.at("skin").size());
}

TEST(GmshReader, UnsupportedElementTypeNamesFileAndType) {
  const Scratch scratch("gmsh");
  const fs::path out = scratch.path / "quad9.msh";
  gmsh_write(
      [] {
        gmsh::open(kGeo);
        gmsh::option::setNumber("Mesh.ElementOrder", 2); // complete: Quad9
        gmsh::model::mesh::generate(2);
      },
      out);
  const std::string msg = input_error(out.string());
  EXPECT_NE(msg.find(out.string()), std::string::npos) << msg;
  EXPECT_NE(msg.find("'right_part' contains elements of type 'Quadrilateral 9' (Gmsh type 10)"),
            std::string::npos)
      << msg;
}

TEST(GmshReader, MissingFileAndOldFormat) {
  const std::string missing = "/nonexistent/dir/no_such_mesh.msh";
  EXPECT_EQ(input_error(missing),
            missing + ": cannot open the Gmsh mesh file (missing or unreadable)");
  const Scratch scratch("gmsh");
  const fs::path old = scratch.path / "v22.msh";
  gmsh_write(
      [] {
        gmsh::open(kGeo);
        gmsh::model::mesh::generate(2);
        gmsh::option::setNumber("Mesh.MshFileVersion", 2.2);
      },
      old);
  EXPECT_EQ(
      input_error(old.string()),
      old.string() +
          ":2: MSH format version 2.2 is not supported; re-export it with 'gmsh -format msh4'");
  EXPECT_NE(input_error(kGeo).find("not a Gmsh MSH file"), std::string::npos);
}

} // namespace
} // namespace bipot
