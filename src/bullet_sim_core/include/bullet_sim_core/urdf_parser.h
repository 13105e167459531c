#pragma once
// URDF text -> ModelDescription, through urdfdom (Debian's liburdfdom), plus the <gazebo>
// extension blocks urdfdom ignores. Every problem becomes a DescriptionError that names
// the source and the element.
#include <string>

#include "bullet_sim_core/model_description.h"
#include "bullet_sim_core/resource_resolver.h"

namespace bullet_sim {

// `source` names the file or request in error messages; relative mesh paths are taken
// relative to `base_dir`.
ModelDescription parseUrdf(const std::string& xml, const std::string& source,
                           const ResourceResolver& resolver, const std::string& base_dir = "");

}  // namespace bullet_sim
