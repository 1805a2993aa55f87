#include "fem/element/element_values.hpp"

#include "fem/core/error.hpp"
#include "fem/mesh/mesh.hpp"
#include "test_cells.hpp"

#include <Eigen/Geometry>
#include <Eigen/LU>
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <string>
#include <vector>

namespace bipot {
namespace {

constexpr double pi = 3.141592653589793238462643383279502884;

double cross2(double ux, double uy, double vx, double vy) {
  return ux * vy - uy * vx;
}

// Shoelace area of the polygon formed by the first n nodes of `x` (n x 3 row-major).
double polygon_area(const std::vector<double>& x, int n) {
  double a = 0;
  for (int i = 0; i < n; ++i) {
    const int j = (i + 1) % n;
    a += cross2(x[3 * i], x[3 * i + 1], x[3 * j], x[3 * j + 1]);
  }
  return 0.5 * a;
}

// x coordinate (radius) of the centroid of that polygon.
double polygon_centroid_x(const std::vector<double>& x, int n) {
  double s = 0;
  for (int i = 0; i < n; ++i) {
    const int j = (i + 1) % n;
    s += (x[3 * i] + x[3 * j]) * cross2(x[3 * i], x[3 * i + 1], x[3 * j], x[3 * j + 1]);
  }
  return s / (6 * polygon_area(x, n));
}

// Area of a 2D cell with n corners whose edge i has its mid-node at index n + i (quadratic
// cells): shoelace of the corners plus, per parabolic edge a→b with mid-node offset d from the
// chord midpoint, (2/3) d × (b − a) (Green's theorem on x(s) = a + s(b−a) + 4s(1−s)d).
double curved_area(const std::vector<double>& x, int n) {
  double area = polygon_area(x, n);
  for (int e = 0; e < n; ++e) {
    const int a = e, b = (e + 1) % n, m = n + e;
    const double dx = x[3 * m] - 0.5 * (x[3 * a] + x[3 * b]);
    const double dy = x[3 * m + 1] - 0.5 * (x[3 * a + 1] + x[3 * b + 1]);
    area += 2.0 / 3 * cross2(dx, dy, x[3 * b] - x[3 * a], x[3 * b + 1] - x[3 * a + 1]);
  }
  return area;
}

double sum_jxw(const ElementValues& ev) {
  double s = 0;
  for (int q = 0; q < ev.num_points(); ++q)
    s += ev.JxW(q);
  return s;
}

TEST(ElementValues, AreaOfDistortedAndCurvedCells) {
  // Quadratic cells: det J has degree 2 (Tri6) or <= 4 per variable (Quad8), integrated
  // exactly by the stiffness rules, so only round-off remains: 1e-12 relative.
  for (CellType type : {CellType::Tri3, CellType::Tri6, CellType::Quad4, CellType::Quad8}) {
    const auto x = test::distorted_cell(type);
    const int corners = (type == CellType::Tri3 || type == CellType::Tri6) ? 3 : 4;
    const double exact = cell_order(type) == 2 ? curved_area(x, corners) : polygon_area(x, corners);
    ElementValues ev(type, Kinematics::PlaneStrain, stiffness_degree(type));
    ev.reinit(x.data());
    EXPECT_NEAR(sum_jxw(ev), exact, 1e-12 * exact) << to_string(type);
  }
}

TEST(ElementValues, VolumeOfTetAndFrustumHex) {
  {
    const auto x = test::distorted_cell(CellType::Tet4);
    Eigen::Matrix3d E;
    for (int k = 0; k < 3; ++k)
      for (int i = 0; i < 3; ++i)
        E(i, k) = x[3 * (k + 1) + i] - x[i];
    ElementValues ev(CellType::Tet4, Kinematics::ThreeD, 0);
    ev.reinit(x.data());
    const double exact = E.determinant() / 6; // closed form of a tetrahedron's volume
    EXPECT_NEAR(sum_jxw(ev), exact, 1e-12 * exact);
  }
  {
    // Oblique square frustum: base [0,2]² at z = 0, top square [0.3,1.3]² at z = h (off
    // centre); trilinear interpolation represents it exactly. V = h (A1 + A2 + √(A1 A2)) / 3
    // (Cavalieri: the shift does not change it), here 3.5. The cell is then rotated (volume kept).
    const double h = 1.5;
    std::vector<Eigen::Vector3d> p = {{0, 0, 0}, {2, 0, 0}, {2, 2, 0}, {0, 2, 0}};
    for (int a = 0; a < 4; ++a)
      p.push_back({0.8 + 0.5 * (p[a].x() - 1), 0.3 + 0.5 * p[a].y(), h});
    const Eigen::Matrix3d R =
        (Eigen::AngleAxisd(0.4, Eigen::Vector3d(1, 2, 3).normalized())).toRotationMatrix();
    std::vector<double> x;
    for (const auto& v : p) {
      const Eigen::Vector3d r = R * v;
      x.insert(x.end(), {r.x(), r.y(), r.z()});
    }
    ElementValues ev(CellType::Hex8, Kinematics::ThreeD, stiffness_degree(CellType::Hex8));
    ev.reinit(x.data());
    EXPECT_NEAR(sum_jxw(ev), 3.5, 1e-12 * 3.5);
  }
}

TEST(ElementValues, AxisymmetricVolumeIsPappus) {
  // Straight-sided cells (mid-nodes at edge midpoints): volume of revolution 2π r_c A.
  // r det J is a polynomial of degree <= 3 (<= 2 per variable on quads), integrated exactly.
  for (CellType type : {CellType::Tri3, CellType::Tri6, CellType::Quad4, CellType::Quad8}) {
    const bool tri = type == CellType::Tri3 || type == CellType::Tri6;
    const int corners = tri ? 3 : 4;
    std::vector<double> x = test::distorted_cell(tri ? CellType::Tri3 : CellType::Quad4);
    if (cell_order(type) == 2) {
      std::vector<std::array<int, 2>> edges;
      for (int e = 0; e < corners; ++e)
        edges.push_back({e, (e + 1) % corners});
      test::add_mid_nodes(x, edges, std::vector<std::array<double, 2>>(corners, {0, 0}));
    }
    const double exact = 2 * pi * polygon_centroid_x(x, corners) * polygon_area(x, corners);
    ElementValues ev(type, Kinematics::Axisymmetric,
                     stiffness_degree(type, Kinematics::Axisymmetric));
    ev.reinit(x.data());
    EXPECT_NEAR(sum_jxw(ev), exact, 1e-12 * exact) << to_string(type);
  }
}

// Nodal values of a displacement field at the nodes of `x`.
std::vector<double> nodal(const std::vector<double>& x, int dim,
                          const std::function<Eigen::Vector3d(const double*)>& u) {
  std::vector<double> ue;
  for (std::size_t a = 0; a < x.size() / 3; ++a) {
    const Eigen::Vector3d v = u(&x[3 * a]);
    for (int i = 0; i < dim; ++i)
      ue.push_back(v[i]);
  }
  return ue;
}

// Checks B u_e and strain(q, u_e) against `exact` (Voigt strain at a physical point).
void expect_strains(ElementValues& ev, const std::vector<double>& x,
                    const std::function<Eigen::Vector3d(const double*)>& u,
                    const std::function<Voigt(const std::array<double, 3>&)>& exact,
                    const std::string& what) {
  ev.reinit(x.data());
  const std::vector<double> ue = nodal(x, ev.dim(), u);
  const Eigen::Map<const Eigen::VectorXd> uv(ue.data(), ue.size());
  StrainDisplacementMatrix B(ev.voigt_size(), ev.num_dofs()); // the allocation-free type
  for (int q = 0; q < ev.num_points(); ++q) {
    ev.strain_displacement(q, B);
    const Eigen::VectorXd eps = B * uv;
    const Voigt eps2 = ev.strain(q, ue.data());
    const Voigt ref = exact(ev.point(q));
    ASSERT_EQ(eps.size(), ref.size());
    // O(1) strains from O(1) coordinates through J⁻¹ of well-shaped cells: round-off ~1e-14.
    for (int k = 0; k < ref.size(); ++k) {
      EXPECT_NEAR(eps[k], ref[k], 1e-12) << what << " point " << q << " component " << k;
      EXPECT_NEAR(eps2[k], ref[k], 1e-12) << what << " point " << q << " component " << k;
    }
  }
}

TEST(ElementValues, LinearFieldStrainsAreExactOnDistortedCells) {
  Eigen::Matrix3d G;
  G << 0.3, -0.7, 0.25, 1.1, -0.4, 0.6, -0.2, 0.9, 0.45;
  const Eigen::Vector3d c(0.15, -0.35, 0.05);
  for (CellType type : {CellType::Tri3, CellType::Tri6, CellType::Quad4, CellType::Quad8,
                        CellType::Tet4, CellType::Hex8}) {
    const int d = cell_dim(type);
    const auto x = test::distorted_cell(type);
    const std::vector<Kinematics> kins =
        d == 3 ? std::vector<Kinematics>{Kinematics::ThreeD}
               : std::vector<Kinematics>{Kinematics::PlaneStrain, Kinematics::Axisymmetric};
    for (Kinematics kin : kins) {
      Eigen::Matrix3d Gd = Eigen::Matrix3d::Zero();
      Gd.topLeftCorner(d, d) = G.topLeftCorner(d, d);
      auto u = [&](const double* p) {
        Eigen::Vector3d v = c + Gd * Eigen::Vector3d(p[0], p[1], d == 3 ? p[2] : 0);
        if (d == 2) v.z() = 0;
        return v;
      };
      auto exact = [&](const std::array<double, 3>& p) {
        Voigt e(voigt_size(d));
        if (d == 2) {
          const double hoop = kin == Kinematics::Axisymmetric ? u(p.data()).x() / p[0] : 0.0;
          e << G(0, 0), G(1, 1), hoop, G(0, 1) + G(1, 0);
        } else {
          e << G(0, 0), G(1, 1), G(2, 2), G(0, 1) + G(1, 0), G(1, 2) + G(2, 1), G(0, 2) + G(2, 0);
        }
        return e;
      };
      ElementValues ev(type, kin, stiffness_degree(type, kin) + 1);
      expect_strains(ev, x, u, exact, to_string(type) + " " + to_string(kin));
    }
  }
}

TEST(ElementValues, QuadraticFieldStrainsAreExactOnQuadraticCells) {
  // Quadratic polynomials lie in the Tri6 and Quad8 spaces when the map is affine:
  // straight-sided triangle, parallelogram.
  const double a[6] = {0.1, 0.4, -0.3, 0.7, -0.5, 0.2}, b[6] = {-0.2, 0.3, 0.6, -0.4, 0.8, 0.35};
  auto u = [&](const double* p) {
    const double x = p[0], y = p[1];
    return Eigen::Vector3d(a[0] + a[1] * x + a[2] * y + a[3] * x * x + a[4] * x * y + a[5] * y * y,
                           b[0] + b[1] * x + b[2] * y + b[3] * x * x + b[4] * x * y + b[5] * y * y,
                           0);
  };
  std::vector<double> tri = test::distorted_cell(CellType::Tri3);
  test::add_mid_nodes(tri, {{0, 1}, {1, 2}, {2, 0}}, {{0, 0}, {0, 0}, {0, 0}});
  std::vector<double> par = {0.5, 0.2, 0, 1.9, 0.5, 0, 2.3, 1.6, 0, 0.9, 1.3, 0};
  test::add_mid_nodes(par, {{0, 1}, {1, 2}, {2, 3}, {3, 0}}, {{0, 0}, {0, 0}, {0, 0}, {0, 0}});
  for (Kinematics kin : {Kinematics::PlaneStrain, Kinematics::Axisymmetric}) {
    auto exact = [&](const std::array<double, 3>& p) {
      const double x = p[0], y = p[1];
      Voigt e(4);
      e << a[1] + 2 * a[3] * x + a[4] * y, b[2] + b[4] * x + 2 * b[5] * y,
          kin == Kinematics::Axisymmetric ? u(p.data()).x() / x : 0.0,
          a[2] + a[4] * x + 2 * a[5] * y + b[1] + 2 * b[3] * x + b[4] * y;
      return e;
    };
    ElementValues tri6(CellType::Tri6, kin, 4), quad8(CellType::Quad8, kin, 5);
    expect_strains(tri6, tri, u, exact, "tri6 " + to_string(kin));
    expect_strains(quad8, par, u, exact, "quad8 " + to_string(kin));
  }
}

TEST(ElementValues, InvertedCellThrowsNamingTheCell) {
  const auto x = test::distorted_cell(CellType::Quad4);
  std::vector<double> cw; // same quad, clockwise
  for (int a : {0, 3, 2, 1})
    cw.insert(cw.end(), x.begin() + 3 * a, x.begin() + 3 * a + 3);
  ElementValues ev(CellType::Quad4, Kinematics::PlaneStrain, 2);
  try {
    ev.reinit(cw.data(), 7);
    FAIL() << "no exception";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("cell 7 (quad4) is inverted or degenerate"),
              std::string::npos)
        << e.what();
  }
  const double flat[9] = {0, 0, 0, 1, 1, 0, 2, 2, 0}; // collinear corners
  ElementValues tri(CellType::Tri3, Kinematics::PlaneStrain, 1);
  EXPECT_THROW(tri.reinit(flat, 3), Error);
}

TEST(ElementValues, AxisymmetricCellAcrossTheAxisThrows) {
  const double x[9] = {-1, 0, 0, 1, 0, 0, -0.5, 1, 0}; // centroid at r = -1/6
  ElementValues ev(CellType::Tri3, Kinematics::Axisymmetric, 1);
  EXPECT_THROW(ev.reinit(x, 2), Error);
}

TEST(ElementValues, CellTypeMustMatchKinematics) {
  EXPECT_THROW(ElementValues(CellType::Tri3, Kinematics::ThreeD, 1), Error);
  EXPECT_THROW(ElementValues(CellType::Hex8, Kinematics::PlaneStrain, 2), Error);
  EXPECT_THROW(ElementValues(CellType::Line2, Kinematics::PlaneStrain, 2), Error);
}

TEST(ElementValues, ReinitFromMesh) {
  Mesh mesh;
  const auto q = test::distorted_cell(CellType::Quad4);
  for (int a = 0; a < 4; ++a)
    mesh.nodes.push_back({q[3 * a], q[3 * a + 1], 0});
  mesh.add_cell(CellType::Quad4, {0, 1, 2, 3}, 0);
  mesh.add_cell(CellType::Tri3, {0, 1, 3}, 0);
  ElementValues ev(CellType::Tri3, Kinematics::PlaneStrain, 1);
  ev.reinit(mesh, 1);
  // Triangle 0-1-3 of the quad: shoelace area by hand, round-off only.
  const double area = 0.5 * cross2(q[3] - q[0], q[4] - q[1], q[9] - q[0], q[10] - q[1]);
  EXPECT_NEAR(sum_jxw(ev), area, 1e-12 * area);
  EXPECT_THROW(ev.reinit(mesh, 0), Error); // a quad4 given to tri3 values
}

} // namespace
} // namespace bipot
