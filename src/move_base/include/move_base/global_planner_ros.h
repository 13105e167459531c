#pragma once
// navfn's NavfnROS (base_global_planner navfn/NavfnROS, parameters in ~NavfnROS) and, on the same
// planner, global_planner's GlobalPlanner (~GlobalPlanner): plans on the global costmap, published
// on ~<name>/plan, and the planner's own ~<name>/make_plan service.
#include <ros/ros.h>

#include <mutex>
#include <string>
#include <vector>

#include <geometry_msgs/PoseStamped.h>
#include <nav_msgs/GetPlan.h>

#include "move_base/costmap_ros.h"
#include "navigation_core/navfn_planner.h"

namespace move_base {

class GlobalPlannerROS {
 public:
  // `type`: the base_global_planner value. Throws std::invalid_argument for a planner we lack.
  GlobalPlannerROS(const std::string& type, CostmapROS& costmap);

  // A plan from start to goal (both in the costmap's global frame), the goal's pose last; within
  // `tolerance` of the goal if it cannot be reached (default_tolerance when negative). False, with
  // the reason, when there is none.
  bool makePlan(const geometry_msgs::PoseStamped& start, const geometry_msgs::PoseStamped& goal, double tolerance,
                std::vector<geometry_msgs::PoseStamped>& plan, std::string* why);

  const std::string& name() const { return name_; }

 private:
  bool onMakePlan(nav_msgs::GetPlan::Request& request, nav_msgs::GetPlan::Response& response);

  std::string name_;  // NavfnROS or GlobalPlanner
  CostmapROS& costmap_;
  navigation_core::NavfnPlanner planner_;
  std::mutex mutex_;
  ros::Publisher plan_pub_;
  ros::ServiceServer make_plan_srv_;
};

}  // namespace move_base
