#pragma once
// geometry_msgs <-> Eigen, with the finiteness checks every service request needs.
#include <geometry_msgs/Pose.h>
#include <geometry_msgs/Twist.h>
#include <geometry_msgs/Vector3.h>

#include <Eigen/Geometry>
#include <string>

#include "bullet_sim_core/physics_model.h"

namespace bullet_sim {

geometry_msgs::Pose toPoseMsg(const Eigen::Isometry3d& pose);
geometry_msgs::Twist toTwistMsg(const Twist& twist);
geometry_msgs::Vector3 toVector3Msg(const Eigen::Vector3d& v);
Eigen::Vector3d toEigen(const geometry_msgs::Vector3& v);
Eigen::Vector3d toEigen(const geometry_msgs::Point& p);
Twist toTwist(const geometry_msgs::Twist& msg);

// Pose from a message; a zero quaternion (an unset orientation) means identity, as in Gazebo.
// Returns false and fills `error` ("<field>: expected finite numbers") for NaN/inf.
bool toPose(const geometry_msgs::Pose& msg, const std::string& field, Eigen::Isometry3d& pose, std::string& error);
bool isFinite(const geometry_msgs::Twist& msg);
bool isFinite(const geometry_msgs::Vector3& msg);

}  // namespace bullet_sim
