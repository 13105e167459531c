#pragma once
// The Pioneer's body-velocity controller (no ROS): turns velocity commands (cmd_vel, from
// move_base or a teleop) into the commands the drive takes (/pioneer/cmd_vel), closing a PID
// loop on each of the linear (m/s) and angular (rad/s) velocity errors with the measured
// velocities from odometry:
//
//     output = feedforward * command + PID(command - measured), clamped to the limits
//
// - No command for cmd_timeout seconds: one zero command, then nothing (the controller goes
//   idle and leaves the drive to whoever else commands it).
// - A zero command is passed straight through and clears the integrators: stop means stop.
// - No odometry for odom_timeout seconds: open loop (feedforward only, integrators cleared),
//   so the robot still obeys, uncorrected (the node warns).
// - Time going backwards (a simulation reset): everything is cleared.
//
// The report's controller multiplied the command by the P gain and left I and D unused; its
// parameter layout (controller_gains/body/{linear,angular}/{p,i,d}) is kept, and the
// configuration below follows it field for field (pioneer_controller_params.yaml).
#include <optional>
#include <string>

#include "pioneer_ros/pid.h"

namespace pioneer_ros {

// One velocity axis: controller_gains/body/<axis>/{p,i,d,i_clamp}, feedforward/<axis>, limits/<axis>.
struct AxisConfig {
  double p = 0.0, i = 0.0, d = 0.0;
  std::optional<double> i_clamp;  // largest integral correction; unset: the limit
  double feedforward = 1.0;       // output per unit of command before the PID's correction
  double limit = 1.0;             // the output stays within +-limit
};

struct ControllerConfig {
  AxisConfig linear;                                          // m/s: limit 1
  AxisConfig angular{0.0, 0.0, 0.0, std::nullopt, 1.0, 2.0};  // rad/s: limit 2
  double derivative_filter_time = 0.0;  // s, the low-pass on both derivatives
  double rate = 20.0;                   // Hz of the caller's clock (sim time in the node)
  double cmd_timeout = 0.5;             // s without a command: one stop, then quiet
  double odom_timeout = 0.5;            // s without odometry: open loop
};

// "" when the configuration can be used; otherwise its first problem, naming the parameter by
// its path in pioneer_controller_params.yaml and saying what was expected:
// "limits/angular: expected a positive number, got -1".
std::string validate(const ControllerConfig& config);

// The PID gains of one axis: output limited to +-limit, i_clamp the limit unless set.
PidGains pidGains(const AxisConfig& axis, double derivative_filter_time);

struct PlanarVelocity {
  double linear = 0.0;   // m/s, forward
  double angular = 0.0;  // rad/s, yaw rate
};

enum class ControllerMode { kIdle, kStopped, kClosedLoop, kOpenLoop };

// Times are seconds of one clock, the caller's (sim time in the node).
class BodyVelocityController {
 public:
  // Throws std::invalid_argument with validate()'s message when the configuration is bad.
  explicit BodyVelocityController(const ControllerConfig& config);

  // Throws std::invalid_argument when a velocity is not finite (the command is not taken).
  void setCommand(const PlanarVelocity& command, double stamp);
  // Ignores a measurement that is not finite.
  void setMeasurement(const PlanarVelocity& measured, double stamp);

  // What to send now, or nothing when there is nothing to send.
  std::optional<PlanarVelocity> update(double now);

  ControllerMode mode() const { return mode_; }
  const ControllerConfig& config() const { return config_; }
  const Pid& linearPid() const { return linear_pid_; }
  const Pid& angularPid() const { return angular_pid_; }

 private:
  struct Stamped {
    PlanarVelocity velocity;
    double stamp;
  };

  void reset();

  ControllerConfig config_;
  Pid linear_pid_, angular_pid_;
  std::optional<Stamped> command_, measurement_;
  ControllerMode mode_ = ControllerMode::kIdle;
  std::optional<double> last_update_;
};

}  // namespace pioneer_ros
