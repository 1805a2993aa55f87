#include "fem/element/facet_values.hpp"

#include "fem/core/error.hpp"
#include "fem/mesh/cell_facets.hpp"
#include "fem/mesh/mesh.hpp"
#include "test_cells.hpp"

#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

namespace bipot {
namespace {

constexpr double pi = 3.141592653589793238462643383279502884;

double sum_jxw(const FacetValues& fv) {
  double s = 0;
  for (int q = 0; q < fv.num_points(); ++q)
    s += fv.JxW(q);
  return s;
}

TEST(FacetValues, LineLengthAndNormal) {
  const double x[6] = {0.4, 0.3, 0, 1.6, 1.2, 0}; // tangent (1.2, 0.9), length 1.5
  FacetValues fv(CellType::Line2, Kinematics::PlaneStrain, 1);
  fv.reinit(x);
  // Straight segment: |t| is constant, sums of at most 2 weights, round-off only.
  EXPECT_NEAR(sum_jxw(fv), 1.5, 1e-14);
  for (int q = 0; q < fv.num_points(); ++q) {
    EXPECT_NEAR(fv.normal(q)[0], 0.9 / 1.5, 1e-15); // (t_y, -t_x) / |t|
    EXPECT_NEAR(fv.normal(q)[1], -1.2 / 1.5, 1e-15);
    EXPECT_EQ(fv.normal(q)[2], 0.0);
  }
  // Line3 on the same segment with its mid-node off-centre (non-uniform parametrisation):
  // the length is unchanged and |x'(ξ)| is linear in ξ, so degree 1 integrates it exactly.
  const double y[9] = {0.4, 0.3, 0, 1.6, 1.2, 0, 0.4 + 0.6 * 1.2, 0.3 + 0.6 * 0.9, 0};
  FacetValues f3(CellType::Line3, Kinematics::PlaneStrain, 1);
  f3.reinit(y);
  EXPECT_NEAR(sum_jxw(f3), 1.5, 1e-14);
}

TEST(FacetValues, AxisymmetricLineIsPappus) {
  // Revolved segment: area 2π r_c L (r_c = mean radius of the segment); r |t| is linear.
  const double x[6] = {0.5, 0.1, 0, 1.7, 0.6, 0};
  const double L = std::hypot(1.2, 0.5), rc = 1.1;
  FacetValues fv(CellType::Line2, Kinematics::Axisymmetric, 1);
  fv.reinit(x);
  EXPECT_NEAR(sum_jxw(fv), 2 * pi * rc * L, 1e-12 * 2 * pi * rc * L);
  const double y[9] = {0.5, 0.1, 0, 1.7, 0.6, 0, 1.1, 0.35, 0};
  FacetValues f3(CellType::Line3, Kinematics::Axisymmetric, 2);
  f3.reinit(y);
  EXPECT_NEAR(sum_jxw(f3), 2 * pi * rc * L, 1e-12 * 2 * pi * rc * L);
  // A facet on the axis has zero revolved area and is not an error.
  const double axis[6] = {0, 0, 0, 0, 1, 0};
  fv.reinit(axis);
  EXPECT_EQ(sum_jxw(fv), 0.0);
}

TEST(FacetValues, SurfaceAreasAndNormals) {
  // Triangle: area |(x1 - x0) × (x2 - x0)| / 2, normal along that cross product.
  const Eigen::Vector3d p0(0.1, 0.2, 0.3), p1(1.4, 0.5, -0.2), p2(0.3, 1.1, 0.9);
  const Eigen::Vector3d c = (p1 - p0).cross(p2 - p0);
  std::vector<double> x;
  for (const auto& p : {p0, p1, p2})
    x.insert(x.end(), {p.x(), p.y(), p.z()});
  FacetValues tri(CellType::Tri3, Kinematics::ThreeD, 1);
  tri.reinit(x.data());
  EXPECT_NEAR(sum_jxw(tri), 0.5 * c.norm(), 1e-14);
  for (int q = 0; q < tri.num_points(); ++q)
    for (int i = 0; i < 3; ++i)
      EXPECT_NEAR(tri.normal(q)[i], c.normalized()[i], 1e-15);

  // Planar trapezoid in a tilted plane: parallel sides 2 and 1, height 0.8, area 1.2.
  const Eigen::Vector3d e1 = Eigen::Vector3d(1, 1, 0).normalized();
  const Eigen::Vector3d e2 = Eigen::Vector3d(-1, 1, 1).normalized();
  const Eigen::Vector3d o(0.3, -0.2, 0.5);
  const double uv[4][2] = {{0, 0}, {2, 0}, {1.6, 0.8}, {0.6, 0.8}};
  x.clear();
  for (const auto& w : uv) {
    const Eigen::Vector3d p = o + w[0] * e1 + w[1] * e2;
    x.insert(x.end(), {p.x(), p.y(), p.z()});
  }
  FacetValues quad(CellType::Quad4, Kinematics::ThreeD, 2);
  quad.reinit(x.data());
  // |∂x/∂ξ × ∂x/∂η| is linear on a planar quad: the 2x2 rule is exact up to round-off.
  EXPECT_NEAR(sum_jxw(quad), 1.2, 1e-14);
  const Eigen::Vector3d n = e1.cross(e2).normalized();
  for (int q = 0; q < quad.num_points(); ++q)
    for (int i = 0; i < 3; ++i)
      EXPECT_NEAR(quad.normal(q)[i], n[i], 1e-15);
}

TEST(FacetValues, CellFacetsHaveOutwardNormalsAndCloseTheSurface) {
  for (CellType type : {CellType::Tri3, CellType::Tri6, CellType::Quad4, CellType::Quad8,
                        CellType::Tet4, CellType::Hex8}) {
    const auto x = test::distorted_cell(type);
    const int d = cell_dim(type);
    const Kinematics kin = d == 3 ? Kinematics::ThreeD : Kinematics::PlaneStrain;
    const CellType ft = facet_type(type);
    FacetValues fv(ft, kin, 4);
    const int corners = num_corners(type);
    Eigen::Vector3d cell_centroid = Eigen::Vector3d::Zero();
    for (int a = 0; a < corners; ++a)
      cell_centroid += Eigen::Vector3d(&x[3 * a]) / corners;
    Eigen::Vector3d closure = Eigen::Vector3d::Zero();
    for (const auto& facet : cell_facets(type)) {
      std::vector<double> fx;
      Eigen::Vector3d fc = Eigen::Vector3d::Zero();
      for (int a : facet) {
        fx.insert(fx.end(), x.begin() + 3 * a, x.begin() + 3 * a + 3);
        fc += Eigen::Vector3d(&x[3 * a]) / facet.size();
      }
      fv.reinit(fx.data());
      for (int q = 0; q < fv.num_points(); ++q) {
        const Eigen::Vector3d n(fv.normal(q).data());
        EXPECT_GT(n.dot(fc - cell_centroid), 0.0) << to_string(type) << " facet point " << q;
        EXPECT_NEAR(n.norm(), 1.0, 1e-15);
        closure += n * fv.JxW(q);
      }
    }
    // ∮ n dA = 0 over a closed surface; the facet integrands (t_y, -t_x) and t1 × t2 are
    // polynomials of degree <= 2 per variable, exact with degree 4, so round-off only.
    EXPECT_LT(closure.norm(), 1e-14) << to_string(type);
  }
}

TEST(FacetValues, ErrorsNameTheFacet) {
  EXPECT_THROW(FacetValues(CellType::Tri3, Kinematics::PlaneStrain, 1), Error);
  EXPECT_THROW(FacetValues(CellType::Line2, Kinematics::ThreeD, 1), Error);
  FacetValues fv(CellType::Line2, Kinematics::Axisymmetric, 1);
  const double point[6] = {1, 1, 0, 1, 1, 0};
  try {
    fv.reinit(point, 5);
    FAIL() << "no exception";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("facet 5 (line2) is degenerate"), std::string::npos)
        << e.what();
  }
  const double negative[6] = {-1, 0, 0, -0.5, 1, 0};
  EXPECT_THROW(fv.reinit(negative), Error);
}

TEST(FacetValues, ReinitFromMesh) {
  Mesh mesh;
  mesh.nodes = {{0.2, 0, 0}, {1, 0, 0}, {1, 0.5, 0}};
  mesh.add_cell(CellType::Tri3, {0, 1, 2}, 0);
  const Facet f{CellType::Line2, {1, 2}, 0};
  FacetValues fv(CellType::Line2, Kinematics::PlaneStrain, 1);
  fv.reinit(mesh, f);
  EXPECT_NEAR(sum_jxw(fv), 0.5, 1e-15);
  EXPECT_NEAR(fv.normal(0)[0], 1.0, 1e-15); // edge 1→2 of a CCW triangle: outward = +x
  EXPECT_THROW(fv.reinit(mesh, Facet{CellType::Line3, {0, 1, 2}, 0}), Error);
}

} // namespace
} // namespace bipot
