#pragma once
// The Katana gripper's grasp controller, without ROS or physics (libgazebo_ros_katana_gripper.so's
// semantics, katana_gazebo_plugins' numbers): both fingers driven by one PID each toward one
// target angle, and the decision when a grasp goal is over.
//
// Each finger's effort is p * error + i * (integral of the error) - d * velocity, clamped to
// +-max_torque; the integral's share is clamped to +-max_torque too and starts from zero with each
// target, so fingers that squeezed an object for seconds open at once when told to. The error is
// measured from a setpoint that moves from where the fingers are toward the target at
// max_velocity (the plugin passes the finger joints' velocity limit): 0.5 N m would swing a 30 g
// finger at 30 rad/s into its joint limit, where the real gripper moves at about 1 rad/s.
//
// A goal is over, in sim time, at the first of:
//  - reached: the gripper's angle (the mean of the fingers) has been within goal_threshold of the
//    target with both fingers still (slower than stall_velocity) for settle_time;
//  - stalled: both fingers have been still for stall_time elsewhere (they press on an object);
//  - goal_timeout after it started (upstream always waits this long): reached if the angle is
//    within goal_threshold, stalled otherwise, as upstream decides.
#include <array>
#include <limits>
#include <string>

namespace bullet_sim {

struct KatanaGripperOptions {
  double max_torque = 0.5;  // <max_torque>, N m: each finger's effort clamp
  // Upstream's grasp controller gains (d acts on -velocity).
  double p_gain = 0.4, i_gain = 0.1, d_gain = 0.0;
  // katana_driver's gripper range (rad): a goal outside it is refused.
  double min_position = -0.44, max_position = 0.30;
  // rad/s: how fast the setpoint moves to the target; infinity: it jumps there (upstream).
  double max_velocity = std::numeric_limits<double>::infinity();
  double goal_threshold = 0.01;  // rad
  double goal_timeout = 3.0;     // s of sim time
  double stall_velocity = 0.05;  // rad/s: a finger slower than this is still
  double settle_time = 0.05;     // s of sim time still within the threshold before a goal is reached
  double stall_time = 0.25;      // s of sim time still elsewhere before a goal is stalled
};

// "" if usable, else what is wrong, naming the field.
std::string validate(const KatanaGripperOptions& options);

// "" if `position` is a goal the gripper takes; else why not, e.g.
// "Goal position (0.5) outside gripper range [-0.44, 0.3]."
std::string checkGoalPosition(double position, const KatanaGripperOptions& options);

// One finger's PID: effort = clamp(p * error + clamp(i * integral, +-limit) - d * velocity, +-limit).
class ClampedPid {
 public:
  ClampedPid(double p, double i, double d, double limit) : p_(p), i_(i), d_(d), limit_(limit) {}
  double update(double error, double velocity, double dt);
  void reset() { integral_ = 0.0; }

 private:
  double p_, i_, d_, limit_;
  double integral_ = 0.0;  // of the error, rad s
};

enum class GraspOutcome { Running, Reached, Stalled };

class KatanaGripperController {
 public:
  using Pair = std::array<double, 2>;  // the r finger's, the l finger's

  // Holds each finger where it is at the start (`positions`), until the first target.
  KatanaGripperController(const KatanaGripperOptions& options, const Pair& positions);

  // Both fingers from `positions` toward `target` (checked with checkGoalPosition by the caller);
  // a goal starts at sim time `now`.
  void startGoal(double target, double now, const Pair& positions);
  // Ends the goal (if any) and holds each finger where it is now.
  void hold(const Pair& positions);
  // The efforts (N m) for the next step of length dt.
  Pair efforts(const Pair& positions, const Pair& velocities, double dt);
  // After a step: Running while there is no goal or it goes on; Reached or Stalled once, when it ends.
  GraspOutcome judge(double now, const Pair& positions, const Pair& velocities);

  bool goalActive() const { return goal_active_; }
  const Pair& targets() const { return targets_; }
  const Pair& setpoints() const { return setpoints_; }  // where the PIDs aim this step
  // The gripper's angle: the mean of its fingers'.
  static double angle(const Pair& positions) { return 0.5 * (positions[0] + positions[1]); }

 private:
  bool still(const Pair& velocities) const;
  void restartClocks();

  KatanaGripperOptions options_;
  Pair targets_, setpoints_;
  std::array<ClampedPid, 2> pids_;
  bool goal_active_ = false;
  double goal_start_ = 0.0;
  // Since when the fingers have been still, and still within the threshold (NaN: they are not).
  double still_since_ = 0.0, settled_since_ = 0.0;
};

}  // namespace bullet_sim
