#pragma once
// What base_local_planner's planners do once the robot is at its goal: within xy_goal_tolerance of
// the goal position (for good, with latch_xy_goal_tolerance) the robot stops, decelerating within
// its acceleration limits, then turns in place to the goal's yaw (without braking again for the
// turn's own speed); within yaw_goal_tolerance it has arrived.
#include "navigation_core/local_planner.h"

namespace navigation_core {

struct GoalApproachOptions {  // base_local_planner's defaults
  double xy_goal_tolerance = 0.10;   // m
  double yaw_goal_tolerance = 0.05;  // rad
  bool latch_xy_goal_tolerance = false;
  double trans_stopped_vel = 0.01, rot_stopped_vel = 0.01;  // below these the robot counts as stopped
  double acc_lim_x = 2.5, acc_lim_theta = 3.2;
  double max_vel_theta = 1.0, min_in_place_vel_theta = 0.4;
  double sim_period = 0.05;  // s: one control period
};

enum class GoalPhase {
  kApproaching,  // not yet within xy_goal_tolerance: the local planner drives
  kStopping,     // there, still moving: brake
  kTurning,      // stopped: turn in place towards the goal's yaw
  kReached,
};

class GoalApproach {
 public:
  explicit GoalApproach(const GoalApproachOptions& options) : options_(options) {}

  // Forget a latched position (a new goal).
  void reset() { latched_ = turning_ = false; }
  // The phase at `pose` moving at `velocity` (robot frame), and the command for stopping, turning
  // or standing still (zero) in the phases other than kApproaching.
  GoalPhase update(const Pose2& pose, const Velocity2& velocity, const Pose2& goal, Velocity2& command);

  const GoalApproachOptions& options() const { return options_; }

 private:
  GoalApproachOptions options_;
  bool latched_ = false;
  bool turning_ = false;  // stopped once at the goal: now turning
};

// a - b wrapped to [-pi, pi].
double angleDifference(double a, double b);

}  // namespace navigation_core
