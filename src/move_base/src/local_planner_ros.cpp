#include "move_base/local_planner_ros.h"

#include <cmath>
#include <stdexcept>

#include <nav_msgs/Path.h>
#include <tf2/utils.h>
#include <tf2_geometry_msgs/tf2_geometry_msgs.h>

#include "move_base/ros_params.h"
#include "ros_params/reader.h"

namespace move_base {

namespace nc = navigation_core;

namespace {

// ~TrajectoryPlannerROS, with base_local_planner's defaults.
void readTrajectoryPlanner(ros_params::Reader& r, nc::LocalPlannerOptions& o, nc::GoalApproachOptions& g) {
  o.acc_lim_x = r.get("acc_lim_x", 2.5);
  o.acc_lim_theta = r.getRenamed("acc_lim_theta", "acc_lim_th", 3.2);
  o.max_vel_x = r.get("max_vel_x", 0.5);
  o.min_vel_x = r.get("min_vel_x", 0.1);
  o.max_vel_theta = r.get("max_vel_theta", 1.0);
  o.min_vel_theta = r.get("min_vel_theta", -1.0);
  o.min_in_place_vel_theta = r.get("min_in_place_vel_theta", 0.4);
  o.escape_vel = r.getRenamed("escape_vel", "backup_vel", -0.1);
  o.sim_time = r.get("sim_time", 1.0);
  o.sim_granularity = r.get("sim_granularity", 0.025);
  o.angular_sim_granularity = r.get("angular_sim_granularity", o.sim_granularity);
  o.vx_samples = r.get("vx_samples", 3);
  o.vtheta_samples = r.get("vtheta_samples", 20);
  o.meter_scoring = r.get("meter_scoring", false);
  o.path_distance_bias = r.get("pdist_scale", 0.6);
  o.goal_distance_bias = r.get("gdist_scale", 0.8);
  o.occdist_scale = r.get("occdist_scale", 0.01);
  o.heading_lookahead = r.get("heading_lookahead", 0.325);
  o.dwa = r.get("dwa", true);
  if (r.get("holonomic_robot", true))
    ROS_INFO("%s/holonomic_robot is true (base_local_planner's default): this planner samples no sideways "
             "velocities, as for the differential and skid-steer robots it drives.", r.path("").c_str());
  g.xy_goal_tolerance = r.get("xy_goal_tolerance", 0.10);
  g.yaw_goal_tolerance = r.get("yaw_goal_tolerance", 0.05);
  g.latch_xy_goal_tolerance = r.get("latch_xy_goal_tolerance", false);
  g.trans_stopped_vel = g.rot_stopped_vel = 1e-2;  // TrajectoryPlannerROS's fixed values
  g.max_vel_theta = o.max_vel_theta;
  g.min_in_place_vel_theta = o.min_in_place_vel_theta;
}

// ~DWAPlannerROS, with dwa_local_planner's defaults; the names it had before Kinetic are honoured
// with a warning (upstream ignores some of them silently).
void readDwaPlanner(ros_params::Reader& r, nc::LocalPlannerOptions& o, nc::GoalApproachOptions& g) {
  o.acc_lim_x = r.get("acc_lim_x", 2.5);
  o.acc_lim_theta = r.getRenamed("acc_lim_theta", "acc_lim_th", 3.2);
  const double max_trans = r.getRenamed("max_vel_trans", "max_trans_vel", 0.55);
  const double min_trans = r.getRenamed("min_vel_trans", "min_trans_vel", 0.1);
  o.max_vel_x = std::min(r.get("max_vel_x", 0.55), max_trans);
  o.min_vel_x = r.get("min_vel_x", 0.0);
  const double max_rot = r.getRenamed("max_vel_theta", "max_rot_vel", 1.0);
  const double min_rot = r.getRenamed("min_vel_theta", "min_rot_vel", 0.4);
  o.max_vel_theta = max_rot;
  o.min_vel_theta = -max_rot;
  o.min_in_place_vel_theta = min_rot;
  o.min_vel_trans = min_trans;
  o.escape_vel = -std::max(min_trans, 0.1);
  o.sim_time = r.get("sim_time", 1.7);
  o.sim_granularity = r.get("sim_granularity", 0.025);
  o.angular_sim_granularity = r.get("angular_sim_granularity", 0.1);
  o.vx_samples = r.get("vx_samples", 3);
  o.vtheta_samples = r.getRenamed("vth_samples", "vtheta_samples", 20);
  // DWA scales its biases by the costmap's resolution: distances in metres.
  o.meter_scoring = true;
  o.path_distance_bias = r.get("path_distance_bias", 32.0);
  o.goal_distance_bias = r.get("goal_distance_bias", 24.0);
  o.occdist_scale = r.get("occdist_scale", 0.01);
  o.heading_lookahead = r.get("forward_point_distance", 0.325);
  o.dwa = r.get("use_dwa", true);
  if (r.get("max_vel_y", 0.1) != 0.0 || r.get("min_vel_y", -0.1) != 0.0)
    ROS_INFO("%s: max_vel_y / min_vel_y are not zero: this planner samples no sideways velocities, as for the "
             "differential and skid-steer robots it drives.", r.path("").c_str());
  g.xy_goal_tolerance = r.get("xy_goal_tolerance", 0.10);
  g.yaw_goal_tolerance = r.get("yaw_goal_tolerance", 0.05);
  g.latch_xy_goal_tolerance = r.get("latch_xy_goal_tolerance", false);
  g.trans_stopped_vel = r.get("trans_stopped_vel", 0.1);
  g.rot_stopped_vel = r.getRenamed("theta_stopped_vel", "rot_stopped_vel", 0.1);
  g.max_vel_theta = max_rot;
  g.min_in_place_vel_theta = min_rot;
}

// Upstream's parameters of each planner that this one accepts without reading: they change nothing
// here (publishing debug clouds, scoring variants it does not have). Not warned about.
const std::set<std::string>& acceptedWithoutEffect(const std::string& name) {
  static const std::set<std::string> trajectory = {
      "acc_lim_y", "y_vels", "heading_scoring", "heading_scoring_timestep", "publish_cost_grid_pc", "global_frame_id",
      "oscillation_reset_dist", "escape_reset_dist", "escape_reset_theta", "simple_attractor", "max_rotational_vel",
      "min_in_place_rotational_vel"};
  static const std::set<std::string> dwa = {
      "acc_lim_y", "acc_lim_trans", "vy_samples", "stop_time_buffer", "scaling_speed", "max_scaling_factor",
      "oscillation_reset_dist", "oscillation_reset_angle", "publish_traj_pc", "publish_cost_grid_pc",
      "global_frame_id", "restore_defaults", "twirling_scale", "holonomic_robot"};
  return name == "DWAPlannerROS" ? dwa : trajectory;
}

}  // namespace

LocalPlannerROS::LocalPlannerROS(const std::string& type, CostmapROS& costmap, tf2_ros::Buffer& tf,
                                 double controller_frequency)
    : costmap_(costmap), tf_(tf) {
  if (type == "base_local_planner/TrajectoryPlannerROS") {
    name_ = "TrajectoryPlannerROS";
  } else if (type == "dwa_local_planner/DWAPlannerROS") {
    name_ = "DWAPlannerROS";
  } else {
    throw std::invalid_argument("base_local_planner: \"" + type + "\" is not a planner this move_base has "
                                "(base_local_planner/TrajectoryPlannerROS, dwa_local_planner/DWAPlannerROS)");
  }
  ros::NodeHandle nh("~" + name_);
  ros_params::Reader params(nh);
  if (name_ == "DWAPlannerROS") readDwaPlanner(params, options_, approach_options_);
  else readTrajectoryPlanner(params, options_, approach_options_);
  // The control period: the planner's own controller_frequency, else move_base's.
  const double frequency = params.get("controller_frequency", controller_frequency);
  options_.sim_period = frequency > 0 ? 1.0 / frequency : 0.05;
  approach_options_.acc_lim_x = options_.acc_lim_x;
  approach_options_.acc_lim_theta = options_.acc_lim_theta;
  approach_options_.sim_period = options_.sim_period;
  prune_plan_ = params.get("prune_plan", true);
  planner_ = std::make_unique<nc::LocalPlanner>(options_);
  approach_ = std::make_unique<nc::GoalApproach>(approach_options_);

  ros::NodeHandle node;
  odom_sub_ = node.subscribe(params.get<std::string>("odom_topic", "odom"), 1, &LocalPlannerROS::onOdometry, this);
  reportParams(params, acceptedWithoutEffect(name_));
  global_plan_pub_ = nh.advertise<nav_msgs::Path>("global_plan", 1);
  local_plan_pub_ = nh.advertise<nav_msgs::Path>("local_plan", 1);
}

void LocalPlannerROS::onOdometry(const nav_msgs::OdometryConstPtr& odom) {
  std::lock_guard<std::mutex> guard(odom_mutex_);
  have_odom_ = true;
  odom_velocity_.x = odom->twist.twist.linear.x;
  odom_velocity_.y = odom->twist.twist.linear.y;
  odom_velocity_.theta = odom->twist.twist.angular.z;
}

nc::Velocity2 LocalPlannerROS::velocity() {
  std::lock_guard<std::mutex> guard(odom_mutex_);
  if (have_odom_) return odom_velocity_;
  // Without odometry upstream plans as if the robot stood still; the last command is closer.
  ROS_WARN_ONCE("%s: no odometry on %s yet: taking the robot's velocity to be the last command.", name_.c_str(),
                odom_sub_.getTopic().c_str());
  return last_command_;
}

bool LocalPlannerROS::setPlan(const std::vector<geometry_msgs::PoseStamped>& plan) {
  if (plan.empty()) return false;
  plan_ = plan;
  progress_ = 0;
  reached_ = false;
  approach_->reset();
  return true;
}

bool LocalPlannerROS::remainingPlan(const nc::Pose2& pose, std::vector<nc::Point2>& points, nc::Pose2& goal,
                                    std::string* why) {
  const std::string& frame = costmap_.globalFrame();
  tf2::Transform to_local = tf2::Transform::getIdentity();
  const std::string plan_frame = frameId(plan_.front().header.frame_id);
  if (!plan_frame.empty() && plan_frame != frame) {
    try {
      tf2::fromMsg(tf_.lookupTransform(frame, plan_frame, ros::Time(0)).transform, to_local);
    } catch (const tf2::TransformException& e) {
      if (why) *why = "cannot transform the global plan from " + plan_frame + " to " + frame + ": " + e.what();
      return false;
    }
  }
  std::vector<nc::Pose2> poses;
  poses.reserve(plan_.size());
  for (const auto& p : plan_) {
    tf2::Transform t;
    tf2::fromMsg(p.pose, t);
    t = to_local * t;
    poses.push_back({t.getOrigin().x(), t.getOrigin().y(), tf2::getYaw(t.getRotation())});
  }
  goal = poses.back();
  // The robot's place on the plan: the nearest point within 1.5 m of path after the last one (a
  // point farther along may lie nearer, on the far side of a wall).
  if (prune_plan_) {
    double best = std::hypot(poses[progress_].x - pose.x, poses[progress_].y - pose.y), along = 0.0;
    std::size_t best_index = progress_;
    for (std::size_t i = progress_ + 1; i < poses.size() && along < 1.5; ++i) {
      along += std::hypot(poses[i].x - poses[i - 1].x, poses[i].y - poses[i - 1].y);
      const double d = std::hypot(poses[i].x - pose.x, poses[i].y - pose.y);
      if (d < best) best = d, best_index = i;
    }
    progress_ = best_index;
  }
  points.clear();
  for (std::size_t i = prune_plan_ ? progress_ : 0; i < poses.size(); ++i) points.push_back({poses[i].x, poses[i].y});
  return true;
}

bool LocalPlannerROS::computeVelocityCommands(geometry_msgs::Twist& command, std::string* why) {
  command = geometry_msgs::Twist();
  if (plan_.empty()) {
    if (why) *why = "no plan";
    return false;
  }
  nc::Pose2 pose;
  if (!costmap_.robotPose(pose)) {
    if (why) *why = "no robot pose in " + costmap_.globalFrame();
    return false;
  }
  std::vector<nc::Point2> remaining;
  nc::Pose2 goal;
  if (!remainingPlan(pose, remaining, goal, why)) return false;
  const nc::Velocity2 now = velocity();
  nc::Velocity2 cmd;
  nc::Trajectory best;
  bool ok = true;
  const nc::GoalPhase phase = approach_->update(pose, now, goal, cmd);
  {
    auto lock = costmap_.lock();
    if (phase == nc::GoalPhase::kApproaching) {
      ok = planner_->computeVelocity(costmap_.costmap(), costmap_.footprint(), pose, now, remaining, best, why);
      cmd = best.velocity;
      if (!ok && why)
        *why = "The rollout planner failed to find a valid plan. This means that the footprint of the robot was in "
               "collision for all simulated trajectories (" + *why + ")";
    } else if (phase == nc::GoalPhase::kTurning) {
      // As rotateToGoal: the turn kept up for sim_time must not bring the footprint onto an obstacle.
      const double angle = std::abs(cmd.theta) * options_.sim_time;
      const int steps = std::max(1, static_cast<int>(std::ceil(angle / options_.angular_sim_granularity)));
      for (int k = 1; k <= steps && ok; ++k) {
        const nc::Pose2 turned{pose.x, pose.y, pose.theta + cmd.theta * options_.sim_time * k / steps};
        ok = planner_->footprintCost(costmap_.costmap(), costmap_.footprint(), turned) >= 0;
      }
      if (!ok && why) *why = "turning in place to the goal's yaw would bring the footprint onto an obstacle";
    }
  }
  reached_ = phase == nc::GoalPhase::kReached;
  if (!ok) cmd = nc::Velocity2();
  command.linear.x = cmd.x;
  command.linear.y = cmd.y;
  command.angular.z = cmd.theta;
  {
    std::lock_guard<std::mutex> guard(odom_mutex_);
    last_command_ = cmd;
  }
  publishPlans(remaining, phase == nc::GoalPhase::kApproaching && ok ? &best : nullptr);
  return ok;
}

void LocalPlannerROS::publishPlans(const std::vector<nc::Point2>& remaining, const nc::Trajectory* local) {
  nav_msgs::Path path;
  path.header.frame_id = costmap_.globalFrame();
  path.header.stamp = ros::Time::now();
  geometry_msgs::PoseStamped pose;
  pose.header = path.header;
  pose.pose.orientation.w = 1.0;
  for (const nc::Point2& p : remaining) {
    pose.pose.position.x = p.x;
    pose.pose.position.y = p.y;
    path.poses.push_back(pose);
  }
  global_plan_pub_.publish(path);
  path.poses.clear();
  if (local) {
    for (const nc::Pose2& p : local->poses) {
      pose.pose.position.x = p.x;
      pose.pose.position.y = p.y;
      tf2::Quaternion q;
      q.setRPY(0, 0, p.theta);
      pose.pose.orientation = tf2::toMsg(q);
      path.poses.push_back(pose);
    }
  }
  local_plan_pub_.publish(path);
}

}  // namespace move_base
