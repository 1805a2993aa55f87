#include "contact/interface/rigid_obstacle.hpp"

#include <cmath>

namespace bipot::contact {

const char* to_string(RigidObstacle::Shape shape) {
  switch (shape) {
  case RigidObstacle::Shape::Plane:
    return "plane";
  case RigidObstacle::Shape::Circle:
    return "circle";
  case RigidObstacle::Shape::Sphere:
    return "sphere";
  case RigidObstacle::Shape::Cylinder:
    return "cylinder";
  }
  return "?";
}

ObstacleDistance distance_to(const RigidObstacle& obstacle, const std::array<double, 3>& x,
                             int dim) {
  ObstacleDistance out;
  std::array<double, 3> d{0, 0, 0};
  for (int i = 0; i < dim; ++i)
    d[i] = x[i] - obstacle.point[i];
  const auto& e = obstacle.direction;
  if (obstacle.shape == RigidObstacle::Shape::Plane) {
    for (int i = 0; i < dim; ++i)
      out.distance += d[i] * e[i];
    out.normal = e;
    return out;
  }
  // Round shapes: the normal is the direction from the centre (or the axis) to x.
  if (obstacle.shape == RigidObstacle::Shape::Cylinder) {
    const double along = d[0] * e[0] + d[1] * e[1] + d[2] * e[2];
    for (int i = 0; i < 3; ++i)
      d[i] -= along * e[i];
  }
  const double r = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
  out.distance = r - obstacle.radius;
  if (!(r > 1e-12 * obstacle.radius)) {
    out.defined = false;
    return out;
  }
  for (int i = 0; i < 3; ++i)
    out.normal[i] = d[i] / r;
  return out;
}

} // namespace bipot::contact
