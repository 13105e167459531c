#pragma once
// One joint's commands from Gazebo's joint control panel, held the way physics::JointController
// holds them (gzclient's "Joints" panel sends msgs::JointCmd), free of ROS and of the physics:
//  - a force, applied every step until changed or reset (the Katana tutorial: "the value should be
//    small and increasing, or else it would move crazily fast");
//  - a position target, held by a PID on (position - target) every step;
//  - a velocity target, held by a PID on (velocity - target) every step;
// the three add up. Each PID's effort is clamped to its cmd bounds and to the joint's effort limit,
// and so is the sum (Gazebo truncates every SetForce to the limit). A command's reset drops all
// three first; whatever else it sets replaces what was held of that kind. A new target keeps its
// PID's integral when the PID was already holding one, as Gazebo's controller keeps its PIDs.
#include <limits>
#include <optional>
#include <string>

#include "bullet_sim_core/pid.h"

namespace bullet_sim {

struct PidTarget {
  double target = 0.0;  // rad or m; rad/s or m/s
  PidGains gains;
};

// What one command says (bullet_sim_msgs/JointCmd without the joint's name).
struct JointCommand {
  bool reset = false;
  std::optional<double> force;  // N m or N
  std::optional<PidTarget> position;
  std::optional<PidTarget> velocity;
};

// "" if the command's numbers are usable, else what is wrong, naming the field, e.g.
// "position.p: expected a finite number, got nan". Targets, gains and the force must be finite;
// bounds may be infinite, not NaN.
std::string validate(const JointCommand& command);

class JointCommandController {
 public:
  // `effort_limit`: the joint's (URDF <limit effort>); infinity, or a value not > 0, for none.
  explicit JointCommandController(double effort_limit = std::numeric_limits<double>::infinity());

  // A command (checked with validate()): reset first, then whatever it sets.
  void command(const JointCommand& command);
  // Whether anything is held: false once reset, or before the first command that sets something.
  bool active() const { return force_ || position_ || velocity_; }

  // The joint's effort for the step of `dt` s about to be taken, from its present position and
  // velocity: the held force plus both PIDs' efforts, within the effort limit.
  double effort(double position, double velocity, double dt);

  const std::optional<double>& force() const { return force_; }
  const std::optional<PidTarget>& position() const { return position_; }
  const std::optional<PidTarget>& velocity() const { return velocity_; }

 private:
  double limited(double effort) const;
  double effort_limit_;
  std::optional<double> force_;
  std::optional<PidTarget> position_, velocity_;
  Pid position_pid_, velocity_pid_;
};

}  // namespace bullet_sim
