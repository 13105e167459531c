// libgazebo_grasp_fix.so (gazebo-pkgs' grasp fix, our own implementation): an object that two
// gripper links squeeze from roughly opposite sides for long enough is fixed to the palm, and let
// go when the gripper opens, so that a simulated gripper can carry what friction alone would drop.
// The decisions are grasp_detector.h's; this file feeds it contacts and applies what it decides.
//
//   <plugin name="gazebo_grasp_fix" filename="libgazebo_grasp_fix.so">
//     <arm> <arm_name>katana</arm_name> <palm_link>...</palm_link>
//           <gripper_link>...</gripper_link> <gripper_link>...</gripper_link> </arm>   (one or more)
//     <forces_angle_tolerance>100</forces_angle_tolerance> <update_rate>5</update_rate>
//     <grip_count_threshold>5</grip_count_threshold> <max_grip_count>10</max_grip_count>
//     <release_tolerance>0.005</release_tolerance> <disable_collisions_on_attach>false</disable_collisions_on_attach>
//   </plugin>
//
// Events (gazebo_grasp_plugin_ros/GazeboGraspEvent: arm, object = the model, attached) go to
// /gazebo/grasp_events; grasp_event_republisher relays them where upstream's clients listen.
// <contact_topic> is Gazebo's internal contact topic: accepted and not needed here.
#include <gazebo_grasp_plugin_ros/GazeboGraspEvent.h>
#include <publish_thread/publish_thread.h>
#include <ros/ros.h>

#include <cmath>
#include <map>
#include <string>
#include <vector>

#include "bullet_sim_core/contacts.h"
#include "bullet_sim_core/description_error.h"
#include "bullet_sim_plugins/grasp_detector.h"
#include "bullet_sim_plugins/plugin_registry.h"
#include "bullet_sim_plugins/ros_names.h"

namespace bullet_sim {
namespace {

GraspFixOptions parseOptions(const SdfElement& p) {
  GraspFixOptions o;
  o.forces_angle_tolerance = p.number("forces_angle_tolerance", o.forces_angle_tolerance);
  o.update_rate = p.number("update_rate", o.update_rate);
  o.max_grip_count = static_cast<int>(std::lround(p.number("max_grip_count", o.max_grip_count)));
  // Upstream's default threshold is half the maximum count.
  o.grip_count_threshold = static_cast<int>(std::lround(p.number("grip_count_threshold", o.max_grip_count / 2)));
  o.release_tolerance = p.number("release_tolerance", o.release_tolerance);
  o.disable_collisions_on_attach = p.boolean("disable_collisions_on_attach", o.disable_collisions_on_attach);
  const std::string problems = validate(o);
  if (!problems.empty()) p.fail(problems);
  return o;
}

class GraspFixPlugin : public ModelPlugin {
 public:
  explicit GraspFixPlugin(const PluginContext& context)
      : world_(context.world), model_(context.model), label_(context.label()),
        options_(parseOptions(context.plugin.element)) {
    for (const SdfElement& a : context.plugin.element.children("arm")) arms_.push_back(parseArm(a));
    if (arms_.empty())
      context.plugin.element.fail("expected an <arm> with <arm_name>, <palm_link> and at least two <gripper_link>");
    node_ = nodeHandleOrFail(context, "/gazebo");
    events_ = advertiseOrFail<gazebo_grasp_plugin_ros::GazeboGraspEvent>(context, node_, "grasp_events", 10);
    for (const Arm& arm : arms_)
      ROS_INFO_STREAM(label_ << ": arm '" << arm.name << "', " << arm.gripper_links.size() << " gripper links, palm '"
                             << arm.palm_link << "'; events on /gazebo/grasp_events");
  }

  void afterStep(const ros::Time& now) override {
    if (now.toSec() + 1e-9 < next_check_) return;
    next_check_ = now.toSec() + 1.0 / options_.update_rate;
    const std::vector<Contact> contacts = currentContacts(world_);
    for (Arm& arm : arms_) check(arm, contacts);
  }

  void reset() override {
    for (Arm& arm : arms_) {
      while (!arm.held.empty()) release(arm, arm.held.begin()->first);
      arm.detector = GraspDetector(options_);  // the world starts again: nothing counted
    }
    next_check_ = 0.0;
  }

 private:
  struct Held {
    int attachment = 0;
    std::string model, link;
  };
  struct Arm {
    std::string name, palm_link;
    std::vector<std::string> gripper_links;
    GraspDetector detector;
    std::map<std::string, Held> held;  // by the detector's key, model::link
  };

  Arm parseArm(const SdfElement& a) const {
    Arm arm{a.requiredChild("arm_name").text(), a.requiredChild("palm_link").text(), {}, GraspDetector(options_), {}};
    for (const SdfElement& g : a.children("gripper_link")) arm.gripper_links.push_back(g.text());
    if (arm.gripper_links.size() < 2) a.fail("expected at least two <gripper_link>s (the links that squeeze)");
    std::vector<std::string> links = arm.gripper_links;
    links.push_back(arm.palm_link);
    for (const std::string& link : links)
      if (!model_.hasLink(link)) a.fail("model '" + model_.name() + "' has no link '" + link + "'");
    return arm;
  }

  // The gripper's spread: its links' mean distance from their centroid (grows as it opens).
  double spread(const Arm& arm) const {
    std::vector<Eigen::Vector3d> centres;
    Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
    for (const std::string& link : arm.gripper_links) {
      centres.push_back(model_.bodyOfLink(link).com.translation());
      centroid += centres.back() / static_cast<double>(arm.gripper_links.size());
    }
    double sum = 0.0;
    for (const Eigen::Vector3d& c : centres) sum += (c - centroid).norm();
    return sum / static_cast<double>(centres.size());
  }

  void check(Arm& arm, const std::vector<Contact>& contacts) {
    std::vector<GraspDetector::Touch> touches;
    for (const Contact& c : contacts) {
      for (int g = 0; g < static_cast<int>(arm.gripper_links.size()); ++g) {
        const btCollisionObject* finger = model_.linkCollider(arm.gripper_links[g]);
        const bool finger_is_a = c.collider_a == finger, finger_is_b = c.collider_b == finger;
        if (!finger_is_a && !finger_is_b) continue;
        const std::string& other = finger_is_a ? c.model_b : c.model_a;
        const PhysicsModel* object = world_.findModel(other);
        if (other == model_.name() || !object || object->isStatic()) continue;  // only loose objects are held
        // The normal points from b to a; the finger pushes the object away from itself.
        const Eigen::Vector3d push = finger_is_a ? Eigen::Vector3d(-c.normal) : c.normal;
        touches.push_back({other + "::" + (finger_is_a ? c.link_b : c.link_a), g, push});
      }
    }
    // Objects deleted while held: the world dropped their constraint with them.
    for (auto it = arm.held.begin(); it != arm.held.end();) {
      if (world_.findModel(it->second.model)) {
        ++it;
        continue;
      }
      arm.detector.forget(it->first);
      publishEvent(arm, it->second.model, false);
      it = arm.held.erase(it);
    }
    for (const GraspDetector::Event& e : arm.detector.update(touches, spread(arm))) {
      if (e.attached)
        attach(arm, e.object);
      else
        release(arm, e.object);
    }
  }

  void attach(Arm& arm, const std::string& key) {
    const std::string model = key.substr(0, key.find("::")), link = key.substr(key.find("::") + 2);
    Held held{0, model, link};
    try {
      held.attachment = world_.attach(model_.name(), arm.palm_link, model, link);
    } catch (const DescriptionError& e) {
      ROS_WARN_STREAM(label_ << ": cannot hold '" << model << "': " << e.what());
      arm.detector.forget(key);
      return;
    }
    if (options_.disable_collisions_on_attach) setCollisions(arm, held, false);
    arm.held[key] = held;
    ROS_INFO_STREAM(label_ << ": arm '" << arm.name << "' holds '" << model << "'");
    publishEvent(arm, model, true);
  }

  void release(Arm& arm, const std::string& key) {
    const auto it = arm.held.find(key);
    if (it == arm.held.end()) return;
    world_.detach(it->second.attachment);
    if (options_.disable_collisions_on_attach) setCollisions(arm, it->second, true);
    ROS_INFO_STREAM(label_ << ": arm '" << arm.name << "' lets go of '" << it->second.model << "'");
    publishEvent(arm, it->second.model, false);
    arm.held.erase(it);
  }

  void setCollisions(const Arm& arm, const Held& held, bool collide) {
    PhysicsModel* object = world_.findModel(held.model);
    if (!object) return;
    btCollisionObject* body = object->linkCollider(held.link);
    for (const std::string& link : arm.gripper_links) {
      btCollisionObject* finger = model_.linkCollider(link);
      if (!finger || !body) continue;
      finger->setIgnoreCollisionCheck(body, !collide);
      body->setIgnoreCollisionCheck(finger, !collide);
    }
  }

  void publishEvent(const Arm& arm, const std::string& object, bool attached) {
    gazebo_grasp_plugin_ros::GazeboGraspEvent event;
    event.arm = arm.name;
    event.object = object;
    event.attached = attached;
    publish_thread::publish(events_, event);
  }

  PhysicsWorld& world_;
  PhysicsModel& model_;
  const std::string label_;
  const GraspFixOptions options_;
  std::vector<Arm> arms_;
  ros::NodeHandle node_;
  ros::Publisher events_;
  double next_check_ = 0.0;
};

}  // namespace
}  // namespace bullet_sim

BULLET_SIM_REGISTER_PLUGIN("libgazebo_grasp_fix.so", bullet_sim::GraspFixPlugin)
