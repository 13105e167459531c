#include "bullet_sim/model_plugins.h"

#include <ros/console.h>

#include "bullet_sim/camera_publisher.h"
#include "bullet_sim/description_error.h"
#include "bullet_sim/drive_plugins.h"
#include "bullet_sim/laser_publisher.h"
#include "bullet_sim/ros_control_plugin.h"

namespace bullet_sim {

std::vector<std::unique_ptr<ModelPlugin>> makeModelPlugins(PhysicsWorld& world, PhysicsModel& model,
                                                           const std::string& robot_namespace) {
  std::vector<std::unique_ptr<ModelPlugin>> plugins;
  const ModelDescription& description = model.description();
  for (const LaserConfig& laser : parseLaserSensors(description.extensions, description.source)) {
    if (!model.hasLink(laser.link))
      throw DescriptionError(description.source + ": <gazebo reference='" + laser.link + "'>/<sensor name='" +
                             laser.name + "'>: expected the name of a link of model '" + model.name() + "'");
    if (laser.plugin_filename.empty()) {
      ROS_WARN_STREAM("model '" << model.name() << "': ray sensor '" << laser.name
                                << "' has no libgazebo_ros_laser.so plugin, so nothing is published for it");
      continue;
    }
    plugins.push_back(std::make_unique<LaserPublisher>(laser, world, model, robot_namespace));
  }
  for (const CameraConfig& camera : parseCameraSensors(description.extensions, description.source)) {
    if (!model.hasLink(camera.link))
      throw DescriptionError(description.source + ": <gazebo reference='" + camera.link + "'>/<sensor name='" +
                             camera.name + "'>: expected the name of a link of model '" + model.name() + "'");
    if (camera.plugin_filename.empty()) {
      ROS_WARN_STREAM("model '" << model.name() << "': camera sensor '" << camera.name
                                << "' has no libgazebo_ros_camera.so plugin, so nothing is published for it");
      continue;
    }
    plugins.push_back(std::make_unique<CameraPublisher>(camera, world, model, robot_namespace));
  }
  if (const auto diff_drive = parseDiffDrive(description))
    plugins.push_back(std::make_unique<DiffDrivePlugin>(model, *diff_drive, robot_namespace));
  if (const auto skid_steer = parseSkidSteerDrive(description))
    plugins.push_back(std::make_unique<SkidSteerDrivePlugin>(model, *skid_steer, robot_namespace));
  RosControlConfig ros_control;
  if (findRosControlPlugin(description, ros_control))
    plugins.push_back(std::make_unique<RosControlPlugin>(model, ros_control, world.settings().max_step_size));
  return plugins;
}

}  // namespace bullet_sim
