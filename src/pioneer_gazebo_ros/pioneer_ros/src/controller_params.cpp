#include "pioneer_ros/controller_params.h"

#include "ros_params/reader.h"

namespace pioneer_ros {
namespace {

void readAxis(ros_params::Reader& params, const std::string& axis, AxisConfig& config) {
  params.read("controller_gains/body/" + axis + "/p", &config.p);
  params.read("controller_gains/body/" + axis + "/i", &config.i);
  params.read("controller_gains/body/" + axis + "/d", &config.d);
  double i_clamp = 0.0;
  if (params.read("controller_gains/body/" + axis + "/i_clamp", &i_clamp)) config.i_clamp = i_clamp;
  params.read("feedforward/" + axis, &config.feedforward);
  params.read("limits/" + axis, &config.limit);
}

}  // namespace

ControllerConfig configFromParams(const XmlRpc::XmlRpcValue& tree, const std::string& ns) {
  ControllerConfig config;
  ros_params::Reader params(tree, ns);
  readAxis(params, "linear", config.linear);
  readAxis(params, "angular", config.angular);
  params.read("derivative_filter_time", &config.derivative_filter_time);
  params.read("rate", &config.rate);
  params.read("cmd_timeout", &config.cmd_timeout);
  params.read("odom_timeout", &config.odom_timeout);
  if (!params.ok()) throw BadParameter(params.problems());
  const std::string problem = validate(config);
  if (!problem.empty()) throw BadParameter(params.path(problem));
  return config;
}

}  // namespace pioneer_ros
