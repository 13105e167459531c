#pragma once
// ros_controllers' JointTrajectoryController, for the three joint interfaces:
//   effort_controllers/JointTrajectoryController    effort   = velocity_ff * v_desired + PID(e_pos, e_vel),
//                                                   clamped to the joint's effort limit; gains/<joint> required
//   velocity_controllers/JointTrajectoryController  velocity = velocity_ff * v_desired + PID(e_pos, e_vel)
//                                                   (gains/<joint> optional here: without it, v_desired alone)
//   position_controllers/JointTrajectoryController  position = p_desired
// (e = desired - actual; for continuous joints the position error takes the short way round.)
//
// Parameters (under the controller's namespace; defaults as ros_controllers):
//   joints                                 required list of joint names
//   gains/<joint>: {p, i, d, i_clamp, ...} control_toolbox PID gains (effort: required; velocity: optional)
//   velocity_ff/<joint>                    feed-forward gain on the desired velocity (0; 1 for a velocity
//                                          joint without gains)
//   constraints/goal_time                  0 s: time after the end allowed to meet the goal tolerances
//   constraints/stopped_velocity_tolerance 0.01: velocity tolerance at the goal
//   constraints/<joint>/trajectory         0 (unchecked): position path tolerance while executing
//   constraints/<joint>/goal               0 (unchecked): position tolerance at the goal
//   stop_trajectory_duration               0 s: holding after a cancel / empty trajectory / path failure
//                                          stops at the current position (0) or decelerates over this time
//   state_publish_rate                     50 Hz (0: no state messages)
//   action_monitor_rate                    20 Hz: action feedback rate
//   allow_partial_joints_goal              false
//
// ROS API (under the controller's namespace):
//   command                   (trajectory_msgs/JointTrajectory, subscribed) replaces the trajectory;
//                             an empty one holds the current position; preempts an active goal
//   state                     (control_msgs/JointTrajectoryControllerState, published)
//   follow_joint_trajectory   (control_msgs/FollowJointTrajectoryAction server)
//   query_state               (control_msgs/QueryTrajectoryState service)
//
// Threading: the simulator runs update() and services the callback queue of the controller's
// node handle (the global queue) in one thread, between steps. The subscriber, the service and
// actionlib's ActionServer (the plain one, constructed with auto_start = false and then started;
// it creates no threads of its own and delivers goal / cancel callbacks and its status timer
// through the node handle's callback queue) therefore never run concurrently with update(), and
// this controller uses no locks. It must not be driven from a multi-threaded spinner: update()
// calls into the ActionServer (setSucceeded / setAborted / publishFeedback) directly, where
// ros_controllers defers that to a timer through its realtime goal handle.
#include <actionlib/server/action_server.h>
#include <control_msgs/FollowJointTrajectoryAction.h>
#include <control_msgs/JointTrajectoryControllerState.h>
#include <control_msgs/QueryTrajectoryState.h>
#include <ros/node_handle.h>
#include <ros/publisher.h>
#include <ros/service_server.h>
#include <ros/subscriber.h>
#include <trajectory_msgs/JointTrajectory.h>

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "sim_control/controller.h"
#include "sim_control/pid.h"
#include "sim_control/trajectory.h"

namespace sim_control {

class JointTrajectoryController : public Controller {
 public:
  explicit JointTrajectoryController(InterfaceType interface) : interface_(interface) {}
  ~JointTrajectoryController() override;

  bool init(RobotHW& hw, ros::NodeHandle& root_nh, ros::NodeHandle& controller_nh, std::string& error) override;
  void starting(const ros::Time& time) override;
  void update(const ros::Time& time, const ros::Duration& period) override;
  void stopping(const ros::Time& time) override;

 private:
  using ActionServer = actionlib::ActionServer<control_msgs::FollowJointTrajectoryAction>;
  using GoalHandle = ActionServer::GoalHandle;

  void commandCallback(const trajectory_msgs::JointTrajectoryConstPtr& msg);
  void goalCallback(GoalHandle goal);
  void cancelCallback(GoalHandle goal);
  bool queryStateCallback(control_msgs::QueryTrajectoryState::Request& request,
                          control_msgs::QueryTrajectoryState::Response& response);

  // Merges `msg` (non-empty) into the trajectory; returns a FollowJointTrajectoryResult code and
  // sets `start_time` (uptime at which the message's time_from_start counts from) or `error`.
  int replaceTrajectory(const trajectory_msgs::JointTrajectory& msg, int goal_id, double& start_time,
                        std::string& error);
  // ros_controllers' setHoldPosition: stay at the current position (stop_trajectory_duration 0)
  // or come to rest within stop_trajectory_duration, from the desired state (as upstream does) or,
  // after a path tolerance violation, when the joints are far from it, from the actual state.
  void setHoldPosition(int goal_id = 0, bool from_actual = false);
  // Cancels the active goal, if any (it ends PREEMPTED), without touching the trajectory.
  void preemptActiveGoal();
  void finishActiveGoal(const trajectory::GoalMonitor::Result& result);
  void sampleTrajectory();
  void writeCommands(const ros::Duration& period);
  void publishState(const ros::Time& time);
  void publishFeedback(const ros::Time& time);

  const InterfaceType interface_;
  std::string ns_;  // the controller's namespace, for messages

  // Configuration.
  std::vector<std::string> joint_names_;
  std::vector<JointData*> joints_;
  std::vector<bool> wraparound_;  // continuous joints
  std::vector<Pid> pids_;
  std::vector<bool> has_pid_;
  std::vector<double> velocity_ff_;
  trajectory::Tolerances default_tolerances_;
  double stop_trajectory_duration_ = 0.0;
  double state_publish_period_ = 1.0 / 50.0;  // 0: never
  double action_monitor_period_ = 1.0 / 20.0;
  bool allow_partial_joints_goal_ = false;

  // Time: the trajectory lives in controller uptime (seconds since starting()), which only moves
  // forward by the update periods; ROS times in messages are converted through the last update's
  // time and period.
  bool running_ = false;
  double uptime_ = 0.0;
  ros::Time last_time_;
  ros::Duration last_period_;

  trajectory::Trajectory trajectory_;
  std::vector<int> segments_;  // per joint: the segment sampled in this update
  std::vector<trajectory::State> desired_, actual_, error_;
  double last_state_publish_ = 0.0;
  double last_feedback_ = 0.0;

  // ROS interfaces. The action server is declared before the goal handle so the handle is
  // destroyed first; all of them after the state they use.
  control_msgs::JointTrajectoryControllerState state_msg_;
  ros::Publisher state_pub_;
  std::unique_ptr<ActionServer> action_server_;
  std::optional<GoalHandle> active_goal_;
  trajectory::GoalMonitor monitor_;
  int next_goal_id_ = 1;
  ros::ServiceServer query_state_srv_;
  ros::Subscriber command_sub_;
};

}  // namespace sim_control
