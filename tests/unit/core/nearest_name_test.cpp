#include "fem/core/nearest_name.hpp"

#include <gtest/gtest.h>

namespace bipot {
namespace {

TEST(NearestName, EditDistanceClosedForms) {
  EXPECT_EQ(edit_distance("", ""), 0);
  EXPECT_EQ(edit_distance("abc", ""), 3);
  EXPECT_EQ(edit_distance("kitten", "sitting"), 3); // textbook example
  EXPECT_EQ(edit_distance("flaw", "lawn"), 2);
}

TEST(NearestName, SuggestsCloseNamesOnly) {
  const std::vector<std::string> keys = {"youngs_modulus", "poissons_ratio", "unit_weight"};
  EXPECT_EQ(nearest_name("youngs_modulos", keys), "youngs_modulus");
  EXPECT_EQ(nearest_name("unit_wieght", keys), "unit_weight");
  EXPECT_EQ(nearest_name("density", keys), "");
  EXPECT_EQ(join_names(keys), "youngs_modulus, poissons_ratio, unit_weight");
}

} // namespace
} // namespace bipot
