#pragma once
// Triangle meshes from STL/DAE/OBJ files through assimp, flattened into one vertex list in
// the file's model frame (node transforms applied, COLLADA units honoured, Z up kept as is).
#include <Eigen/Core>
#include <array>
#include <string>
#include <vector>

namespace bullet_sim {

struct TriangleMesh {
  std::vector<Eigen::Vector3d> vertices;
  std::vector<std::array<int, 3>> triangles;
};

// Throws DescriptionError naming the file when it cannot be read or holds no triangles.
// Results are cached by path, so a mesh used by many links is read once.
const TriangleMesh& loadMesh(const std::string& path);

}  // namespace bullet_sim
