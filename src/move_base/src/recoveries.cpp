#include "move_base/recoveries.h"

#include <cmath>

#include <geometry_msgs/Twist.h>

#include "move_base/ros_params.h"
#include "ros_params/reader.h"
#include "navigation_core/goal_approach.h"
#include "navigation_core/local_planner.h"

namespace move_base {

namespace nc = navigation_core;

ClearCostmapRecovery::ClearCostmapRecovery(const std::string& name, CostmapROS& global, CostmapROS& local)
    : global_(global), local_(local) {
  ros::NodeHandle nh("~" + name);
  ros_params::Reader params(nh);
  reset_distance_ = params.get("reset_distance", 3.0);
  affected_maps_ = params.get<std::string>("affected_maps", "both");
  if (affected_maps_ != "both" && affected_maps_ != "global" && affected_maps_ != "local") {
    ROS_ERROR("%s/affected_maps: \"%s\" is none of local, global, both; clearing both.", nh.getNamespace().c_str(),
              affected_maps_.c_str());
    affected_maps_ = "both";
  }
  if (params.get("invert_area_to_clear", false))
    ROS_WARN("%s/invert_area_to_clear is not supported: the area outside the window is cleared.",
             nh.getNamespace().c_str());
  reportParams(params, {"layer_names", "force_updating"});  // upstream's; every obstacle layer is cleared here
}

void ClearCostmapRecovery::run() {
  // Every obstacle layer, whatever its name: upstream's default layer_names ["obstacles"] misses
  // layers named otherwise (obstacle_layer, obstacles_laser, ...), and then clears nothing.
  for (CostmapROS* costmap : {&global_, &local_}) {
    if ((costmap == &global_ && affected_maps_ == "local") || (costmap == &local_ && affected_maps_ == "global"))
      continue;
    nc::Pose2 pose;
    if (!costmap->robotPose(pose)) {
      ROS_WARN("%s: cannot clear the %s without the robot's pose.", name.c_str(), costmap->name().c_str());
      continue;
    }
    costmap->resetObstaclesOutside(pose.x, pose.y, reset_distance_);
  }
  ROS_WARN("Clearing %s costmap%s outside a square (%.2fm) large centered on the robot.",
           affected_maps_ == "both" ? "both" : affected_maps_.c_str(), affected_maps_ == "both" ? "s" : "",
           reset_distance_);
}

RotateRecovery::RotateRecovery(const std::string& name, CostmapROS& local, ros::Publisher& cmd_vel)
    : local_(local), cmd_vel_(cmd_vel) {
  ros_params::Reader params(ros::NodeHandle("~" + name));
  sim_granularity_ = params.get("sim_granularity", 0.017);
  frequency_ = params.get("frequency", 20.0);
  reportParams(params);
  // As upstream's rotate_recovery: the turn's limits are base_local_planner's, whichever planner runs
  // (the local planner's own reader reports that namespace when it is TrajectoryPlannerROS).
  ros_params::Reader blp(ros::NodeHandle("~TrajectoryPlannerROS"));
  acc_lim_theta_ = blp.getRenamed("acc_lim_theta", "acc_lim_th", 3.2);
  max_vel_theta_ = blp.getRenamed("max_vel_theta", "max_rotational_vel", 1.0);
  min_in_place_vel_theta_ = blp.getRenamed("min_in_place_vel_theta", "min_in_place_rotational_vel", 0.4);
  tolerance_ = blp.get("yaw_goal_tolerance", 0.10);
  for (const std::string& problem : blp.problemList()) ROS_ERROR("%s; using the default.", problem.c_str());
}

void RotateRecovery::run() {
  ROS_WARN("Rotate recovery behavior started.");
  nc::Pose2 pose;
  if (!local_.robotPose(pose)) {
    ROS_ERROR("Rotate recovery: no robot pose in %s; not rotating.", local_.globalFrame().c_str());
    return;
  }
  ros::Rate rate(frequency_);
  double last_yaw = pose.theta, turned = 0.0;
  // A robot that cannot turn (stuck, or its drive off) is given up on after a generous time.
  const ros::Time deadline = ros::Time::now() + ros::Duration(3.0 * 2 * M_PI / std::max(0.05, min_in_place_vel_theta_) + 5.0);
  geometry_msgs::Twist twist;
  while (ros::ok() && turned < 2 * M_PI - tolerance_ && ros::Time::now() < deadline) {
    if (!local_.robotPose(pose)) break;
    turned += std::abs(nc::angleDifference(pose.theta, last_yaw));
    last_yaw = pose.theta;
    const double left = std::max(0.0, 2 * M_PI - turned);
    {
      auto lock = local_.lock();
      for (double a = 0.0; a < left; a += sim_granularity_) {
        const double cost = nc::LocalPlanner::footprintCost(local_.costmap(), local_.footprint(),
                                                            {pose.x, pose.y, pose.theta + a});
        if (cost < 0) {
          ROS_WARN("Rotate recovery can't rotate in place because there is a potential collision. Cost: %.2f", cost);
          cmd_vel_.publish(geometry_msgs::Twist());
          return;
        }
      }
    }
    twist.angular.z = std::clamp(std::sqrt(2 * acc_lim_theta_ * left), min_in_place_vel_theta_, max_vel_theta_);
    cmd_vel_.publish(twist);
    rate.sleep();
  }
  cmd_vel_.publish(geometry_msgs::Twist());
}

std::vector<std::unique_ptr<RecoveryBehavior>> loadRecoveries(ros_params::Reader& params, CostmapROS& global,
                                                              CostmapROS& local, ros::Publisher& cmd_vel) {
  ros::NodeHandle nh("~");
  std::vector<std::unique_ptr<RecoveryBehavior>> behaviours;
  const auto add = [&](const std::string& name, const std::string& type) {
    std::unique_ptr<RecoveryBehavior> b;
    if (type == "clear_costmap_recovery/ClearCostmapRecovery") b = std::make_unique<ClearCostmapRecovery>(name, global, local);
    else if (type == "rotate_recovery/RotateRecovery") b = std::make_unique<RotateRecovery>(name, local, cmd_vel);
    if (!b) {
      ROS_ERROR("recovery_behaviors: %s has type %s, which this move_base does not have "
                "(clear_costmap_recovery/ClearCostmapRecovery, rotate_recovery/RotateRecovery); left out.",
                name.c_str(), type.c_str());
      return;
    }
    b->name = name;
    b->type = type;
    behaviours.push_back(std::move(b));
  };
  const bool rotate = params.get("clearing_rotation_allowed", true);
  const double conservative_reset_dist = params.get("conservative_reset_dist", 3.0);
  XmlRpc::XmlRpcValue list;
  if (params.read("recovery_behaviors", &list)) {
    if (list.getType() == XmlRpc::XmlRpcValue::TypeArray) {
      for (int i = 0; i < list.size(); ++i) {
        if (list[i].getType() == XmlRpc::XmlRpcValue::TypeStruct && list[i].hasMember("name") && list[i].hasMember("type"))
          add(static_cast<std::string>(list[i]["name"]), static_cast<std::string>(list[i]["type"]));
        else
          ROS_ERROR("recovery_behaviors[%d]: expected {name: ..., type: ...}; left out.", i);
      }
      return behaviours;
    }
    ROS_ERROR("recovery_behaviors: expected a list of {name: ..., type: ...}; using the default behaviours.");
  }
  // move_base's defaults, the resets' distances set as upstream sets them.
  nh.setParam("conservative_reset/reset_distance", conservative_reset_dist);
  nh.setParam("aggressive_reset/reset_distance", global.circumscribedRadius() * 4);
  add("conservative_reset", "clear_costmap_recovery/ClearCostmapRecovery");
  if (rotate) add("rotate_recovery", "rotate_recovery/RotateRecovery");
  add("aggressive_reset", "clear_costmap_recovery/ClearCostmapRecovery");
  if (rotate) add("rotate_recovery", "rotate_recovery/RotateRecovery");
  return behaviours;
}

}  // namespace move_base
