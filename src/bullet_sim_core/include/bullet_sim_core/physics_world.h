#pragma once
// The physics: a btMultiBodyDynamicsWorld, the models in it, and a fixed-step clock.
// No ROS here; the simulator node drives it.
#include "bullet_sim_core/bullet_precision.h"
#include <btBulletDynamicsCommon.h>
#include <BulletDynamics/Featherstone/btMultiBodyConstraintSolver.h>
#include <BulletDynamics/Featherstone/btMultiBodyDynamicsWorld.h>

#include <map>
#include <memory>
#include <string>
#include <vector>

#include "bullet_sim_core/contact_solver.h"
#include "bullet_sim_core/model_description.h"
#include "bullet_sim_core/physics_model.h"

namespace bullet_sim {

class PhysicsWorld {
 public:
  explicit PhysicsWorld(const PhysicsSettings& settings = PhysicsSettings());
  ~PhysicsWorld();

  // Throws DescriptionError on a duplicate name or a model that cannot be built.
  PhysicsModel& addModel(const ModelDescription& description, const Eigen::Isometry3d& pose);
  bool removeModel(const std::string& name);
  PhysicsModel* findModel(const std::string& name);
  const PhysicsModel* findModel(const std::string& name) const;
  std::vector<std::string> modelNames() const;  // in insertion order

  void step();                // one fixed step of settings().max_step_size
  double time() const { return time_; }
  void setTime(double t) { time_ = t; }
  void resetModels();         // every model back to its initial pose, joints to zero, at rest

  const PhysicsSettings& settings() const { return settings_; }
  void setSettings(const PhysicsSettings& settings);  // throws DescriptionError on bad values

  // The solver's counts of solves and sweeps (see contact_solver.h), for benchmarks and tests.
  ContactSolver& solver() { return *solver_; }
  btMultiBodyDynamicsWorld& bulletWorld() { return *world_; }
  const btMultiBodyDynamicsWorld& bulletWorld() const { return *world_; }
  // Fixes `link_b` of `model_b` to `link_a` of `model_a` where they are now (a fixed constraint
  // holding their present relative pose, so nothing jumps), as Gazebo's grasp fix and link
  // attacher do. Returns the attachment's id. Throws DescriptionError for an unknown model or
  // link, a static model, or two links of one body. Removing either model detaches them.
  int attach(const std::string& model_a, const std::string& link_a, const std::string& model_b,
             const std::string& link_b);
  bool detach(int id);  // false if there is no such attachment
  // What the last addModel substituted (e.g. a missing inertial), for the node to log.
  const std::vector<std::string>& warnings() const { return warnings_; }

 private:
  PhysicsSettings settings_;
  double time_ = 0.0;
  std::unique_ptr<btDefaultCollisionConfiguration> collision_config_;
  std::unique_ptr<btCollisionAlgorithmCreateFunc> cylinder_plane_, plane_cylinder_;  // outlive the dispatcher
  std::unique_ptr<btCollisionAlgorithmCreateFunc> cylinder_cylinder_;
  std::unique_ptr<btCollisionDispatcher> dispatcher_;
  std::unique_ptr<btDbvtBroadphase> broadphase_;
  std::unique_ptr<ContactSolver> solver_;
  std::unique_ptr<btMultiBodyDynamicsWorld> world_;
  struct Attachment {
    int id = 0;
    std::string model_a, model_b;
    std::unique_ptr<btMultiBodyConstraint> constraint;
  };
  std::vector<Attachment> attachments_;  // destroyed before the models they join
  int next_attachment_id_ = 1;
  std::vector<std::unique_ptr<PhysicsModel>> models_;  // destroyed before the world
  std::vector<std::string> warnings_;
};

}  // namespace bullet_sim
