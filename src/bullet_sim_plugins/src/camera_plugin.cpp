// libgazebo_ros_camera.so: see camera_plugin.h.
#include "bullet_sim_plugins/camera_plugin.h"

#include <ros/ros.h>
#include <sensor_msgs/CameraInfo.h>
#include <sensor_msgs/Image.h>

#include <cmath>
#include <functional>
#include <memory>

#include "bullet_sim_core/image_noise.h"
#include "bullet_sim_core/scene_renderer.h"
#include "bullet_sim_plugins/plugin_registry.h"
#include "bullet_sim_plugins/ros_names.h"
#include "publish_thread/publish_thread.h"

namespace bullet_sim {

CameraPluginConfig parseCameraPlugin(const PluginDescription& plugin) {
  const SdfElement& p = plugin.element;
  CameraPluginConfig c;
  c.robot_namespace_given = static_cast<bool>(p.child("robotNamespace"));
  c.robot_namespace = p.string("robotNamespace", "");
  c.camera_name = p.string("cameraName", c.camera_name);
  c.image_topic_name = p.name("imageTopicName", c.image_topic_name);
  c.camera_info_topic_name = p.name("cameraInfoTopicName", c.camera_info_topic_name);
  c.frame_name = p.string("frameName", c.frame_name);
  c.update_rate = p.number("updateRate", 0.0, nonNegative());
  c.hack_baseline = p.number("hackBaseline", 0.0);
  c.focal_length = p.number("focalLength", 0.0, {[](double v) { return v >= 0; }, ">= 0 (0: computed from the fov)"});
  c.cx = p.number("Cx", 0.0);
  c.cy = p.number("Cy", 0.0);
  c.cx_prime = p.number("CxPrime", 0.0);
  c.distortion_k1 = p.number("distortionK1", 0.0);
  c.distortion_k2 = p.number("distortionK2", 0.0);
  c.distortion_k3 = p.number("distortionK3", 0.0);
  c.distortion_t1 = p.number("distortionT1", 0.0);
  c.distortion_t2 = p.number("distortionT2", 0.0);
  return c;
}

CameraIntrinsics cameraIntrinsics(const CameraConfig& sensor, const CameraPluginConfig& plugin) {
  CameraIntrinsics k;
  const double computed = sensor.width / (2.0 * std::tan(sensor.horizontal_fov / 2.0));
  k.fx = k.fy = plugin.focal_length != 0 ? plugin.focal_length : computed;
  k.cx = plugin.cx != 0 ? plugin.cx : (sensor.width + 1.0) / 2.0;  // gazebo_ros_camera_utils' formula, see the header
  k.cy = plugin.cy != 0 ? plugin.cy : (sensor.height + 1.0) / 2.0;
  k.K = {k.fx, 0, k.cx, 0, k.fy, k.cy, 0, 0, 1};
  k.R = {1, 0, 0, 0, 1, 0, 0, 0, 1};
  k.P = {k.fx, 0, k.cx, -k.fx * plugin.hack_baseline, 0, k.fy, k.cy, 0, 0, 0, 1, 0};
  k.D = {plugin.distortion_k1, plugin.distortion_k2, plugin.distortion_t1, plugin.distortion_t2, plugin.distortion_k3};
  return k;
}

namespace {

std::uint64_t seedOf(const std::string& text) { return static_cast<std::uint64_t>(std::hash<std::string>()(text)); }

CameraConfig cameraSensorOf(const PluginContext& context) {
  if (!context.sensor || !isCameraSensor(*context.sensor))
    context.plugin.element.fail("expected this plugin inside a <sensor type='camera'>");
  return parseCameraSensor(*context.sensor);
}

class CameraPlugin : public ModelPlugin {
 public:
  explicit CameraPlugin(const PluginContext& context);
  void afterStep(const ros::Time& now) override;
  void reset() override;
  std::optional<SensorTopic> sensorTopic() const override {
    return SensorTopic{"camera", image_publisher_.getTopic(), config_.link, config_.pose, config_.far_clip};
  }

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

CameraPlugin::CameraPlugin(const PluginContext& context)
    : config_(cameraSensorOf(context)),
      world_(context.world),
      model_(context.model),
      sensor_period_(config_.update_rate > 0 ? 1.0 / config_.update_rate : 0.0) {
  const CameraPluginConfig plugin = parseCameraPlugin(context.plugin);
  publish_period_ = ros::Duration(plugin.update_rate > 0 ? 1.0 / plugin.update_rate : 0.0);
  // gazebo_ros_camera_utils: NodeHandle(robotNamespace + "/" + cameraName), topics relative to it.
  const std::string ns = sensorPluginNamespace(context, plugin.robot_namespace_given, plugin.robot_namespace);
  node_ = nodeHandleOrFail(context, ns.empty() || plugin.camera_name.empty() ? ns + plugin.camera_name
                                                                              : ns + "/" + plugin.camera_name);
  image_publisher_ = advertiseOrFail<sensor_msgs::Image>(context, node_, plugin.image_topic_name, 2);
  info_publisher_ = advertiseOrFail<sensor_msgs::CameraInfo>(context, node_, plugin.camera_info_topic_name, 2);
  // Seeded from the sensor's name so that runs are repeatable.
  if (config_.noise_type != "none" && (config_.noise_stddev > 0 || config_.noise_mean != 0))
    noise_ = std::make_unique<ImageNoise>(config_.noise_mean, config_.noise_stddev,
                                          seedOf(model_.name() + "/" + config_.name));

  const std::string frame = tfFrame(plugin.frame_name);
  image_.header.frame_id = frame;
  image_.height = config_.height;
  image_.width = config_.width;
  image_.encoding = config_.encoding;
  image_.is_bigendian = 0;
  image_.step = config_.width * (config_.encoding == "mono8" ? 1 : 3);

  const CameraIntrinsics k = cameraIntrinsics(config_, plugin);
  info_.header.frame_id = frame;
  info_.height = config_.height;
  info_.width = config_.width;
  info_.distortion_model = "plumb_bob";
  info_.D.assign(k.D.begin(), k.D.end());
  std::copy(k.K.begin(), k.K.end(), info_.K.begin());
  std::copy(k.R.begin(), k.R.end(), info_.R.begin());
  std::copy(k.P.begin(), k.P.end(), info_.P.begin());
}

void CameraPlugin::reset() {
  next_update_ = ros::Time(0);
  published_ = false;
}

void CameraPlugin::afterStep(const ros::Time& now) {
  if (now < next_update_) return;
  // Catch up without bursting after a pause or a reset.
  next_update_ = (next_update_.isZero() || now - next_update_ > sensor_period_) ? now + sensor_period_
                                                                                 : next_update_ + sensor_period_;
  const bool want_image = image_publisher_.getNumSubscribers() > 0;
  const bool want_info = info_publisher_.getNumSubscribers() > 0;
  if (!want_image && !want_info) return;  // like Gazebo: no readers, no rendering
  // The plugin's <updateRate> throttles the sensor's ticks, as in gazebo_ros_camera. Ticks fall on
  // physics steps, so allow half a tick of slack: equal rates must not drop every other frame.
  const double tick = sensor_period_.isZero() ? world_.settings().max_step_size : sensor_period_.toSec();
  if (published_ && (now - last_publish_).toSec() + 0.5 * tick < publish_period_.toSec()) return;
  published_ = true;
  last_publish_ = now;

  if (want_image) {
    renderer_.render(world_, model_.linkPose(config_.link) * config_.pose, config_, frame_);
    for (const std::string& warning : renderer_.takeWarnings())
      ROS_WARN_STREAM("model '" << model_.name() << "', camera '" << config_.name << "': " << warning);
    encodeImage(frame_, config_.encoding, image_.data);  // a copy, or mono8's conversion
    if (noise_) noise_->apply(image_.data);
    image_.header.stamp = now;
    publish_thread::publish(image_publisher_, image_);
  }
  if (want_info) {
    info_.header.stamp = now;
    publish_thread::publish(info_publisher_, info_);
  }
}

}  // namespace
}  // namespace bullet_sim

BULLET_SIM_REGISTER_PLUGIN("libgazebo_ros_camera.so", bullet_sim::CameraPlugin)
