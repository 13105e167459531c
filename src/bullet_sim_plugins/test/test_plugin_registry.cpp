// Plugins by library name: the registry holds gazebo_ros's plugins, a new plugin joins it with one
// registration line (example_altimeter_plugin.cpp), and the loader creates a model's plugins from
// its <plugin> elements and says once, naming the model, what it cannot simulate.
#include <gtest/gtest.h>
#include <ros/console.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "bullet_sim_core/description_error.h"
#include "bullet_sim_core/urdf_parser.h"
#include "bullet_sim_plugins/plugin_loader.h"
#include "bullet_sim_plugins/plugin_registry.h"

namespace bullet_sim {

std::vector<double>& altimeterReadings();  // example_altimeter_plugin.cpp

namespace {

// Collects what the loader logs at WARN and above.
class WarningCollector : public ros::console::LogAppender {
 public:
  WarningCollector() { ros::console::register_appender(this); }
  ~WarningCollector() override { ros::console::deregister_appender(this); }
  void log(ros::console::Level level, const char* text, const char*, const char*, int) override {
    if (level >= ros::console::levels::Warn) warnings.push_back(text);
  }
  std::vector<std::string> warnings;
};

// A 1 kg box whose link "body" starts 2 m up, with `blocks` added to its URDF.
ModelDescription boxWith(const std::string& blocks) {
  return parseUrdf("<robot name='box'><link name='body'><inertial><mass value='1'/><inertia ixx='0.1' iyy='0.1' "
                   "izz='0.1' ixy='0' ixz='0' iyz='0'/></inertial><collision><geometry><box size='0.2 0.2 0.2'/>"
                   "</geometry></collision></link>" + blocks + "</robot>",
                   "box.urdf", ResourceResolver(), "");
}

Eigen::Isometry3d raised(double z) {
  Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
  t.translation().z() = z;
  return t;
}

TEST(PluginRegistry, HoldsGazeboRosPluginsByLibraryName) {
  const std::vector<std::string> names = registeredPlugins();
  for (const char* name : {"libgazebo_ros_laser.so", "libgazebo_ros_gpu_laser.so", "libgazebo_ros_camera.so",
                           "libgazebo_ros_diff_drive.so", "libgazebo_ros_skid_steer_drive.so", "libexample_altimeter.so"})
    EXPECT_NE(std::find(names.begin(), names.end(), name), names.end()) << name;
  EXPECT_NE(findPlugin("/usr/lib/x86_64-linux-gnu/gazebo-11/plugins/libgazebo_ros_laser.so"), nullptr);  // a folder is fine
  EXPECT_EQ(findPlugin("libgazebo_ros_teleport.so"), nullptr);
  EXPECT_FALSE(registerPlugin("libgazebo_ros_laser.so", nullptr));  // first come, first kept
}

TEST(PluginRegistry, ANewSensorPluginRunsFromItsRegistrationLine) {
  const ModelDescription box = boxWith(
      "<gazebo reference='body'><sensor name='alt' type='altimeter'><update_rate>10</update_rate>"
      "<plugin name='a' filename='libexample_altimeter.so'><offset>0.5</offset></plugin></sensor></gazebo>");
  PhysicsWorld world;
  PhysicsModel& model = world.addModel(box, raised(2.0));
  WarningCollector log;
  std::vector<LoadedPlugin> plugins = loadModelPlugins(world, model, "");
  ASSERT_EQ(plugins.size(), 1u);
  EXPECT_EQ(plugins[0].label, "model 'box': libexample_altimeter.so (sensor 'alt')");
  EXPECT_TRUE(log.warnings.empty());
  altimeterReadings().clear();
  for (int i = 0; i < 500; ++i) {  // 0.5 s of free fall
    world.step();
    for (auto& p : plugins) p.plugin->afterStep(ros::Time(world.time()));
  }
  // 10 Hz for 0.5 s, each the height + 0.5: from 2.5 m down by g t^2 / 2 = 1.225 m.
  ASSERT_EQ(altimeterReadings().size(), 5u);
  EXPECT_NEAR(altimeterReadings().front(), 2.5, 1e-3);
  EXPECT_NEAR(altimeterReadings().back(), 2.5 - 0.5 * 9.8 * 0.401 * 0.401, 5e-3);
  // Its parameters are read like every plugin's.
  const ModelDescription bad = boxWith(
      "<gazebo reference='body'><sensor name='alt' type='altimeter'><update_rate>-1</update_rate>"
      "<plugin name='a' filename='libexample_altimeter.so'/></sensor></gazebo>");
  PhysicsWorld other;
  PhysicsModel& bad_model = other.addModel(bad, raised(2.0));
  EXPECT_THROW(loadModelPlugins(other, bad_model, ""), DescriptionError);
}

TEST(PluginLoader, SaysOnceWhatItCannotSimulate) {
  const ModelDescription box = boxWith(
      "<gazebo><plugin name='t1' filename='libgazebo_ros_teleport.so'/><plugin name='t2' "
      "filename='libgazebo_ros_teleport.so'/></gazebo>"
      "<gazebo reference='body'><sensor name='imu' type='imu'/></gazebo>");
  PhysicsWorld world;
  PhysicsModel& model = world.addModel(box, raised(1.0));
  WarningCollector log;
  EXPECT_TRUE(loadModelPlugins(world, model, "").empty());
  ASSERT_EQ(log.warnings.size(), 2u);
  EXPECT_EQ(log.warnings[0], "model 'box': imu sensor 'imu' has no plugin, so nothing is published for it");
  EXPECT_EQ(log.warnings[1].rfind("model 'box': unknown plugin 'libgazebo_ros_teleport.so' (box.urdf: <gazebo>/"
                                  "<plugin name='t1' filename='libgazebo_ros_teleport.so'>); bullet_sim does not "
                                  "simulate it. Known plugins: ",
                                  0),
            0u)
      << log.warnings[1];
}

TEST(PluginLoader, APluginInTheWrongPlaceIsAnErrorNamingIt) {
  const ModelDescription box = boxWith("<gazebo><plugin name='l' filename='libgazebo_ros_laser.so'/></gazebo>");
  PhysicsWorld world;
  PhysicsModel& model = world.addModel(box, raised(1.0));
  try {
    loadModelPlugins(world, model, "");
    FAIL() << "expected a DescriptionError";
  } catch (const DescriptionError& e) {
    EXPECT_EQ(std::string(e.what()), "box.urdf: <gazebo>/<plugin name='l' filename='libgazebo_ros_laser.so'>: "
                                     "expected this plugin inside a <sensor type='ray'> (or gpu_ray)");
  }
}

// Gazebo's way when a plugin cannot find its joints: it says so and does nothing; the model is
// simulated without it (and no ROS name is taken).
TEST(PluginLoader, AKatanaGripperWithoutItsFingerJointsStaysInactiveAndSaysWhy) {
  const ModelDescription box = boxWith(
      "<gazebo><plugin name='gazebo_ros_katana_gripper' filename='libgazebo_ros_katana_gripper.so'>"
      "<r_finger_joint>finger</r_finger_joint></plugin></gazebo>");
  PhysicsWorld world;
  PhysicsModel& model = world.addModel(box, raised(1.0));
  WarningCollector log;
  std::vector<LoadedPlugin> plugins = loadModelPlugins(world, model, "");
  ASSERT_EQ(plugins.size(), 1u);
  ASSERT_EQ(log.warnings.size(), 1u);
  EXPECT_EQ(log.warnings[0],
            "model 'box': libgazebo_ros_katana_gripper.so: box.urdf: <gazebo>/<plugin name='gazebo_ros_katana_gripper' "
            "filename='libgazebo_ros_katana_gripper.so'>/<r_finger_joint>: model 'box' has no joint 'finger'; the "
            "gripper plugin stays inactive");
  plugins[0].plugin->beforeStep(ros::Time(0.001), 0.001);
  world.step();
  plugins[0].plugin->afterStep(ros::Time(0.001));
  plugins[0].plugin->reset();
  EXPECT_TRUE(std::isfinite(model.pose().translation().z()));
}

}  // namespace
}  // namespace bullet_sim
