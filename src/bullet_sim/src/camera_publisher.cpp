#include "bullet_sim/camera_publisher.h"

#include <functional>

#include "bullet_sim/description_error.h"

namespace bullet_sim {
namespace {

std::string stripLeadingSlash(const std::string& s) { return !s.empty() && s[0] == '/' ? s.substr(1) : s; }

std::uint64_t seedOf(const std::string& text) { return static_cast<std::uint64_t>(std::hash<std::string>()(text)); }

}  // namespace

CameraPublisher::CameraPublisher(const CameraConfig& config, PhysicsWorld& world, const PhysicsModel& model,
                                 const std::string& robot_namespace, const RenderSettings& settings)
    : config_(config),
      world_(world),
      model_(model),
      renderer_(settings),
      sensor_period_(config.update_rate > 0 ? 1.0 / config.update_rate : 0.0),
      publish_period_(config.plugin_update_rate > 0 ? 1.0 / config.plugin_update_rate : 0.0) {
  // Like gazebo_ros: a given but empty <robotNamespace> means the model's name.
  const std::string ns = config.robot_namespace_given
                             ? (config.robot_namespace.empty() ? model.name() : config.robot_namespace)
                             : robot_namespace;
  try {
    // gazebo_ros_camera_utils: NodeHandle(robotNamespace + "/" + cameraName), topics relative to it.
    node_ = ros::NodeHandle(ros::NodeHandle(ns), config.camera_name);
    image_publisher_ = node_.advertise<sensor_msgs::Image>(config.image_topic_name, 2);
    info_publisher_ = node_.advertise<sensor_msgs::CameraInfo>(config.camera_info_topic_name, 2);
  } catch (const ros::InvalidNameException& e) {
    throw DescriptionError("model '" + model.name() + "': camera sensor '" + config.name +
                           "': expected valid ROS names for robotNamespace, cameraName and the topics: " + e.what());
  }
  // Seeded from the sensor's name so that runs are repeatable.
  if (config.noise_type != "none" && (config.noise_stddev > 0 || config.noise_mean != 0))
    noise_ = std::make_unique<ImageNoise>(config.noise_mean, config.noise_stddev,
                                          seedOf(model.name() + "/" + config.name));

  const std::string frame = stripLeadingSlash(config.frame_name);
  image_.header.frame_id = frame;
  image_.height = config.height;
  image_.width = config.width;
  image_.encoding = config.encoding;
  image_.is_bigendian = 0;
  image_.step = config.width * (config.encoding == "mono8" ? 1 : 3);

  const CameraIntrinsics k = cameraIntrinsics(config);
  info_.header.frame_id = frame;
  info_.height = config.height;
  info_.width = config.width;
  info_.distortion_model = "plumb_bob";
  info_.D.assign(k.D.begin(), k.D.end());
  std::copy(k.K.begin(), k.K.end(), info_.K.begin());
  std::copy(k.R.begin(), k.R.end(), info_.R.begin());
  std::copy(k.P.begin(), k.P.end(), info_.P.begin());
}

void CameraPublisher::reset() {
  next_update_ = ros::Time(0);
  published_ = false;
}

void CameraPublisher::afterStep(const ros::Time& now) {
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
    image_publisher_.publish(image_);
  }
  if (want_info) {
    info_.header.stamp = now;
    info_publisher_.publish(info_);
  }
}

}  // namespace bullet_sim
