#include "bullet_sim_plugins/ros_conversions.h"

#include <cmath>

namespace bullet_sim {

geometry_msgs::Pose toPoseMsg(const Eigen::Isometry3d& pose) {
  geometry_msgs::Pose msg;
  msg.position.x = pose.translation().x();
  msg.position.y = pose.translation().y();
  msg.position.z = pose.translation().z();
  const Eigen::Quaterniond q(pose.linear());
  msg.orientation.x = q.x();
  msg.orientation.y = q.y();
  msg.orientation.z = q.z();
  msg.orientation.w = q.w();
  return msg;
}

geometry_msgs::Vector3 toVector3Msg(const Eigen::Vector3d& v) {
  geometry_msgs::Vector3 msg;
  msg.x = v.x();
  msg.y = v.y();
  msg.z = v.z();
  return msg;
}

geometry_msgs::Twist toTwistMsg(const Twist& twist) {
  geometry_msgs::Twist msg;
  msg.linear = toVector3Msg(twist.linear);
  msg.angular = toVector3Msg(twist.angular);
  return msg;
}

Eigen::Vector3d toEigen(const geometry_msgs::Vector3& v) { return Eigen::Vector3d(v.x, v.y, v.z); }
Eigen::Vector3d toEigen(const geometry_msgs::Point& p) { return Eigen::Vector3d(p.x, p.y, p.z); }

Twist toTwist(const geometry_msgs::Twist& msg) {
  Twist t;
  t.linear = toEigen(msg.linear);
  t.angular = toEigen(msg.angular);
  return t;
}

bool isFinite(const geometry_msgs::Vector3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }
bool isFinite(const geometry_msgs::Twist& msg) { return isFinite(msg.linear) && isFinite(msg.angular); }

bool toPose(const geometry_msgs::Pose& msg, const std::string& field, Eigen::Isometry3d& pose, std::string& error) {
  const auto& p = msg.position;
  const auto& o = msg.orientation;
  for (double v : {p.x, p.y, p.z, o.x, o.y, o.z, o.w}) {
    if (!std::isfinite(v)) {
      error = field + ": expected finite numbers in position and orientation";
      return false;
    }
  }
  Eigen::Quaterniond q(o.w, o.x, o.y, o.z);
  if (q.norm() < 1e-9) q = Eigen::Quaterniond::Identity();
  pose = Eigen::Isometry3d::Identity();
  pose.linear() = q.normalized().toRotationMatrix();
  pose.translation() = Eigen::Vector3d(p.x, p.y, p.z);
  return true;
}

}  // namespace bullet_sim
