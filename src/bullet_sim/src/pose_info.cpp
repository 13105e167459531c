#include "bullet_sim/pose_info.h"

#include "bullet_sim_plugins/ros_conversions.h"

namespace bullet_sim {
namespace {
// A browser redraws at 60 Hz; more would only cost the loop and the connection.
const ros::WallDuration kPoseInfoPeriod(1.0 / 60.0);
}  // namespace

PoseInfo::PoseInfo(const PhysicsWorld& world) : world_(world) {
  ros::NodeHandle gazebo("/gazebo");
  publisher_.advertise<gazebo_msgs::LinkStates>(gazebo, "pose_info", 1);
}

void PoseInfo::publish() {
  if (!publisher_.hasSubscribers()) return;  // the common case costs one comparison per step
  const ros::WallTime now = ros::WallTime::now();
  if (now - last_ < kPoseInfoPeriod) return;
  last_ = now;
  publisher_.publish(linkStates(world_));
}

gazebo_msgs::LinkStates linkStates(const PhysicsWorld& world) {
  gazebo_msgs::LinkStates states;
  for (const std::string& name : world.modelNames()) {
    const PhysicsModel* model = world.findModel(name);
    for (const std::string& link : model->linkNames()) {
      states.name.push_back(name + "::" + link);
      states.pose.push_back(toPoseMsg(model->linkPose(link)));
      states.twist.push_back(toTwistMsg(model->linkTwist(link)));
    }
  }
  return states;
}

}  // namespace bullet_sim
