#pragma once
// The node's two message conversions: the planar velocity measured in a nav_msgs/Odometry and
// the planar velocity command the drive takes.
#include <geometry_msgs/Twist.h>
#include <nav_msgs/Odometry.h>

#include "pioneer_ros/body_velocity_controller.h"

namespace pioneer_ros {

// Forward speed and yaw rate of an odometry message, whose twist is in the robot frame (REP 105).
inline PlanarVelocity planarVelocity(const nav_msgs::Odometry& odometry) {
  return PlanarVelocity{odometry.twist.twist.linear.x, odometry.twist.twist.angular.z};
}

// A command with linear.x (m/s) and angular.z (rad/s), the rest 0.
inline geometry_msgs::Twist twistMessage(const PlanarVelocity& velocity) {
  geometry_msgs::Twist msg;
  msg.linear.x = velocity.linear;
  msg.angular.z = velocity.angular;
  return msg;
}

}  // namespace pioneer_ros
