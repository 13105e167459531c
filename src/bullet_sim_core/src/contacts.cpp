#include "bullet_sim_core/contacts.h"

#include <BulletDynamics/Featherstone/btMultiBodyDynamicsWorld.h>

#include <map>
#include <utility>

#include "bullet_sim_core/physics_world.h"

namespace bullet_sim {

std::vector<Contact> currentContacts(PhysicsWorld& world, double tolerance) {  // Bullet's dispatcher has no const API
  // Which model and link each collider belongs to, built once per call.
  std::map<const btCollisionObject*, std::pair<std::string, std::string>> owner;
  for (const std::string& name : world.modelNames()) {
    const PhysicsModel* model = world.findModel(name);
    for (const std::string& link : model->linkNames())
      if (const btCollisionObject* c = model->linkCollider(link)) owner.emplace(c, std::make_pair(name, link));
  }
  std::vector<Contact> out;
  btDispatcher* dispatcher = world.bulletWorld().getDispatcher();
  const double step = world.settings().max_step_size;
  for (int m = 0; m < dispatcher->getNumManifolds(); ++m) {
    const btPersistentManifold* manifold = dispatcher->getManifoldByIndexInternal(m);
    const auto a = owner.find(manifold->getBody0());
    const auto b = owner.find(manifold->getBody1());
    if (a == owner.end() || b == owner.end()) continue;
    for (int k = 0; k < manifold->getNumContacts(); ++k) {
      const btManifoldPoint& p = manifold->getContactPoint(k);
      if (p.getDistance() > tolerance) continue;
      Contact c;
      c.collider_a = a->first;
      c.collider_b = b->first;
      c.model_a = a->second.first;
      c.link_a = a->second.second;
      c.model_b = b->second.first;
      c.link_b = b->second.second;
      const btVector3 mid = 0.5 * (p.getPositionWorldOnA() + p.getPositionWorldOnB());
      c.position = Eigen::Vector3d(mid.x(), mid.y(), mid.z());
      c.normal = Eigen::Vector3d(p.m_normalWorldOnB.x(), p.m_normalWorldOnB.y(), p.m_normalWorldOnB.z());
      c.depth = -p.getDistance();
      c.force = std::max(0.0, static_cast<double>(p.getAppliedImpulse())) / step;
      out.push_back(std::move(c));
    }
  }
  return out;
}

}  // namespace bullet_sim
