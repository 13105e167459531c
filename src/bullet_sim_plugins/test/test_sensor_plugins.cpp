// The sensor plugins' parameters: gazebo_ros_laser's and gazebo_ros_camera's defaults, every
// parameter, CameraInfo's intrinsics, and the errors a user sees.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "bullet_sim_core/description_error.h"
#include "bullet_sim_core/urdf_parser.h"
#include "bullet_sim_plugins/camera_plugin.h"
#include "bullet_sim_plugins/laser_plugin.h"
#include "bullet_sim_core/testing/error_of.h"

namespace bullet_sim {
namespace {

// The first sensor of a URDF with the link `link` and the <gazebo> block `block`.
SensorDescription sensorOf(const std::string& block, const std::string& link = "base_scan") {
  const ModelDescription m = parseUrdf("<robot name='m'><link name='" + link + "'/>" + block + "</robot>",
                                       "model.urdf", ResourceResolver(), "");
  return m.sensors.at(0);
}

std::string laser(const std::string& plugin) {
  return "<gazebo reference='base_scan'><sensor name='lidar' type='ray'><ray><range><min>0.1</min><max>30</max>"
         "</range></ray><plugin name='p' filename='libgazebo_ros_laser.so'>" + plugin + "</plugin></sensor></gazebo>";
}

TEST(LaserPlugin, DefaultsAreGazeboRosLasers) {
  const LaserPluginConfig c = parseLaserPlugin(sensorOf(laser("")).plugins.at(0));
  EXPECT_EQ(c.topic_name, "/world");
  EXPECT_EQ(c.frame_name, "/world");
  EXPECT_FALSE(c.robot_namespace_given);
  EXPECT_EQ(c.gaussian_noise, 0.0);
}

TEST(LaserPlugin, ReadsEveryParameterAndNamesBadOnes) {
  const LaserPluginConfig c = parseLaserPlugin(
      sensorOf(laser("<topicName>/rrbot/laser/scan</topicName><frameName>hokuyo_link</frameName>"
                     "<robotNamespace>rrbot</robotNamespace><gaussianNoise>0.005</gaussianNoise>"
                     "<hokuyoMinIntensity>101</hokuyoMinIntensity>"))
          .plugins.at(0));
  EXPECT_EQ(c.topic_name, "/rrbot/laser/scan");
  EXPECT_EQ(c.frame_name, "hokuyo_link");
  EXPECT_TRUE(c.robot_namespace_given);
  EXPECT_EQ(c.robot_namespace, "rrbot");
  EXPECT_DOUBLE_EQ(c.gaussian_noise, 0.005);
  const std::string at =
      "model.urdf: <gazebo reference='base_scan'>/<sensor name='lidar'>/<plugin name='p' filename='libgazebo_ros_laser.so'>";
  EXPECT_EQ(errorOf([] { parseLaserPlugin(sensorOf(laser("<gaussianNoise>-1</gaussianNoise>")).plugins.at(0)); }),
            at + "/<gaussianNoise>: expected a number >= 0, got '-1'");
  EXPECT_EQ(errorOf([] { parseLaserPlugin(sensorOf(laser("<topicName> </topicName>")).plugins.at(0)); }),
            at + "/<topicName>: expected a name, got ''");
}

std::string camera(const std::string& plugin) {
  return "<gazebo reference='camera_link'><sensor name='cam' type='camera'><camera><horizontal_fov>1.3962634"
         "</horizontal_fov><image><width>800</width><height>600</height></image></camera>"
         "<plugin name='camera_controller' filename='libgazebo_ros_camera.so'>" + plugin + "</plugin></sensor></gazebo>";
}

CameraPluginConfig cameraPluginOf(const std::string& plugin) {
  return parseCameraPlugin(sensorOf(camera(plugin), "camera_link").plugins.at(0));
}

TEST(CameraPlugin, DefaultsAreGazeboRosCamerasAndSoAreTheIntrinsics) {
  const CameraPluginConfig c = cameraPluginOf("");
  EXPECT_EQ(c.image_topic_name, "image_raw");
  EXPECT_EQ(c.camera_info_topic_name, "camera_info");
  EXPECT_EQ(c.camera_name, "");
  EXPECT_EQ(c.frame_name, "");
  EXPECT_FALSE(c.robot_namespace_given);
  EXPECT_EQ(c.update_rate, 0.0);
  const CameraIntrinsics k = cameraIntrinsics(parseCameraSensor(sensorOf(camera(""), "camera_link")), c);
  const double f = 800 / (2 * std::tan(1.3962634 / 2));
  EXPECT_NEAR(k.fx, f, 1e-9);
  EXPECT_DOUBLE_EQ(k.cx, 400.5);  // gazebo_ros_camera_utils: (width + 1) / 2
  EXPECT_DOUBLE_EQ(k.cy, 300.5);
  EXPECT_EQ(k.P, (std::array<double, 12>{f, 0, 400.5, 0, 0, f, 300.5, 0, 0, 0, 1, 0}));
  EXPECT_EQ(k.D, (std::array<double, 5>{0, 0, 0, 0, 0}));
}

// The rrbot tutorial's camera plugin, with the optional parameters.
TEST(CameraPlugin, ReadsEveryParameterIntoCameraInfo) {
  const std::string plugin =
      "<alwaysOn>true</alwaysOn><updateRate>10.0</updateRate><robotNamespace>/rrbot</robotNamespace>"
      "<cameraName>rrbot/camera1</cameraName><imageTopicName>image</imageTopicName>"
      "<cameraInfoTopicName>info</cameraInfoTopicName><frameName>/camera_link_optical</frameName>"
      "<hackBaseline>0.07</hackBaseline><distortionK1>0.1</distortionK1><distortionK2>0.2</distortionK2>"
      "<distortionK3>0.3</distortionK3><distortionT1>0.4</distortionT1><distortionT2>0.5</distortionT2>";
  const CameraPluginConfig c = cameraPluginOf(plugin);
  EXPECT_EQ(c.update_rate, 10.0);
  EXPECT_TRUE(c.robot_namespace_given);
  EXPECT_EQ(c.robot_namespace, "/rrbot");
  EXPECT_EQ(c.camera_name, "rrbot/camera1");
  EXPECT_EQ(c.image_topic_name, "image");
  EXPECT_EQ(c.camera_info_topic_name, "info");
  EXPECT_EQ(c.frame_name, "/camera_link_optical");
  const CameraIntrinsics k = cameraIntrinsics(parseCameraSensor(sensorOf(camera(plugin), "camera_link")), c);
  const double f = 800 / (2 * std::tan(1.3962634 / 2));
  EXPECT_EQ(k.K, (std::array<double, 9>{f, 0, 400.5, 0, f, 300.5, 0, 0, 1}));
  EXPECT_EQ(k.R, (std::array<double, 9>{1, 0, 0, 0, 1, 0, 0, 0, 1}));
  EXPECT_EQ(k.P, (std::array<double, 12>{f, 0, 400.5, -f * 0.07, 0, f, 300.5, 0, 0, 0, 1, 0}));
  EXPECT_EQ(k.D, (std::array<double, 5>{0.1, 0.2, 0.4, 0.5, 0.3}));  // k1 k2 t1 t2 k3
  // Given focal length and centre win over the computed ones.
  const CameraIntrinsics given = cameraIntrinsics(parseCameraSensor(sensorOf(camera(""), "camera_link")),
                                                  cameraPluginOf("<focalLength>500</focalLength><Cx>320</Cx><Cy>240</Cy>"));
  EXPECT_EQ(given.K, (std::array<double, 9>{500, 0, 320, 0, 500, 240, 0, 0, 1}));
}

TEST(CameraPlugin, BadParametersAreNamed) {
  const std::string at = "model.urdf: <gazebo reference='camera_link'>/<sensor name='cam'>/<plugin "
                         "name='camera_controller' filename='libgazebo_ros_camera.so'>";
  EXPECT_EQ(errorOf([] { cameraPluginOf("<imageTopicName> </imageTopicName>"); }),
            at + "/<imageTopicName>: expected a name, got ''");
  EXPECT_EQ(errorOf([] { cameraPluginOf("<updateRate>fast</updateRate>"); }),
            at + "/<updateRate>: expected a number >= 0, got 'fast'");
  EXPECT_EQ(errorOf([] { cameraPluginOf("<focalLength>-3</focalLength>"); }),
            at + "/<focalLength>: expected a number >= 0 (0: computed from the fov), got '-3'");
}

}  // namespace
}  // namespace bullet_sim
