#pragma once
// move_base's recovery behaviours: clear_costmap_recovery's ClearCostmapRecovery (obstacles outside
// a square about the robot forgotten) and rotate_recovery's RotateRecovery (a full turn in place,
// so the sensors see all round), named and configured as upstream's, in the order move_base runs
// them (its recovery_behaviors list, or its defaults).
#include <ros/ros.h>

#include <memory>
#include <string>
#include <vector>

#include "move_base/costmap_ros.h"
#include "ros_params/reader.h"

namespace move_base {

class RecoveryBehavior {
 public:
  virtual ~RecoveryBehavior() = default;
  virtual void run() = 0;
  std::string name, type;
};

class ClearCostmapRecovery : public RecoveryBehavior {
 public:
  ClearCostmapRecovery(const std::string& name, CostmapROS& global, CostmapROS& local);
  void run() override;

 private:
  CostmapROS& global_;
  CostmapROS& local_;
  double reset_distance_;
  std::string affected_maps_;
};

class RotateRecovery : public RecoveryBehavior {
 public:
  RotateRecovery(const std::string& name, CostmapROS& local, ros::Publisher& cmd_vel);
  void run() override;

 private:
  CostmapROS& local_;
  ros::Publisher& cmd_vel_;
  double sim_granularity_, frequency_, acc_lim_theta_, max_vel_theta_, min_in_place_vel_theta_, tolerance_;
};

// The behaviours of ~recovery_behaviors, or move_base's defaults (conservative_reset, rotate,
// aggressive_reset, rotate; the rotations only with clearing_rotation_allowed).
std::vector<std::unique_ptr<RecoveryBehavior>> loadRecoveries(ros_params::Reader& params, CostmapROS& global,
                                                              CostmapROS& local,
                                                              ros::Publisher& cmd_vel);

}  // namespace move_base
