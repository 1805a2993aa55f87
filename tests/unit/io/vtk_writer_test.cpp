#include "fem/io/vtk_writer.hpp"

#include "fem/core/error.hpp"
#include "fem/mesh/structured_mesh.hpp"

#include <vtkCellData.h>
#include <vtkCellType.h>
#include <vtkDataArray.h>
#include <vtkIdList.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLDataElement.h>
#include <vtkXMLDataParser.h>
#include <vtkXMLPUnstructuredGridReader.h>
#include <vtkXMLUnstructuredGridReader.h>

#include "tests/support/scratch_dir.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>
#include <unistd.h>

namespace bipot {
namespace {

namespace fs = std::filesystem;

using Scratch = test::ScratchDir;

std::string read_text(const fs::path& p) {
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

std::size_t count_of(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (auto pos = text.find(what); pos != std::string::npos; pos = text.find(what, pos + 1))
    ++n;
  return n;
}

/// Closed-form displacement-like field, scaled by the step's time.
std::array<double, 2> u_of(const std::array<double, 3>& x, double t) {
  return {t * (x[0] + 2.0 * x[1]), t * (3.0 * x[0] - x[1])};
}

Field point_vector(const Mesh& m, double t) {
  Field f{"u", 2, {}};
  for (const auto& x : m.nodes) {
    const auto u = u_of(x, t);
    f.values.insert(f.values.end(), u.begin(), u.end());
  }
  return f;
}

/// Cell scalar "s" = 10 c + t and cell 2-vector "q" = (c, -c) for the listed cells.
std::vector<Field> cell_fields(const std::vector<Index>& cells, double t) {
  Field s{"s", 1, {}}, q{"q", 2, {}};
  for (Index c : cells) {
    s.values.push_back(10.0 * double(c) + t);
    q.values.insert(q.values.end(), {double(c), -double(c)});
  }
  return {s, q};
}

vtkSmartPointer<vtkUnstructuredGrid> read_vtu(const fs::path& p) {
  vtkNew<vtkXMLUnstructuredGridReader> r;
  r->SetFileName(p.string().c_str());
  r->Update();
  return r->GetOutput();
}

TEST(VtkSeriesWriter, TwoStepsReadBackExactly) {
  const Scratch scratch("vtk");
  const fs::path dir = scratch.path / "nested" / "out"; // parents are created too
  const Mesh m = make_rectangle(0.0, 2.0, 2, 0.0, 1.0, 1, CellType::Tri6);
  std::vector<Index> all(m.num_cells());
  for (Index c = 0; c < m.num_cells(); ++c)
    all[c] = c;
  VtkSeriesWriter w(dir.string(), "sol", 0, 1);
  const double times[2] = {0.5, 1.0};
  for (double t : times)
    w.write_step(t, m, all, {point_vector(m, t)}, cell_fields(all, t));
  EXPECT_EQ(w.num_steps(), 2);

  for (int step = 0; step < 2; ++step) {
    const double t = times[step];
    const auto g = read_vtu(dir / w.piece_name(step, 0));
    ASSERT_EQ(g->GetNumberOfPoints(), m.num_nodes());
    ASSERT_EQ(g->GetNumberOfCells(), m.num_cells());
    vtkDataArray* u = g->GetPointData()->GetArray("u");
    ASSERT_NE(u, nullptr);
    ASSERT_EQ(u->GetNumberOfComponents(), 3); // 2D vectors padded for ParaView
    // Float64 written raw: the round trip is exact, 1e-14 only forgives nothing but noise.
    for (Index i = 0; i < m.num_nodes(); ++i) {
      double x[3];
      g->GetPoint(i, x);
      for (int k = 0; k < 3; ++k)
        EXPECT_NEAR(x[k], m.nodes[i][k], 1e-14);
      const auto ue = u_of(m.nodes[i], t);
      EXPECT_NEAR(u->GetComponent(i, 0), ue[0], 1e-14);
      EXPECT_NEAR(u->GetComponent(i, 1), ue[1], 1e-14);
      EXPECT_EQ(u->GetComponent(i, 2), 0.0);
    }
    vtkDataArray* s = g->GetCellData()->GetArray("s");
    vtkDataArray* q = g->GetCellData()->GetArray("q");
    vtkDataArray* region = g->GetCellData()->GetArray("region");
    ASSERT_TRUE(s && q && region);
    EXPECT_EQ(q->GetNumberOfComponents(), 3);
    vtkNew<vtkIdList> ids;
    for (Index c = 0; c < m.num_cells(); ++c) {
      EXPECT_EQ(g->GetCellType(c), VTK_QUADRATIC_TRIANGLE);
      EXPECT_NEAR(s->GetComponent(c, 0), 10.0 * double(c) + t, 1e-14);
      EXPECT_EQ(q->GetComponent(c, 0), double(c));
      EXPECT_EQ(q->GetComponent(c, 1), -double(c));
      EXPECT_EQ(region->GetComponent(c, 0), m.cell_regions[c]);
      g->GetCellPoints(c, ids);
      ASSERT_EQ(ids->GetNumberOfIds(), 6);
      for (int a = 0; a < 6; ++a) { // same node order as the mesh (Gmsh = VTK ordering)
        double x[3];
        g->GetPoint(ids->GetId(a), x);
        EXPECT_EQ(x[0], m.nodes[m.cell(c)[a]][0]);
        EXPECT_EQ(x[1], m.nodes[m.cell(c)[a]][1]);
      }
    }
  }

  const std::string pvd = read_text(w.pvd_path());
  EXPECT_EQ(count_of(pvd, "<DataSet "), 2u);
  EXPECT_NE(pvd.find("timestep=\"0.5\" part=\"0\" file=\"sol_0000_0.vtu\""), std::string::npos);
  EXPECT_NE(pvd.find("timestep=\"1\" part=\"0\" file=\"sol_0001_0.vtu\""), std::string::npos);
  EXPECT_FALSE(fs::exists(w.pvd_path() + ".tmp"));
  EXPECT_FALSE(fs::exists(dir / "sol_0000.pvtu")); // one rank: no .pvtu

  vtkNew<vtkXMLDataParser> parser;
  parser->SetFileName(w.pvd_path().c_str());
  ASSERT_EQ(parser->Parse(), 1);
  vtkXMLDataElement* root = parser->GetRootElement();
  ASSERT_NE(root, nullptr);
  EXPECT_STREQ(root->GetName(), "VTKFile");
  EXPECT_STREQ(root->GetAttribute("type"), "Collection");
  vtkXMLDataElement* collection = root->FindNestedElementWithName("Collection");
  ASSERT_NE(collection, nullptr);
  ASSERT_EQ(collection->GetNumberOfNestedElements(), 2);
  for (int step = 0; step < 2; ++step) {
    double t = -1.0;
    collection->GetNestedElement(step)->GetScalarAttribute("timestep", t);
    EXPECT_EQ(t, times[step]);
    EXPECT_EQ(std::string(collection->GetNestedElement(step)->GetAttribute("file")),
              w.piece_name(step, 0));
  }
}

TEST(VtkSeriesWriter, PvdListsEveryCompletedStep) {
  const Scratch scratch("vtk");
  const fs::path dir = scratch.path;
  const Mesh m = make_rectangle(0.0, 1.0, 1, 0.0, 1.0, 1, CellType::Quad4);
  VtkSeriesWriter w(dir.string(), "run", 0, 1);
  w.write_step(0.25, m, {0}, {}, {});
  EXPECT_EQ(count_of(read_text(w.pvd_path()), "<DataSet "), 1u);
  w.write_step(0.5, m, {0}, {}, {});
  EXPECT_EQ(count_of(read_text(w.pvd_path()), "<DataSet "), 2u);
  EXPECT_EQ(read_vtu(dir / w.piece_name(1, 0))->GetCellType(0), VTK_QUAD);
}

TEST(VtkSeriesWriter, ThreeDimensionalKeepsComponents) {
  const Scratch scratch("vtk");
  const fs::path dir = scratch.path;
  const Mesh m = make_box(0, 1, 1, 0, 2, 1, 0, 3, 1, CellType::Hex8);
  VtkSeriesWriter w(dir.string(), "box", 0, 1);
  Field v{"v", 3, {}}, p{"pair", 2, {}};
  for (const auto& x : m.nodes) {
    v.values.insert(v.values.end(), {x[2], x[0], x[1]});
    p.values.insert(p.values.end(), {x[0], -x[2]});
  }
  w.write_step(0.0, m, {0}, {v, p}, {});
  const auto g = read_vtu(dir / w.piece_name(0, 0));
  EXPECT_EQ(g->GetCellType(0), VTK_HEXAHEDRON);
  EXPECT_EQ(g->GetPointData()->GetArray("pair")->GetNumberOfComponents(), 2); // 3D: no padding
  for (Index i = 0; i < m.num_nodes(); ++i) {
    double x[3];
    g->GetPoint(i, x);
    EXPECT_EQ(x[2], m.nodes[i][2]); // z kept in 3D
    EXPECT_EQ(g->GetPointData()->GetArray("v")->GetComponent(i, 0), m.nodes[i][2]);
  }
}

TEST(VtkSeriesWriter, TwoRanksWritePvtuReferencingBothPieces) {
  // Serial simulation of a 2-rank run: two writers, rank 1 first (as if it were faster).
  const Scratch scratch("vtk");
  const fs::path dir = scratch.path;
  const Mesh m = make_rectangle(0.0, 3.0, 3, 0.0, 1.0, 2, CellType::Quad4);
  const std::vector<Index> cells[2] = {{0, 1, 2}, {3, 4, 5}}; // bottom row, top row
  VtkSeriesWriter w0(dir.string(), "sol", 0, 2), w1(dir.string(), "sol", 1, 2);
  w1.write_step(1.0, m, cells[1], {point_vector(m, 1.0)}, cell_fields(cells[1], 1.0));
  EXPECT_FALSE(fs::exists(w1.pvd_path())); // only rank 0 writes the collection
  w0.write_step(1.0, m, cells[0], {point_vector(m, 1.0)}, cell_fields(cells[0], 1.0));

  // Each piece holds only its cells' nodes: 2 rows of 4 nodes.
  const auto piece1 = read_vtu(dir / "sol_0000_1.vtu");
  ASSERT_EQ(piece1->GetNumberOfPoints(), 8);
  for (vtkIdType i = 0; i < 8; ++i)
    EXPECT_GE(piece1->GetPoint(i)[1], 0.5);

  const std::string pvtu = read_text(dir / "sol_0000.pvtu");
  EXPECT_NE(pvtu.find("<Piece Source=\"sol_0000_0.vtu\"/>"), std::string::npos);
  EXPECT_NE(pvtu.find("<Piece Source=\"sol_0000_1.vtu\"/>"), std::string::npos);
  EXPECT_NE(read_text(w0.pvd_path()).find("file=\"sol_0000.pvtu\""), std::string::npos);

  vtkNew<vtkXMLPUnstructuredGridReader> r;
  r->SetFileName((dir / "sol_0000.pvtu").string().c_str());
  r->Update();
  vtkUnstructuredGrid* g = r->GetOutput();
  ASSERT_EQ(g->GetNumberOfCells(), 6);
  ASSERT_EQ(g->GetNumberOfPoints(), 16); // the 4 nodes on y = 0.5 appear in both pieces
  vtkDataArray* u = g->GetPointData()->GetArray("u");
  ASSERT_NE(u, nullptr);
  for (vtkIdType i = 0; i < 16; ++i) {
    double x[3];
    g->GetPoint(i, x);
    const auto ue = u_of({x[0], x[1], x[2]}, 1.0);
    EXPECT_NEAR(u->GetComponent(i, 0), ue[0], 1e-14); // exact round trip, see above
    EXPECT_NEAR(u->GetComponent(i, 1), ue[1], 1e-14);
  }
  vtkDataArray* s = g->GetCellData()->GetArray("s");
  ASSERT_NE(s, nullptr);
  double sum = 0.0;
  for (vtkIdType c = 0; c < 6; ++c)
    sum += s->GetComponent(c, 0);
  EXPECT_EQ(sum, 10.0 * (0 + 1 + 2 + 3 + 4 + 5) + 6.0); // every cell once
}

std::string error_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const Error& e) {
    return e.what();
  }
  return "no error";
}

TEST(VtkSeriesWriter, BadArgumentsAreErrors) {
  const Scratch scratch("vtk");
  const fs::path dir = scratch.path;
  const Mesh m = make_rectangle(0.0, 1.0, 1, 0.0, 1.0, 1, CellType::Quad4);
  VtkSeriesWriter w(dir.string(), "x", 0, 1);
  EXPECT_EQ(error_of([&] {
              w.write_step(0, m, {0}, {Field{"u", 2, {1.0, 2.0}}}, {});
            }),
            "VtkSeriesWriter: point field 'u' has 2 values, expected 2 x 4 points");
  EXPECT_EQ(error_of([&] {
              w.write_step(0, m, {0}, {}, {Field{"region", 1, {1.0}}});
            }),
            "VtkSeriesWriter: cell field 'region': the name is reserved for the region ids");
  EXPECT_EQ(error_of([&] { w.write_step(0, m, {7}, {}, {}); }),
            "VtkSeriesWriter: cell id 7 is not in the mesh");
  EXPECT_EQ(w.num_steps(), 0);
  EXPECT_EQ(error_of([&] { VtkSeriesWriter(dir.string(), "x", 2, 2); }),
            "VtkSeriesWriter: invalid rank 2 of size 2");
  // A regular file in the way of the directory.
  std::ofstream(dir / "file").put('x');
  EXPECT_NE(error_of([&] {
              VtkSeriesWriter((dir / "file" / "sub").string(), "x", 0, 1);
            }).find("cannot create directory '" + (dir / "file" / "sub").string() + "'"),
            std::string::npos);
}

} // namespace
} // namespace bipot
