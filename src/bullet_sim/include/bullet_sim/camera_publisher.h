#pragma once
// gazebo_ros_camera's ROS side: renders what a camera sensor sees (SceneRenderer) and publishes
// sensor_msgs/Image and sensor_msgs/CameraInfo on <robotNamespace>/<cameraName>/<imageTopicName>
// and .../<cameraInfoTopicName>, stamped with sim time, at the sensor's update_rate (throttled
// further by the plugin's <updateRate>). Renders only while someone subscribes to the image.
#include <ros/ros.h>
#include <sensor_msgs/CameraInfo.h>
#include <sensor_msgs/Image.h>

#include <memory>

#include "bullet_sim/camera_sensor.h"
#include "bullet_sim/model_plugin.h"
#include "bullet_sim/physics_world.h"

namespace bullet_sim {

class CameraPublisher : public ModelPlugin {
 public:
  // `robot_namespace` is the spawn request's; the plugin's <robotNamespace> wins over it.
  // Throws DescriptionError when the namespace or topic names are not valid ROS names.
  CameraPublisher(const CameraConfig& config, PhysicsWorld& world, const PhysicsModel& model,
                  const std::string& robot_namespace, const RenderSettings& settings = RenderSettings());
  void afterStep(const ros::Time& now) override;
  void reset() override;

 private:
  CameraConfig config_;
  PhysicsWorld& world_;
  const PhysicsModel& model_;
  SceneRenderer renderer_;
  std::unique_ptr<ImageNoise> noise_;  // null without noise
  CameraImage frame_;  // rendered in the message encoding's channel order (rgb for mono8)
  ros::NodeHandle node_;
  ros::Publisher image_publisher_;
  ros::Publisher info_publisher_;
  sensor_msgs::Image image_;
  sensor_msgs::CameraInfo info_;
  ros::Duration sensor_period_;   // <update_rate>
  ros::Duration publish_period_;  // the plugin's <updateRate>
  ros::Time next_update_;
  ros::Time last_publish_;
  bool published_ = false;
};

}  // namespace bullet_sim
