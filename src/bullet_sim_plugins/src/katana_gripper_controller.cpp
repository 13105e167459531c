#include "bullet_sim_plugins/katana_gripper_controller.h"

#include <algorithm>
#include <cmath>

#include "bullet_sim_core/sdf_element.h"  // formatNumber

namespace bullet_sim {

std::string validate(const KatanaGripperOptions& o) {
  std::string problems;
  const auto add = [&](const std::string& p) { problems += (problems.empty() ? "" : "; ") + p; };
  const auto nonNegativeFinite = [](double v) { return v >= 0 && std::isfinite(v); };
  if (!(o.max_torque > 0 && std::isfinite(o.max_torque)))
    add("max_torque: expected a torque > 0 (N m), got " + formatNumber(o.max_torque));
  if (!nonNegativeFinite(o.p_gain) || !nonNegativeFinite(o.i_gain) || !nonNegativeFinite(o.d_gain))
    add("p, i, d: expected gains >= 0, got " + formatNumber(o.p_gain) + ", " + formatNumber(o.i_gain) + ", " +
        formatNumber(o.d_gain));
  if (!(o.min_position < o.max_position) || !std::isfinite(o.min_position) || !std::isfinite(o.max_position))
    add("gripper range: expected min < max, got [" + formatNumber(o.min_position) + ", " +
        formatNumber(o.max_position) + "]");
  if (!(o.max_velocity > 0)) add("max_velocity: expected a speed > 0 (rad/s), got " + formatNumber(o.max_velocity));
  if (!(o.goal_threshold > 0 && std::isfinite(o.goal_threshold)))
    add("goal_threshold: expected an angle > 0 (rad), got " + formatNumber(o.goal_threshold));
  if (!(o.goal_timeout > 0 && std::isfinite(o.goal_timeout)))
    add("goal_timeout: expected a time > 0 (s), got " + formatNumber(o.goal_timeout));
  if (!(o.stall_velocity > 0 && std::isfinite(o.stall_velocity)))
    add("stall_velocity: expected a speed > 0 (rad/s), got " + formatNumber(o.stall_velocity));
  if (!nonNegativeFinite(o.settle_time))
    add("settle_time: expected a time >= 0 (s), got " + formatNumber(o.settle_time));
  if (!nonNegativeFinite(o.stall_time)) add("stall_time: expected a time >= 0 (s), got " + formatNumber(o.stall_time));
  return problems;
}

std::string checkGoalPosition(double position, const KatanaGripperOptions& o) {
  if (position >= o.min_position && position <= o.max_position) return "";  // false for NaN
  return "Goal position (" + formatNumber(position) + ") outside gripper range [" + formatNumber(o.min_position) +
         ", " + formatNumber(o.max_position) + "].";
}

double ClampedPid::update(double error, double velocity, double dt) {
  integral_ += error * dt;
  if (i_ > 0) integral_ = std::clamp(integral_, -limit_ / i_, limit_ / i_);  // its share stays within the limit
  return std::clamp(p_ * error + i_ * integral_ - d_ * velocity, -limit_, limit_);
}

namespace {
ClampedPid fingerPid(const KatanaGripperOptions& o) { return ClampedPid(o.p_gain, o.i_gain, o.d_gain, o.max_torque); }
}  // namespace

KatanaGripperController::KatanaGripperController(const KatanaGripperOptions& options, const Pair& positions)
    : options_(options),
      targets_(positions),
      setpoints_(positions),
      pids_{fingerPid(options), fingerPid(options)} {
  restartClocks();
}

void KatanaGripperController::restartClocks() {
  still_since_ = settled_since_ = std::numeric_limits<double>::quiet_NaN();
}

void KatanaGripperController::startGoal(double target, double now, const Pair& positions) {
  targets_ = {target, target};
  setpoints_ = positions;
  for (ClampedPid& pid : pids_) pid.reset();
  goal_active_ = true;
  goal_start_ = now;
  restartClocks();
}

void KatanaGripperController::hold(const Pair& positions) {
  targets_ = setpoints_ = positions;
  for (ClampedPid& pid : pids_) pid.reset();
  goal_active_ = false;
}

KatanaGripperController::Pair KatanaGripperController::efforts(const Pair& positions, const Pair& velocities,
                                                               double dt) {
  Pair out{};
  const double step = options_.max_velocity * dt;  // infinity: straight to the target
  for (size_t f = 0; f < out.size(); ++f) {
    setpoints_[f] += std::clamp(targets_[f] - setpoints_[f], -step, step);
    out[f] = pids_[f].update(setpoints_[f] - positions[f], velocities[f], dt);
  }
  return out;
}

bool KatanaGripperController::still(const Pair& velocities) const {
  return std::all_of(velocities.begin(), velocities.end(),
                     [&](double v) { return std::abs(v) < options_.stall_velocity; });
}

GraspOutcome KatanaGripperController::judge(double now, const Pair& positions, const Pair& velocities) {
  if (!goal_active_) return GraspOutcome::Running;
  const bool within = std::abs(targets_[0] - angle(positions)) <= options_.goal_threshold;
  const bool is_still = still(velocities);
  const auto since = [&](double& clock, bool holds) {  // how long `holds` has held, NaN if not now
    if (!holds) clock = std::numeric_limits<double>::quiet_NaN();
    else if (std::isnan(clock)) clock = now;
    return now - clock;
  };
  const double still_for = since(still_since_, is_still);
  const double settled_for = since(settled_since_, is_still && within);
  GraspOutcome outcome = GraspOutcome::Running;
  if (settled_for >= options_.settle_time - 1e-9)  // false for NaN
    outcome = GraspOutcome::Reached;
  else if (!within && still_for >= options_.stall_time - 1e-9)
    outcome = GraspOutcome::Stalled;
  else if (now - goal_start_ >= options_.goal_timeout - 1e-9)
    outcome = within ? GraspOutcome::Reached : GraspOutcome::Stalled;
  if (outcome != GraspOutcome::Running) goal_active_ = false;
  return outcome;
}

}  // namespace bullet_sim
