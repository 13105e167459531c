#pragma once
// base_local_planner's TrajectoryPlannerROS (the default base_local_planner, parameters in
// ~TrajectoryPlannerROS) and dwa_local_planner's DWAPlannerROS (~DWAPlannerROS), on
// navigation_core's trajectory rollout: follows the global plan on the local costmap, stops and
// turns to the goal's yaw at the goal, publishes ~<name>/global_plan and ~<name>/local_plan.
#include <ros/ros.h>
#include <tf2_ros/buffer.h>

#include <mutex>
#include <set>
#include <string>
#include <vector>

#include <geometry_msgs/PoseStamped.h>
#include <geometry_msgs/Twist.h>
#include <nav_msgs/Odometry.h>

#include "move_base/costmap_ros.h"
#include "navigation_core/goal_approach.h"
#include "navigation_core/local_planner.h"

namespace move_base {

class LocalPlannerROS {
 public:
  // `type`: the base_local_planner value. Throws std::invalid_argument for a planner we lack.
  LocalPlannerROS(const std::string& type, CostmapROS& costmap, tf2_ros::Buffer& tf, double controller_frequency);

  // A new global plan (poses in its header's frame).
  bool setPlan(const std::vector<geometry_msgs::PoseStamped>& plan);
  // The command for now; false, with the reason, when no safe one was found.
  bool computeVelocityCommands(geometry_msgs::Twist& command, std::string* why);
  bool isGoalReached() const { return reached_; }

  const std::string& name() const { return name_; }

 private:
  void onOdometry(const nav_msgs::OdometryConstPtr& odom);
  navigation_core::Velocity2 velocity();
  // The plan in the local costmap's frame from the point nearest the robot on; false without tf.
  bool remainingPlan(const navigation_core::Pose2& pose, std::vector<navigation_core::Point2>& points,
                     navigation_core::Pose2& goal, std::string* why);
  void publishPlans(const std::vector<navigation_core::Point2>& remaining, const navigation_core::Trajectory* local);

  std::string name_;
  CostmapROS& costmap_;
  tf2_ros::Buffer& tf_;
  navigation_core::LocalPlannerOptions options_;
  navigation_core::GoalApproachOptions approach_options_;
  std::unique_ptr<navigation_core::LocalPlanner> planner_;
  std::unique_ptr<navigation_core::GoalApproach> approach_;
  bool prune_plan_ = true;

  std::vector<geometry_msgs::PoseStamped> plan_;
  std::size_t progress_ = 0;  // index of the plan point nearest the robot
  bool reached_ = false;

  std::mutex odom_mutex_;
  bool have_odom_ = false;
  navigation_core::Velocity2 odom_velocity_, last_command_;
  ros::Subscriber odom_sub_;
  ros::Publisher global_plan_pub_, local_plan_pub_;
};

}  // namespace move_base
