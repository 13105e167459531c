#ifndef HECTOR_STYLE_MAPPING_ROS_SCAN_INPUT_H
#define HECTOR_STYLE_MAPPING_ROS_SCAN_INPUT_H

#include <cmath>

#include <Eigen/Geometry>
#include <geometry_msgs/Transform.h>
#include <ros/time.h>

namespace hector_style_mapping {

// What a scan's stamp says against the last accepted one.
enum class StampOrder {
  kNewer,           // later than the last (or the first scan)
  kClockRestarted,  // more than kTimeResetSeconds earlier: a simulator reset or a bag loop, not a late scan
  kStale,           // no later than the last, and not by that much: drop the scan
};

// The stamps of the scans a mapping node accepted, shared by hector_mapping and slam_gmapping.
class ScanStamps {
 public:
  static constexpr double kTimeResetSeconds = 1.0;

  // Classifies `stamp`; unless it is stale, it becomes the last one.
  StampOrder accept(const ros::Time& stamp) {
    if (last_.isZero() || stamp > last_) {
      last_ = stamp;
      return StampOrder::kNewer;
    }
    if ((last_ - stamp).toSec() > kTimeResetSeconds) {
      last_ = stamp;
      return StampOrder::kClockRestarted;
    }
    return StampOrder::kStale;
  }
  const ros::Time& last() const { return last_; }

 private:
  ros::Time last_;
};

inline Eigen::Isometry3d isometryOf(const geometry_msgs::Transform& t) {
  Eigen::Isometry3d result = Eigen::Isometry3d::Identity();
  const auto& r = t.rotation;
  result.linear() = Eigen::Quaterniond(r.w, r.x, r.y, r.z).normalized().toRotationMatrix();
  result.translation() = Eigen::Vector3d(t.translation.x, t.translation.y, t.translation.z);
  return result;
}

}  // namespace hector_style_mapping

#endif  // HECTOR_STYLE_MAPPING_ROS_SCAN_INPUT_H
