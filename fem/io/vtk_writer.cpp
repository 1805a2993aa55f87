#include "fem/io/vtk_writer.hpp"

#include "fem/core/error.hpp"

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkCellType.h>
#include <vtkDoubleArray.h>
#include <vtkIntArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkUnsignedCharArray.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLUnstructuredGridWriter.h>

#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <limits>
#include <set>

namespace bipot {

namespace {

int vtk_cell_type(CellType type) {
  switch (type) {
  case CellType::Point1:
    return VTK_VERTEX;
  case CellType::Line2:
    return VTK_LINE;
  case CellType::Line3:
    return VTK_QUADRATIC_EDGE;
  case CellType::Tri3:
    return VTK_TRIANGLE;
  case CellType::Tri6:
    return VTK_QUADRATIC_TRIANGLE;
  case CellType::Quad4:
    return VTK_QUAD;
  case CellType::Quad8:
    return VTK_QUADRATIC_QUAD;
  case CellType::Tet4:
    return VTK_TETRA;
  case CellType::Hex8:
    return VTK_HEXAHEDRON;
  }
  return VTK_EMPTY_CELL;
}

/// Components written for a field: 2D vectors are padded to 3 for ParaView.
int written_components(int components, int dim) {
  return dim == 2 && components == 2 ? 3 : components;
}

std::string xml_escape(const std::string& s) {
  std::string out;
  for (char c : s) {
    switch (c) {
    case '&':
      out += "&amp;";
      break;
    case '<':
      out += "&lt;";
      break;
    case '>':
      out += "&gt;";
      break;
    case '"':
      out += "&quot;";
      break;
    default:
      out += c;
    }
  }
  return out;
}

void check_fields(const std::vector<Field>& fields, std::size_t entities, const char* kind) {
  std::set<std::string> names;
  for (const Field& f : fields) {
    const std::string what = std::string("VtkSeriesWriter: ") + kind + " field '" + f.name + "'";
    if (f.name.empty())
      throw Error(std::string("VtkSeriesWriter: a ") + kind + " field has no name");
    if (f.name == "region") throw Error(what + ": the name is reserved for the region ids");
    if (!names.insert(f.name).second) throw Error(what + " is given twice");
    if (f.components < 1)
      throw Error(what + " has " + std::to_string(f.components) + " components");
    if (f.data().size() != entities * std::size_t(f.components))
      throw Error(what + " has " + std::to_string(f.data().size()) + " values, expected " +
                  std::to_string(f.components) + " x " + std::to_string(entities) + " " + kind +
                  "s");
  }
}

/// Copies the values of the listed entities (ids into f.data()) into a VTK array, padding
/// 2D vectors to 3 components.
// The tuples `ids` of f (all of them, in order, if null), with 3 components for a 2D vector.
vtkNew<vtkDoubleArray> to_vtk(const Field& f, const std::vector<Index>* ids, int dim) {
  const int nc = written_components(f.components, dim);
  vtkNew<vtkDoubleArray> a;
  a->SetName(f.name.c_str());
  a->SetNumberOfComponents(nc);
  if (!ids && nc == f.components) {
    // The field's own array, as written: VTK reads it in place (save = 1: VTK neither frees
    // nor writes it) instead of a copy, 10s of MB at 1M DOFs at the peak, when a stage ends.
    const std::vector<double>& values = f.data();
    a->SetArray(const_cast<double*>(values.data()), static_cast<vtkIdType>(values.size()), 1);
    return a;
  }
  const std::vector<double>& values = f.data();
  const std::size_t n = ids ? ids->size() : values.size() / f.components;
  a->SetNumberOfTuples(static_cast<vtkIdType>(n));
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t at = static_cast<std::size_t>(ids ? (*ids)[i] : Index(i)) * f.components;
    for (int c = 0; c < nc; ++c)
      a->SetTypedComponent(vtkIdType(i), c, c < f.components ? values[at + c] : 0.0);
  }
  return a;
}

} // namespace

VtkSeriesWriter::VtkSeriesWriter(std::string directory, std::string basename, int rank, int size)
    : directory_(std::move(directory)), basename_(std::move(basename)), rank_(rank), size_(size) {
  if (size_ < 1 || rank_ < 0 || rank_ >= size_)
    throw Error("VtkSeriesWriter: invalid rank " + std::to_string(rank_) + " of size " +
                std::to_string(size_));
  if (basename_.empty()) throw Error("VtkSeriesWriter: empty basename");
  std::error_code ec;
  std::filesystem::create_directories(directory_, ec);
  // Several ranks may race to create it: only a missing directory afterwards is an error.
  if (!std::filesystem::is_directory(directory_))
    throw Error("VtkSeriesWriter: cannot create directory '" + directory_ + "': " + ec.message());
}

std::string VtkSeriesWriter::piece_name(int step, int rank) const {
  char buf[32];
  std::snprintf(buf, sizeof buf, "_%04d_%d.vtu", step, rank);
  return basename_ + buf;
}

std::string VtkSeriesWriter::pvtu_name(int step) const {
  char buf[32];
  std::snprintf(buf, sizeof buf, "_%04d.pvtu", step);
  return basename_ + buf;
}

std::string VtkSeriesWriter::pvd_path() const {
  return path(basename_ + ".pvd");
}

std::string VtkSeriesWriter::path(const std::string& name) const {
  return (std::filesystem::path(directory_) / name).string();
}

void VtkSeriesWriter::write_step(double time, const Mesh& mesh, const std::vector<Index>& cells,
                                 const std::vector<Field>& point_fields,
                                 const std::vector<Field>& cell_fields) {
  check_fields(point_fields, std::size_t(mesh.num_nodes()), "point");
  check_fields(cell_fields, cells.size(), "cell");
  const int step = num_steps();

  // Local numbering of the nodes this rank's cells use, in increasing global id.
  std::vector<Index> local(mesh.num_nodes(), -1);
  for (Index c : cells) {
    if (c < 0 || c >= mesh.num_cells())
      throw Error("VtkSeriesWriter: cell id " + std::to_string(c) + " is not in the mesh");
    for (int a = 0; a < mesh.cell_num_nodes(c); ++a)
      local[mesh.cell(c)[a]] = 0;
  }
  std::vector<Index> global;
  for (Index n = 0; n < mesh.num_nodes(); ++n)
    if (local[n] == 0) {
      local[n] = Index(global.size());
      global.push_back(n);
    }

  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(vtkIdType(global.size()));
  for (std::size_t i = 0; i < global.size(); ++i) {
    const auto& x = mesh.nodes[global[i]];
    points->SetPoint(vtkIdType(i), x[0], x[1], mesh.dim == 2 ? 0.0 : x[2]);
  }
  vtkNew<vtkUnstructuredGrid> grid;
  grid->SetPoints(points);
  // Connectivity in 32 bits when the node ids fit (VTK's default is 64): at 1M DOFs the
  // connectivity is the largest array of a step.
  vtkIdType connectivity = 0;
  for (Index c : cells)
    connectivity += mesh.cell_num_nodes(c);
  vtkNew<vtkCellArray> cell_array;
  if (global.size() < std::size_t(std::numeric_limits<std::int32_t>::max()) &&
      connectivity < vtkIdType(std::numeric_limits<std::int32_t>::max()))
    cell_array->Use32BitStorage();
  cell_array->AllocateExact(vtkIdType(cells.size()), connectivity);
  vtkNew<vtkUnsignedCharArray> types;
  types->SetNumberOfValues(vtkIdType(cells.size()));
  std::vector<vtkIdType> ids;
  vtkNew<vtkIntArray> region;
  region->SetName("region");
  region->SetNumberOfTuples(vtkIdType(cells.size()));
  for (std::size_t i = 0; i < cells.size(); ++i) {
    const Index c = cells[i];
    ids.clear();
    for (int a = 0; a < mesh.cell_num_nodes(c); ++a)
      ids.push_back(local[mesh.cell(c)[a]]);
    cell_array->InsertNextCell(vtkIdType(ids.size()), ids.data());
    types->SetValue(vtkIdType(i), static_cast<unsigned char>(vtk_cell_type(mesh.cell_types[c])));
    region->SetValue(vtkIdType(i), mesh.cell_regions[c]);
  }
  std::vector<Index>().swap(local); // not needed any more: the writer's peak is ahead
  grid->SetCells(types, cell_array);
  for (const Field& f : point_fields)
    grid->GetPointData()->AddArray(to_vtk(f, &global, mesh.dim));
  for (const Field& f : cell_fields) // given for `cells`, in their order
    grid->GetCellData()->AddArray(to_vtk(f, nullptr, mesh.dim));
  grid->GetCellData()->AddArray(region);

  const std::string file = path(piece_name(step, rank_));
  vtkNew<vtkXMLUnstructuredGridWriter> writer;
  writer->SetFileName(file.c_str());
  writer->SetInputData(grid);
  writer->SetDataModeToAppended();
  writer->EncodeAppendedDataOff(); // raw binary: smaller and faster than base64
  writer->SetHeaderTypeToUInt64(); // no 4 GiB limit per array
  // LZ4: at 300k DOFs a step took 0.8 s with the default zlib, 0.1 s with LZ4, for files a
  // third larger (ParaView reads them since 5.5).
  writer->SetCompressorTypeToLZ4();
  if (writer->Write() != 1) throw Error("VtkSeriesWriter: cannot write '" + file + "'");

  times_.push_back(time);
  files_.push_back(size_ > 1 ? pvtu_name(step) : piece_name(step, 0));
  if (rank_ != 0) return;
  if (size_ > 1) write_pvtu(step, mesh.dim, point_fields, cell_fields);
  write_pvd();
}

void VtkSeriesWriter::write_pvtu(int step, int dim, const std::vector<Field>& point_fields,
                                 const std::vector<Field>& cell_fields) const {
  const std::string file = path(pvtu_name(step));
  std::ofstream out(file);
  auto array = [&](const Field& f) {
    out << "      <PDataArray type=\"Float64\" Name=\"" << xml_escape(f.name)
        << "\" NumberOfComponents=\"" << written_components(f.components, dim) << "\"/>\n";
  };
  out << "<?xml version=\"1.0\"?>\n"
      << "<VTKFile type=\"PUnstructuredGrid\" version=\"0.1\">\n"
      << "  <PUnstructuredGrid GhostLevel=\"0\">\n"
      << "    <PPointData>\n";
  for (const Field& f : point_fields)
    array(f);
  out << "    </PPointData>\n"
      << "    <PCellData>\n";
  for (const Field& f : cell_fields)
    array(f);
  out << "      <PDataArray type=\"Int32\" Name=\"region\" NumberOfComponents=\"1\"/>\n"
      << "    </PCellData>\n"
      << "    <PPoints>\n"
      << "      <PDataArray type=\"Float64\" Name=\"Points\" NumberOfComponents=\"3\"/>\n"
      << "    </PPoints>\n";
  for (int r = 0; r < size_; ++r)
    out << "    <Piece Source=\"" << xml_escape(piece_name(step, r)) << "\"/>\n";
  out << "  </PUnstructuredGrid>\n"
      << "</VTKFile>\n";
  out.close();
  if (!out) throw Error("VtkSeriesWriter: cannot write '" + file + "'");
}

void VtkSeriesWriter::write_pvd() const {
  const std::string file = pvd_path();
  const std::string tmp = file + ".tmp";
  std::ofstream out(tmp);
  out << "<?xml version=\"1.0\"?>\n"
      << "<VTKFile type=\"Collection\" version=\"0.1\">\n"
      << "  <Collection>\n";
  char time[32];
  for (int s = 0; s < num_steps(); ++s) {
    std::snprintf(time, sizeof time, "%.17g", times_[s]);
    out << "    <DataSet timestep=\"" << time << "\" part=\"0\" file=\"" << xml_escape(files_[s])
        << "\"/>\n";
  }
  out << "  </Collection>\n"
      << "</VTKFile>\n";
  out.close();
  if (!out) throw Error("VtkSeriesWriter: cannot write '" + tmp + "'");
  // rename() replaces the old collection atomically (POSIX): never a half-written .pvd.
  if (std::rename(tmp.c_str(), file.c_str()) != 0)
    throw Error("VtkSeriesWriter: cannot rename '" + tmp + "' to '" + file + "'");
}

} // namespace bipot
