#include "navigation_core/goal_approach.h"

#include <algorithm>
#include <cmath>

namespace navigation_core {

double angleDifference(double a, double b) { return std::remainder(a - b, 2.0 * M_PI); }

GoalPhase GoalApproach::update(const Pose2& pose, const Velocity2& velocity, const Pose2& goal, Velocity2& command) {
  command = Velocity2();
  const bool at_position = std::hypot(goal.x - pose.x, goal.y - pose.y) <= options_.xy_goal_tolerance;
  if (at_position && options_.latch_xy_goal_tolerance) latched_ = true;
  if (!at_position && !latched_) {
    turning_ = false;
    return GoalPhase::kApproaching;
  }

  const double turn = angleDifference(goal.theta, pose.theta);
  if (std::abs(turn) <= options_.yaw_goal_tolerance) return GoalPhase::kReached;

  const double dt = options_.sim_period;
  // Brake until stopped once; the turn that follows is not braked again.
  if (!turning_ && (std::abs(velocity.x) > options_.trans_stopped_vel || std::abs(velocity.y) > options_.trans_stopped_vel ||
      std::abs(velocity.theta) > options_.rot_stopped_vel)) {
    // Brake as hard as the limits allow, towards zero without overshooting it.
    const auto brake = [](double v, double step) { return v > 0 ? std::max(0.0, v - step) : std::min(0.0, v + step); };
    command.x = brake(velocity.x, options_.acc_lim_x * dt);
    command.y = brake(velocity.y, options_.acc_lim_x * dt);
    command.theta = brake(velocity.theta, options_.acc_lim_theta * dt);
    return GoalPhase::kStopping;
  }
  turning_ = true;
  // Turn towards the yaw: at least min_in_place_vel_theta, at most max_vel_theta, no faster than
  // one can still stop from in the angle left, and within one period's acceleration of now.
  double speed = std::clamp(std::abs(turn), options_.min_in_place_vel_theta, options_.max_vel_theta);
  speed = std::min(speed, std::sqrt(2.0 * options_.acc_lim_theta * std::abs(turn)));
  const double now = std::abs(velocity.theta);
  speed = std::clamp(speed, std::max(0.0, now - options_.acc_lim_theta * dt), now + options_.acc_lim_theta * dt);
  command.theta = std::copysign(speed, turn);
  return GoalPhase::kTurning;
}

}  // namespace navigation_core
