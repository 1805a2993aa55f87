#include "fem/element/kinematics.hpp"

#include "fem/core/error.hpp"
#include "fem/core/nearest_name.hpp"

#include <vector>

namespace bipot {

int spatial_dim(Kinematics kin) {
  return kin == Kinematics::ThreeD ? 3 : 2;
}

std::string to_string(Kinematics kin) {
  switch (kin) {
  case Kinematics::PlaneStrain:
    return "plane_strain";
  case Kinematics::Axisymmetric:
    return "axisymmetric";
  case Kinematics::ThreeD:
    return "three_d";
  }
  return "?";
}

Kinematics parse_kinematics(const std::string& name) {
  const Kinematics all[] = {Kinematics::PlaneStrain, Kinematics::Axisymmetric, Kinematics::ThreeD};
  std::vector<std::string> names;
  for (Kinematics k : all) {
    if (to_string(k) == name) return k;
    names.push_back(to_string(k));
  }
  std::string msg = "unknown kinematics '" + name + "'";
  const std::string near = nearest_name(name, names);
  if (!near.empty()) msg += "; did you mean '" + near + "'?";
  throw InputError(msg + " (allowed: " + join_names(names) + ")");
}

} // namespace bipot
