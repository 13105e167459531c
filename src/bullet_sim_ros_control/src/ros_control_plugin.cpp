// libgazebo_ros_control.so: expose the joints that the URDF's <transmission>s name as a
// sim_control::RobotHW, run a controller manager in the robot's namespace every <controlPeriod>,
// and turn the controllers' commands into joint efforts or joint motors (position/velocity joints
// without PID gains follow through the physics, as with gazebo_ros_control's default).
//
// Parameters, as gazebo_ros_control: <robotNamespace> (default: the model's name), <controlPeriod>
// (s; default and minimum: the physics step), <robotParam> (read for the record: the transmissions
// come from the spawned URDF itself). Gains for position/velocity joints come from
// <robotNamespace>/gazebo_ros_control/pid_gains/<joint>/{p,i,d,...} when given.
#include <ros/ros.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "bullet_sim_core/description_error.h"
#include "bullet_sim_plugins/plugin_registry.h"
#include "bullet_sim_ros_control/ros_control_config.h"
#include "sim_control/controller_manager.h"
#include "sim_control/pid.h"
#include "sim_control/robot_hw.h"

namespace bullet_sim {
namespace {

const char* kPluginFile = "libgazebo_ros_control.so";
// A motor needs a finite force bound; joints without an effort limit get a generous one.
constexpr double kUnlimitedMotorForce = 1e4;
// PyBullet's POSITION_CONTROL default: close 10 % of the position error per step.
constexpr double kMotorPositionGain = 0.1;

double wrapAngle(double a) { return std::remainder(a, 2.0 * M_PI); }

class RosControlPlugin : public ModelPlugin {
 public:
  explicit RosControlPlugin(const PluginContext& context);
  void beforeStep(const ros::Time& now, double dt) override;
  void reset() override;

 private:
  struct Actuated {
    int physics_joint = -1;
    sim_control::JointData* data = nullptr;
    bool has_pid = false;
    sim_control::Pid pid;
  };
  void readState();
  void applyCommands(double dt);

  PhysicsModel& model_;
  ros::Duration control_period_;
  ros::Time last_update_;
  sim_control::RobotHW hw_;
  std::vector<Actuated> actuated_;
  std::unique_ptr<sim_control::ControllerManager> manager_;
};

RosControlPlugin::RosControlPlugin(const PluginContext& context) : model_(context.model) {
  const RosControlConfig config = parseRosControlConfig(context.plugin, context.model.name());
  control_period_ = ros::Duration(std::max(config.control_period, context.world.settings().max_step_size));
  const PhysicsModel& model = context.model;
  const std::vector<TransmissionJoint> transmissions = transmissionJoints(model.description());
  hw_.joints().reserve(transmissions.size());  // JointData pointers must stay valid
  ros::NodeHandle robot_nh;
  try {
    robot_nh = ros::NodeHandle(config.robot_namespace);
  } catch (const ros::InvalidNameException& e) {
    context.plugin.element.child("robotNamespace").fail("expected a valid ROS namespace: " + std::string(e.what()));
  }
  for (const TransmissionJoint& t : transmissions) {
    const int j = model.jointIndex(t.joint);
    if (j < 0) {
      throw DescriptionError(model.description().source + ": <transmission> joint '" + t.joint +
                             "': expected a revolute, continuous or prismatic joint of model '" + model.name() + "'");
    }
    const JointDescription& d = model.joints()[j];
    sim_control::JointLimits limits;
    limits.continuous = d.type == JointType::Continuous;
    limits.has_position_limits = d.type == JointType::Revolute || d.type == JointType::Prismatic;
    limits.lower = d.lower;
    limits.upper = d.upper;
    limits.effort = d.effort_limit;
    limits.velocity = d.velocity_limit;
    Actuated a;
    a.physics_joint = j;
    a.data = &hw_.addJoint(t.joint, t.interface, limits);
    if (t.interface == sim_control::InterfaceType::Position) a.data->command = model.jointPosition(j);
    // gazebo_ros_control's optional PID for position/velocity joints.
    ros::NodeHandle gains(robot_nh, "gazebo_ros_control/pid_gains/" + t.joint);
    if (t.interface != sim_control::InterfaceType::Effort && gains.hasParam("p")) {
      std::string error;
      if (!a.pid.init(gains, error)) throw DescriptionError(error);
      a.has_pid = true;
    }
    actuated_.push_back(a);
  }
  if (actuated_.empty())
    ROS_WARN_STREAM("model '" << model.name() << "': " << kPluginFile
                              << " found no <transmission>; its controllers will have no joints to command");
  readState();
  manager_ = std::make_unique<sim_control::ControllerManager>(hw_, robot_nh);
  ROS_INFO_STREAM("model '" << model.name() << "': controller manager at " << robot_nh.resolveName("controller_manager")
                            << " for " << actuated_.size() << " joints, control period " << control_period_.toSec()
                            << " s");
}

void RosControlPlugin::readState() {
  for (Actuated& a : actuated_) {
    a.data->position = model_.jointPosition(a.physics_joint);
    a.data->velocity = model_.jointVelocity(a.physics_joint);
    a.data->effort = model_.jointEffort(a.physics_joint) + model_.jointMotorForce(a.physics_joint);
  }
}

void RosControlPlugin::beforeStep(const ros::Time& now, double dt) {
  readState();
  if (last_update_.isZero() || now - last_update_ >= control_period_ - ros::Duration(1e-9)) {
    const ros::Duration period = last_update_.isZero() ? control_period_ : now - last_update_;
    manager_->update(now, period);
    last_update_ = now;
  }
  applyCommands(dt);
}

void RosControlPlugin::applyCommands(double dt) {
  for (Actuated& a : actuated_) {
    const sim_control::JointData& d = *a.data;
    if (!d.driven) {
      // No running controller: the joint is free (upstream would keep applying the last command).
      model_.clearJointMotor(a.physics_joint);
      continue;
    }
    const double limit = d.limits.effort;
    const double command = std::isfinite(d.command) ? d.command : 0.0;
    double effort = 0.0;
    switch (d.interface) {
      case sim_control::InterfaceType::Effort:
        effort = command;
        break;
      case sim_control::InterfaceType::Position:
        if (!a.has_pid) {
          const double target = d.limits.has_position_limits ? std::clamp(command, d.limits.lower, d.limits.upper)
                                                             : command;
          // Continuous joints go the short way round.
          const double goal = d.limits.continuous ? d.position + wrapAngle(target - d.position) : target;
          model_.setJointMotor(a.physics_joint, goal, 0.0, kMotorPositionGain,
                               std::isfinite(limit) ? limit : kUnlimitedMotorForce);
          continue;
        }
        effort = a.pid.compute(d.limits.continuous ? wrapAngle(command - d.position) : command - d.position, dt);
        break;
      case sim_control::InterfaceType::Velocity:
        if (!a.has_pid) {
          model_.setJointMotor(a.physics_joint, 0.0, command, 0.0, std::isfinite(limit) ? limit : kUnlimitedMotorForce);
          continue;
        }
        effort = a.pid.compute(command - d.velocity, dt);
        break;
    }
    model_.addJointEffort(a.physics_joint, std::clamp(effort, -limit, limit));
  }
}

void RosControlPlugin::reset() {
  last_update_ = ros::Time();
  for (Actuated& a : actuated_) {
    a.pid.reset();
    if (a.data->interface == sim_control::InterfaceType::Position) a.data->command = model_.jointPosition(a.physics_joint);
  }
}

}  // namespace
}  // namespace bullet_sim

BULLET_SIM_REGISTER_PLUGIN("libgazebo_ros_control.so", bullet_sim::RosControlPlugin)
