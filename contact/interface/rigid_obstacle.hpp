#pragma once
/// Analytical rigid obstacles: the surface an interface's body is pressed on, bonded to or
/// slides along when the other side is not meshed (a rigid foundation, a rigid indenter).
/// Pure geometry (docs/theory.md, "Rigid obstacles").

#include <array>
#include <string>

namespace bipot::contact {

/// A rigid surface, given in the undeformed configuration. Its motion (a translation, data
/// of each stage) is not part of it.
struct RigidObstacle {
  enum class Shape {
    Plane,    ///< a line in 2D; the obstacle is the half-space behind `direction`
    Circle,   ///< 2D disc of centre `point` (a sphere about the axis in axisymmetry)
    Sphere,   ///< 3D ball of centre `point`
    Cylinder, ///< 3D solid cylinder of axis through `point` along `direction`
  };
  Shape shape = Shape::Plane;
  std::array<double, 3> point{0, 0, 0};     ///< m: on the plane, centre, or on the axis
  std::array<double, 3> direction{0, 0, 0}; ///< plane: unit normal out of the obstacle
                                            ///< (towards the body); cylinder: unit axis
  double radius = 0;                        ///< m (circle, sphere, cylinder)
};

/// "plane", "circle", "sphere", "cylinder".
const char* to_string(RigidObstacle::Shape shape);

/// Where a point stands with respect to an obstacle.
struct ObstacleDistance {
  /// m: signed distance from the surface, > 0 outside the obstacle (on the body's side).
  double distance = 0;
  /// Unit normal of the surface at the closest point, pointing out of the obstacle.
  std::array<double, 3> normal{0, 0, 0};
  /// False where the closest point is not unique (the centre of a circle or sphere, a point
  /// of a cylinder's axis): no normal there.
  bool defined = true;
};

/// Signed distance of `x` from `obstacle` and the obstacle's outward normal at the closest
/// point. `dim` is 2 or 3 (the z components are ignored in 2D).
ObstacleDistance distance_to(const RigidObstacle& obstacle, const std::array<double, 3>& x,
                             int dim);

} // namespace bipot::contact
