#pragma once
// libgazebo_ros_camera.so: renders what a camera sensor sees (SceneRenderer) and publishes
// sensor_msgs/Image and sensor_msgs/CameraInfo on <robotNamespace>/<cameraName>/<imageTopicName>
// and .../<cameraInfoTopicName>, stamped with sim time, at the sensor's update_rate (throttled
// further by the plugin's <updateRate>). Renders only while someone subscribes to the image.
#include <array>
#include <string>

#include "bullet_sim_core/camera_sensor.h"
#include "bullet_sim_core/model_description.h"

namespace bullet_sim {

// The <plugin>'s parameters, with gazebo_ros_camera_utils' defaults.
struct CameraPluginConfig {
  // <robotNamespace>: absent -> the spawn request's namespace; present but empty -> the model name.
  std::string robot_namespace;
  bool robot_namespace_given = false;
  std::string camera_name;  // topics live under <robotNamespace>/<cameraName>
  std::string image_topic_name = "image_raw";
  std::string camera_info_topic_name = "camera_info";
  std::string frame_name;      // gazebo_ros_camera_utils leaves it empty when missing
  double update_rate = 0.0;    // <updateRate>: throttles publishing further; 0 = the sensor's rate
  double hack_baseline = 0.0;  // m; P[3] = -fx * hackBaseline (the right camera of a stereo pair)
  // 0 means "compute it" for these, as in gazebo_ros_camera_utils.
  double focal_length = 0.0;
  double cx = 0.0;
  double cy = 0.0;
  double cx_prime = 0.0;  // read, unused: gazebo_ros_camera_utils does not put it in CameraInfo either
  // Copied into CameraInfo.D = {k1, k2, t1, t2, k3}; the image itself is not distorted (as in
  // Gazebo unless <camera><distortion> is given, which is not supported here).
  double distortion_k1 = 0.0, distortion_k2 = 0.0, distortion_k3 = 0.0;
  double distortion_t1 = 0.0, distortion_t2 = 0.0;
};

// Throws DescriptionError naming the element for a bad value (see sdf_element.h).
CameraPluginConfig parseCameraPlugin(const PluginDescription& plugin);

// sensor_msgs/CameraInfo's matrices as gazebo_ros_camera_utils fills them:
// fx = fy = width / (2 tan(hfov / 2)) (or <focalLength>), cx = (width + 1) / 2,
// cy = (height + 1) / 2 (or <Cx>, <Cy>), R = I, P = [fx 0 cx -fx*hackBaseline; 0 fy cy 0; 0 0 1 0],
// D = {k1, k2, t1, t2, k3} (plumb_bob). Note Gazebo's cx, cy sit one pixel right of and below the
// true image centre ((width - 1) / 2 in pixel indices), where both Gazebo and SceneRenderer put
// the optical axis; we publish Gazebo's numbers so that downstream code sees the same CameraInfo.
struct CameraIntrinsics {
  double fx = 0, fy = 0, cx = 0, cy = 0;
  std::array<double, 9> K{};
  std::array<double, 9> R{};
  std::array<double, 12> P{};
  std::array<double, 5> D{};
};
CameraIntrinsics cameraIntrinsics(const CameraConfig& sensor, const CameraPluginConfig& plugin);

}  // namespace bullet_sim
