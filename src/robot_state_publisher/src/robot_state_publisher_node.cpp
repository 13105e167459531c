// robot_state_publisher, as ROS 1 Noetic's node: the robot's links on tf from robot_description
// and joint_states. Fixed joints once on /tf_static (or, with use_tf_static false, on /tf every
// publish period, dated half a second ahead); moving joints on /tf at each joint_states message,
// at most publish_frequency times a second per joint unless ignore_timestamp. Unlike Debian's
// 1.15 binary, tf_prefix is looked up once at start rather than with three parameter-server calls
// per message (ros/robot_state_publisher#200), which at 10x real time loaded the master by a
// fifth of a core. Run as `state_publisher`, the node's pre-Noetic name, it says so once.
#include <cstring>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include <geometry_msgs/TransformStamped.h>
#include <ros/ros.h>
#include <sensor_msgs/JointState.h>
#include <tf2_ros/static_transform_broadcaster.h>
#include <tf2_ros/transform_broadcaster.h>
#include <urdf/model.h>

#include "publish_thread/no_delay.h"
#include "ros_params/reader.h"
#include "robot_state_publisher/kinematic_tree.h"

namespace robot_state_publisher {
namespace {

geometry_msgs::TransformStamped toMessage(const KDL::Frame& f, const std::string& parent, const std::string& child,
                                          const ros::Time& stamp) {
  geometry_msgs::TransformStamped t;
  t.header.stamp = stamp;
  t.header.frame_id = parent;
  t.child_frame_id = child;
  t.transform.translation.x = f.p.x();
  t.transform.translation.y = f.p.y();
  t.transform.translation.z = f.p.z();
  f.M.GetQuaternion(t.transform.rotation.x, t.transform.rotation.y, t.transform.rotation.z, t.transform.rotation.w);
  return t;
}

class StatePublisher {
 public:
  explicit StatePublisher(const KinematicTree& tree) : tree_(tree), private_("~") {
    // A value of the wrong type is said (upstream silently takes the default) and the default used.
    ros_params::Reader params(private_);
    const double frequency = params.get("publish_frequency", 50.0);
    params.read("use_tf_static", &use_tf_static_);
    params.read("ignore_timestamp", &ignore_timestamp_);
    params.search("tf_prefix", &tf_prefix_);
    for (const std::string& problem : params.problemList()) ROS_ERROR("%s; using the default.", problem.c_str());
    publish_interval_ = ros::Duration(1.0 / std::max(frequency, 1.0));
    for (const std::string& joint : tree_.floatingJoints())
      ROS_INFO("Floating joint %s is left out: joint_states cannot say where its child link is.", joint.c_str());
    joint_states_ = ros::NodeHandle().subscribe("joint_states", 1, &StatePublisher::onJointState, this,
                                                ros::TransportHints().tcpNoDelay());
    fixed_timer_ = private_.createTimer(publish_interval_, &StatePublisher::publishFixed, this, use_tf_static_);
  }

 private:
  void publishFixed(const ros::TimerEvent&) {
    // On /tf, dated ahead so that lookups between two periods find them.
    const ros::Time stamp = use_tf_static_ ? ros::Time::now() : ros::Time::now() + ros::Duration(0.5);
    std::vector<geometry_msgs::TransformStamped> transforms;
    for (const JointFrame& j : tree_.fixedJoints())
      transforms.push_back(toMessage(j.segment.pose(0.0), prefixedFrame(tf_prefix_, j.parent),
                                     prefixedFrame(tf_prefix_, j.child), stamp));
    if (use_tf_static_)
      static_broadcaster_.sendTransform(transforms);
    else
      broadcaster_.sendTransform(transforms);
  }

  void onJointState(const sensor_msgs::JointStateConstPtr& state) {
    if (state->name.size() != state->position.size()) {
      if (state->position.empty())
        ROS_WARN_THROTTLE(10, "Robot state publisher ignored a JointState message about joint(s) \"%s\"(,...) whose "
                          "position member was empty.", state->name.empty() ? "" : state->name[0].c_str());
      else
        ROS_ERROR("Robot state publisher ignored an invalid JointState message: %zu names, %zu positions.",
                  state->name.size(), state->position.size());
      return;
    }
    const ros::Time now = ros::Time::now();
    if (now < last_callback_) {
      ROS_WARN("Moved backwards in time (probably because ROS clock was reset), re-publishing joint transforms!");
      last_published_.clear();
    }
    last_callback_ = now;
    if (state->header.stamp + ros::Duration(30.0) < now)
      ROS_WARN_THROTTLE(10, "Received JointState is %f seconds old.", (now - state->header.stamp).toSec());
    // Published when the least recently published of its joints is a period old.
    ros::Time oldest = now;
    for (const std::string& name : state->name) oldest = std::min(oldest, last_published_[name]);
    if (!ignore_timestamp_ && state->header.stamp < oldest + publish_interval_) return;

    std::map<std::string, double> positions;
    for (std::size_t i = 0; i < state->name.size(); ++i) positions.emplace(state->name[i], state->position[i]);
    for (const MimicRule& m : tree_.mimicRules()) {
      const auto source = positions.find(m.follows);
      if (source != positions.end()) positions.emplace(m.joint, source->second * m.multiplier + m.offset);
    }
    std::vector<geometry_msgs::TransformStamped> transforms;
    transforms.reserve(positions.size());
    for (const auto& [name, position] : positions) {
      const JointFrame* joint = tree_.movingJoint(name);
      if (!joint) {
        ROS_WARN_THROTTLE(10, "Joint state with name: \"%s\" was received but not found in URDF", name.c_str());
        continue;
      }
      transforms.push_back(toMessage(joint->segment.pose(position), prefixedFrame(tf_prefix_, joint->parent),
                                     prefixedFrame(tf_prefix_, joint->child), state->header.stamp));
    }
    broadcaster_.sendTransform(transforms);
    for (const std::string& name : state->name) last_published_[name] = state->header.stamp;
  }

  const KinematicTree& tree_;
  ros::NodeHandle private_;
  bool use_tf_static_ = true, ignore_timestamp_ = false;
  std::string tf_prefix_;
  ros::Duration publish_interval_;
  ros::Time last_callback_;
  std::map<std::string, ros::Time> last_published_;
  tf2_ros::TransformBroadcaster broadcaster_;
  tf2_ros::StaticTransformBroadcaster static_broadcaster_;
  ros::Subscriber joint_states_;
  ros::Timer fixed_timer_;
};

}  // namespace
}  // namespace robot_state_publisher

int main(int argc, char** argv) {
  ros::init(argc, argv, "robot_state_publisher");
  const char* slash = std::strrchr(argv[0], '/');
  if (std::strcmp(slash ? slash + 1 : argv[0], "state_publisher") == 0)
    ROS_WARN("state_publisher: deprecated name (since ROS Groovy), running robot_state_publisher");
  urdf::Model model;
  if (!model.initParam("robot_description")) return -1;  // urdf names the parameter and the error
  try {
    const robot_state_publisher::KinematicTree tree(model);
    robot_state_publisher::StatePublisher publisher(tree);
    publish_thread::sendWithoutDelay();  // subscribers get each message at once, even faster than real time
    ros::spin();
  } catch (const std::invalid_argument& e) {
    ROS_ERROR("%s", e.what());
    return -1;
  }
  return 0;
}
