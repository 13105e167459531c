#pragma once
// Laser (ray) sensor, free of ROS: what a Gazebo <sensor type="ray"> (or "gpu_ray") describes, and
// a scanner that casts its beams into a Bullet world. The gazebo_ros_laser plugin turns the
// readings into a sensor_msgs/LaserScan.
#include "bullet_sim_core/bullet_precision.h"
#include <btBulletCollisionCommon.h>

#include <Eigen/Geometry>
#include <random>
#include <string>
#include <vector>

#include "bullet_sim_core/model_description.h"

namespace bullet_sim {

// Defaults are Gazebo's (sdformat's sensor.sdf / ray.sdf, gazebo_ros_laser.cpp).
struct LaserConfig {
  std::string name;    // <sensor name>
  std::string type;    // "ray" or "gpu_ray" (both are cast with Bullet rays here)
  std::string link;    // the <gazebo reference> (URDF) or the SDF link the sensor sits on
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();  // sensor frame in the link frame
  double update_rate = 0.0;  // Hz; 0 means "every physics step", as in Gazebo
  bool always_on = false;
  bool visualize = false;    // ignored: nothing is drawn

  // <ray><scan><horizontal>: beams sweep about the sensor's z axis, angle 0 along +x (a single
  // beam always looks along +x, as in Gazebo).
  int samples = 640;
  double resolution = 1.0;   // Gazebo publishes int(samples * resolution) readings
  double min_angle = 0.0;    // rad
  double max_angle = 0.0;    // rad

  // <ray><scan><vertical>: kept for the record; only the first layer is scanned (pitch 0
  // when there is one layer, vertical_min_angle otherwise), like the LaserScan gazebo_ros_laser publishes.
  int vertical_samples = 1;
  double vertical_resolution = 1.0;
  double vertical_min_angle = 0.0;
  double vertical_max_angle = 0.0;

  // <ray><range>
  double range_min = 0.0;         // m
  double range_max = 0.0;         // m; must be > range_min (sdformat's default 0 is rejected)
  double range_resolution = 0.0;  // m; readings are rounded to multiples of it when > 0

  // <ray><noise>: "none", "gaussian" or "gaussian_quantized" (treated as gaussian)
  std::string noise_type = "none";
  double noise_mean = 0.0;    // m
  double noise_stddev = 0.0;  // m
};

// Whether the sensor is a laser: type "ray" or "gpu_ray".
bool isLaserSensor(const SensorDescription& sensor);
// The <sensor>'s <ray> and sensor-wide settings. Throws DescriptionError naming the source, the
// element path and what was expected (see sdf_element.h).
LaserConfig parseLaserSensor(const SensorDescription& sensor);

class LaserScanner {
 public:
  explicit LaserScanner(LaserConfig config);

  const LaserConfig& config() const { return config_; }
  int beam_count() const { return static_cast<int>(directions_.size()); }
  // LaserScan.angle_increment: Gazebo's RaySensor::AngleResolution, (max - min) / (count - 1);
  // 0 for a single beam (Gazebo would divide by zero).
  double angle_increment() const { return angle_increment_; }
  double angle_min() const { return config_.min_angle; }
  double angle_max() const { return config_.max_angle; }

  // One scan; ranges_out gets beam_count() readings in metres, following REP 117:
  //   nothing within range_max -> +inf; a hit closer than range_min (or starting inside a
  //   solid) -> -inf; otherwise the distance from the sensor origin, plus noise, rounded to
  //   range_resolution and clamped to [range_min, range_max].
  // Objects in `ignore` (e.g. the body of the sensor's own link) are never hit.
  // The world's broadphase must be current (stepSimulation / updateAabbs keep it so).
  void scan(const btCollisionWorld& world, const btTransform& sensor_in_world,
            const std::vector<const btCollisionObject*>& ignore, std::mt19937& rng,
            std::vector<float>& ranges_out) const;

 private:
  LaserConfig config_;
  double angle_increment_ = 0.0;
  btScalar pitch_ = 0;                 // elevation of the scanned layer
  std::vector<btVector3> directions_;  // unit beam directions in the sensor frame
};

}  // namespace bullet_sim
