#pragma once
// Turns the URIs found in URDF/SDF (package://, model://, file://, absolute or relative
// paths) into absolute file paths, the way gazebo_ros does with ROS_PACKAGE_PATH and
// GAZEBO_MODEL_PATH.
#include <string>
#include <vector>

namespace bullet_sim {

class ResourceResolver {
 public:
  // Reads ROS_PACKAGE_PATH, GAZEBO_MODEL_PATH and HOME from the environment; the model path is
  // GAZEBO_MODEL_PATH's folders, then ~/.gazebo/models, then every "models/" folder of a package on
  // ROS_PACKAGE_PATH.
  static ResourceResolver fromEnvironment();

  // Absolute path of uri; relative paths are taken relative to base_dir. Throws
  // DescriptionError naming the URI and what was searched when nothing exists there.
  std::string resolve(const std::string& uri, const std::string& base_dir = "") const;

  // Folder of model NAME (holding model.sdf or model.config) on the model path; throws
  // DescriptionError listing the folders searched when there is none.
  std::string findModelDir(const std::string& name) const;

  // Folder of ROS package NAME, or "" if it is not on the package path.
  std::string findPackage(const std::string& name) const;

  std::vector<std::string> package_path;  // folders searched recursively for package.xml
  std::vector<std::string> model_path;    // folders whose sub-folders are models

 private:
  mutable std::vector<std::pair<std::string, std::string>> package_cache_;  // name -> dir
  mutable bool package_cache_ready_ = false;
};

}  // namespace bullet_sim
