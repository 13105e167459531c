#include "move_base/ros_params.h"

#include <algorithm>
#include <vector>

namespace move_base {
namespace {

std::size_t editDistance(const std::string& a, const std::string& b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t up = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diagonal = up;
    }
  }
  return row[b.size()];
}

std::string nearest(const std::string& name, const std::set<std::string>& known) {
  std::string best;
  std::size_t best_distance = 4;  // farther than 3 edits is no suggestion
  for (const std::string& k : known) {
    const std::size_t d = editDistance(name, k);
    if (d < best_distance) {
      best_distance = d;
      best = k;
    }
  }
  return best;
}

}  // namespace

std::string frameId(const std::string& frame) {
  std::size_t start = 0;
  while (start < frame.size() && frame[start] == '/') ++start;
  return frame.substr(start);
}

void warnUnknownParams(const ros::NodeHandle& nh, const std::set<std::string>& known,
                       const std::set<std::string>& namespaces) {
  std::vector<std::string> names;
  if (!ros::param::getParamNames(names)) return;
  const std::string prefix = nh.getNamespace() + "/";
  std::set<std::string> reported;
  for (const std::string& full : names) {
    if (full.compare(0, prefix.size(), prefix) != 0) continue;
    const std::string rest = full.substr(prefix.size());
    const std::size_t slash = rest.find('/');
    const std::string first = rest.substr(0, slash);
    const bool is_namespace = slash != std::string::npos;
    if ((is_namespace ? namespaces : known).count(first) || !reported.insert(first).second) continue;
    const std::string suggestion = nearest(first, is_namespace ? namespaces : known);
    ROS_WARN("%s%s is no %s that move_base reads%s%s%s: it has no effect.", prefix.c_str(), first.c_str(),
             is_namespace ? "namespace" : "parameter", suggestion.empty() ? "" : " (did you mean ", suggestion.c_str(),
             suggestion.empty() ? "" : "?)");
  }
}

}  // namespace move_base
