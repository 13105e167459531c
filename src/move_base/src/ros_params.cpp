#include "move_base/ros_params.h"

namespace move_base {

std::string frameId(const std::string& frame) {
  std::size_t start = 0;
  while (start < frame.size() && frame[start] == '/') ++start;
  return frame.substr(start);
}

void reportParams(const ros_params::Reader& params, const std::set<std::string>& also) {
  for (const std::string& problem : params.problemList()) ROS_ERROR("%s; using the default.", problem.c_str());
  for (const std::string& name : params.unknown(also))
    ROS_WARN("%s is no parameter that move_base reads: it has no effect.", name.c_str());
}

}  // namespace move_base
