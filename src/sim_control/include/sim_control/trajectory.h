#pragma once
// The ROS-free part of the JointTrajectoryController, with ros_controllers' semantics:
//  - splines between waypoints: linear if a waypoint has positions only, cubic with velocities,
//    quintic with accelerations too (the lowest order both ends specify);
//  - a trajectory per joint as a list of segments sorted by start time; the segment active at t
//    is the last one starting at or before t; outside a segment its start / end position is held
//    with zero velocity and acceleration (so after the last point the last position is held);
//  - merging a new command into the current trajectory: points at or before `now` are dropped,
//    the current trajectory is kept up to the new start time, a bridge segment joins its state
//    there to the first remaining point, and the rest of the old trajectory is replaced;
//  - tolerance checks (path, goal, goal time) as control_msgs/FollowJointTrajectory defines them.
// All times are seconds in one time base (the controller uses its uptime, as ros_controllers does,
// so that jumps of the ROS clock do not disturb a running trajectory).
#include <array>
#include <cstddef>
#include <string>
#include <vector>

namespace sim_control {
namespace trajectory {

// Result codes of control_msgs/FollowJointTrajectoryResult.
enum ErrorCode : int {
  kSuccessful = 0,
  kInvalidGoal = -1,
  kInvalidJoints = -2,
  kOldHeaderTimestamp = -3,
  kPathToleranceViolated = -4,
  kGoalToleranceViolated = -5,
};

// How much of a state a waypoint specifies, and so how a segment interpolates.
enum class Order { Linear = 1, Cubic = 2, Quintic = 3 };

struct State {
  double position = 0.0;
  double velocity = 0.0;
  double acceleration = 0.0;
};

// One joint's motion between two states: a polynomial of degree 1, 3 or 5 in (t - start_time).
class Segment {
 public:
  Segment() = default;
  // Boundary conditions up to `order` are met (linear: positions; cubic: and velocities; quintic:
  // and accelerations). Requires end_time >= start_time.
  Segment(double start_time, const State& start, double end_time, const State& end, Order order);

  // Inside [start, end] the polynomial; before it the start position, after it the end position,
  // both with zero velocity and acceleration.
  State sample(double time) const;

  double startTime() const { return start_time_; }
  double endTime() const { return start_time_ + duration_; }
  Order order() const { return order_; }

  int goal_id = 0;  // the action goal the segment belongs to; 0 for none (topic commands, holding)

 private:
  double start_time_ = 0.0;
  double duration_ = 0.0;
  Order order_ = Order::Linear;
  double end_position_ = 0.0;
  std::array<double, 6> c_{};  // c_[0] + c_[1] x + ... + c_[5] x^5, x = t - start_time
};

using JointTrajectory = std::vector<Segment>;     // one joint, sorted by start time
using Trajectory = std::vector<JointTrajectory>;  // one per controller joint, in the controller's order

// Index of the segment active at `time` (the last one starting at or before it); -1 if `time`
// precedes the first segment or there is none.
int findSegment(const JointTrajectory& trajectory, double time);
// Samples the active segment (the first segment if `time` precedes it); returns findSegment().
// `state` is left unchanged if the trajectory is empty.
int sample(const JointTrajectory& trajectory, double time, State& state);

// Holding `position` from `time` on (ros_controllers' hold with stop_trajectory_duration = 0):
// one zero-length segment.
JointTrajectory holdTrajectory(double time, double position, int goal_id = 0);
// Coming to rest from `from` within `duration` > 0 (ros_controllers' stop trajectory): a quintic to
// the midpoint of the symmetric segment from (p, v, 0) to (p, -v, 0) over 2 * duration, where the
// velocity is zero; then that end state is held.
JointTrajectory stopTrajectory(double time, const State& from, double duration, int goal_id = 0);

// Continuous joints: the signed angle in (-pi, pi] from `from` to `to`.
double shortestAngularDistance(double from, double to);
// What to add to a new trajectory's positions so its first point is reached from `previous` the
// short way round (a multiple of 2 pi); ties at exactly pi go the way the raw numbers point.
double wraparoundOffset(double previous, double next);

// A trajectory_msgs/JointTrajectory without ROS: time_from_start in seconds.
struct Waypoint {
  std::vector<double> positions, velocities, accelerations;
  double time_from_start = 0.0;
};
struct Command {
  std::vector<std::string> joint_names;
  std::vector<Waypoint> points;
};

// The command's joints must be the controller's (any order), each once; all of them unless
// `allow_partial`. On success `mapping[k]` is the controller index of command joint k.
// Returns kSuccessful or kInvalidJoints with a message naming the offending joints.
int validateJoints(const Command& command, const std::vector<std::string>& joints, bool allow_partial,
                   std::vector<std::size_t>& mapping, std::string& error);
// Every point has one position per command joint, velocities and accelerations empty or one per
// joint, finite numbers, and time_from_start strictly increasing.
// Returns kSuccessful or kInvalidGoal with a message naming the point and field.
int validatePoints(const Command& command, std::string& error);

struct MergeOptions {
  std::vector<std::string> joints;  // the controller's joints
  std::vector<bool> wraparound;     // per controller joint: continuous (empty: none)
  bool allow_partial = false;
  int goal_id = 0;  // tagged on the new segments and on the kept ones from `now` on
};
struct MergeResult {
  int error_code = kSuccessful;
  std::string error;
  std::size_t dropped_points = 0;  // points at or before `now`
  Trajectory trajectory;
};
// The trajectory to follow after receiving `command`, whose time_from_start values count from
// `start_time`; `now` is the time of the next control update (points at or before it are dropped).
// Validates the command first (validateJoints, validatePoints; all points in the past is
// kInvalidGoal, as ros_controllers rejects it). Joints the command leaves out (partial goals) keep
// their current trajectory. `current` must have one (non-empty) trajectory per controller joint.
MergeResult merge(const Trajectory& current, const Command& command, double start_time, double now,
                  const MergeOptions& options);

// Tolerances on the state error (desired - actual); a component <= 0 is not checked.
struct StateTolerance {
  double position = 0.0;
  double velocity = 0.0;
  double acceleration = 0.0;
};
struct Tolerances {
  std::vector<StateTolerance> path;  // per controller joint, while a segment executes
  std::vector<StateTolerance> goal;  // per controller joint, after the last segment ends
  double goal_time = 0.0;            // how long after the end the goal tolerances may take to be met
};
// control_msgs/JointTolerance.
struct ToleranceOverride {
  std::string name;
  double position = 0.0, velocity = 0.0, acceleration = 0.0;
};
// An action goal's tolerances over the defaults, per joint by name: > 0 replaces the default,
// < 0 means no check, 0 keeps the default. Names that are not controller joints are ignored.
void applyOverrides(const std::vector<ToleranceOverride>& overrides, const std::vector<std::string>& joints,
                    std::vector<StateTolerance>& tolerances);
// goal_time_tolerance of a goal: > 0 replaces the default, < 0 means 0, 0 keeps the default.
double applyGoalTimeOverride(double goal_time, double default_goal_time);

// True if `error` is within `tolerance`; otherwise `violation` (if given) says which component
// and by how much, e.g. "position error 0.12 exceeds the tolerance 0.05 by 0.07".
bool withinTolerance(const State& error, const StateTolerance& tolerance, std::string* violation = nullptr);

// Watches one action goal through the control updates, the way ros_controllers' update() does:
// while a segment of the goal executes, its joint's path tolerance is checked; once a joint's last
// segment has ended, its goal tolerance: met -> that joint is done (for good); not met -> wait
// until goal_time after the end, then the goal fails. All joints done -> success.
class GoalMonitor {
 public:
  struct Result {
    bool done = false;          // the goal reached a terminal state this update
    int error_code = kSuccessful;
    std::string message;        // for error_string: which joint, by how much
  };

  // `start_time`: when the goal's trajectory starts (for messages only).
  void start(int goal_id, const Tolerances& tolerances, const std::vector<std::string>& joints, double start_time);
  void clear() { goal_id_ = 0; }
  bool active() const { return goal_id_ != 0; }
  int goalId() const { return goal_id_; }
  const Tolerances& tolerances() const { return tolerances_; }

  // One control update at `now`: `segments[i]` is what sample() returned for joint i of
  // `trajectory`, `errors[i]` its desired - actual state. A terminal result clears the monitor.
  Result check(double now, const Trajectory& trajectory, const std::vector<int>& segments,
               const std::vector<State>& errors);

 private:
  int goal_id_ = 0;
  Tolerances tolerances_;
  std::vector<std::string> joints_;
  std::vector<bool> reached_;
  double start_time_ = 0.0;
};

}  // namespace trajectory
}  // namespace sim_control
