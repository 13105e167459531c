#pragma once
// libgazebo_ros_control.so's job in our simulator: expose the joints that the URDF's
// <transmission>s name as a sim_control::RobotHW, run a controller manager in the robot's
// namespace every controlPeriod, and turn the controllers' commands into joint efforts or
// joint motors (position/velocity joints without PID gains follow through the physics).
#include <ros/ros.h>

#include <memory>
#include <string>
#include <vector>

#include "bullet_sim/model_plugin.h"
#include "bullet_sim/physics_model.h"
#include "sim_control/controller_manager.h"
#include "sim_control/pid.h"
#include "sim_control/robot_hw.h"

namespace bullet_sim {

struct RosControlConfig {
  std::string robot_namespace;  // <robotNamespace>, default the model name
  double control_period = 0.0;  // <controlPeriod> in s; 0: every physics step
  std::string robot_param = "robot_description";  // <robotParam>, kept for the record
};

struct TransmissionJoint {
  std::string joint;
  sim_control::InterfaceType interface = sim_control::InterfaceType::Effort;
  double mechanical_reduction = 1.0;  // read; joint-space control makes it invisible here
};

// The gazebo_ros_control plugin block among the model's extensions, if any (false if none).
bool findRosControlPlugin(const ModelDescription& model, RosControlConfig& config);
// Every <transmission> of the URDF. Throws DescriptionError for a transmission that names an
// unknown interface or a joint the model does not have.
std::vector<TransmissionJoint> parseTransmissions(const ModelDescription& model);

class RosControlPlugin : public ModelPlugin {
 public:
  RosControlPlugin(PhysicsModel& model, const RosControlConfig& config, double step_size);
  void beforeStep(const ros::Time& now, double dt) override;
  void reset() override;

 private:
  struct Actuated {
    int physics_joint;
    sim_control::JointData* data;
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

}  // namespace bullet_sim
