#pragma once
// The ROS-free arithmetic of the wheeled-drive plugins: wheel speeds from a body twist, the
// acceleration ramp and command timeout, and odometry integrated from the wheel encoders.
// Lengths in m, angles in rad, times in s.

namespace bullet_sim {

struct WheelSpeeds {
  double left = 0.0;   // rad/s
  double right = 0.0;  // rad/s
};

// Wheel angular velocities for a forward speed `linear` (m/s) and a turn rate `angular` (rad/s,
// counter-clockwise seen from above, REP 103): (linear -/+ angular * separation / 2) / (diameter / 2),
// minus for the left wheel.
WheelSpeeds wheelSpeeds(double linear, double angular, double wheel_separation, double wheel_diameter);

// `current` moved toward `target` by at most `max_change` (>= 0; infinity jumps to the target).
double rampToward(double current, double target, double max_change);

// What the wheels are told at each update: the last twist command through the acceleration ramp,
// and a stop once the command is older than the timeout.
class DriveCommand {
 public:
  // wheel_acceleration: m/s^2 at the wheel rim (0: unlimited); cmd_timeout: s (0: never).
  DriveCommand(double wheel_separation, double wheel_diameter, double wheel_acceleration = 0.0,
               double cmd_timeout = 0.0);

  // A new command (linear.x, angular.z) that arrived at `time`.
  void setTwist(double linear, double angular, double time);
  // True when there was a command, a timeout is set and the command is older than it at `time`.
  bool timedOut(double time) const;
  // The wheel velocities to command at `time`, `dt` after the previous update: the target
  // wheelSpeeds() of the command (zero without one, or timed out), each wheel's change limited to
  // wheel_acceleration / radius * dt.
  WheelSpeeds update(double time, double dt);
  const WheelSpeeds& current() const { return current_; }
  void reset();  // no command, wheels commanded at rest

 private:
  double wheel_separation_, wheel_diameter_, wheel_acceleration_, cmd_timeout_;
  bool has_command_ = false;
  double linear_ = 0.0, angular_ = 0.0, command_time_ = 0.0;
  WheelSpeeds current_;
};

// Pose on the plane (x, y, heading) of the base from the wheels' rotations, each step taken as a
// circular arc (wheels turning at constant rates in between), so that a run of constant commands
// is integrated exactly whatever the step size. Wheel angles grow as the wheel drives forward.
class EncoderOdometry {
 public:
  EncoderOdometry(double wheel_separation, double wheel_diameter);

  void reset(double x = 0.0, double y = 0.0, double heading = 0.0);  // pose and distance; keeps the reference
  // Adds the motion for wheel rotations `left`, `right` (rad) since the last call.
  void integrate(double left_rotation, double right_rotation);
  // Absolute wheel angles (rad): the first call after construction or resetReference() only takes
  // them as the reference; later calls integrate the change.
  void update(double left_angle, double right_angle);
  void resetReference() { has_reference_ = false; }

  double x() const { return x_; }
  double y() const { return y_; }
  double heading() const { return heading_; }    // rad, not wrapped
  double distance() const { return distance_; }  // signed path length of the base since reset (m)

 private:
  double wheel_separation_, wheel_radius_;
  double x_ = 0.0, y_ = 0.0, heading_ = 0.0, distance_ = 0.0;
  bool has_reference_ = false;
  double left_reference_ = 0.0, right_reference_ = 0.0;
};

}  // namespace bullet_sim
