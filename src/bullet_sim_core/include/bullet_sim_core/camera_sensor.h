#pragma once
// Camera sensor, free of ROS: what a Gazebo <sensor type="camera"> describes (field of view, image
// size and format, clipping, noise). SceneRenderer draws what it sees; the gazebo_ros_camera
// plugin publishes it.
#include <Eigen/Geometry>
#include <string>

#include "bullet_sim_core/model_description.h"

namespace bullet_sim {

// Defaults are Gazebo's (sdformat's sensor.sdf / camera.sdf, gazebo_ros_camera_utils.cpp).
struct CameraConfig {
  std::string name;  // <sensor name>
  std::string link;  // the <gazebo reference> (URDF) or the SDF link the sensor sits on
  // Sensor frame in the link frame. As in Gazebo the camera looks along the sensor's +x with
  // +z up: image right is -y, image down is -z (the ROS optical frame is z forward, x right, y down).
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  double update_rate = 0.0;  // Hz; 0 means every physics step
  bool always_on = false;
  bool visualize = false;  // ignored

  // <camera>
  double horizontal_fov = 1.047;  // rad, in (0, pi); the vertical one follows from the aspect ratio
  int width = 320;
  int height = 240;
  std::string format = "R8G8B8";  // <image><format>
  std::string encoding = "rgb8";  // sensor_msgs encoding it maps to: rgb8, bgr8 or mono8
  double near_clip = 0.1;         // m
  double far_clip = 100.0;        // m
  // <camera><noise>: gaussian noise added to every channel, in [0, 1] colour units.
  std::string noise_type = "none";  // none, gaussian, gaussian_quantized (treated as gaussian)
  double noise_mean = 0.0;
  double noise_stddev = 0.0;
};

// Whether the sensor is a camera (type "camera").
bool isCameraSensor(const SensorDescription& sensor);
// The <sensor>'s <camera> and sensor-wide settings. Throws DescriptionError naming the source, the
// element path and what was expected (see sdf_element.h).
CameraConfig parseCameraSensor(const SensorDescription& sensor);

}  // namespace bullet_sim
