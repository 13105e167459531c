// pioneer_ros's message conversions: the planar velocity in an odometry message and the planar
// command (message types only, no ROS master).
#include <gtest/gtest.h>

#include "pioneer_ros/velocity_messages.h"

namespace pioneer_ros {
namespace {

TEST(VelocityMessages, PlanarVelocityIsTheForwardSpeedAndYawRate) {
  nav_msgs::Odometry odometry;
  odometry.twist.twist.linear.x = 0.5;
  odometry.twist.twist.linear.y = 0.1;  // sideways slip: not a planar velocity component
  odometry.twist.twist.angular.z = 0.2;
  const PlanarVelocity velocity = planarVelocity(odometry);
  EXPECT_EQ(velocity.linear, 0.5);
  EXPECT_EQ(velocity.angular, 0.2);
}

TEST(VelocityMessages, TwistMessageIsPlanar) {
  const geometry_msgs::Twist msg = twistMessage({0.3, -0.4});
  EXPECT_EQ(msg.linear.x, 0.3);
  EXPECT_EQ(msg.linear.y, 0.0);
  EXPECT_EQ(msg.linear.z, 0.0);
  EXPECT_EQ(msg.angular.x, 0.0);
  EXPECT_EQ(msg.angular.y, 0.0);
  EXPECT_EQ(msg.angular.z, -0.4);
}

}  // namespace
}  // namespace pioneer_ros
