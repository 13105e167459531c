// libgazebo_ros_katana_gripper.so (katana_gazebo_plugins' gripper plugin, our own implementation):
// the Katana's two fingers driven by one PID each toward one target angle, commanded through a
// control_msgs/GripperCommand action. The controller and its decisions are
// katana_gripper_controller.h's, the parameters katana_gripper_config.h's; this file reads the
// finger joints, applies the efforts and speaks ROS.
//
// In the root namespace, as upstream (a <remap> of the simulator node moves them):
//  - action gripper_grasp_posture_controller (control_msgs/GripperCommandAction): command.position
//    outside [-0.44, 0.30] is aborted with the range in the text; otherwise the fingers go there and
//    the goal succeeds when they get there, stop against something, or after 3 s of sim time, with
//    result.position = the gripper's angle and reached_goal or stalled. command.max_effort is
//    ignored: <max_torque> bounds each finger. A new goal preempts the running one; a
//    cancel ends it (preempted) and holds the fingers where they are.
//  - service gripper_grasp_status (control_msgs/QueryTrajectoryState): position = [the gripper's
//    angle], the mean of the two fingers.
// The fingers' positions reach /joint_states through their ros_control transmissions; the efforts
// here add to what ros_control applies (nothing, while no controller claims the finger joints).
// actionlib publishes the goal statuses and results itself, from the loop's thread rather than
// through publish_thread: a few messages per goal, and its status timer at 5 Hz.
//
// A finger joint the model does not have (or another bad parameter) is an error naming the plugin
// and the element; the plugin then stays inactive and the model is simulated without it, as
// Gazebo does when a plugin's Load gives up.
#include <actionlib/server/simple_action_server.h>
#include <control_msgs/GripperCommandAction.h>
#include <control_msgs/QueryTrajectoryState.h>
#include <ros/ros.h>

#include <array>
#include <memory>
#include <optional>
#include <string>

#include "bullet_sim_core/description_error.h"
#include "bullet_sim_plugins/katana_gripper_config.h"
#include "bullet_sim_plugins/katana_gripper_controller.h"
#include "bullet_sim_plugins/plugin_registry.h"
#include "bullet_sim_plugins/ros_names.h"

namespace bullet_sim {
namespace {

using GraspServer = actionlib::SimpleActionServer<control_msgs::GripperCommandAction>;

class KatanaGripperPlugin : public ModelPlugin {
 public:
  explicit KatanaGripperPlugin(const PluginContext& context)
      : world_(context.world), model_(context.model), label_(context.label()) {
    KatanaGripperConfig config;
    try {
      config = parseKatanaGripperConfig(context.plugin, context.model.description());
    } catch (const DescriptionError& e) {
      ROS_ERROR_STREAM(label_ << ": " << e.what() << "; the gripper plugin stays inactive");
      return;
    }
    options_ = config.options;
    fingers_ = {model_.jointIndex(config.r_finger_joint), model_.jointIndex(config.l_finger_joint)};
    controller_ = std::make_unique<KatanaGripperController>(options_, positions());
    root_ = nodeHandleOrFail(context, "/");
    server_ = std::make_unique<GraspServer>(*root_, "gripper_grasp_posture_controller", false);
    server_->registerGoalCallback([this] { onGoal(); });
    server_->registerPreemptCallback([this] { onPreempt(); });
    server_->start();
    status_ = root_->advertiseService("gripper_grasp_status", &KatanaGripperPlugin::onStatus, this);
    ROS_INFO_STREAM(label_ << ": fingers '" << config.r_finger_joint << "' and '" << config.l_finger_joint
                           << "', max_torque " << options_.max_torque << " N m, at most "
                           << options_.max_velocity << " rad/s; action "
                           << root_->resolveName("gripper_grasp_posture_controller") << ", service "
                           << status_.getService());
  }

  ~KatanaGripperPlugin() override {
    if (server_ && server_->isActive() && ros::ok()) server_->setAborted(result(), "the model was removed");
  }

  void beforeStep(const ros::Time& /*now*/, double dt) override {
    if (!controller_) return;
    const auto efforts = controller_->efforts(positions(), velocities(), dt);
    for (size_t f = 0; f < fingers_.size(); ++f) model_.addJointEffort(fingers_[f], efforts[f]);
  }

  void afterStep(const ros::Time& now) override {
    if (!controller_ || !controller_->goalActive()) return;
    const GraspOutcome outcome = controller_->judge(now.toSec(), positions(), velocities());
    if (outcome == GraspOutcome::Running || !server_->isActive()) return;
    control_msgs::GripperCommandResult r = result();
    r.reached_goal = outcome == GraspOutcome::Reached;
    r.stalled = outcome == GraspOutcome::Stalled;
    server_->setSucceeded(r, r.reached_goal ? "reached the goal position" : "stalled before the goal position");
  }

  // reset_world / reset_simulation put the fingers back where they spawned; they stay there.
  void reset() override {
    if (!controller_) return;
    if (server_->isActive()) server_->setAborted(result(), "the simulation was reset");
    controller_->hold(positions());
  }

 private:
  KatanaGripperController::Pair positions() const {
    return {model_.jointPosition(fingers_[0]), model_.jointPosition(fingers_[1])};
  }
  KatanaGripperController::Pair velocities() const {
    return {model_.jointVelocity(fingers_[0]), model_.jointVelocity(fingers_[1])};
  }
  control_msgs::GripperCommandResult result() const {
    control_msgs::GripperCommandResult r;
    r.position = KatanaGripperController::angle(positions());
    r.effort = 0.5 * (model_.jointEffort(fingers_[0]) + model_.jointEffort(fingers_[1]));
    return r;
  }

  // Runs between steps (the simulator's one thread spins the callbacks): the target takes effect
  // from the next step, and the goal's sim time starts there.
  void onGoal() {
    const double position = server_->acceptNewGoal()->command.position;  // ends a running goal (preempted)
    const std::string refused = checkGoalPosition(position, options_);
    if (!refused.empty()) {
      ROS_WARN_STREAM(label_ << ": " << refused);
      server_->setAborted(result(), refused);
      return;
    }
    controller_->startGoal(position, world_.time(), positions());
  }

  // A cancel (a new goal's preemption is onGoal's): the fingers stay where they are.
  void onPreempt() {
    if (server_->isNewGoalAvailable()) return;
    controller_->hold(positions());
    server_->setPreempted(result(), "canceled; the fingers hold where they are");
  }

  bool onStatus(control_msgs::QueryTrajectoryState::Request& /*request*/,
                control_msgs::QueryTrajectoryState::Response& response) {
    response.position = {KatanaGripperController::angle(positions())};
    return true;
  }

  const PhysicsWorld& world_;
  PhysicsModel& model_;
  const std::string label_;
  KatanaGripperOptions options_;
  std::array<int, 2> fingers_{{-1, -1}};
  std::unique_ptr<KatanaGripperController> controller_;  // nullptr: inactive
  std::optional<ros::NodeHandle> root_;  // only when active: an inactive plugin needs no ROS
  std::unique_ptr<GraspServer> server_;
  ros::ServiceServer status_;
};

}  // namespace
}  // namespace bullet_sim

BULLET_SIM_REGISTER_PLUGIN("libgazebo_ros_katana_gripper.so", bullet_sim::KatanaGripperPlugin)
