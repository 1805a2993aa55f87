#include "fem/mesh/structured_mesh.hpp"

#include "fem/core/error.hpp"
#include "fem/mesh/cell_facets.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace bipot {

namespace {

std::string num(double v) {
  std::ostringstream os;
  os << v;
  return os.str();
}

/// Appends the problems of one axis; returns true if the axis is usable.
bool check_axis(const std::string& name, const AxisSegments& axis,
                std::vector<std::string>& problems) {
  const std::string where = "block mesh: " + name + ".";
  const std::size_t before = problems.size();
  if (axis.breaks.size() < 2)
    problems.push_back(where + "breaks needs at least 2 values, got " +
                       std::to_string(axis.breaks.size()));
  for (std::size_t i = 0; i < axis.breaks.size(); ++i) {
    if (!std::isfinite(axis.breaks[i]))
      problems.push_back(where + "breaks[" + std::to_string(i) + "] is not finite");
    else if (i > 0 && !(axis.breaks[i] > axis.breaks[i - 1]))
      problems.push_back(where + "breaks must be strictly increasing, but breaks[" +
                         std::to_string(i) + "] = " + num(axis.breaks[i]) + " <= breaks[" +
                         std::to_string(i - 1) + "] = " + num(axis.breaks[i - 1]));
  }
  const std::size_t segments = axis.breaks.empty() ? 0 : axis.breaks.size() - 1;
  if (axis.cells.size() != segments)
    problems.push_back(where + "cells has " + std::to_string(axis.cells.size()) +
                       " entries, expected " + std::to_string(segments) + " (one per segment)");
  for (std::size_t i = 0; i < axis.cells.size(); ++i)
    if (axis.cells[i] < 1)
      problems.push_back(where + "cells[" + std::to_string(i) +
                         "] = " + std::to_string(axis.cells[i]) + " must be at least 1");
  if (!axis.grading.empty() && axis.grading.size() != segments)
    problems.push_back(where + "grading has " + std::to_string(axis.grading.size()) +
                       " entries, expected " + std::to_string(segments) +
                       " (one per segment) or none");
  for (std::size_t i = 0; i < axis.grading.size(); ++i)
    if (!(axis.grading[i] > 0.0) || !std::isfinite(axis.grading[i]))
      problems.push_back(where + "grading[" + std::to_string(i) + "] = " + num(axis.grading[i]) +
                         " must be a finite number > 0");
  return problems.size() == before;
}

/// Segment index of every cell along an axis.
std::vector<int> cell_segments(const AxisSegments& axis) {
  std::vector<int> seg;
  for (std::size_t s = 0; s < axis.cells.size(); ++s)
    seg.insert(seg.end(), axis.cells[s], int(s));
  return seg;
}

/// Node coordinates of the lattice: every `step`-th is a cell corner, the others mid-nodes.
std::vector<double> lattice_coordinates(const AxisSegments& axis, int step) {
  const std::vector<double> corners = axis_coordinates(axis);
  if (step == 1) return corners;
  std::vector<double> out;
  for (std::size_t i = 0; i + 1 < corners.size(); ++i) {
    out.push_back(corners[i]);
    out.push_back(0.5 * (corners[i] + corners[i + 1]));
  }
  out.push_back(corners.back());
  return out;
}

using Pattern = std::vector<std::vector<std::array<int, 3>>>;

/// Lattice offsets (in units of the lattice, cell origin at 0) of the nodes of every cell that
/// one structured cell (square/cube of side `step`) is split into; triangles as `diagonals`
/// says (Alternating: use Right and Left). All counter-clockwise / positively oriented.
Pattern cell_patterns(CellType type, Diagonals diagonals = Diagonals::Right) {
  if (type == CellType::Tri3 && diagonals == Diagonals::Left)
    return {{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {{1, 0, 0}, {1, 1, 0}, {0, 1, 0}}};
  if (type == CellType::Tri3 && diagonals == Diagonals::Crossed) // lattice step 2, centre 1,1
    return {{{0, 0, 0}, {2, 0, 0}, {1, 1, 0}},
            {{2, 0, 0}, {2, 2, 0}, {1, 1, 0}},
            {{2, 2, 0}, {0, 2, 0}, {1, 1, 0}},
            {{0, 2, 0}, {0, 0, 0}, {1, 1, 0}}};
  if (type == CellType::Tri6 && diagonals == Diagonals::Left)
    return {{{0, 0, 0}, {2, 0, 0}, {0, 2, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}},
            {{2, 0, 0}, {2, 2, 0}, {0, 2, 0}, {2, 1, 0}, {1, 2, 0}, {1, 1, 0}}};
  switch (type) {
  case CellType::Quad4:
    return {{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}}};
  case CellType::Quad8:
    return {
        {{0, 0, 0}, {2, 0, 0}, {2, 2, 0}, {0, 2, 0}, {1, 0, 0}, {2, 1, 0}, {1, 2, 0}, {0, 1, 0}}};
  case CellType::Tri3:
    return {{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}}, {{0, 0, 0}, {1, 1, 0}, {0, 1, 0}}};
  case CellType::Tri6:
    return {{{0, 0, 0}, {2, 0, 0}, {2, 2, 0}, {1, 0, 0}, {2, 1, 0}, {1, 1, 0}},
            {{0, 0, 0}, {2, 2, 0}, {0, 2, 0}, {1, 1, 0}, {1, 2, 0}, {0, 1, 0}}};
  case CellType::Hex8:
    return {
        {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}}};
  case CellType::Tet4: {
    // Kuhn subdivision: one tet per path 000 -> 111 along the axes in each of the 6 orders.
    // Every cube face is cut along the diagonal through its lowest corner, the same seen
    // from both neighbouring cubes, hence conforming.
    std::vector<std::vector<std::array<int, 3>>> tets;
    std::array<int, 3> perm{0, 1, 2};
    do {
      std::array<int, 3> v1{0, 0, 0};
      v1[perm[0]] = 1;
      std::array<int, 3> v2 = v1;
      v2[perm[1]] = 1;
      const std::array<int, 3> v3{1, 1, 1};
      const int det = v1[0] * (v2[1] * v3[2] - v2[2] * v3[1]) -
                      v1[1] * (v2[0] * v3[2] - v2[2] * v3[0]) +
                      v1[2] * (v2[0] * v3[1] - v2[1] * v3[0]);
      if (det > 0)
        tets.push_back({{0, 0, 0}, v1, v2, v3});
      else
        tets.push_back({{0, 0, 0}, v2, v1, v3}); // positive orientation (Gmsh)
    } while (std::next_permutation(perm.begin(), perm.end()));
    return tets;
  }
  default:
    return {};
  }
}

} // namespace

const char* to_string(Diagonals diagonals) {
  switch (diagonals) {
  case Diagonals::Right:
    return "right";
  case Diagonals::Left:
    return "left";
  case Diagonals::Alternating:
    return "alternating";
  case Diagonals::Crossed:
    return "crossed";
  }
  return "?";
}

std::vector<double> axis_coordinates(const AxisSegments& axis) {
  std::vector<double> x{axis.breaks.front()};
  for (std::size_t s = 0; s < axis.cells.size(); ++s) {
    const double a = axis.breaks[s], b = axis.breaks[s + 1];
    const int n = axis.cells[s];
    const double g = axis.grading.empty() ? 1.0 : axis.grading[s];
    for (int i = 1; i < n; ++i) {
      // x_i = a + L (g^i - 1)/(g^n - 1); expm1 keeps it accurate for g close to 1.
      const double t =
          g == 1.0 ? double(i) / n : std::expm1(i * std::log(g)) / std::expm1(n * std::log(g));
      x.push_back(a + (b - a) * t);
    }
    x.push_back(b); // segment ends are hit exactly
  }
  return x;
}

Mesh make_block_mesh(const BlockMeshSpec& spec) {
  std::vector<std::string> problems;
  const CellType type = spec.cell;
  const Diagonals diagonals = spec.diagonals;
  const auto patterns = cell_patterns(type, diagonals);
  // Alternating: Right where i + j is even, Left where odd.
  const auto odd_patterns =
      cell_patterns(type, diagonals == Diagonals::Alternating ? Diagonals::Left : diagonals);
  if (patterns.empty())
    problems.push_back("block mesh: cell type " + to_string(type) +
                       " is not supported (tri3, tri6, quad4, quad8, tet4, hex8)");
  const bool triangles = type == CellType::Tri3 || type == CellType::Tri6;
  if (diagonals != Diagonals::Right && !triangles)
    problems.push_back(std::string("block mesh: diagonals '") + to_string(diagonals) +
                       "' applies to triangle cells (tri3, tri6), not to " + to_string(type));
  else if (diagonals == Diagonals::Crossed && type != CellType::Tri3)
    problems.push_back("block mesh: diagonals 'crossed' is available for tri3 cells only");
  const int dim = patterns.empty() ? 2 : cell_dim(type);
  bool axes_ok = check_axis("x", spec.x, problems);
  axes_ok = check_axis("y", spec.y, problems) && axes_ok;
  if (dim == 3) axes_ok = check_axis("z", spec.z, problems) && axes_ok;
  if (axes_ok) {
    const std::size_t nbx = spec.x.cells.size(), nby = spec.y.cells.size();
    const std::size_t nbz = dim == 3 ? spec.z.cells.size() : 1;
    if (spec.block_regions.size() != nbx * nby * nbz)
      problems.push_back("block mesh: block_regions has " +
                         std::to_string(spec.block_regions.size()) + " names, expected " +
                         std::to_string(nbx * nby * nbz) + " (" + std::to_string(nbx) + " x " +
                         std::to_string(nby) + (dim == 3 ? " x " + std::to_string(nbz) : "") +
                         " blocks, x fastest)");
    else if (std::all_of(spec.block_regions.begin(), spec.block_regions.end(),
                         [](const std::string& s) { return s.empty(); }))
      problems.push_back("block mesh: every block is a hole (all region names are empty)");
  }
  if (!problems.empty()) throw InputError(problems);

  // Lattice points per cell edge; Crossed uses the middle of the Tri3 lattice for its centre.
  const int step = diagonals == Diagonals::Crossed ? 2 : cell_order(type);
  const std::vector<double> X = lattice_coordinates(spec.x, step);
  const std::vector<double> Y = lattice_coordinates(spec.y, step);
  const std::vector<double> Z = dim == 3 ? lattice_coordinates(spec.z, step) : std::vector{0.0};
  const std::vector<int> sx = cell_segments(spec.x), sy = cell_segments(spec.y);
  const std::vector<int> sz = dim == 3 ? cell_segments(spec.z) : std::vector{0};
  const Index NX = Index(X.size()), NY = Index(Y.size());
  const std::size_t nbx = spec.x.cells.size(), nby = spec.y.cells.size();

  Mesh mesh;
  mesh.dim = dim;
  // Regions get ids in order of first appearance among the blocks.
  for (const auto& name : spec.block_regions)
    if (!name.empty()) mesh.region_id(name);

  // Cells in lattice indices first, so that nodes can be numbered in lattice order and only
  // the lattice points that cells use (no Quad8 centres, nothing inside holes) become nodes.
  std::vector<Index> lattice_cells;
  std::vector<int> regions;
  std::vector<char> used(X.size() * Y.size() * Z.size(), 0);
  for (std::size_t k = 0; k < sz.size(); ++k)
    for (std::size_t j = 0; j < sy.size(); ++j)
      for (std::size_t i = 0; i < sx.size(); ++i) {
        const std::string& name = spec.block_regions[sx[i] + nbx * (sy[j] + nby * sz[k])];
        if (name.empty()) continue;
        for (const auto& pattern : (i + j) % 2 == 0 ? patterns : odd_patterns) {
          for (const auto& o : pattern) {
            const Index p = (step * Index(i) + o[0]) +
                            NX * ((step * Index(j) + o[1]) + NY * (step * Index(k) + o[2]));
            lattice_cells.push_back(p);
            used[p] = 1;
          }
          regions.push_back(mesh.regions.at(name));
        }
      }
  std::vector<Index> node_of(used.size(), -1);
  for (std::size_t p = 0; p < used.size(); ++p) {
    if (!used[p]) continue;
    node_of[p] = mesh.num_nodes();
    const Index I = Index(p) % NX, J = (Index(p) / NX) % NY, K = Index(p) / (NX * NY);
    mesh.nodes.push_back({X[I], Y[J], Z[K]});
  }
  const int nn = num_nodes(type);
  std::vector<Index> ids(nn);
  for (std::size_t c = 0; c < regions.size(); ++c) {
    for (int a = 0; a < nn; ++a)
      ids[a] = node_of[lattice_cells[c * nn + a]];
    mesh.add_cell(type, ids, regions[c]);
  }

  // Outer sides: boundary facets whose nodes all lie on one plane of the bounding box (the
  // lattice coordinates are copied, never recomputed, so exact comparison is safe).
  const char* names[3][2] = {{"left", "right"}, {"bottom", "top"}, {"back", "front"}};
  const double bounds[3][2] = {{X.front(), X.back()}, {Y.front(), Y.back()}, {Z.front(), Z.back()}};
  for (int d = 0; d < dim; ++d)
    for (int side = 0; side < 2; ++side)
      mesh.facet_sets[names[d][side]];
  for (Facet& f : boundary_facets(mesh))
    for (int d = 0; d < dim; ++d)
      for (int side = 0; side < 2; ++side)
        if (std::all_of(f.nodes.begin(), f.nodes.end(),
                        [&](Index n) { return mesh.nodes[n][d] == bounds[d][side]; }))
          mesh.facet_sets[names[d][side]].push_back(f);
  for (const auto& kv : mesh.facet_sets)
    mesh.node_sets[kv.first] = mesh.facet_set_nodes(kv.first);
  return mesh;
}

Mesh make_rectangle(double x0, double x1, int nx, double y0, double y1, int ny, CellType cell,
                    const std::string& region, double gx, double gy) {
  if (cell_dim(cell) != 2)
    throw InputError("make_rectangle: cell type " + to_string(cell) + " is not a 2D type");
  BlockMeshSpec spec;
  spec.x = {{x0, x1}, {nx}, {gx}};
  spec.y = {{y0, y1}, {ny}, {gy}};
  spec.cell = cell;
  spec.block_regions = {region};
  return make_block_mesh(spec);
}

Mesh make_box(double x0, double x1, int nx, double y0, double y1, int ny, double z0, double z1,
              int nz, CellType cell, const std::string& region, double gx, double gy, double gz) {
  if (cell_dim(cell) != 3)
    throw InputError("make_box: cell type " + to_string(cell) + " is not a 3D type");
  BlockMeshSpec spec;
  spec.x = {{x0, x1}, {nx}, {gx}};
  spec.y = {{y0, y1}, {ny}, {gy}};
  spec.z = {{z0, z1}, {nz}, {gz}};
  spec.cell = cell;
  spec.block_regions = {region};
  return make_block_mesh(spec);
}

} // namespace bipot
