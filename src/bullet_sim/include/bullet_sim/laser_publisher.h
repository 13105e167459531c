#pragma once
// gazebo_ros_laser's ROS side: publishes a LaserScanner's readings as sensor_msgs/LaserScan
// at the sensor's update_rate, stamped with sim time.
#include <ros/ros.h>
#include <sensor_msgs/LaserScan.h>

#include <random>

#include "bullet_sim/laser_sensor.h"
#include "bullet_sim/model_plugin.h"
#include "bullet_sim/physics_world.h"

namespace bullet_sim {

class LaserPublisher : public ModelPlugin {
 public:
  // `robot_namespace` is the spawn request's; the plugin's <robotNamespace> wins over it.
  LaserPublisher(const LaserConfig& config, PhysicsWorld& world, const PhysicsModel& model,
                 const std::string& robot_namespace);
  void afterStep(const ros::Time& now) override;
  void reset() override { next_update_ = ros::Time(0); }

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

}  // namespace bullet_sim
