// The suggestion for a misspelt parameter name.
#include <gtest/gtest.h>

#include "ros_params/nearest_name.h"

using ros_params::editDistance;
using ros_params::nearestName;

TEST(EditDistance, CountsInsertionsDeletionsAndSubstitutions) {
  EXPECT_EQ(editDistance("", ""), 0u);
  EXPECT_EQ(editDistance("map_size", "map_size"), 0u);
  EXPECT_EQ(editDistance("map_size", "map_sze"), 1u);     // a deletion
  EXPECT_EQ(editDistance("map_size", "map_sizes"), 1u);   // an insertion
  EXPECT_EQ(editDistance("max_vel_x", "max_vel_y"), 1u);  // a substitution
  EXPECT_EQ(editDistance("kitten", "sitting"), 3u);
  EXPECT_EQ(editDistance("abc", ""), 3u);
}

TEST(NearestName, SuggestsTheClosestWithinThreeEditsElseNothing) {
  const std::set<std::string> known{"map_resolution", "map_size", "map_start_x", "controller_frequency"};
  EXPECT_EQ(nearestName("map_sise", known), "map_size");
  EXPECT_EQ(nearestName("controler_frequency", known), "controller_frequency");
  EXPECT_EQ(nearestName("map_start_y", known), "map_start_x");
  EXPECT_EQ(nearestName("odom_frame", known), "");  // nothing close: no suggestion
  EXPECT_EQ(nearestName("map_size", {}), "");
  EXPECT_EQ(nearestName("mapsize_xx", known, 1), "");  // 3 edits from map_size, 1 allowed
}
