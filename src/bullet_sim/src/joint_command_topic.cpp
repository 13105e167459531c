#include "bullet_sim/joint_command_topic.h"

namespace bullet_sim {
namespace {

const ros::WallDuration kWarningPeriod(1.0);

PidTarget pidTarget(const bullet_sim_msgs::Pid& msg) {
  PidTarget t;
  t.target = msg.target;
  t.gains.p = msg.p;
  t.gains.i = msg.i;
  t.gains.d = msg.d;
  t.gains.i_max = msg.i_max;
  t.gains.i_min = msg.i_min;
  t.gains.cmd_max = msg.cmd_max;
  t.gains.cmd_min = msg.cmd_min;
  return t;
}

}  // namespace

JointCommand jointCommand(const bullet_sim_msgs::JointCmd& msg) {
  JointCommand c;
  c.reset = msg.reset;
  if (msg.set_force) c.force = msg.force;
  if (msg.set_position) c.position = pidTarget(msg.position);
  if (msg.set_velocity) c.velocity = pidTarget(msg.velocity);
  return c;
}

JointCommandTopic::JointCommandTopic(PhysicsWorld& world) : world_(world) {
  ros::NodeHandle gazebo("/gazebo");
  // A panel sends a handful of commands a second; a queue of 100 loses none of a burst.
  subscriber_ = gazebo.subscribe("joint_cmd", 100, &JointCommandTopic::onCommand, this);
}

void JointCommandTopic::warn(const std::string& name, const std::string& problem) {
  const ros::WallTime now = ros::WallTime::now();
  if (warned_.size() > 1000) warned_.clear();  // a client sending ever new names does not grow this
  ros::WallTime& last = warned_[name];
  if (!last.isZero() && now - last < kWarningPeriod) return;
  last = now;
  ROS_WARN_STREAM("/gazebo/joint_cmd: '" << name << "': " << problem << "; nothing applied");
}

void JointCommandTopic::onCommand(const bullet_sim_msgs::JointCmd& msg) {
  const auto scope = msg.name.find("::");
  if (scope == std::string::npos) return warn(msg.name, "expected 'model::joint'");
  const std::string model_name = msg.name.substr(0, scope), joint_name = msg.name.substr(scope + 2);
  const PhysicsModel* model = world_.findModel(model_name);
  if (!model) return warn(msg.name, "model [" + model_name + "] does not exist");
  const int joint = model->jointIndex(joint_name);
  if (joint < 0) return warn(msg.name, "model [" + model_name + "] has no moving joint [" + joint_name + "]");
  const JointCommand command = jointCommand(msg);
  if (const std::string error = validate(command); !error.empty()) return warn(msg.name, error);
  auto found = held_.find(msg.name);
  if (found == held_.end()) {
    if (!command.force && !command.position && !command.velocity) return;  // a reset of nothing
    found = held_.emplace(msg.name, Held{model_name, joint, JointCommandController(model->joints()[joint].effort_limit)})
                .first;
  }
  found->second.controller.command(command);
  if (!found->second.controller.active()) held_.erase(found);
}

void JointCommandTopic::beforeStep(double dt) {
  for (auto& [name, held] : held_) {
    PhysicsModel* model = world_.findModel(held.model);  // held only while the model exists
    const double effort =
        held.controller.effort(model->jointPosition(held.joint), model->jointVelocity(held.joint), dt);
    model->addJointEffort(held.joint, effort);
  }
}

void JointCommandTopic::forgetModel(const std::string& model) {
  for (auto it = held_.begin(); it != held_.end();) it = it->second.model == model ? held_.erase(it) : std::next(it);
}

void JointCommandTopic::clear() { held_.clear(); }

}  // namespace bullet_sim
