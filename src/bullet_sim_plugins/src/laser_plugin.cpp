// libgazebo_ros_laser.so: see laser_plugin.h.
#include "bullet_sim_plugins/laser_plugin.h"

#include <ros/ros.h>
#include <sensor_msgs/LaserScan.h>

#include <functional>
#include <random>

#include "bullet_sim_core/collision_shapes.h"
#include "bullet_sim_core/laser_sensor.h"
#include "bullet_sim_plugins/plugin_registry.h"
#include "bullet_sim_plugins/ros_names.h"
#include "publish_thread/publish_thread.h"

namespace bullet_sim {

LaserPluginConfig parseLaserPlugin(const PluginDescription& plugin) {
  const SdfElement& p = plugin.element;
  LaserPluginConfig c;
  c.topic_name = p.name("topicName", c.topic_name);
  c.frame_name = p.string("frameName", c.frame_name);
  c.robot_namespace_given = static_cast<bool>(p.child("robotNamespace"));
  c.robot_namespace = p.string("robotNamespace", "");
  c.gaussian_noise = p.number("gaussianNoise", 0.0, nonNegative());
  // <hokuyoMinIntensity> and anything else is ignored, as by gazebo_ros_laser.
  return c;
}

namespace {

class LaserPlugin : public ModelPlugin {
 public:
  explicit LaserPlugin(const PluginContext& context);
  void afterStep(const ros::Time& now) override;
  void reset() override { next_update_ = ros::Time(0); }
  std::optional<SensorTopic> sensorTopic() const override {
    const LaserConfig& c = scanner_.config();
    return SensorTopic{"laser", publisher_.getTopic(), c.link, c.pose, c.range_max};
  }

 private:
  LaserScanner scanner_;
  PhysicsWorld& world_;
  const PhysicsModel& model_;
  ros::NodeHandle node_;
  ros::Publisher publisher_;
  sensor_msgs::LaserScan message_;
  std::mt19937 rng_;
  ros::Duration period_;
  ros::Time next_update_;
};

LaserConfig laserSensorOf(const PluginContext& context) {
  if (!context.sensor || !isLaserSensor(*context.sensor))
    context.plugin.element.fail("expected this plugin inside a <sensor type='ray'> (or gpu_ray)");
  return parseLaserSensor(*context.sensor);
}

LaserPlugin::LaserPlugin(const PluginContext& context)
    : scanner_(laserSensorOf(context)), world_(context.world), model_(context.model) {
  const LaserPluginConfig config = parseLaserPlugin(context.plugin);
  node_ = pluginNodeHandle(context, config.robot_namespace_given, config.robot_namespace);
  // Seeded from the sensor's name so that runs are repeatable.
  rng_.seed(static_cast<std::mt19937::result_type>(std::hash<std::string>()(model_.name() + "/" + context.sensor->name)));
  const LaserConfig& sensor = scanner_.config();
  period_ = ros::Duration(sensor.update_rate > 0 ? 1.0 / sensor.update_rate : 0.0);
  publisher_ = advertiseOrFail<sensor_msgs::LaserScan>(context, node_, config.topic_name, 1);
  message_.header.frame_id = tfFrame(config.frame_name);
  message_.angle_min = scanner_.angle_min();
  message_.angle_max = scanner_.angle_max();
  message_.angle_increment = scanner_.angle_increment();
  message_.time_increment = 0.0;  // every beam is cast at the same instant
  message_.scan_time = period_.toSec();
  message_.range_min = sensor.range_min;
  message_.range_max = sensor.range_max;
}

void LaserPlugin::afterStep(const ros::Time& now) {
  if (now < next_update_) return;
  // Catch up without bursting after a pause or a reset.
  next_update_ = (next_update_.isZero() || now - next_update_ > period_) ? now + period_ : next_update_ + period_;
  if (publisher_.getNumSubscribers() == 0) return;  // like Gazebo: no readers, no rays
  const LaserConfig& config = scanner_.config();
  const btTransform sensor = toBullet(model_.linkPose(config.link) * config.pose);
  std::vector<const btCollisionObject*> ignore;
  if (const btCollisionObject* own = model_.linkCollider(config.link)) ignore.push_back(own);
  scanner_.scan(world_.bulletWorld(), sensor, ignore, rng_, message_.ranges);
  message_.intensities.assign(message_.ranges.size(), 0.0f);
  message_.header.stamp = now;
  publish_thread::publish(publisher_, message_);
}

}  // namespace
}  // namespace bullet_sim

BULLET_SIM_REGISTER_PLUGIN("libgazebo_ros_laser.so", bullet_sim::LaserPlugin)
BULLET_SIM_REGISTER_PLUGIN("libgazebo_ros_gpu_laser.so", bullet_sim::LaserPlugin)
