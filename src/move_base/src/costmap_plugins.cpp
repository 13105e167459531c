#include "move_base/costmap_plugins.h"

#include <set>
#include <string>

namespace move_base {

namespace nc = navigation_core;

namespace {

std::vector<nc::LayerSpec> listed(ros_params::Reader& params, XmlRpc::XmlRpcValue& plugins) {
  std::vector<nc::LayerSpec> layers;
  if (plugins.getType() != XmlRpc::XmlRpcValue::TypeArray) {
    ROS_ERROR("%s: expected a list of {name: ..., type: ...}, got %s; the costmap has no layers.",
              params.path("plugins").c_str(), ros_params::describe(plugins).c_str());
    return layers;
  }
  for (int i = 0; i < plugins.size(); ++i) {
    XmlRpc::XmlRpcValue& entry = plugins[i];
    const auto isString = [&entry](const char* key) {
      return entry.hasMember(key) && entry[key].getType() == XmlRpc::XmlRpcValue::TypeString;
    };
    if (entry.getType() != XmlRpc::XmlRpcValue::TypeStruct || !isString("name") || !isString("type")) {
      ROS_ERROR("%s[%d]: expected {name: ..., type: ...}, got %s; left out.", params.path("plugins").c_str(), i,
                ros_params::describe(entry).c_str());
      continue;
    }
    layers.push_back({static_cast<std::string>(entry["name"]), static_cast<std::string>(entry["type"])});
  }
  return layers;
}

// Pre-Hydro parameters: moved into the layers' namespaces as costmap_2d moves them.
std::vector<nc::LayerSpec> translated(const ros::NodeHandle& nh, ros_params::Reader& params) {
  std::vector<std::string> names;
  std::set<std::string> present;
  ros::param::getParamNames(names);
  const std::string prefix = nh.getNamespace() + "/";
  for (const std::string& n : names)
    if (n.compare(0, prefix.size(), prefix) == 0)
      present.insert(n.substr(prefix.size(), n.find('/', prefix.size()) - prefix.size()));
  const nc::LegacyCostmapTranslation t =
      nc::translateLegacyCostmapParams(present, params.get("static_map", false), params.get<std::string>("map_type", ""),
                                       params.get<std::string>("observation_sources", ""));
  for (const nc::ParamMove& m : t.moves) {
    XmlRpc::XmlRpcValue value;
    if (!nh.getParam(m.from, value)) continue;
    nh.setParam(m.to, value);
    if (!m.keep_original) nh.deleteParam(m.from);
  }
  return t.plugins;
}

}  // namespace

std::vector<nc::LayerSpec> costmapPlugins(const ros::NodeHandle& nh, ros_params::Reader& params) {
  XmlRpc::XmlRpcValue plugins;
  return params.read("plugins", &plugins) ? listed(params, plugins) : translated(nh, params);
}

}  // namespace move_base
