// joint_state_publisher, as ROS 1 Noetic's (1.15): sensor_msgs/JointState on joint_states for every
// moving joint of robot_description, `rate` times a second of ROS time, at default positions or as
// the topics of `source_list` last gave them. Parameters are looked up privately first, then in
// the node's namespace, as upstream's get_param does.
#include <ros/ros.h>
#include <sensor_msgs/JointState.h>

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "joint_state_publisher/joint_list.h"
#include "publish_thread/no_delay.h"
#include "ros_params/reader.h"

namespace joint_state_publisher {
namespace {

// Upstream's get_param: the private name, else the one in the node's namespace. A value of the
// wrong type is a problem of the reader it came from (the node then stops and says which).
class Params {
 public:
  Params() : private_(ros::NodeHandle("~")), public_(ros::NodeHandle()) {}

  template <typename T>
  bool read(const std::string& name, T* value, const std::string& expected) {
    return private_.has(name) ? private_.read(name, value, expected) : public_.read(name, value, expected);
  }
  bool read(const std::string& name, XmlRpc::XmlRpcValue* value) {
    return private_.read(name, value) || public_.read(name, value);
  }
  template <typename T>
  T get(const std::string& name, T fallback, const std::string& expected) {
    read(name, &fallback, expected);
    return fallback;
  }
  // The problems of both, one a line; "" when there are none.
  std::string problems() const {
    const std::string mine = private_.problems(), theirs = public_.problems();
    return mine + (mine.empty() || theirs.empty() ? "" : "\n") + theirs;
  }

 private:
  ros_params::Reader private_, public_;
};

double number(const XmlRpc::XmlRpcValue& v, const std::string& what) {
  if (v.getType() == XmlRpc::XmlRpcValue::TypeDouble) return static_cast<double>(v);
  if (v.getType() == XmlRpc::XmlRpcValue::TypeInt) return static_cast<int>(v);
  throw JointListError(what + ": expected a number, got " + ros_params::describe(v));
}

// zeros: {joint: position}; dependent_joints: {joint: {parent: joint, factor: f, offset: o}}.
Options readOptions(Params& params) {
  Options o;
  const std::string flag = "true or false";
  o.use_mimic_tags = params.get("use_mimic_tags", true, flag);
  o.use_smallest_joint_limits = params.get("use_smallest_joint_limits", true, flag);
  o.publish_default_positions = params.get("publish_default_positions", true, flag);
  o.publish_default_velocities = params.get("publish_default_velocities", false, flag);
  o.publish_default_efforts = params.get("publish_default_efforts", false, flag);
  XmlRpc::XmlRpcValue zeros;
  if (params.read("zeros", &zeros)) {
    if (zeros.getType() != XmlRpc::XmlRpcValue::TypeStruct)
      throw JointListError("parameter zeros: expected a dictionary {joint: position}, got " + ros_params::describe(zeros));
    for (auto& [joint, value] : zeros) o.zeros[joint] = number(value, "parameter zeros/" + joint);
  }
  XmlRpc::XmlRpcValue dependents;
  if (params.read("dependent_joints", &dependents)) {
    if (dependents.getType() != XmlRpc::XmlRpcValue::TypeStruct)
      throw JointListError("parameter dependent_joints: expected a dictionary {joint: {parent: ..., factor: ..., offset: ...}}");
    for (auto& [joint, entry] : dependents) {
      const std::string where = "parameter dependent_joints/" + joint;
      if (entry.getType() != XmlRpc::XmlRpcValue::TypeStruct || !entry.hasMember("parent") ||
          entry["parent"].getType() != XmlRpc::XmlRpcValue::TypeString)
        throw JointListError(where + ": expected {parent: joint name, factor: f, offset: o}");
      Options::Dependent d;
      d.parent = static_cast<std::string>(entry["parent"]);
      if (entry.hasMember("factor")) d.factor = number(entry["factor"], where + "/factor");
      if (entry.hasMember("offset")) d.offset = number(entry["offset"], where + "/offset");
      o.dependent_joints[joint] = d;
    }
  }
  return o;
}

class Publisher {
 public:
  Publisher(std::unique_ptr<JointList> joints, double rate, double delta, const std::vector<std::string>& source_list)
      : joints_(std::move(joints)), delta_(delta) {
    ros::NodeHandle nh;
    publisher_ = nh.advertise<sensor_msgs::JointState>("joint_states", 5);
    for (const std::string& source : source_list)
      sources_.push_back(nh.subscribe(source, 10, &Publisher::onSource, this));
    timer_ = nh.createTimer(ros::Duration(1.0 / rate), &Publisher::publish, this);
  }

 private:
  void onSource(const sensor_msgs::JointStateConstPtr& msg) {
    for (size_t i = 0; i < msg->name.size(); ++i) {
      // As upstream: an array that is present gives every name's value.
      const auto at = [&](const std::vector<double>& v) {
        return i < v.size() ? std::optional<double>(v[i]) : std::nullopt;
      };
      joints_->set(msg->name[i], at(msg->position), at(msg->velocity), at(msg->effort));
    }
  }

  void publish(const ros::TimerEvent&) {
    if (delta_ > 0) joints_->sweep(delta_);
    JointStateArrays a = joints_->arrays();
    if (a.name.empty()) return;  // only non-empty messages, as upstream
    sensor_msgs::JointState msg;
    msg.header.stamp = ros::Time::now();
    msg.name = std::move(a.name);
    msg.position = std::move(a.position);
    msg.velocity = std::move(a.velocity);
    msg.effort = std::move(a.effort);
    publisher_.publish(msg);
  }

  std::unique_ptr<JointList> joints_;
  double delta_;
  ros::Publisher publisher_;
  std::vector<ros::Subscriber> sources_;
  ros::Timer timer_;
};

}  // namespace
}  // namespace joint_state_publisher

int main(int argc, char** argv) {
  using namespace joint_state_publisher;
  ros::init(argc, argv, "joint_state_publisher");
  ros::NodeHandle nh;
  publish_thread::sendWithoutDelay();  // subscribers get each message at once, even faster than real time
  Params params;
  std::string description;
  if (!params.read("robot_description", &description, "the robot's URDF")) {
    const std::string problems = params.problems();
    ROS_FATAL("%s", problems.empty() ? "The robot_description parameter is required and not set." : problems.c_str());
    return 1;
  }
  std::unique_ptr<Publisher> publisher;
  try {
    Options options = readOptions(params);
    const double rate = params.get("rate", 10.0, "a rate > 0 Hz");
    const double delta = params.get("delta", 0.0, "a number (radians a joint moves per update)");
    const auto source_list = params.get("source_list", std::vector<std::string>(), "a list of JointState topics");
    if (!params.problems().empty()) throw JointListError(params.problems());
    if (!(rate > 0)) throw JointListError("parameter rate: expected a rate > 0 Hz, got " + std::to_string(rate));
    auto joints = std::make_unique<JointList>(description, options);
    for (const std::string& w : joints->warnings()) ROS_WARN("%s", w.c_str());
    publisher = std::make_unique<Publisher>(std::move(joints), rate, delta, source_list);
  } catch (const JointListError& e) {
    ROS_FATAL("joint_state_publisher: %s", e.what());
    return 1;
  }
  ros::spin();
  return 0;
}
