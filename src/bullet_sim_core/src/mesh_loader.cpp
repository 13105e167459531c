#include "bullet_sim_core/mesh_loader.h"

#include <assimp/Importer.hpp>
#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <map>
#include <memory>
#include <mutex>

#include "bullet_sim_core/description_error.h"

namespace bullet_sim {
namespace {

void collect(const aiScene& scene, const aiNode& node, const aiMatrix4x4& parent, TriangleMesh& out) {
  const aiMatrix4x4 transform = parent * node.mTransformation;
  for (unsigned m = 0; m < node.mNumMeshes; ++m) {
    const aiMesh& mesh = *scene.mMeshes[node.mMeshes[m]];
    const int offset = static_cast<int>(out.vertices.size());
    for (unsigned v = 0; v < mesh.mNumVertices; ++v) {
      const aiVector3D p = transform * mesh.mVertices[v];
      out.vertices.emplace_back(p.x, p.y, p.z);
    }
    for (unsigned f = 0; f < mesh.mNumFaces; ++f) {
      const aiFace& face = mesh.mFaces[f];
      if (face.mNumIndices != 3) continue;  // points and lines have no surface
      out.triangles.push_back({offset + static_cast<int>(face.mIndices[0]), offset + static_cast<int>(face.mIndices[1]),
                               offset + static_cast<int>(face.mIndices[2])});
    }
  }
  for (unsigned c = 0; c < node.mNumChildren; ++c) collect(scene, *node.mChildren[c], transform, out);
}

}  // namespace

const TriangleMesh& loadMesh(const std::string& path) {
  static std::mutex mutex;
  static std::map<std::string, std::unique_ptr<TriangleMesh>> cache;
  std::lock_guard<std::mutex> lock(mutex);
  auto it = cache.find(path);
  if (it != cache.end()) return *it->second;

  Assimp::Importer importer;
  // ROS and Gazebo use COLLADA files' coordinates as they are (Z up); assimp would rotate them.
  importer.SetPropertyBool(AI_CONFIG_IMPORT_COLLADA_IGNORE_UP_DIRECTION, true);
  const aiScene* scene = importer.ReadFile(path, aiProcess_Triangulate | aiProcess_JoinIdenticalVertices);
  if (!scene || !scene->mRootNode)
    throw DescriptionError(path + ": cannot read mesh: " + importer.GetErrorString());
  auto mesh = std::make_unique<TriangleMesh>();
  collect(*scene, *scene->mRootNode, aiMatrix4x4(), *mesh);
  if (mesh->triangles.empty()) throw DescriptionError(path + ": mesh holds no triangles");
  return *cache.emplace(path, std::move(mesh)).first->second;
}

}  // namespace bullet_sim
