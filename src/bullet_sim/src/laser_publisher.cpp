#include "bullet_sim/laser_publisher.h"

#include <functional>

namespace bullet_sim {
namespace {
std::string stripLeadingSlash(const std::string& s) { return !s.empty() && s[0] == '/' ? s.substr(1) : s; }
}  // namespace

LaserPublisher::LaserPublisher(const LaserConfig& config, PhysicsWorld& world, const PhysicsModel& model,
                               const std::string& robot_namespace)
    : scanner_(config),
      world_(world),
      model_(model),
      node_(config.robot_namespace_given ? (config.robot_namespace.empty() ? model.name() : config.robot_namespace)
                                         : robot_namespace),
      // Seeded from the sensor's name so that runs are repeatable.
      rng_(static_cast<std::mt19937::result_type>(std::hash<std::string>()(model.name() + "/" + config.name))),
      period_(config.update_rate > 0 ? 1.0 / config.update_rate : 0.0) {
  publisher_ = node_.advertise<sensor_msgs::LaserScan>(config.topic_name, 1);
  message_.header.frame_id = stripLeadingSlash(config.frame_name);
  message_.angle_min = scanner_.angle_min();
  message_.angle_max = scanner_.angle_max();
  message_.angle_increment = scanner_.angle_increment();
  message_.time_increment = 0.0;  // every beam is cast at the same instant
  message_.scan_time = period_.toSec();
  message_.range_min = config.range_min;
  message_.range_max = config.range_max;
}

void LaserPublisher::afterStep(const ros::Time& now) {
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
  publisher_.publish(message_);
}

}  // namespace bullet_sim
