#include "bullet_sim_core/physics_model.h"

#include <BulletDynamics/Featherstone/btMultiBodyDynamicsWorld.h>
#include <BulletDynamics/Featherstone/btMultiBodyJointLimitConstraint.h>
#include <BulletDynamics/Featherstone/btMultiBodyJointMotor.h>
#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>

#include "bullet_sim_core/description_error.h"

namespace bullet_sim {
namespace {

// Links joined by fixed joints form one rigid body; its frame is its first link's frame.
struct BodyPlan {
  const JointDescription* joint = nullptr;  // the moving joint to the parent body (none for the base)
  int parent = -1;                          // index into the plans
  std::vector<std::pair<const LinkDescription*, Eigen::Isometry3d>> members;  // link frame in the body frame
  double mass = 0.0;
  Eigen::Isometry3d com = Eigen::Isometry3d::Identity();  // principal-axes COM frame in the body frame
  Eigen::Vector3d principal = Eigen::Vector3d::Ones();
};

// Sum of the member links' inertials about the body's COM, and its principal axes.
void computeMassProperties(BodyPlan& body, const std::string& model, bool needs_mass,
                           std::vector<std::string>& warnings) {
  double mass = 0.0;
  Eigen::Vector3d weighted = Eigen::Vector3d::Zero();
  for (const auto& [link, frame] : body.members) {
    mass += link->inertial.mass;
    weighted += link->inertial.mass * (frame * link->inertial.origin).translation();
  }
  if (mass <= 0.0) {
    if (needs_mass) {
      warnings.push_back("model '" + model + "': link '" + body.members.front().first->name +
                         "' moves but has no <inertial>; using 0.01 kg");
    }
    body.mass = needs_mass ? 0.01 : 1.0;
    body.principal = Eigen::Vector3d::Constant(needs_mass ? 1e-5 : 1.0);
    body.com.setIdentity();
    return;
  }
  const Eigen::Vector3d com = weighted / mass;
  Eigen::Matrix3d inertia = Eigen::Matrix3d::Zero();
  for (const auto& [link, frame] : body.members) {
    const Eigen::Isometry3d inertial_frame = frame * link->inertial.origin;
    const Eigen::Matrix3d r = inertial_frame.linear();
    const Eigen::Vector3d d = inertial_frame.translation() - com;
    inertia += r * link->inertial.inertia * r.transpose() +
               link->inertial.mass * (d.squaredNorm() * Eigen::Matrix3d::Identity() - d * d.transpose());
  }
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(inertia);
  Eigen::Matrix3d axes = solver.eigenvectors();
  if (axes.determinant() < 0) axes.col(2) = -axes.col(2);
  body.mass = mass;
  // Featherstone needs positive moments; a point mass gets a tiny sphere's worth.
  body.principal = solver.eigenvalues().cwiseMax(1e-9);
  body.com.linear() = axes;
  body.com.translation() = com;
}

btQuaternion rotationOf(const Eigen::Isometry3d& t) { return toBullet(t).getRotation(); }

}  // namespace

PhysicsModel::PhysicsModel(const ModelDescription& description, const Eigen::Isometry3d& pose,
                           btMultiBodyDynamicsWorld& world, double step_size, std::vector<std::string>& warnings)
    : description_(description), initial_pose_(pose), world_(world) {
  if (description_.links.empty()) throw DescriptionError(description_.source + ": model '" + name() + "' has no links");
  if (description_.is_static)
    buildStatic(pose);
  else
    buildMultiBody(pose, step_size, warnings);
}

PhysicsModel::~PhysicsModel() {
  for (auto& m : motors_)
    if (m) world_.removeMultiBodyConstraint(m.get());
  for (auto& c : constraints_) world_.removeMultiBodyConstraint(c.get());
  for (auto& l : limits_)
    if (l.in_world) world_.removeMultiBodyConstraint(l.constraint.get());
  for (auto& c : colliders_) world_.removeCollisionObject(c.get());
  for (auto& part : static_parts_) world_.removeCollisionObject(part.object.get());
  if (multibody_) world_.removeMultiBody(multibody_.get());
}

void PhysicsModel::buildStatic(const Eigen::Isometry3d& pose) {
  // Every link is where the joints at zero put it; nothing moves.
  std::map<std::string, Eigen::Isometry3d> frames{{description_.links.front().name, description_.root_pose}};
  for (const auto& j : description_.joints) frames[j.child] = frames[j.parent] * j.origin;
  // One plain collision object per shape, not one compound: Bullet pairs a compound with a compound
  // through its most expensive algorithm, which re-creates contact manifolds every step for every
  // link near the ground plane; a plain shape keeps its child algorithms from step to step.
  static_pose_ = pose;
  for (const auto& link : description_.links) {
    links_[link.name] = LinkRef{-1, frames[link.name]};
    for (const auto& c : link.collisions) {
      StaticPart part;
      part.link = link.name;
      part.in_model = frames[link.name] * c.origin;
      part.object = std::make_unique<btCollisionObject>();
      part.object->setCollisionShape(
          shapes_.make(c.geometry, true, description_.source + ": <link name='" + link.name + "'>"));
      part.object->setWorldTransform(toBullet(pose * part.in_model));
      part.object->setCollisionFlags(part.object->getCollisionFlags() | btCollisionObject::CF_STATIC_OBJECT);
      part.object->setFriction(0.5 * (link.mu1 + link.mu2));
      world_.addCollisionObject(part.object.get(), btBroadphaseProxy::StaticFilter,
                                btBroadphaseProxy::AllFilter ^ btBroadphaseProxy::StaticFilter);
      static_parts_.push_back(std::move(part));
    }
  }
}

void PhysicsModel::buildMultiBody(const Eigen::Isometry3d& pose, double step_size, std::vector<std::string>& warnings) {
  // 1. Group links into bodies; links come parent-first, so parents are planned first.
  std::map<std::string, const JointDescription*> parent_joint;
  for (const auto& j : description_.joints) parent_joint[j.child] = &j;
  std::vector<BodyPlan> plans;
  std::map<std::string, std::pair<int, Eigen::Isometry3d>> where;  // link -> (plan, frame in body)
  for (const auto& link : description_.links) {
    auto it = parent_joint.find(link.name);
    if (it == parent_joint.end()) {
      if (!plans.empty())
        throw DescriptionError(description_.source + ": link '" + link.name + "' is not connected to the tree");
      plans.emplace_back();
      plans.back().members.emplace_back(&link, Eigen::Isometry3d::Identity());
      where[link.name] = {0, Eigen::Isometry3d::Identity()};
      continue;
    }
    const JointDescription& joint = *it->second;
    const auto& [parent_plan, parent_frame] = where.at(joint.parent);
    if (joint.type == JointType::Fixed) {
      const Eigen::Isometry3d frame = parent_frame * joint.origin;
      plans[parent_plan].members.emplace_back(&link, frame);
      where[link.name] = {parent_plan, frame};
    } else {
      BodyPlan plan;
      plan.joint = &joint;
      plan.parent = parent_plan;
      plan.members.emplace_back(&link, Eigen::Isometry3d::Identity());
      where[link.name] = {static_cast<int>(plans.size()), Eigen::Isometry3d::Identity()};
      plans.push_back(plan);
    }
  }
  const bool fixed_base = description_.fixed_base;
  for (size_t i = 0; i < plans.size(); ++i)
    computeMassProperties(plans[i], name(), i > 0 || !fixed_base, warnings);
  for (size_t i = 0; i < plans.size(); ++i) {
    const BodyPlan& plan = plans[i];
    Weightless w{static_cast<int>(i) - 1, 0.0, Eigen::Vector3d::Zero()};
    const bool all = std::all_of(plan.members.begin(), plan.members.end(), [](const auto& m) { return !m.first->gravity; });
    if (all) {
      w.mass = plan.mass;  // including a substituted mass
    } else {
      Eigen::Vector3d weighted = Eigen::Vector3d::Zero();
      for (const auto& [link, frame] : plan.members) {
        if (link->gravity) continue;
        w.mass += link->inertial.mass;
        weighted += link->inertial.mass * (plan.com.inverse() * frame * link->inertial.origin).translation();
      }
      if (w.mass > 0) w.com_in_body = weighted / w.mass;
    }
    if (w.mass > 0) weightless_.push_back(w);
  }

  // 2. The multibody: plan i > 0 is Bullet link i-1. Frames follow Bullet's URDF importer:
  //    every body is represented in its principal-axes COM frame.
  const int num_links = static_cast<int>(plans.size()) - 1;
  multibody_ = std::make_unique<btMultiBody>(num_links, plans[0].mass, toBullet(plans[0].principal), fixed_base,
                                             /*canSleep=*/false);
  multibody_->setBaseWorldTransform(toBullet(pose * description_.root_pose * plans[0].com));
  for (int i = 1; i <= num_links; ++i) {
    const BodyPlan& plan = plans[i];
    const BodyPlan& parent = plans[plan.parent];
    const JointDescription& joint = *plan.joint;
    const Eigen::Isometry3d parent_to_joint = where.at(joint.parent).second * joint.origin;
    const Eigen::Isometry3d offset_in_parent = parent.com.inverse() * parent_to_joint;
    const Eigen::Isometry3d offset_in_child = plan.com.inverse();
    const btQuaternion rot_parent_to_this = rotationOf(offset_in_child) * rotationOf(offset_in_parent).inverse();
    const btVector3 axis = toBullet(Eigen::Vector3d(offset_in_child.linear() * joint.axis));
    // The joint turns about its pivot (the child link's origin in URDF, the joint <pose> in SDF).
    const btVector3 parent_com_to_pivot = toBullet(Eigen::Vector3d(offset_in_parent * joint.pivot));
    const btVector3 pivot_to_com = toBullet(Eigen::Vector3d(-(offset_in_child * joint.pivot)));
    if (joint.type == JointType::Prismatic)
      multibody_->setupPrismatic(i - 1, plan.mass, toBullet(plan.principal), plan.parent - 1, rot_parent_to_this, axis,
                                 parent_com_to_pivot, pivot_to_com, true);
    else
      multibody_->setupRevolute(i - 1, plan.mass, toBullet(plan.principal), plan.parent - 1, rot_parent_to_this, axis,
                                parent_com_to_pivot, pivot_to_com, true);
    joints_.push_back(joint);
    joint_body_.push_back(i - 1);
  }
  multibody_->finalizeMultiDof();
  // Bullet's defaults damp every body a little; Gazebo's ODE does not, and our tests
  // compare against undamped analytic motion.
  multibody_->setLinearDamping(0.0);
  multibody_->setAngularDamping(0.0);
  multibody_->setUseGyroTerm(true);
  multibody_->setHasSelfCollision(false);
  world_.addMultiBody(multibody_.get());

  // 3. One compound collider per body, shapes placed in the COM frame.
  for (int i = 0; i <= num_links; ++i) {
    const BodyPlan& plan = plans[i];
    for (const auto& [link, frame] : plan.members) links_[link->name] = LinkRef{i - 1, plan.com.inverse() * frame};
    btCompoundShape* compound = shapes_.makeCompound();
    auto surfaces = std::make_unique<ColliderSurfaces>();  // the contact solver's, by child shape
    double mu = 1.0;
    for (const auto& [link, frame] : plan.members) {
      for (const auto& c : link->collisions) {
        compound->addChildShape(toBullet(plan.com.inverse() * frame * c.origin),
                                shapes_.make(c.geometry, false, description_.source + ": <link name='" + link->name + "'>"));
        surfaces->by_child.push_back(c.surface);
        mu = 0.5 * (link->mu1 + link->mu2);
      }
    }
    // Every body gets a collider, even without shapes: Bullet finds a joint limit's
    // simulation island through the link's collider and skips the limit without one.
    auto collider = std::make_unique<btMultiBodyLinkCollider>(multibody_.get(), i - 1);
    collider->setCollisionShape(compound);
    collider->setFriction(mu);
    collider->setUserPointer(surfaces.get());
    collider_surfaces_.push_back(std::move(surfaces));
    collider->setActivationState(DISABLE_DEACTIVATION);
    const bool is_fixed = (i == 0 && fixed_base);
    world_.addCollisionObject(collider.get(),
                              is_fixed ? btBroadphaseProxy::StaticFilter : btBroadphaseProxy::DefaultFilter,
                              is_fixed ? btBroadphaseProxy::AllFilter ^ btBroadphaseProxy::StaticFilter
                                       : btBroadphaseProxy::AllFilter);
    if (i == 0)
      multibody_->setBaseCollider(collider.get());
    else
      multibody_->getLink(i - 1).m_collider = collider.get();
    colliders_.push_back(std::move(collider));
  }

  // 4. Limits and Coulomb friction as constraints the solver enforces.
  for (size_t j = 0; j < joints_.size(); ++j) {
    const JointDescription& joint = joints_[j];
    if (joint.type != JointType::Continuous && std::isfinite(joint.lower) && std::isfinite(joint.upper)) {
      limits_.push_back({std::make_unique<btMultiBodyJointLimitConstraint>(multibody_.get(), joint_body_[j],
                                                                          joint.lower, joint.upper),
                         static_cast<int>(j), false});
    }
    if (joint.friction > 0) {
      // A velocity motor aiming at rest with a bounded impulse is Coulomb friction.
      constraints_.push_back(
          std::make_unique<btMultiBodyJointMotor>(multibody_.get(), joint_body_[j], 0.0, joint.friction * step_size));
      world_.addMultiBodyConstraint(constraints_.back().get());
    }
  }
  pending_effort_.assign(joints_.size(), 0.0);
  applied_effort_.assign(joints_.size(), 0.0);
  motors_.resize(joints_.size());
  step_size_ = step_size;
  updateKinematics();
  updateLimits();
}

// Bullet's limit constraint pushes only once its joint has crossed the limit, yet its rows cost
// the solver and the island builder every step (5 % of the benchmark arm's step). So a limit is in
// the world only while its joint is within reach of it: four steps at the current speed plus
// kLimitWatch (rad or m), which also covers an acceleration of 5e4 rad/s^2 within a 1 ms step. The
// joint then stops exactly as with the limit always in (AJointThrownAtItsLimitStopsThere).
void PhysicsModel::updateLimits() {
  constexpr double kLimitWatch = 0.05;
  for (Limit& l : limits_) {
    const JointDescription& joint = joints_[l.joint];
    const double q = jointPosition(l.joint);
    const double reach = 4.0 * std::abs(jointVelocity(l.joint)) * step_size_ + kLimitWatch;
    const bool near = !(q - reach > joint.lower && q + reach < joint.upper);  // NaN counts as near
    if (near && !l.in_world) world_.addMultiBodyConstraint(l.constraint.get());
    if (!near && l.in_world) world_.removeMultiBodyConstraint(l.constraint.get());
    l.in_world = near;
  }
}

void PhysicsModel::updateKinematics() {
  if (!multibody_) {
    for (auto& part : static_parts_) {
      part.object->setWorldTransform(toBullet(static_pose_ * part.in_model));
      world_.updateSingleAabb(part.object.get());
    }
    return;
  }
  btAlignedObjectArray<btQuaternion> rotations;
  btAlignedObjectArray<btVector3> origins;
  multibody_->forwardKinematics(rotations, origins);
  multibody_->updateCollisionObjectWorldTransforms(rotations, origins);
  for (auto& c : colliders_) world_.updateSingleAabb(c.get());
}

Eigen::Isometry3d PhysicsModel::bodyComPose(int body) const {
  if (!multibody_) return static_pose_;
  if (body < 0) return fromBullet(multibody_->getBaseWorldTransform());
  // The link's collider is moved with it at the end of every step (and by updateKinematics);
  // Bullet's m_cachedWorldTransform would need another forward-kinematics pass each step.
  return fromBullet(multibody_->getLink(body).m_collider->getWorldTransform());
}

Twist PhysicsModel::bodyComTwist(int body) const {
  Twist t;
  if (!multibody_) return t;
  if (body < 0) {
    t.linear = fromBullet(multibody_->getBaseVel());
    t.angular = fromBullet(multibody_->getBaseOmega());
    return t;
  }
  // Bullet gives link velocities in each link's own frame.
  std::vector<btVector3> omega(multibody_->getNumLinks() + 1), vel(multibody_->getNumLinks() + 1);
  multibody_->compTreeLinkVelocities(omega.data(), vel.data());
  const Eigen::Matrix3d r = bodyComPose(body).linear();
  t.linear = r * fromBullet(vel[body + 1]);
  t.angular = r * fromBullet(omega[body + 1]);
  return t;
}

Eigen::Isometry3d PhysicsModel::pose() const {
  return linkPose(description_.links.front().name) * description_.root_pose.inverse();
}

Twist PhysicsModel::twist() const {
  Twist t = linkTwist(description_.links.front().name);
  const Eigen::Vector3d root = linkPose(description_.links.front().name).translation();
  t.linear += t.angular.cross(pose().translation() - root);
  return t;
}

void PhysicsModel::setPose(const Eigen::Isometry3d& pose) {
  if (!multibody_) {
    static_pose_ = pose;
  } else {
    const LinkRef& root = links_.at(description_.links.front().name);
    multibody_->setBaseWorldTransform(toBullet(pose * description_.root_pose * root.link_in_com.inverse()));
  }
  updateKinematics();
}

void PhysicsModel::setTwist(const Twist& twist) {
  if (!multibody_ || description_.fixed_base) return;
  const Eigen::Vector3d origin = pose().translation();
  const Eigen::Vector3d com = bodyComPose(-1).translation();
  multibody_->setBaseVel(toBullet(Eigen::Vector3d(twist.linear + twist.angular.cross(com - origin))));
  multibody_->setBaseOmega(toBullet(twist.angular));
}

std::vector<std::string> PhysicsModel::linkNames() const {
  std::vector<std::string> names;
  for (const auto& l : description_.links) {
    // The "world" link only anchors a fixed robot; Gazebo does not list it either.
    if (description_.fixed_base && l.name == "world") continue;
    names.push_back(l.name);
  }
  return names;
}

Eigen::Isometry3d PhysicsModel::linkPose(const std::string& link) const {
  const LinkRef& ref = links_.at(link);
  return bodyComPose(ref.body) * ref.link_in_com;
}

Twist PhysicsModel::linkTwist(const std::string& link) const {
  const LinkRef& ref = links_.at(link);
  Twist t = bodyComTwist(ref.body);
  const Eigen::Isometry3d com = bodyComPose(ref.body);
  const Eigen::Vector3d origin = (com * ref.link_in_com).translation();
  t.linear += t.angular.cross(origin - com.translation());
  return t;
}

const btCollisionObject* PhysicsModel::linkCollider(const std::string& link) const {
  auto it = links_.find(link);
  if (it == links_.end()) return nullptr;
  if (!multibody_) {
    for (const auto& part : static_parts_)
      if (part.link == link) return part.object.get();  // its first shape
    return nullptr;
  }
  return it->second.body < 0 ? multibody_->getBaseCollider() : multibody_->getLink(it->second.body).m_collider;
}

PhysicsModel::BodyOfLink PhysicsModel::bodyOfLink(const std::string& link) const {
  const LinkRef& ref = links_.at(link);
  return {multibody_.get(), ref.body, bodyComPose(ref.body)};
}

btCollisionObject* PhysicsModel::linkCollider(const std::string& link) {
  return const_cast<btCollisionObject*>(static_cast<const PhysicsModel&>(*this).linkCollider(link));
}

void PhysicsModel::addLinkWrench(const std::string& link, const Eigen::Vector3d& force, const Eigen::Vector3d& torque,
                                 const Eigen::Vector3d& point) {
  if (!multibody_) return;
  const LinkRef& ref = links_.at(link);
  const Eigen::Vector3d com = bodyComPose(ref.body).translation();
  const btVector3 f = toBullet(force);
  const btVector3 tau = toBullet(Eigen::Vector3d(torque + (point - com).cross(force)));
  if (ref.body < 0) {
    multibody_->addBaseForce(f);
    multibody_->addBaseTorque(tau);
  } else {
    multibody_->addLinkForce(ref.body, f);
    multibody_->addLinkTorque(ref.body, tau);
  }
}

int PhysicsModel::jointIndex(const std::string& joint) const {
  for (size_t j = 0; j < joints_.size(); ++j)
    if (joints_[j].name == joint) return static_cast<int>(j);
  return -1;
}

double PhysicsModel::jointPosition(int j) const { return multibody_->getJointPos(joint_body_[j]); }
double PhysicsModel::jointVelocity(int j) const { return multibody_->getJointVel(joint_body_[j]); }

void PhysicsModel::setJointState(int j, double position, double velocity) {
  multibody_->setJointPos(joint_body_[j], position);
  multibody_->setJointVel(joint_body_[j], velocity);
  updateKinematics();
}

void PhysicsModel::addJointEffort(int j, double effort) { pending_effort_[j] += effort; }

void PhysicsModel::setJointMotor(int j, double position, double velocity, double position_gain, double max_force) {
  auto& motor = motors_[j];
  if (!motor) {
    motor = std::make_unique<btMultiBodyJointMotor>(multibody_.get(), joint_body_[j], 0.0, 0.0);
    world_.addMultiBodyConstraint(motor.get());
  }
  motor->setVelocityTarget(velocity, 1.0);
  motor->setPositionTarget(position, position_gain);
  motor->setMaxAppliedImpulse(max_force * step_size_);
}

void PhysicsModel::clearJointMotor(int j) {
  if (!motors_[j]) return;
  world_.removeMultiBodyConstraint(motors_[j].get());
  motors_[j].reset();
}

double PhysicsModel::jointMotorForce(int j) const {
  return motors_[j] ? motors_[j]->getAppliedImpulse(0) / step_size_ : 0.0;
}

void PhysicsModel::beforeStep() {
  if (!multibody_) return;
  updateLimits();
  const Eigen::Vector3d gravity(world_.getGravity().x(), world_.getGravity().y(), world_.getGravity().z());
  for (const Weightless& w : weightless_) {
    const Eigen::Isometry3d com = bodyComPose(w.body);
    const Eigen::Vector3d force = -w.mass * gravity;
    const btVector3 f = toBullet(force);
    const btVector3 tau = toBullet(Eigen::Vector3d((com.linear() * w.com_in_body).cross(force)));
    if (w.body < 0) {
      multibody_->addBaseForce(f);
      multibody_->addBaseTorque(tau);
    } else {
      multibody_->addLinkForce(w.body, f);
      multibody_->addLinkTorque(w.body, tau);
    }
  }
  for (size_t j = 0; j < joints_.size(); ++j) {
    // Viscous damping from <dynamics damping>, applied explicitly like Gazebo's ODE joints.
    const double damping = -joints_[j].damping * jointVelocity(static_cast<int>(j));
    multibody_->addJointTorque(joint_body_[j], pending_effort_[j] + damping);
    applied_effort_[j] = pending_effort_[j];
    pending_effort_[j] = 0.0;
  }
}

void PhysicsModel::afterStep() {
  if (multibody_) multibody_->clearForcesAndTorques();
}

void PhysicsModel::resetToInitial() {
  if (multibody_) {
    for (size_t j = 0; j < joints_.size(); ++j) {
      multibody_->setJointPos(joint_body_[j], 0.0);
      multibody_->setJointVel(joint_body_[j], 0.0);
    }
    multibody_->setBaseVel(btVector3(0, 0, 0));
    multibody_->setBaseOmega(btVector3(0, 0, 0));
    multibody_->clearForcesAndTorques();
    std::fill(pending_effort_.begin(), pending_effort_.end(), 0.0);
  }
  setPose(initial_pose_);
}

}  // namespace bullet_sim
