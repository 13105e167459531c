#pragma once
// The colours of Gazebo's named materials ("Gazebo/Red", from media/materials/scripts/
// gazebo.material), for SDF <material><script><name> and URDF <gazebo reference="link"><material>.
// One table, so that the camera and rviz's scene markers show a model the same way.
#include <array>
#include <optional>
#include <string>

namespace bullet_sim {

// The diffuse RGBA of a named material, or nothing for a name the table does not know.
std::optional<std::array<float, 4>> gazeboMaterialColour(const std::string& name);

}  // namespace bullet_sim
