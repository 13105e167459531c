#pragma once
// The flat, static floor the physics tests stand their bodies on (Gazebo's ground_plane model,
// as a description).
#include "bullet_sim_core/model_description.h"

namespace bullet_sim {

inline ModelDescription groundPlane() {
  ModelDescription ground;
  ground.name = "ground_plane";
  ground.is_static = true;
  ground.links.emplace_back();
  ground.links[0].name = "link";
  ground.links[0].collisions.emplace_back();
  ground.links[0].collisions[0].geometry.type = GeometryType::Plane;
  return ground;
}

}  // namespace bullet_sim
