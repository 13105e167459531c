#pragma once
// The ROS-free part of diff_drive_controller/DiffDriveController: differential-drive kinematics,
// wheel odometry and the twist speed limiter, with ros_controllers' semantics
// (diff_drive_controller's odometry.cpp and speed_limiter.cpp). Times are in seconds.
#include <cstddef>
#include <vector>

namespace sim_control {
namespace diff_drive {

// Wheel angular velocities (rad/s) for a body twist: linear x (m/s) and angular z (rad/s).
// wheel_separation: distance between the wheels' contact points (m); radii in m.
struct WheelVelocities {
  double left = 0.0;
  double right = 0.0;
};
WheelVelocities inverseKinematics(double linear, double angular, double wheel_separation,
                                  double left_wheel_radius, double right_wheel_radius);

// Body twist for wheel angular velocities (rad/s).
struct BodyTwist {
  double linear = 0.0;   // m/s along the base's x
  double angular = 0.0;  // rad/s about z
};
BodyTwist forwardKinematics(double left_wheel_velocity, double right_wheel_velocity, double wheel_separation,
                            double left_wheel_radius, double right_wheel_radius);

// Mean of the last `size` samples (boost::accumulators' rolling_mean: the mean of what there
// is while fewer than `size` samples have arrived; 0 with none).
class RollingMean {
 public:
  explicit RollingMean(std::size_t size = 10);
  void push(double value);
  double mean() const;
  void reset();
  std::size_t size() const { return size_; }

 private:
  std::size_t size_;
  std::vector<double> samples_;  // ring buffer once full
  std::size_t next_ = 0;
};

// Pose (x, y, heading) of the base in the odometry frame, integrated from the wheel positions
// (or, open loop, from the commanded twist), and the base velocity as a rolling mean.
class Odometry {
 public:
  explicit Odometry(std::size_t velocity_rolling_window_size = 10);

  // Resets the velocity estimate and sets the time base (the pose is kept, as ros_controllers does).
  void init(double time);
  // Wheel positions in rad (the mean over each side's wheels). Integrates the pose from the
  // change since the last call; returns false (pose still integrated, velocities unchanged)
  // when less than 0.1 ms has passed since the last velocity estimate. The first call after
  // construction or resetWheelPositions() only takes the positions as the reference.
  bool update(double left_position, double right_position, double time);
  // Integrates the pose from a twist held since the last call (open_loop).
  void updateOpenLoop(double linear, double angular, double time);

  // Adds one step: `linear` m travelled and `angular` rad turned. Runge-Kutta 2 when the
  // turn is below 1e-6 rad, otherwise the exact circular arc.
  void integrate(double linear, double angular);
  void integrateRungeKutta2(double linear, double angular);
  void integrateExact(double linear, double angular);

  void setWheelParams(double wheel_separation, double left_wheel_radius, double right_wheel_radius);
  void setVelocityRollingWindowSize(std::size_t size);
  void resetPose(double x = 0.0, double y = 0.0, double heading = 0.0);
  void resetWheelPositions() { has_wheel_positions_ = false; }

  double x() const { return x_; }
  double y() const { return y_; }
  double heading() const { return heading_; }  // rad, not wrapped (as ros_controllers)
  double linear() const { return linear_; }    // m/s
  double angular() const { return angular_; }  // rad/s

 private:
  double timestamp_ = 0.0;
  double x_ = 0.0, y_ = 0.0, heading_ = 0.0;
  double linear_ = 0.0, angular_ = 0.0;
  double wheel_separation_ = 0.0, left_wheel_radius_ = 0.0, right_wheel_radius_ = 0.0;
  bool has_wheel_positions_ = false;
  double left_wheel_old_pos_ = 0.0, right_wheel_old_pos_ = 0.0;  // m (position * radius)
  RollingMean linear_mean_, angular_mean_;
};

// ros_controllers' diff_drive_controller::SpeedLimiter: limits a velocity command given the
// two previous (limited) commands v0 (last) and v1 (the one before) and the period dt.
struct SpeedLimiter {
  bool has_velocity_limits = false;
  bool has_acceleration_limits = false;
  bool has_jerk_limits = false;
  double min_velocity = 0.0, max_velocity = 0.0;
  double min_acceleration = 0.0, max_acceleration = 0.0;
  double min_jerk = 0.0, max_jerk = 0.0;

  // Jerk, then acceleration, then velocity. Each returns the ratio limited/requested (1 if the
  // request was 0).
  double limit(double& v, double v0, double v1, double dt) const;
  double limitVelocity(double& v) const;
  double limitAcceleration(double& v, double v0, double dt) const;
  // As ros_controllers: the change of velocity change, v - 2 v0 + v1, is clamped to
  // [min_jerk, max_jerk] * 2 dt^2.
  double limitJerk(double& v, double v0, double v1, double dt) const;
};

}  // namespace diff_drive
}  // namespace sim_control
