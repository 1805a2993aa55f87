// Signed distance and normal of the analytical obstacles against hand-computed points.
#include "contact/interface/rigid_obstacle.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace bipot::contact {
namespace {

using Shape = RigidObstacle::Shape;

void expect_normal(const ObstacleDistance& d, double x, double y, double z) {
  EXPECT_NEAR(d.normal[0], x, 1e-15);
  EXPECT_NEAR(d.normal[1], y, 1e-15);
  EXPECT_NEAR(d.normal[2], z, 1e-15);
}

TEST(RigidObstacle, PlaneDistanceIsSignedAlongTheNormal) {
  const double s = std::sqrt(0.5);
  const RigidObstacle plane{Shape::Plane, {1, 0, 0}, {s, s, 0}, 0};
  const auto above = distance_to(plane, {2, 1, 0}, 2); // (1, 1)·n = 2 s
  EXPECT_NEAR(above.distance, 2 * s, 1e-15);
  expect_normal(above, s, s, 0);
  EXPECT_NEAR(distance_to(plane, {0, 0, 0}, 2).distance, -s, 1e-15); // behind: inside
  // In 2D the z coordinate is ignored.
  EXPECT_NEAR(distance_to(plane, {2, 1, 7}, 2).distance, 2 * s, 1e-15);
}

TEST(RigidObstacle, CircleAndSphereMeasureFromTheCentre) {
  const RigidObstacle circle{Shape::Circle, {1, 1, 0}, {0, 0, 0}, 2};
  const auto d = distance_to(circle, {4, 5, 0}, 2); // 5 from the centre
  EXPECT_NEAR(d.distance, 3, 1e-15);
  expect_normal(d, 0.6, 0.8, 0);
  EXPECT_NEAR(distance_to(circle, {1, 2, 0}, 2).distance, -1, 1e-15); // inside
  EXPECT_FALSE(distance_to(circle, {1, 1, 0}, 2).defined);
  const RigidObstacle sphere{Shape::Sphere, {0, 0, 1}, {0, 0, 0}, 1};
  const auto e = distance_to(sphere, {2, 3, 7}, 3); // (2, 3, 6): 7 from the centre
  EXPECT_NEAR(e.distance, 6, 1e-15);
  expect_normal(e, 2.0 / 7, 3.0 / 7, 6.0 / 7);
}

TEST(RigidObstacle, CylinderMeasuresFromItsAxis) {
  const RigidObstacle cylinder{Shape::Cylinder, {0, 0, 0}, {0, 0, 1}, 0.5};
  const auto d = distance_to(cylinder, {3, 4, -9}, 3); // 5 from the axis, whatever z
  EXPECT_NEAR(d.distance, 4.5, 1e-15);
  expect_normal(d, 0.6, 0.8, 0);
  EXPECT_FALSE(distance_to(cylinder, {0, 0, 3}, 3).defined);
}

} // namespace
} // namespace bipot::contact
