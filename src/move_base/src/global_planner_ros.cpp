#include "move_base/global_planner_ros.h"

#include <stdexcept>

#include <nav_msgs/Path.h>

#include "move_base/ros_params.h"
#include "ros_params/reader.h"

namespace move_base {

namespace nc = navigation_core;

namespace {

nc::NavfnOptions readOptions(ros_params::Reader& r, bool global_planner) {
  nc::NavfnOptions o;
  o.allow_unknown = r.get("allow_unknown", true);
  o.default_tolerance = r.get("default_tolerance", 0.0);
  if (global_planner) {
    // global_planner's other choices change its paths; we plan as navfn (its old_navfn_behavior).
    if (!r.get("use_dijkstra", true) || r.get("use_grid_path", false) || !r.get("use_quadratic", true))
      ROS_WARN("%s: use_dijkstra, use_quadratic and use_grid_path are not honoured: this GlobalPlanner plans as navfn "
               "does (Dijkstra, quadratic interpolation, gradient descent).", r.path("").c_str());
  }
  return o;
}

// Upstream's parameters that this planner accepts without reading: they change nothing here.
const std::set<std::string> kAcceptedWithoutEffect = {
    "visualize_potential", "planner_window_x", "planner_window_y", "planner_costmap_publish_frequency",
    "old_navfn_behavior", "lethal_cost", "neutral_cost", "cost_factor", "publish_potential", "orientation_mode",
    "orientation_window_size", "outline_map", "use_dijkstra", "use_quadratic", "use_grid_path"};

}  // namespace

GlobalPlannerROS::GlobalPlannerROS(const std::string& type, CostmapROS& costmap) : costmap_(costmap) {
  if (type == "navfn/NavfnROS") {
    name_ = "NavfnROS";
  } else if (type == "global_planner/GlobalPlanner") {
    name_ = "GlobalPlanner";
  } else {
    throw std::invalid_argument("base_global_planner: \"" + type +
                                "\" is not a planner this move_base has (navfn/NavfnROS, global_planner/GlobalPlanner)");
  }
  ros::NodeHandle nh("~" + name_);
  ros_params::Reader params(nh);
  planner_ = nc::NavfnPlanner(readOptions(params, name_ == "GlobalPlanner"));
  reportParams(params, kAcceptedWithoutEffect);
  plan_pub_ = nh.advertise<nav_msgs::Path>("plan", 1);
  make_plan_srv_ = nh.advertiseService("make_plan", &GlobalPlannerROS::onMakePlan, this);
}

bool GlobalPlannerROS::makePlan(const geometry_msgs::PoseStamped& start, const geometry_msgs::PoseStamped& goal,
                                double tolerance, std::vector<geometry_msgs::PoseStamped>& plan, std::string* why) {
  plan.clear();
  std::vector<nc::Point2> points;
  {
    std::lock_guard<std::mutex> planning(mutex_);
    auto costs = costmap_.lock();
    points = planner_.makePlan(costmap_.costmap(), {start.pose.position.x, start.pose.position.y},
                               {goal.pose.position.x, goal.pose.position.y}, tolerance, why);
  }
  nav_msgs::Path path;
  path.header.frame_id = costmap_.globalFrame();
  path.header.stamp = ros::Time::now();
  for (const nc::Point2& p : points) {
    geometry_msgs::PoseStamped pose;
    pose.header = path.header;
    pose.pose.position.x = p.x;
    pose.pose.position.y = p.y;
    pose.pose.orientation.w = 1.0;
    plan.push_back(pose);
  }
  // As navfn: the plan ends facing as the goal does (at the goal, or at the reachable point nearest it).
  if (!plan.empty()) plan.back().pose.orientation = goal.pose.orientation;
  path.poses = plan;
  plan_pub_.publish(path);
  return !plan.empty();
}

bool GlobalPlannerROS::onMakePlan(nav_msgs::GetPlan::Request& request, nav_msgs::GetPlan::Response& response) {
  std::string why;
  if (!makePlan(request.start, request.goal, request.tolerance, response.plan.poses, &why))
    ROS_WARN("%s make_plan: %s", name_.c_str(), why.c_str());
  response.plan.header.frame_id = costmap_.globalFrame();
  response.plan.header.stamp = ros::Time::now();
  return true;
}

}  // namespace move_base
