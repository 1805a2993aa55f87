#include "fem/input/rigid_body_checks.hpp"

#include "fem/input/detail/check_support.hpp"
#include "fem/input/detail/sections.hpp"

#include <Eigen/Geometry>
#include <Eigen/SVD>
#include <array>
#include <cmath>
#include <cstdio>
#include <set>
#include <unordered_set>

namespace bipot {

namespace {

using Eigen::MatrixXd;
using Eigen::Vector3d;

// Cells connected through shared nodes.
struct Bodies {
  std::vector<int> of_node;              ///< -1 for a node of no cell
  std::vector<std::vector<Index>> cells; ///< per body, increasing
  std::vector<std::vector<Index>> nodes; ///< per body, increasing
  std::vector<std::set<int>> regions;    ///< per body

  explicit Bodies(const Mesh& mesh) : of_node(mesh.num_nodes(), -1) {
    input::UnionFind connected(mesh.num_nodes());
    for (Index c = 0; c < mesh.num_cells(); ++c)
      for (int a = 1; a < mesh.cell_num_nodes(c); ++a)
        connected.join(mesh.cell(c)[0], mesh.cell(c)[a]);
    std::vector<int> of_root(mesh.num_nodes(), -1);
    for (Index c = 0; c < mesh.num_cells(); ++c) {
      int& b = of_root[connected.find(mesh.cell(c)[0])];
      if (b < 0) {
        b = static_cast<int>(cells.size());
        cells.emplace_back();
        regions.emplace_back();
      }
      cells[b].push_back(c);
      regions[b].insert(mesh.cell_regions[c]);
      for (int a = 0; a < mesh.cell_num_nodes(c); ++a)
        of_node[mesh.cell(c)[a]] = b;
    }
    nodes.resize(cells.size());
    for (Index n = 0; n < mesh.num_nodes(); ++n)
      if (of_node[n] >= 0) nodes[of_node[n]].push_back(n);
  }
};

std::string quoted_list(const std::vector<std::string>& names) {
  std::string out;
  for (std::size_t i = 0; i < names.size(); ++i)
    out += (i == 0 ? "'" : (i + 1 == names.size() ? " and '" : ", '")) + names[i] + "'";
  return out;
}

// "0-99, 120, 130-140, ..." (the first four runs of an increasing list).
std::string id_ranges(const std::vector<Index>& ids) {
  std::string out;
  int runs = 0;
  for (std::size_t i = 0; i < ids.size(); ++runs) {
    std::size_t j = i;
    while (j + 1 < ids.size() && ids[j + 1] == ids[j] + 1)
      ++j;
    if (runs == 4) return out + ", ...";
    out += (runs ? ", " : "") + std::to_string(ids[i]) +
           (j > i ? "-" + std::to_string(ids[j]) : std::string());
    i = j + 1;
  }
  return out;
}

std::string describe_body(const Mesh& mesh, const Bodies& bodies, int b) {
  std::vector<std::string> names;
  for (int r : bodies.regions[b])
    names.push_back(mesh.region_name(r));
  return "the body of region" + std::string(names.size() > 1 ? "s " : " ") + quoted_list(names) +
         (bodies.cells[b].size() > 1 ? " (cells " : " (cell ") + id_ranges(bodies.cells[b]) + ")";
}

// The rigid motions of one body as columns: translations first, then rotations about the
// body's centre, divided by its radius so that every column is of order one.
struct RigidModes {
  std::vector<int> translated; ///< component of each translation
  int rotations = 0;           ///< 0 (axisymmetric), 1 (about z, in plane) or 3 (x, y, z)
  Vector3d center = Vector3d::Zero();
  double radius = 1;
  const std::vector<std::string>* components = nullptr;

  int size() const { return static_cast<int>(translated.size()) + rotations; }
  Vector3d axis(int k) const { return rotations == 1 ? Vector3d::UnitZ() : Vector3d::Unit(k); }
  double value(int mode, const std::array<double, 3>& x, int component) const {
    const int nt = static_cast<int>(translated.size());
    if (mode < nt) return translated[mode] == component ? 1.0 : 0.0;
    const Vector3d d = Vector3d(x[0], x[1], x[2]) - center;
    return axis(mode - nt).cross(d)(component) / radius;
  }
};

RigidModes rigid_modes(const std::string& kinematics, const Mesh& mesh,
                       const std::vector<Index>& nodes) {
  RigidModes m;
  m.components = &input::component_names(kinematics);
  if (kinematics == "axisymmetric")
    m.translated = {1};
  else
    for (int i = 0; i < mesh.dim; ++i)
      m.translated.push_back(i);
  m.rotations = kinematics == "axisymmetric" ? 0 : (mesh.dim == 2 ? 1 : 3);
  for (Index n : nodes)
    m.center += Vector3d(mesh.nodes[n][0], mesh.nodes[n][1], mesh.nodes[n][2]);
  m.center /= static_cast<double>(nodes.size());
  double r = 0;
  for (Index n : nodes)
    r = std::max(
        r, (Vector3d(mesh.nodes[n][0], mesh.nodes[n][1], mesh.nodes[n][2]) - m.center).norm());
  if (r > 0) m.radius = r;
  return m;
}

// An orthonormal basis of the null space of `a` (columns), or of its column space.
MatrixXd null_space(const MatrixXd& a) {
  if (a.rows() == 0) return MatrixXd::Identity(a.cols(), a.cols());
  Eigen::JacobiSVD<MatrixXd> svd(a, Eigen::ComputeFullV);
  svd.setThreshold(1e-10);
  return svd.matrixV().rightCols(a.cols() - svd.rank());
}
MatrixXd column_space(const MatrixXd& a) {
  if (a.cols() == 0) return MatrixXd(a.rows(), 0);
  Eigen::JacobiSVD<MatrixXd> svd(a, Eigen::ComputeFullU);
  svd.setThreshold(1e-10);
  return svd.matrixU().leftCols(svd.rank());
}

// The axis `d` lies along, or -1.
int aligned_axis(const Vector3d& d) {
  for (int i = 0; i < 3; ++i)
    if (std::abs(d.normalized()(i)) > 1 - 1e-9) return i;
  return -1;
}

// The unit vector along `d`, its first non-zero component positive: "(0.707, 0.707)".
std::string unit_vector(Vector3d d, int dim) {
  d.normalize();
  for (int i = 0; i < dim; ++i)
    if (std::abs(d(i)) > 1e-9) {
      if (d(i) < 0) d = -d;
      break;
    }
  char text[96];
  std::snprintf(text, sizeof text, dim == 2 ? "(%.3g, %.3g)" : "(%.3g, %.3g, %.3g)", d(0), d(1),
                d(2));
  return text;
}

// "x" for a direction along an axis, else its unit vector.
std::string direction(const Vector3d& d, const RigidModes& m, int dim) {
  const int i = aligned_axis(d);
  return i >= 0 ? (*m.components)[i] : unit_vector(d, dim);
}

// In 3D: "y and z" for the plane normal to x, else "" (a plane along no two axes).
std::string plane_axes(const Vector3d& normal, const RigidModes& m) {
  const int i = aligned_axis(normal);
  if (i < 0) return "";
  return (*m.components)[i == 0 ? 1 : 0] + " and " + (*m.components)[i == 2 ? 1 : 2];
}

// The directions of the pure translations `t` (columns: coefficients of m's translations).
std::vector<Vector3d> directions(const MatrixXd& t, const RigidModes& m) {
  std::vector<Vector3d> out;
  for (int j = 0; j < t.cols(); ++j) {
    Vector3d d = Vector3d::Zero();
    for (std::size_t i = 0; i < m.translated.size(); ++i)
      d(m.translated[i]) = t(i, j);
    out.push_back(d.normalized());
  }
  return out;
}

// Names the pure translations along the orthonormal directions `d`.
std::string translations(const std::vector<Vector3d>& d, const RigidModes& m, int dim) {
  const auto& c = *m.components;
  if (d.size() == 1) return "translation along " + direction(d[0], m, dim);
  if (d.size() == 2 && dim == 2) return "translations along " + c[0] + " and " + c[1];
  if (d.size() == 3) return "translations along " + c[0] + ", " + c[1] + " and " + c[2];
  const Vector3d normal = d[0].cross(d[1]);
  const std::string axes = plane_axes(normal, m);
  return axes.empty() ? "translations normal to " + unit_vector(normal, dim)
                      : "translations along " + axes;
}

// Names the rotations of the free motions `n` (columns: coefficients of m's modes), whose
// pure translations are along the orthonormal directions `d`. A single rotation is named
// with its centre (2D) or with its axis through a point (3D) when those are unique.
std::string rotations(const MatrixXd& n, const std::vector<Vector3d>& d, const RigidModes& m,
                      int dim) {
  const int nt = static_cast<int>(m.translated.size());
  const MatrixXd rot = n.bottomRows(m.rotations);
  const MatrixXd axes = column_space(rot);
  if (axes.cols() == 0) return "";
  if (axes.cols() == 3) return "rotations about x, y and z";
  if (axes.cols() == 2) {
    const Vector3d normal = Vector3d(axes.col(0)).cross(Vector3d(axes.col(1)));
    const std::string about = plane_axes(normal, m);
    return about.empty() ? "rotations about every axis normal to " + unit_vector(normal, dim)
                         : "rotations about " + about;
  }
  // A free motion whose rotation part is that axis, without its pure translations:
  // u(x) = t + (w / radius) × (x − centre), zero on the line through p along w when t ⊥ w.
  const Eigen::VectorXd motion =
      n * rot.jacobiSvd(Eigen::ComputeFullU | Eigen::ComputeFullV).solve(axes.col(0));
  Vector3d t = Vector3d::Zero(), w = Vector3d::Zero();
  for (int i = 0; i < nt; ++i)
    t(m.translated[i]) = motion(i);
  for (int k = 0; k < m.rotations; ++k)
    w += motion(nt + k) * m.axis(k);
  bool unique_axis = std::abs(t.dot(w)) <= 1e-9 * t.norm() * w.norm();
  for (const Vector3d& e : d) {
    t -= t.dot(e) * e;
    unique_axis = unique_axis && e.cross(w).norm() <= 1e-9 * w.norm(); // sliding along it
  }
  const Vector3d p = m.center + m.radius * w.cross(t) / w.squaredNorm();
  // Six digits, round-off (relative to the body's size) shown as 0: a place to look at.
  std::array<double, 3> at{};
  for (int i = 0; i < 3; ++i)
    at[i] = std::abs(p(i)) <= 1e-9 * (m.radius + m.center.norm()) ? 0.0 : p(i);
  char point[96];
  std::snprintf(point, sizeof point, dim == 2 ? "(%.6g, %.6g)" : "(%.6g, %.6g, %.6g)", at[0], at[1],
                at[2]);
  if (dim == 2) return unique_axis ? "rotation about " + std::string(point) : "rotation";
  if (unique_axis)
    return "rotation about the axis along " + direction(w, m, dim) + " through " + point;
  const int i = aligned_axis(w);
  return "rotation about " +
         (i >= 0 ? (*m.components)[i] : "the axis along " + unit_vector(w, dim));
}

// The motions spanned by the columns of `n` (coefficients of RigidModes' columns).
std::string motions(const MatrixXd& n, const RigidModes& m, int dim) {
  const int nt = static_cast<int>(m.translated.size());
  // Pure translations: the combinations with no rotation part.
  const MatrixXd pure = m.rotations
                            ? MatrixXd(n.topRows(nt) * null_space(n.bottomRows(m.rotations)))
                            : MatrixXd(n.topRows(nt));
  const std::vector<Vector3d> d = directions(column_space(pure), m);
  std::string out = d.empty() ? "" : translations(d, m, dim);
  const std::string r = m.rotations ? rotations(n, d, m, dim) : "";
  if (!out.empty() && !r.empty())
    out += out.find(" and ") != std::string::npos ? ", and " : " and ";
  return out + r;
}

// What may press each body onto its interfaces in stage `s` (see the header).
std::vector<bool> pressed_bodies(const ProblemSpec& spec, std::size_t s, const Mesh& mesh,
                                 const Bodies& bodies,
                                 const std::vector<OpeningInterface>& interfaces) {
  const StageSpec& stage = spec.stages[s];
  std::vector<bool> pressed(bodies.cells.size(), false);
  for (const auto& load : stage.loads) {
    if (load.type == LoadSpec::Type::Gravity) return std::vector<bool>(pressed.size(), true);
    const auto it = mesh.facet_sets.find(load.set);
    if (it != mesh.facet_sets.end())
      for (const Facet& f : it->second)
        if (!f.nodes.empty() && bodies.of_node[f.nodes[0]] >= 0)
          pressed[bodies.of_node[f.nodes[0]]] = true;
  }
  for (const auto& stress : spec.initial_stress) {
    const auto it = mesh.regions.find(stress.region);
    if (it != mesh.regions.end())
      for (std::size_t b = 0; b < pressed.size(); ++b)
        if (bodies.regions[b].count(it->second)) pressed[b] = true;
  }
  for (const auto& iface : interfaces) {
    double shift = 0; // a gap shift is a state: the last value named up to this stage
    for (std::size_t k = 0; k <= s; ++k)
      for (const auto& gap : spec.stages[k].interface_gaps)
        if (gap.interface == iface.name) shift = gap.value;
    bool moved = false; // an obstacle moved so far may push the body
    for (std::size_t k = 0; k <= s; ++k)
      for (const auto& d : spec.stages[k].obstacle_displacements)
        moved = moved || d.interface == iface.name;
    if (iface.smallest_gap + shift < 0 || moved)
      for (const auto& [a, b] : iface.pairs)
        for (Index n : {a, b})
          if (n >= 0 && bodies.of_node[n] >= 0) pressed[bodies.of_node[n]] = true;
  }
  return pressed;
}

} // namespace

std::vector<std::string> free_rigid_body_modes(const ProblemSpec& spec, const Mesh& mesh,
                                               const std::vector<OpeningInterface>& interfaces,
                                               const std::vector<Index>& held_nodes,
                                               const std::vector<ReferenceNode>& references) {
  const Bodies bodies(mesh);
  const std::size_t num_bodies = bodies.cells.size();
  const int num_components = spec.kinematics == "three_d" ? 3 : 2;
  std::vector<RigidModes> modes;
  for (std::size_t b = 0; b < num_bodies; ++b)
    modes.push_back(rigid_modes(spec.kinematics, mesh, bodies.nodes[b]));
  // The opening interfaces each body hangs on.
  std::vector<std::vector<std::string>> held_by(num_bodies);
  for (const auto& iface : interfaces) {
    std::set<int> touched;
    for (const auto& [a, b] : iface.pairs) {
      if (b < 0 && bodies.of_node[a] >= 0) touched.insert(bodies.of_node[a]); // an obstacle
      if (b >= 0 && bodies.of_node[a] >= 0 && bodies.of_node[b] >= 0 &&
          bodies.of_node[a] != bodies.of_node[b])
        touched.insert({bodies.of_node[a], bodies.of_node[b]});
    }
    for (int b : touched)
      held_by[b].push_back(iface.name);
  }

  input::BoundedReport report(spec.file, "bodies free to move");
  std::vector<std::string> problems;
  for (std::size_t s = 0; s < spec.stages.size(); ++s) {
    const StageSpec& stage = spec.stages[s];
    // The fixed DOFs of each body, once each.
    std::unordered_set<Index> seen;
    std::vector<std::vector<std::pair<Index, int>>> fixed(num_bodies);
    for (const auto& bc : stage.boundary_conditions) {
      if (bc.component < 0 || bc.component >= num_components) continue;
      for (Index node : mesh.set_nodes(bc.set))
        if (bodies.of_node[node] >= 0 && seen.insert(3 * node + bc.component).second)
          fixed[bodies.of_node[node]].emplace_back(node, bc.component);
    }
    for (Index node : held_nodes)
      for (int c = 0; c < num_components; ++c)
        if (bodies.of_node[node] >= 0 && seen.insert(3 * node + c).second)
          fixed[bodies.of_node[node]].emplace_back(node, c);
    // Rigid bodies' reference nodes: (component, reference) rows per body; loads press.
    std::vector<std::vector<std::pair<int, const ReferenceNode*>>> held(num_bodies);
    std::vector<bool> loaded(num_bodies, false);
    for (const auto& c : stage.rigid_body_conditions)
      for (const ReferenceNode& ref : references)
        if (ref.name == c.body && ref.node >= 0 && bodies.of_node[ref.node] >= 0) {
          const int b = bodies.of_node[ref.node];
          if (c.force)
            loaded[b] = true;
          else
            held[b].emplace_back(c.component, &ref);
        }
    std::vector<bool> pressed;
    for (std::size_t b = 0; b < num_bodies; ++b) {
      const RigidModes& m = modes[b];
      MatrixXd rows(fixed[b].size() + held[b].size(), m.size());
      for (std::size_t r = 0; r < fixed[b].size(); ++r)
        for (int k = 0; k < m.size(); ++k)
          rows(r, k) = m.value(k, mesh.nodes[fixed[b][r].first], fixed[b][r].second);
      const int nt = static_cast<int>(m.translated.size());
      for (std::size_t r = 0; r < held[b].size(); ++r) {
        const auto [component, ref] = held[b][r];
        const Index row = static_cast<Index>(fixed[b].size() + r);
        for (int k = 0; k < m.size(); ++k)
          if (component < mesh.dim) // a translation: as a node at the reference point
            rows(row, k) = m.value(k, ref->point, component);
          else // a rotation about axis component − dim (2D: z)
            rows(row, k) =
                k < nt ? 0.0 : m.axis(k - nt)(mesh.dim == 2 ? 2 : component - 3) / m.radius;
      }
      const MatrixXd free = null_space(rows);
      if (free.cols() == 0) continue;
      std::string message = stage.where + ": stage '" + stage.name +
                            "': " + describe_body(mesh, bodies, static_cast<int>(b));
      if (!held_by[b].empty()) {
        // Conservative: some support of its own, or a push onto the interface, may hold it.
        if (free.cols() < m.size()) continue;
        if (pressed.empty()) pressed = pressed_bodies(spec, s, mesh, bodies, interfaces);
        if (pressed[b] || loaded[b]) continue;
        message += " hangs only on interface" + std::string(held_by[b].size() > 1 ? "s " : " ") +
                   quoted_list(held_by[b]) +
                   ", which can open, and no gravity, load, initial stress or interference "
                   "presses it on";
      }
      message += ": free " + motions(free, m, mesh.dim) + "; add boundary conditions that stop " +
                 (free.cols() == 1 ? "it" : "them");
      report.add_line(message);
    }
  }
  report.append_to(problems);
  return problems;
}

} // namespace bipot
