#include "fem/input/mesh_checks.hpp"

#include "fem/core/error.hpp"
#include "fem/element/element_values.hpp"
#include "fem/input/detail/check_support.hpp"
#include "fem/mesh/node_grid.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <memory>

namespace bipot {

namespace {

using input::BoundedReport;

bool finite(const std::array<double, 3>& x) {
  return std::isfinite(x[0]) && std::isfinite(x[1]) && std::isfinite(x[2]);
}

std::string cell_label(const Mesh& mesh, Index c) {
  return "cell " + std::to_string(c) + " (" + to_string(mesh.cell_types[c]) + ", region '" +
         mesh.region_name(mesh.cell_regions[c]) + "')";
}

// The cells of every node (compressed rows).
class NodeCells {
public:
  explicit NodeCells(const Mesh& mesh) : offsets_(mesh.num_nodes() + 1, 0) {
    for (Index c = 0; c < mesh.num_cells(); ++c)
      for (int a = 0; a < mesh.cell_num_nodes(c); ++a)
        ++offsets_[mesh.cell(c)[a] + 1];
    for (Index n = 0; n < mesh.num_nodes(); ++n)
      offsets_[n + 1] += offsets_[n];
    cells_.resize(offsets_.back());
    std::vector<Index> next(offsets_.begin(), offsets_.end() - 1);
    for (Index c = 0; c < mesh.num_cells(); ++c)
      for (int a = 0; a < mesh.cell_num_nodes(c); ++a)
        cells_[next[mesh.cell(c)[a]]++] = c;
  }
  Index count(Index n) const { return offsets_[n + 1] - offsets_[n]; }
  Index first(Index n) const { return cells_[offsets_[n]]; }
  /// Whether one cell holds both nodes.
  bool share_a_cell(const Mesh& mesh, Index a, Index b) const {
    for (Index k = offsets_[a]; k < offsets_[a + 1]; ++k) {
      const Index c = cells_[k];
      if (std::find(mesh.cell(c), mesh.cell(c) + mesh.cell_num_nodes(c), b) !=
          mesh.cell(c) + mesh.cell_num_nodes(c))
        return true;
    }
    return false;
  }

private:
  std::vector<Index> offsets_, cells_;
};

// det J of one cell type at its corners and at the points of the stiffness rule, through
// ElementValues (whose reinit refuses det J <= 0): all points at once, and one point at a time
// to say where a cell fails.
class JacobianCheck {
public:
  JacobianCheck(CellType type, Kinematics kin) : type_(type) {
    // Plane strain for 2D whatever `kin` says: only det J matters here, and the axisymmetric
    // r > 0 test would refuse corners on the axis.
    const Kinematics geometry = cell_dim(type) == 3 ? Kinematics::ThreeD : Kinematics::PlaneStrain;
    const auto nodes = reference_nodes(type);
    corners_ = cell_order(type) == 1 ? num_nodes(type) : (type == CellType::Tri6 ? 3 : 4);
    points_.assign(nodes.begin(), nodes.begin() + corners_);
    const auto rule = gauss_rule(type, stiffness_degree(type, kin));
    points_.insert(points_.end(), rule.points.begin(), rule.points.end());
    QuadratureRule all;
    all.points = points_;
    all.weights.assign(points_.size(), 1.0);
    all_ = std::make_unique<ElementValues>(type, geometry, all);
    for (const auto& p : points_)
      single_.emplace_back(type, geometry, QuadratureRule{{p}, {1.0}, 0});
  }

  /// "" if det J > 0 at every point of cell `c`, else what is wrong and where.
  std::string problem(const Mesh& mesh, Index c) {
    try {
      all_->reinit(mesh, c);
      return "";
    } catch (const Error&) {
    }
    int first = -1, failed = 0;
    for (std::size_t p = 0; p < single_.size(); ++p) {
      try {
        single_[p].reinit(mesh, c);
      } catch (const Error&) {
        if (first < 0) first = static_cast<int>(p);
        ++failed;
      }
    }
    const std::string what = cell_label(mesh, c) + " is inverted or degenerate: det J <= 0 ";
    const int total = static_cast<int>(points_.size());
    if (failed == total)
      return what + "at every corner and quadrature point (" +
             (mesh.dim == 2 ? "nodes in clockwise order, or no area)"
                            : "nodes in the wrong order, or no volume)");
    std::string at;
    if (first < corners_) {
      at = "at its corner " + mesh.describe_node(mesh.cell(c)[first]);
    } else {
      std::array<double, max_cell_nodes> N{};
      shape_values(type_, points_[first].data(), N.data());
      std::array<double, 3> x{0, 0, 0};
      for (int a = 0; a < mesh.cell_num_nodes(c); ++a)
        for (int i = 0; i < 3; ++i)
          x[i] += N[a] * mesh.nodes[mesh.cell(c)[a]][i];
      at = "at the quadrature point " + input::format_point(x, mesh.dim);
    }
    return what + at + " (at " + std::to_string(failed) + " of its " + std::to_string(total) +
           " corners and quadrature points)";
  }

private:
  CellType type_;
  int corners_ = 0;
  std::vector<std::array<double, 3>> points_;
  std::unique_ptr<ElementValues> all_;
  std::vector<ElementValues> single_;
};

void check_cells(const Mesh& mesh, Kinematics kin, const std::vector<bool>& finite_node,
                 BoundedReport& report) {
  std::map<CellType, JacobianCheck> checks;
  for (Index c = 0; c < mesh.num_cells(); ++c) {
    const CellType type = mesh.cell_types[c];
    // Cells of the wrong dimension are refused when the model is built.
    if (cell_dim(type) != mesh.dim) continue;
    const Index* nodes = mesh.cell(c);
    if (!std::all_of(nodes, nodes + mesh.cell_num_nodes(c),
                     [&](Index n) { return finite_node[n]; }))
      continue;
    auto it = checks.find(type);
    if (it == checks.end()) it = checks.emplace(type, JacobianCheck(type, kin)).first;
    const std::string problem = it->second.problem(mesh, c);
    if (!problem.empty()) report.add(problem);
  }
}

// Pairs of coincident nodes that nothing joins.
void check_coincident(const Mesh& mesh, const NodeCells& node_cells,
                      const std::vector<bool>& finite_node,
                      const std::vector<std::pair<Index, Index>>& joined, BoundedReport& report) {
  std::vector<Index> ids;
  std::array<double, 3> lo, hi;
  lo.fill(std::numeric_limits<double>::infinity());
  hi.fill(-std::numeric_limits<double>::infinity());
  for (Index n = 0; n < mesh.num_nodes(); ++n) {
    if (!finite_node[n] || node_cells.count(n) == 0) continue;
    ids.push_back(n);
    for (int i = 0; i < 3; ++i) {
      lo[i] = std::min(lo[i], mesh.nodes[n][i]);
      hi[i] = std::max(hi[i], mesh.nodes[n][i]);
    }
  }
  if (ids.size() < 2) return;
  double diagonal = 0;
  for (int i = 0; i < 3; ++i)
    diagonal += (hi[i] - lo[i]) * (hi[i] - lo[i]);
  const double tol = 1e-9 * std::sqrt(diagonal); // as interfaces pair coincident nodes
  std::vector<std::pair<Index, Index>> coincident;
  const NodeGrid grid(mesh, ids, tol);
  for (Index a : ids)
    grid.for_each_near(mesh.nodes[a], [&](Index b) {
      double d2 = 0;
      for (int i = 0; i < 3; ++i)
        d2 += (mesh.nodes[a][i] - mesh.nodes[b][i]) * (mesh.nodes[a][i] - mesh.nodes[b][i]);
      if (b > a && d2 <= tol * tol) coincident.emplace_back(a, b);
    });
  // Joined: through the interfaces' pairs, or through a cell that holds both (a degenerate
  // cell, which check_cells reports), in any chain of these.
  input::UnionFind together(mesh.num_nodes());
  for (const auto& [a, b] : joined)
    together.join(a, b);
  for (const auto& [a, b] : coincident)
    if (node_cells.share_a_cell(mesh, a, b)) together.join(a, b);
  for (const auto& [a, b] : coincident) {
    if (!together.join(a, b)) continue; // joined, or its crack already reported
    report.add(mesh.describe_node(a) + " and node " + std::to_string(b) +
               " coincide, but no cell and no interface joins them (cell " +
               std::to_string(node_cells.first(a)) + " uses the one, cell " +
               std::to_string(node_cells.first(b)) +
               " the other): the body is cracked there; merge the two nodes in the mesh, or "
               "pair them by an interface with facet_sets if the bodies are meant to be apart");
  }
}

} // namespace

std::vector<std::string> mesh_problems(const Mesh& mesh, Kinematics kin,
                                       const std::vector<std::pair<Index, Index>>& joined,
                                       const std::string& where,
                                       const std::vector<Index>& reference_nodes) {
  BoundedReport not_finite(where, "nodes with a coordinate that is not a finite number");
  BoundedReport bad_cells(where, "inverted or degenerate cells");
  BoundedReport coincident(where, "pairs of coincident nodes that nothing joins");
  BoundedReport unused(where, "nodes used by no cell");
  const NodeCells node_cells(mesh);
  std::vector<bool> finite_node(mesh.num_nodes());
  for (Index n = 0; n < mesh.num_nodes(); ++n) {
    finite_node[n] = finite(mesh.nodes[n]);
    if (!finite_node[n])
      not_finite.add(mesh.describe_node(n) + " has a coordinate that is not a finite number");
    if (node_cells.count(n) == 0 &&
        std::find(reference_nodes.begin(), reference_nodes.end(), n) == reference_nodes.end())
      unused.add(mesh.describe_node(n) +
                 " belongs to no cell: nothing gives its displacement a stiffness (the system "
                 "to solve would be singular)");
  }
  check_cells(mesh, kin, finite_node, bad_cells);
  check_coincident(mesh, node_cells, finite_node, joined, coincident);
  std::vector<std::string> problems;
  for (const BoundedReport* r : {&not_finite, &bad_cells, &coincident, &unused})
    r->append_to(problems);
  return problems;
}

} // namespace bipot
