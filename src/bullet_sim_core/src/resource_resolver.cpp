// URI -> absolute path, following the conventions of gazebo_ros: ROS packages are found by
// crawling ROS_PACKAGE_PATH for package.xml (as rospack does), models on GAZEBO_MODEL_PATH
// and in the models/ folder of every package.
#include "bullet_sim_core/resource_resolver.h"

#include <tinyxml2.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <set>
#include <system_error>

#include "bullet_sim_core/description_error.h"

namespace fs = std::filesystem;

namespace bullet_sim {
namespace {

std::vector<std::string> splitPathList(const char* value) {
  std::vector<std::string> out;
  if (!value) return out;
  std::string s(value);
  size_t start = 0;
  while (start <= s.size()) {
    size_t end = s.find(':', start);
    if (end == std::string::npos) end = s.size();
    if (end > start) out.push_back(s.substr(start, end - start));  // skip empty entries ("a::b")
    start = end + 1;
  }
  return out;
}

std::string joinList(const std::vector<std::string>& items) {
  if (items.empty()) return "(none)";
  std::string out;
  for (const auto& i : items) out += (out.empty() ? "" : ", ") + i;
  return out;
}

bool pathExists(const fs::path& p) {
  std::error_code ec;
  return fs::exists(p, ec);
}

bool isFolder(const fs::path& p) {
  std::error_code ec;
  return fs::is_directory(p, ec);
}

// The <name> of a package.xml; the folder name if the manifest cannot be read, which is
// what catkin would make of a package whose folder matches its name anyway.
std::string packageName(const fs::path& dir) {
  tinyxml2::XMLDocument doc;
  if (doc.LoadFile((dir / "package.xml").c_str()) == tinyxml2::XML_SUCCESS) {
    const auto* root = doc.FirstChildElement("package");
    const auto* name = root ? root->FirstChildElement("name") : nullptr;
    if (name && name->GetText()) {
      std::string n = name->GetText();
      n.erase(0, n.find_first_not_of(" \t\r\n"));
      n.erase(n.find_last_not_of(" \t\r\n") + 1);
      if (!n.empty()) return n;
    }
  }
  return dir.filename().string();
}

// Depth-first crawl like rospack: a folder holding package.xml is a package and is not
// descended further; hidden folders and those with CATKIN_IGNORE are skipped. Sub-folders
// are visited in sorted order so that the first package of a given name is deterministic.
void crawl(const fs::path& dir, std::set<fs::path>& visited,
           std::vector<std::pair<std::string, std::string>>& found) {
  std::error_code ec;
  fs::path canon = fs::canonical(dir, ec);
  if (ec || !visited.insert(canon).second) return;  // unreadable, or a symlink loop
  if (pathExists(dir / "CATKIN_IGNORE")) return;
  if (pathExists(dir / "package.xml")) {
    found.emplace_back(packageName(dir), fs::absolute(dir).lexically_normal().string());
    return;
  }
  std::vector<fs::path> subdirs;
  for (fs::directory_iterator it(dir, fs::directory_options::skip_permission_denied, ec), end;
       !ec && it != end; it.increment(ec)) {
    const std::string leaf = it->path().filename().string();
    if (!leaf.empty() && leaf[0] != '.' && isFolder(it->path())) subdirs.push_back(it->path());
  }
  std::sort(subdirs.begin(), subdirs.end());
  for (const auto& s : subdirs) crawl(s, visited, found);
}

}  // namespace

ResourceResolver ResourceResolver::fromEnvironment() {
  ResourceResolver r;
  r.package_path = splitPathList(std::getenv("ROS_PACKAGE_PATH"));
  r.model_path = splitPathList(std::getenv("GAZEBO_MODEL_PATH"));
  // Gazebo's own model folder, where tutorials tell users to copy models they made.
  if (const char* home = std::getenv("HOME"); home && *home) {
    const fs::path user_models = fs::path(home) / ".gazebo" / "models";
    if (isFolder(user_models)) r.model_path.push_back(user_models.string());
  }
  r.findPackage("");  // fills the cache, needed for the packages' models/ folders
  for (const auto& [name, dir] : r.package_cache_) {
    const fs::path models = fs::path(dir) / "models";
    if (isFolder(models)) r.model_path.push_back(models.string());
  }
  return r;
}

std::string ResourceResolver::findPackage(const std::string& name) const {
  if (!package_cache_ready_) {
    std::set<fs::path> visited;
    for (const auto& root : package_path) crawl(root, visited, package_cache_);
    package_cache_ready_ = true;
  }
  // First match wins: earlier ROS_PACKAGE_PATH entries overlay later ones.
  for (const auto& [pkg, dir] : package_cache_)
    if (pkg == name) return dir;
  return "";
}

std::string ResourceResolver::findModelDir(const std::string& name) const {
  std::vector<std::string> searched;
  for (const auto& folder : model_path) {
    const fs::path dir = fs::path(folder) / name;
    if (!name.empty() && (pathExists(dir / "model.sdf") || pathExists(dir / "model.config")))
      return fs::absolute(dir).lexically_normal().string();
    searched.push_back(folder);
  }
  throw DescriptionError("model://" + name + ": not found; searched: " + joinList(searched) +
                         " (set GAZEBO_MODEL_PATH, or put the model in a package's models/ folder)");
}

std::string ResourceResolver::resolve(const std::string& uri, const std::string& base_dir) const {
  auto startsWith = [&](const char* prefix) { return uri.rfind(prefix, 0) == 0; };
  // Splits "scheme://first/rest" into first and rest.
  auto split = [&](size_t scheme_len) {
    std::string body = uri.substr(scheme_len);
    size_t slash = body.find('/');
    if (slash == std::string::npos) return std::make_pair(body, std::string());
    return std::make_pair(body.substr(0, slash), body.substr(slash + 1));
  };
  auto finish = [&](const fs::path& p) { return fs::absolute(p).lexically_normal().string(); };

  if (startsWith("package://")) {
    auto [pkg, rel] = split(10);
    const std::string dir = findPackage(pkg);
    if (dir.empty())
      throw DescriptionError(uri + ": package '" + pkg + "' not found; searched ROS_PACKAGE_PATH: " +
                             joinList(package_path));
    const fs::path p = fs::path(dir) / rel;
    if (!pathExists(p)) throw DescriptionError(uri + ": no such file " + p.string() + " in package '" + pkg + "'");
    return finish(p);
  }
  if (startsWith("model://")) {
    // As Gazebo does: the first model folder that holds NAME/rel, so that meshes of a
    // model can be found even in a folder without model.config.
    auto [name, rel] = split(8);
    for (const auto& folder : model_path) {
      const fs::path p = fs::path(folder) / name / rel;
      if (!name.empty() && pathExists(p)) return finish(p);
    }
    throw DescriptionError(uri + ": not found; searched: " + joinList(model_path));
  }
  std::string path = uri;
  if (startsWith("file://")) path = uri.substr(7);
  else if (uri.find("://") != std::string::npos)
    throw DescriptionError(uri + ": unsupported URI scheme; expected package://, model://, file:// or a path");
  if (path.empty()) throw DescriptionError("empty URI; expected package://, model://, file:// or a path");

  fs::path p(path);
  if (p.is_relative()) p = (base_dir.empty() ? fs::current_path() : fs::path(base_dir)) / p;
  if (!pathExists(p))
    throw DescriptionError(uri + ": no such file " + p.lexically_normal().string() +
                           (fs::path(path).is_relative() ? " (relative to " +
                                (base_dir.empty() ? std::string("the current folder") : base_dir) + ")"
                                                         : std::string()));
  return finish(p);
}

}  // namespace bullet_sim
