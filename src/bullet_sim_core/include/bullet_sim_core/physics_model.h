#pragma once
// One model in the physics world: a btMultiBody built from a ModelDescription (links joined
// by fixed joints are merged into one body), or static collision objects for a static model.
// The model frame is where the description puts it: the root link sits at root_pose in it.
#include "bullet_sim_core/bullet_precision.h"
#include <BulletDynamics/Featherstone/btMultiBody.h>
#include <BulletDynamics/Featherstone/btMultiBodyConstraint.h>
#include <BulletDynamics/Featherstone/btMultiBodyJointMotor.h>
#include <BulletDynamics/Featherstone/btMultiBodyLinkCollider.h>

#include <map>
#include <memory>
#include <string>
#include <vector>

#include "bullet_sim_core/collision_shapes.h"
#include "bullet_sim_core/contact_solver.h"
#include "bullet_sim_core/model_description.h"

class btMultiBodyDynamicsWorld;

namespace bullet_sim {

struct Twist {
  Eigen::Vector3d linear = Eigen::Vector3d::Zero();   // world axes
  Eigen::Vector3d angular = Eigen::Vector3d::Zero();  // world axes
};

class PhysicsModel {
 public:
  // Builds and adds the model to `world` at `pose`. Throws DescriptionError for what cannot
  // be built (e.g. a plane on a moving link). `warnings` receives what was substituted.
  PhysicsModel(const ModelDescription& description, const Eigen::Isometry3d& pose, btMultiBodyDynamicsWorld& world,
               double step_size, std::vector<std::string>& warnings);
  ~PhysicsModel();  // removes everything it added from the world
  PhysicsModel(const PhysicsModel&) = delete;
  PhysicsModel& operator=(const PhysicsModel&) = delete;

  const std::string& name() const { return description_.name; }
  const ModelDescription& description() const { return description_; }
  bool isStatic() const { return description_.is_static; }
  const Eigen::Isometry3d& initialPose() const { return initial_pose_; }

  Eigen::Isometry3d pose() const;  // model frame in the world
  Twist twist() const;             // of the model frame's origin
  void setPose(const Eigen::Isometry3d& pose);
  void setTwist(const Twist& twist);

  std::vector<std::string> linkNames() const;
  bool hasLink(const std::string& link) const { return links_.count(link) > 0; }
  Eigen::Isometry3d linkPose(const std::string& link) const;
  Twist linkTwist(const std::string& link) const;  // of the link frame's origin
  // Collision object that carries this link (after merging; a static model's link: its first
  // shape's), or nullptr; sensors ignore it.
  const btCollisionObject* linkCollider(const std::string& link) const;
  btCollisionObject* linkCollider(const std::string& link);  // e.g. to stop it colliding with another
  // The multibody link a link moves with (body -1: the base) and that body's COM frame in the
  // world, for constraints between models (PhysicsWorld::attach); multibody is nullptr for a
  // static model. Throws std::out_of_range for an unknown link.
  struct BodyOfLink {
    btMultiBody* multibody = nullptr;
    int body = -1;
    Eigen::Isometry3d com = Eigen::Isometry3d::Identity();
  };
  BodyOfLink bodyOfLink(const std::string& link) const;
  // Adds a world-frame force/torque at `point` (world) to the link for the next step only.
  void addLinkWrench(const std::string& link, const Eigen::Vector3d& force, const Eigen::Vector3d& torque,
                     const Eigen::Vector3d& point);

  // Moving joints (revolute, continuous, prismatic), in description order.
  const std::vector<JointDescription>& joints() const { return joints_; }
  int jointIndex(const std::string& joint) const;  // -1 if there is none
  double jointPosition(int j) const;
  double jointVelocity(int j) const;
  double jointEffort(int j) const { return applied_effort_[j]; }  // applied in the last step
  void setJointState(int j, double position, double velocity);
  void addJointEffort(int j, double effort);  // for the next step only
  // A motor the solver drives (the joint follows through the physics, nothing teleports):
  // position_gain > 0 aims at `position`, and the velocity error is always corrected toward
  // `velocity`, with at most max_force. Stays on until clearJointMotor.
  void setJointMotor(int j, double position, double velocity, double position_gain, double max_force);
  void clearJointMotor(int j);
  double jointMotorForce(int j) const;  // applied by the motor in the last step

  // Called by PhysicsWorld around each step.
  void beforeStep();
  void afterStep();
  void resetToInitial();
  void updateKinematics();  // after poses or joint positions were set directly

 private:
  struct LinkRef {
    int body = -1;                                                  // -1: base
    Eigen::Isometry3d link_in_com = Eigen::Isometry3d::Identity();  // link frame in the body's COM frame
  };
  Eigen::Isometry3d bodyComPose(int body) const;
  Twist bodyComTwist(int body) const;
  void buildStatic(const Eigen::Isometry3d& pose);
  void buildMultiBody(const Eigen::Isometry3d& pose, double step_size, std::vector<std::string>& warnings);

  ModelDescription description_;
  Eigen::Isometry3d initial_pose_;
  btMultiBodyDynamicsWorld& world_;
  ShapeStore shapes_;
  std::map<std::string, LinkRef> links_;
  std::vector<JointDescription> joints_;
  std::vector<int> joint_body_;  // multibody link index moved by each joint
  std::vector<double> pending_effort_, applied_effort_;
  std::unique_ptr<btMultiBody> multibody_;
  std::vector<std::unique_ptr<btMultiBodyLinkCollider>> colliders_;
  std::vector<std::unique_ptr<ColliderSurfaces>> collider_surfaces_;  // each collider's user pointer
  struct StaticPart {  // one collision shape of a static model
    std::unique_ptr<btCollisionObject> object;
    Eigen::Isometry3d in_model = Eigen::Isometry3d::Identity();
    std::string link;
  };
  std::vector<StaticPart> static_parts_;
  Eigen::Isometry3d static_pose_ = Eigen::Isometry3d::Identity();  // a static model's frame
  std::vector<std::unique_ptr<btMultiBodyConstraint>> constraints_;  // always in the world
  // A joint limit is in the solver only while its joint is near it (updateLimits()).
  struct Limit {
    std::unique_ptr<btMultiBodyConstraint> constraint;
    int joint = -1;  // index into joints_
    bool in_world = false;
  };
  std::vector<Limit> limits_;
  void updateLimits();
  std::vector<std::unique_ptr<btMultiBodyJointMotor>> motors_;  // per joint, created on first use
  // The mass of a body's links with gravity off, held up by an equal and opposite force at
  // their centre of mass every step (Bullet applies gravity per multibody, not per link).
  struct Weightless {
    int body = -1;
    double mass = 0.0;
    Eigen::Vector3d com_in_body = Eigen::Vector3d::Zero();  // in the body's COM frame
  };
  std::vector<Weightless> weightless_;
  double step_size_ = 0.001;
};

}  // namespace bullet_sim
