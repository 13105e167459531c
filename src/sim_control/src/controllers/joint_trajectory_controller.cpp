// ros_controllers' JointTrajectoryController (effort_, position_ and velocity_controllers/
// JointTrajectoryController); see joint_trajectory_controller.h for the behaviour, parameters,
// ROS API and threading.
#include "joint_trajectory_controller.h"

#include <ros/console.h>

#include <cmath>
#include <limits>

#include "controller_util.h"
#include "sim_control/controller_registry.h"
#include "sim_control/controller_params.h"

namespace sim_control {
namespace {

using Result = control_msgs::FollowJointTrajectoryResult;

constexpr bool sameCode(int a, int b) { return a == b; }
static_assert(sameCode(trajectory::kSuccessful, Result::SUCCESSFUL) &&
                  sameCode(trajectory::kInvalidGoal, Result::INVALID_GOAL) &&
                  sameCode(trajectory::kInvalidJoints, Result::INVALID_JOINTS) &&
                  sameCode(trajectory::kOldHeaderTimestamp, Result::OLD_HEADER_TIMESTAMP) &&
                  sameCode(trajectory::kPathToleranceViolated, Result::PATH_TOLERANCE_VIOLATED) &&
                  sameCode(trajectory::kGoalToleranceViolated, Result::GOAL_TOLERANCE_VIOLATED),
              "trajectory::ErrorCode must match control_msgs/FollowJointTrajectoryResult");

trajectory::Command toCommand(const trajectory_msgs::JointTrajectory& msg) {
  trajectory::Command command;
  command.joint_names = msg.joint_names;
  command.points.reserve(msg.points.size());
  for (const auto& p : msg.points) {
    trajectory::Waypoint w;
    w.positions = p.positions;
    w.velocities = p.velocities;
    w.accelerations = p.accelerations;
    w.time_from_start = p.time_from_start.toSec();
    command.points.push_back(std::move(w));
  }
  return command;
}

std::vector<trajectory::ToleranceOverride> toOverrides(const std::vector<control_msgs::JointTolerance>& msgs) {
  std::vector<trajectory::ToleranceOverride> overrides;
  for (const auto& m : msgs) overrides.push_back({m.name, m.position, m.velocity, m.acceleration});
  return overrides;
}

const char* resultName(int code) {
  switch (code) {
    case Result::SUCCESSFUL: return "SUCCESSFUL";
    case Result::INVALID_GOAL: return "INVALID_GOAL";
    case Result::INVALID_JOINTS: return "INVALID_JOINTS";
    case Result::OLD_HEADER_TIMESTAMP: return "OLD_HEADER_TIMESTAMP";
    case Result::PATH_TOLERANCE_VIOLATED: return "PATH_TOLERANCE_VIOLATED";
    case Result::GOAL_TOLERANCE_VIOLATED: return "GOAL_TOLERANCE_VIOLATED";
  }
  return "UNKNOWN";
}

}  // namespace

JointTrajectoryController::~JointTrajectoryController() = default;

bool JointTrajectoryController::init(RobotHW& hw, ros::NodeHandle& /*root_nh*/, ros::NodeHandle& nh,
                                     std::string& error) {
  ns_ = nh.getNamespace();

  // Joints, through the interface this type writes.
  ros_params::Reader params(nh);
  if (!readJointNames(params, &joint_names_)) return noProblems(params, error);
  const std::size_t n = joint_names_.size();
  for (const auto& name : joint_names_) {
    JointData* joint = claim(hw, name, interface_, error);
    if (!joint) return false;
    joints_.push_back(joint);
    wraparound_.push_back(joint->limits.continuous);
  }

  // PIDs and velocity feed-forward (ros_controllers' ClosedLoopHardwareInterfaceAdapter).
  pids_.assign(n, Pid());
  has_pid_.assign(n, false);
  velocity_ff_.assign(n, 0.0);
  if (interface_ != InterfaceType::Position) {
    for (std::size_t i = 0; i < n; ++i) {
      const std::string gains = "gains/" + joint_names_[i];
      if (params.has(gains)) {
        if (!pids_[i].init(ros::NodeHandle(nh, gains), error)) return false;
        has_pid_[i] = true;
      } else if (interface_ == InterfaceType::Effort) {
        params.problem(params.path(gains) + ": required parameter missing; expected the joint's PID gains, "
                       "e.g. {p: 100, i: 0.01, d: 10, i_clamp: 1}");
      } else {
        ROS_WARN_STREAM(ns_ << ": no " << params.path(gains) << "; joint '" << joint_names_[i]
                            << "' gets the desired velocity alone (open loop), so its position may drift");
      }
      // ros_controllers' default is 0 (PID only); a velocity joint without gains has nothing but
      // the feed-forward, so there it defaults to 1.
      velocity_ff_[i] = has_pid_[i] ? 0.0 : 1.0;
      readFinite(params, "velocity_ff/" + joint_names_[i], &velocity_ff_[i], "a number (the velocity feed-forward gain)");
    }
  }

  // Rates and durations.
  double state_publish_rate = 50.0, action_monitor_rate = 20.0;
  if (readFinite(params, "state_publish_rate", &state_publish_rate, "a rate in Hz (0: do not publish)") &&
      state_publish_rate < 0.0)
    params.fail("state_publish_rate",
                "expected a rate in Hz >= 0 (0: do not publish), got " + std::to_string(state_publish_rate));
  if (readFinite(params, "action_monitor_rate", &action_monitor_rate, "a rate in Hz") && action_monitor_rate <= 0.0)
    params.fail("action_monitor_rate", "expected a rate in Hz > 0, got " + std::to_string(action_monitor_rate));
  if (readFinite(params, "stop_trajectory_duration", &stop_trajectory_duration_, "a duration in seconds") &&
      stop_trajectory_duration_ < 0.0)
    params.fail("stop_trajectory_duration",
                "expected a duration in seconds >= 0, got " + std::to_string(stop_trajectory_duration_));
  params.read("allow_partial_joints_goal", &allow_partial_joints_goal_);

  // Default tolerances (ros_controllers' getSegmentTolerances).
  double stopped_velocity_tolerance = 0.01;
  readFinite(params, "constraints/stopped_velocity_tolerance", &stopped_velocity_tolerance, "a velocity (0: unchecked)");
  readFinite(params, "constraints/goal_time", &default_tolerances_.goal_time, "a duration in seconds");
  default_tolerances_.path.assign(n, {});
  default_tolerances_.goal.assign(n, {});
  for (std::size_t i = 0; i < n; ++i) {
    const std::string joint = "constraints/" + joint_names_[i];
    readFinite(params, joint + "/trajectory", &default_tolerances_.path[i].position, "a position tolerance (0: unchecked)");
    readFinite(params, joint + "/goal", &default_tolerances_.goal[i].position, "a position tolerance (0: unchecked)");
    default_tolerances_.goal[i].velocity = stopped_velocity_tolerance;
  }
  if (!noProblems(params, error)) return false;
  state_publish_period_ = state_publish_rate > 0.0 ? 1.0 / state_publish_rate : 0.0;
  action_monitor_period_ = 1.0 / action_monitor_rate;

  // State.
  trajectory_.assign(n, {});
  segments_.assign(n, -1);
  desired_.assign(n, {});
  actual_.assign(n, {});
  error_.assign(n, {});
  state_msg_.joint_names = joint_names_;
  state_msg_.desired.positions.resize(n);
  state_msg_.desired.velocities.resize(n);
  state_msg_.desired.accelerations.resize(n);
  state_msg_.actual.positions.resize(n);
  state_msg_.actual.velocities.resize(n);
  state_msg_.error.positions.resize(n);
  state_msg_.error.velocities.resize(n);

  // ROS API, last: callbacks may only come once everything above is set up.
  state_pub_ = nh.advertise<control_msgs::JointTrajectoryControllerState>("state", 1);
  action_server_ = std::make_unique<ActionServer>(
      nh, "follow_joint_trajectory", [this](GoalHandle goal) { goalCallback(goal); },
      [this](GoalHandle goal) { cancelCallback(goal); }, false);
  action_server_->start();
  query_state_srv_ = nh.advertiseService("query_state", &JointTrajectoryController::queryStateCallback, this);
  command_sub_ = nh.subscribe("command", 1, &JointTrajectoryController::commandCallback, this);
  return true;
}

void JointTrajectoryController::starting(const ros::Time& time) {
  uptime_ = 0.0;
  last_time_ = time;
  last_period_ = ros::Duration(0.0);
  // The desired state starts at the current one (the stop trajectory starts from it).
  for (std::size_t i = 0; i < joints_.size(); ++i) {
    desired_[i] = {joints_[i]->position, joints_[i]->velocity, 0.0};
    actual_[i] = {joints_[i]->position, joints_[i]->velocity, 0.0};
    error_[i] = {};
  }
  setHoldPosition();
  last_state_publish_ = 0.0;
  // Hardware adapters' starting(): position joints are commanded where they are, PIDs reset and
  // effort / velocity commands zeroed.
  for (std::size_t i = 0; i < joints_.size(); ++i) {
    pids_[i].reset();
    joints_[i]->command = interface_ == InterfaceType::Position ? joints_[i]->position : 0.0;
  }
  running_ = true;
}

void JointTrajectoryController::stopping(const ros::Time& /*time*/) {
  preemptActiveGoal();
  running_ = false;
}

void JointTrajectoryController::update(const ros::Time& time, const ros::Duration& period) {
  uptime_ += period.toSec();
  last_time_ = time;
  last_period_ = period;

  sampleTrajectory();
  if (active_goal_ && monitor_.active()) {
    const trajectory::GoalMonitor::Result result = monitor_.check(uptime_, trajectory_, segments_, error_);
    if (result.done) {
      finishActiveGoal(result);
      if (result.error_code == Result::PATH_TOLERANCE_VIOLATED) {
        // ros_controllers carries on along the trajectory after this abort; we stop instead
        // (as ROS 2's JTC does), from where the joints actually are.
        setHoldPosition(0, true);
        sampleTrajectory();
      }
    }
  }
  writeCommands(period);
  publishFeedback(time);
  publishState(time);
}

void JointTrajectoryController::sampleTrajectory() {
  for (std::size_t i = 0; i < joints_.size(); ++i) {
    const JointData& joint = *joints_[i];
    segments_[i] = trajectory::sample(trajectory_[i], uptime_, desired_[i]);
    actual_[i] = {joint.position, joint.velocity, 0.0};  // no measured acceleration
    error_[i].position = controllers::positionError(joint, desired_[i].position);
    error_[i].velocity = desired_[i].velocity - joint.velocity;
    error_[i].acceleration = 0.0;
  }
}

void JointTrajectoryController::writeCommands(const ros::Duration& period) {
  const double dt = period.toSec();
  for (std::size_t i = 0; i < joints_.size(); ++i) {
    JointData& joint = *joints_[i];
    switch (interface_) {
      case InterfaceType::Position:
        joint.command = desired_[i].position;
        break;
      case InterfaceType::Velocity:
      case InterfaceType::Effort: {
        double command = velocity_ff_[i] * desired_[i].velocity;
        if (has_pid_[i]) command += pids_[i].compute(error_[i].position, error_[i].velocity, dt);
        joint.command = interface_ == InterfaceType::Effort ? controllers::clampEffort(joint, command) : command;
        break;
      }
    }
  }
}

void JointTrajectoryController::setHoldPosition(int goal_id, bool from_actual) {
  for (std::size_t i = 0; i < joints_.size(); ++i) {
    const trajectory::State actual{joints_[i]->position, joints_[i]->velocity, 0.0};
    trajectory_[i] = stop_trajectory_duration_ > 0.0
                         ? trajectory::stopTrajectory(uptime_, from_actual ? actual : desired_[i],
                                                      stop_trajectory_duration_, goal_id)
                         : trajectory::holdTrajectory(uptime_, joints_[i]->position, goal_id);
  }
}

int JointTrajectoryController::replaceTrajectory(const trajectory_msgs::JointTrajectory& msg, int goal_id,
                                                 double& start_time, std::string& error) {
  // Commands take effect from the next update; a zero stamp means "start then".
  const ros::Time next_time = last_time_ + last_period_;
  const double next_uptime = uptime_ + last_period_.toSec();
  start_time = msg.header.stamp.isZero() ? next_uptime : next_uptime + (msg.header.stamp - next_time).toSec();

  trajectory::MergeOptions options;
  options.joints = joint_names_;
  options.wraparound = wraparound_;
  options.allow_partial = allow_partial_joints_goal_;
  options.goal_id = goal_id;
  trajectory::MergeResult result = trajectory::merge(trajectory_, toCommand(msg), start_time, next_uptime, options);
  if (result.error_code != trajectory::kSuccessful) {
    error = result.error;
    return result.error_code;
  }
  if (result.dropped_points > 0) {
    const auto& first = msg.points[result.dropped_points];
    ROS_WARN_STREAM(ns_ << ": dropping the first " << result.dropped_points << " of " << msg.points.size()
                        << " trajectory point(s), as they occur before the current time; the first valid point will "
                           "be reached in "
                        << (start_time + first.time_from_start.toSec() - next_uptime) << " s");
  }
  trajectory_ = std::move(result.trajectory);
  return trajectory::kSuccessful;
}

void JointTrajectoryController::commandCallback(const trajectory_msgs::JointTrajectoryConstPtr& msg) {
  if (!running_) {
    ROS_ERROR_STREAM(ns_ << "/command: can't accept new commands; the controller is not running");
    return;
  }
  if (msg->points.empty()) {
    setHoldPosition();  // ros_controllers: an empty trajectory stops the robot
    preemptActiveGoal();
    return;
  }
  double start_time = 0.0;
  std::string error;
  if (replaceTrajectory(*msg, 0, start_time, error) != trajectory::kSuccessful) {
    ROS_ERROR_STREAM(ns_ << "/command: ignoring the trajectory: " << error);
    return;
  }
  preemptActiveGoal();
}

void JointTrajectoryController::goalCallback(GoalHandle goal) {
  const auto reject = [&](int code, const std::string& message) {
    ROS_ERROR_STREAM(ns_ << "/follow_joint_trajectory: rejecting the goal (" << resultName(code) << "): " << message);
    Result result;
    result.error_code = code;
    result.error_string = message;
    goal.setRejected(result, message);
  };
  if (!running_) return reject(Result::INVALID_GOAL, "Can't accept new action goals. Controller is not running.");
  const auto msg = goal.getGoal();
  if (!msg) return reject(Result::INVALID_GOAL, "the goal could not be read");

  // Joints first (INVALID_JOINTS), as ros_controllers checks them before the points.
  std::vector<std::size_t> mapping;
  std::string error;
  if (trajectory::validateJoints(toCommand(msg->trajectory), joint_names_, allow_partial_joints_goal_, mapping,
                                 error) != trajectory::kSuccessful)
    return reject(Result::INVALID_JOINTS, error);

  const int goal_id = next_goal_id_++;
  double start_time = uptime_;
  if (msg->trajectory.points.empty()) {
    setHoldPosition(goal_id);  // succeeds once the joints are within the goal tolerances
  } else {
    const int code = replaceTrajectory(msg->trajectory, goal_id, start_time, error);
    if (code != trajectory::kSuccessful) return reject(code, error);
  }

  trajectory::Tolerances tolerances = default_tolerances_;
  trajectory::applyOverrides(toOverrides(msg->path_tolerance), joint_names_, tolerances.path);
  trajectory::applyOverrides(toOverrides(msg->goal_tolerance), joint_names_, tolerances.goal);
  tolerances.goal_time = trajectory::applyGoalTimeOverride(msg->goal_time_tolerance.toSec(), tolerances.goal_time);

  preemptActiveGoal();
  goal.setAccepted();
  active_goal_ = goal;
  monitor_.start(goal_id, tolerances, joint_names_, start_time);
  last_feedback_ = -std::numeric_limits<double>::infinity();
}

void JointTrajectoryController::cancelCallback(GoalHandle goal) {
  if (!active_goal_ || !(*active_goal_ == goal)) return;
  GoalHandle canceled = *active_goal_;
  active_goal_.reset();
  monitor_.clear();
  setHoldPosition();
  canceled.setCanceled();
}

void JointTrajectoryController::preemptActiveGoal() {
  monitor_.clear();
  if (!active_goal_) return;
  GoalHandle preempted = *active_goal_;
  active_goal_.reset();
  preempted.setCanceled();  // ACTIVE -> PREEMPTED
}

void JointTrajectoryController::finishActiveGoal(const trajectory::GoalMonitor::Result& outcome) {
  if (!active_goal_) return;
  GoalHandle goal = *active_goal_;
  active_goal_.reset();
  Result result;
  result.error_code = outcome.error_code;
  result.error_string = outcome.message;
  if (outcome.error_code == Result::SUCCESSFUL) {
    goal.setSucceeded(result);
  } else {
    ROS_WARN_STREAM(ns_ << "/follow_joint_trajectory: aborting the goal (" << resultName(outcome.error_code)
                        << "): " << outcome.message);
    goal.setAborted(result, outcome.message);
  }
}

bool JointTrajectoryController::queryStateCallback(control_msgs::QueryTrajectoryState::Request& request,
                                                   control_msgs::QueryTrajectoryState::Response& response) {
  if (!running_) {
    ROS_ERROR_STREAM(ns_ << "/query_state: can't sample the trajectory; the controller is not running");
    return false;
  }
  const double time = uptime_ + (request.time - last_time_).toSec();
  const std::size_t n = joints_.size();
  response.name = joint_names_;
  response.position.resize(n);
  response.velocity.resize(n);
  response.acceleration.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    trajectory::State state;
    if (trajectory::sample(trajectory_[i], time, state) < 0) {
      ROS_ERROR_STREAM(ns_ << "/query_state: the requested time " << request.time.toSec()
                           << " precedes the start of the trajectory (current time " << last_time_.toSec() << ")");
      return false;
    }
    response.position[i] = state.position;
    response.velocity[i] = state.velocity;
    response.acceleration[i] = state.acceleration;
  }
  return true;
}

void JointTrajectoryController::publishFeedback(const ros::Time& time) {
  if (!active_goal_ || uptime_ - last_feedback_ < action_monitor_period_) return;
  last_feedback_ = uptime_;
  control_msgs::FollowJointTrajectoryFeedback feedback;
  feedback.header.stamp = time;
  feedback.joint_names = joint_names_;
  const std::size_t n = joints_.size();
  feedback.desired.positions.resize(n);
  feedback.desired.velocities.resize(n);
  feedback.desired.accelerations.resize(n);
  feedback.actual.positions.resize(n);
  feedback.actual.velocities.resize(n);
  feedback.error.positions.resize(n);
  feedback.error.velocities.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    feedback.desired.positions[i] = desired_[i].position;
    feedback.desired.velocities[i] = desired_[i].velocity;
    feedback.desired.accelerations[i] = desired_[i].acceleration;
    feedback.actual.positions[i] = actual_[i].position;
    feedback.actual.velocities[i] = actual_[i].velocity;
    feedback.error.positions[i] = error_[i].position;
    feedback.error.velocities[i] = error_[i].velocity;
  }
  active_goal_->publishFeedback(feedback);
}

void JointTrajectoryController::publishState(const ros::Time& time) {
  if (state_publish_period_ <= 0.0 || uptime_ < last_state_publish_ + state_publish_period_) return;
  last_state_publish_ += state_publish_period_;
  if (last_state_publish_ + state_publish_period_ <= uptime_) last_state_publish_ = uptime_;  // no bursts
  if (state_pub_.getNumSubscribers() == 0) return;
  state_msg_.header.stamp = time;
  for (std::size_t i = 0; i < joints_.size(); ++i) {
    state_msg_.desired.positions[i] = desired_[i].position;
    state_msg_.desired.velocities[i] = desired_[i].velocity;
    state_msg_.desired.accelerations[i] = desired_[i].acceleration;
    state_msg_.actual.positions[i] = actual_[i].position;
    state_msg_.actual.velocities[i] = actual_[i].velocity;
    state_msg_.error.positions[i] = error_[i].position;
    state_msg_.error.velocities[i] = error_[i].velocity;
  }
  publish_thread::publish(state_pub_, state_msg_);
}

namespace {

class EffortJointTrajectoryController : public JointTrajectoryController {
 public:
  EffortJointTrajectoryController() : JointTrajectoryController(InterfaceType::Effort) {}
};
class PositionJointTrajectoryController : public JointTrajectoryController {
 public:
  PositionJointTrajectoryController() : JointTrajectoryController(InterfaceType::Position) {}
};
class VelocityJointTrajectoryController : public JointTrajectoryController {
 public:
  VelocityJointTrajectoryController() : JointTrajectoryController(InterfaceType::Velocity) {}
};

}  // namespace

SIM_CONTROL_REGISTER_CONTROLLER("effort_controllers/JointTrajectoryController", EffortJointTrajectoryController)
SIM_CONTROL_REGISTER_CONTROLLER("position_controllers/JointTrajectoryController", PositionJointTrajectoryController)
SIM_CONTROL_REGISTER_CONTROLLER("velocity_controllers/JointTrajectoryController", VelocityJointTrajectoryController)

}  // namespace sim_control
