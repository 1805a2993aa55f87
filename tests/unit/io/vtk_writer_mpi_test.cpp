// VtkSeriesWriter under mpiexec: every rank writes its piece, rank 0 the .pvtu and .pvd; after
// the caller's barrier the whole step reads back through the .pvtu.
#include "fem/io/vtk_writer.hpp"

#include "fem/linalg/communicator.hpp"
#include "fem/mesh/structured_mesh.hpp"

#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLPUnstructuredGridReader.h>
#include <vtkXMLUnstructuredGridReader.h>

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <unistd.h>

namespace bipot {
namespace {

namespace fs = std::filesystem;

TEST(VtkSeriesWriterMpi, EveryRankWritesItsPiece) {
  const int rank = mpi_rank(), size = mpi_size();
  std::string dir =
      (fs::temp_directory_path() / ("bipot_vtk_mpi_" + std::to_string(getpid()))).string();
  broadcast(dir, 0); // one directory for all ranks, named after rank 0's process
  if (rank == 0) fs::remove_all(dir);
  barrier();

  // Two columns of cells per rank; rank r owns the cells with x in [r, r + 1].
  const Mesh m = make_rectangle(0.0, double(size), 2 * size, 0.0, 1.0, 2, CellType::Quad4);
  std::vector<Index> mine;
  for (Index c = 0; c < m.num_cells(); ++c)
    if (m.nodes[m.cell(c)[0]][0] >= rank && m.nodes[m.cell(c)[0]][0] < rank + 1) mine.push_back(c);
  ASSERT_EQ(mine.size(), 4u);

  VtkSeriesWriter w(dir, "sol", rank, size);
  for (double t : {0.5, 1.0}) {
    Field u{"u", 2, {}};
    for (const auto& x : m.nodes)
      u.values.insert(u.values.end(), {t * x[0], t * x[1] * x[1]});
    Field owner{"owner", 1, std::vector<double>(mine.size(), double(rank))};
    w.write_step(t, m, mine, {u}, {owner});
  }
  barrier(); // the documented contract: nobody reads the step before every piece is written

  // Each rank's own last piece: its 4 cells and their 3 x 3 nodes.
  vtkNew<vtkXMLUnstructuredGridReader> piece;
  piece->SetFileName((fs::path(dir) / w.piece_name(1, rank)).string().c_str());
  piece->Update();
  EXPECT_EQ(piece->GetOutput()->GetNumberOfCells(), 4);
  EXPECT_EQ(piece->GetOutput()->GetNumberOfPoints(), 9);

  if (rank == 0) {
    std::ifstream in(w.pvd_path());
    std::stringstream pvd;
    pvd << in.rdbuf();
    const std::string step1 = size > 1 ? w.pvtu_name(1) : w.piece_name(1, 0);
    EXPECT_NE(pvd.str().find("timestep=\"1\" part=\"0\" file=\"" + step1 + "\""), std::string::npos)
        << pvd.str();
    if (size > 1) {
      vtkNew<vtkXMLPUnstructuredGridReader> r;
      r->SetFileName((fs::path(dir) / w.pvtu_name(1)).string().c_str());
      r->Update();
      vtkUnstructuredGrid* g = r->GetOutput();
      EXPECT_EQ(g->GetNumberOfCells(), m.num_cells());
      EXPECT_EQ(g->GetNumberOfPoints(), 9 * size); // shared column of 3 nodes duplicated
      vtkDataArray* u = g->GetPointData()->GetArray("u");
      vtkDataArray* owner = g->GetCellData()->GetArray("owner");
      ASSERT_TRUE(u && owner);
      for (vtkIdType i = 0; i < g->GetNumberOfPoints(); ++i) {
        double x[3];
        g->GetPoint(i, x);
        // Float64 written raw: exact round trip; 1e-14 forgives nothing but noise.
        EXPECT_NEAR(u->GetComponent(i, 0), x[0], 1e-14);
        EXPECT_NEAR(u->GetComponent(i, 1), x[1] * x[1], 1e-14);
      }
      double owners = 0.0; // 4 cells per rank, each tagged with its rank
      for (vtkIdType c = 0; c < g->GetNumberOfCells(); ++c)
        owners += owner->GetComponent(c, 0);
      EXPECT_EQ(owners, 4.0 * size * (size - 1) / 2.0);
    }
  }
  barrier();
  if (rank == 0) fs::remove_all(dir);
}

} // namespace
} // namespace bipot
