#pragma once
// gazebo_ros's dynamic_reconfigure server for the physics, under /gazebo: the parameters of its
// Physics.cfg (time_step, max_update_rate, gravity_x/y/z, the ODE solver's and contacts' values)
// on /gazebo/parameter_descriptions and /gazebo/parameter_updates, set through
// /gazebo/set_parameters, so that `rosrun dynamic_reconfigure dynparam set /gazebo time_step 0.002`
// and rqt_reconfigure work as with Gazebo. The messages are built here (there is no generated
// PhysicsConfig): a server of one fixed parameter set needs no code generation.
#include <dynamic_reconfigure/Config.h>
#include <dynamic_reconfigure/Reconfigure.h>
#include <ros/ros.h>

namespace bullet_sim {

class Simulator;

class PhysicsReconfigure {
 public:
  explicit PhysicsReconfigure(Simulator& sim);
  // Publishes the values in effect on parameter_updates; call after the physics changed elsewhere
  // (set_physics_properties).
  void publishUpdate();

 private:
  bool setParameters(dynamic_reconfigure::Reconfigure::Request& req, dynamic_reconfigure::Reconfigure::Response& res);
  dynamic_reconfigure::Config current() const;

  Simulator& sim_;
  ros::NodeHandle node_;  // /gazebo
  ros::Publisher descriptions_, updates_;
  ros::ServiceServer service_;
};

}  // namespace bullet_sim
