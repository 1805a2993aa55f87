#include "fem/element/kinematics.hpp"

#include "fem/core/error.hpp"

#include <gtest/gtest.h>

namespace bipot {
namespace {

TEST(Kinematics, NamesRoundTripAndDimensions) {
  for (Kinematics k : {Kinematics::PlaneStrain, Kinematics::Axisymmetric, Kinematics::ThreeD})
    EXPECT_EQ(parse_kinematics(to_string(k)), k);
  EXPECT_EQ(to_string(Kinematics::PlaneStrain), "plane_strain");
  EXPECT_EQ(to_string(Kinematics::Axisymmetric), "axisymmetric");
  EXPECT_EQ(to_string(Kinematics::ThreeD), "three_d");
  EXPECT_EQ(spatial_dim(Kinematics::PlaneStrain), 2);
  EXPECT_EQ(spatial_dim(Kinematics::Axisymmetric), 2);
  EXPECT_EQ(spatial_dim(Kinematics::ThreeD), 3);
}

TEST(Kinematics, UnknownNameSuggestsNearest) {
  try {
    parse_kinematics("plane_stain");
    FAIL() << "no exception";
  } catch (const InputError& e) {
    EXPECT_STREQ(e.what(), "unknown kinematics 'plane_stain'; did you mean 'plane_strain'? "
                           "(allowed: plane_strain, axisymmetric, three_d)");
  }
  EXPECT_THROW(parse_kinematics("3d_solid_of_doom"), InputError);
}

} // namespace
} // namespace bipot
