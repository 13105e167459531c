// joint_state_controller/JointStateController: publishes every joint of the robot as
// sensor_msgs/JointState on <robot namespace>/joint_states at `publish_rate` Hz of sim time.
// It reads the joints only, so it claims nothing and runs alongside any other controller.
#include <ros/console.h>
#include <sensor_msgs/JointState.h>

#include <sstream>

#include "publish_thread/publish_thread.h"
#include "sim_control/controller_registry.h"
#include "sim_control/controller_params.h"

namespace sim_control {
namespace {

class JointStateController : public Controller {
 public:
  bool init(RobotHW& hw, ros::NodeHandle& root_nh, ros::NodeHandle& controller_nh, std::string& error) override {
    const std::string expected = "a rate in Hz, e.g. 50";
    ros_params::Reader params(controller_nh);
    double rate = 0.0;
    if (readFinite(params, "publish_rate", &rate, expected, true) && rate <= 0.0) {
      std::ostringstream got;
      got << rate;
      params.fail("publish_rate", "expected " + expected + " (greater than 0), got " + got.str());
    }
    if (!noProblems(params, error)) return false;
    period_ = ros::Duration(1.0 / rate);
    // ros_controllers can add joints the hardware lacks, with fixed values; nothing here needs
    // that yet, so say so rather than silently dropping them.
    if (params.has("extra_joints"))
      ROS_WARN_STREAM(params.path("extra_joints") << ": not supported by sim_control; ignored");
    for (JointData& joint : hw.joints()) {
      joints_.push_back(&joint);
      msg_.name.push_back(joint.name);
    }
    msg_.position.resize(joints_.size());
    msg_.velocity.resize(joints_.size());
    msg_.effort.resize(joints_.size());
    pub_ = root_nh.advertise<sensor_msgs::JointState>("joint_states", 4);
    return true;
  }

  void starting(const ros::Time& time) override { last_publish_ = time; }

  void update(const ros::Time& time, const ros::Duration& /*period*/) override {
    if (time < last_publish_) last_publish_ = time;  // sim time went back (world reset)
    // Like ros_controllers: first message one period after starting, and the schedule advances
    // by whole periods so the rate does not drift with the update rate. If updates are further
    // apart than a period (update rate below publish_rate), re-anchor instead of falling behind.
    if (!(last_publish_ + period_ < time)) return;
    last_publish_ += period_;
    if (last_publish_ + period_ < time) last_publish_ = time;
    msg_.header.stamp = time;
    for (std::size_t k = 0; k < joints_.size(); ++k) {
      msg_.position[k] = joints_[k]->position;
      msg_.velocity[k] = joints_[k]->velocity;
      msg_.effort[k] = joints_[k]->effort;
    }
    publish_thread::publish(pub_, msg_);
  }

 private:
  std::vector<const JointData*> joints_;  // the simulator keeps RobotHW's joints in place
  ros::Duration period_;
  ros::Time last_publish_;
  sensor_msgs::JointState msg_;
  ros::Publisher pub_;
};

}  // namespace
SIM_CONTROL_REGISTER_CONTROLLER("joint_state_controller/JointStateController", JointStateController)
}  // namespace sim_control
