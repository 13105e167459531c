#pragma once
// Reading controller parameters with errors that name the full parameter path and what was
// expected, so a wrong yaml file says which line to fix:
//   "/rrbot/joint1_position_controller/joint: required parameter missing; expected the name of a joint"
//   "/rrbot/joint1_position_controller/pid/p: expected a number (the proportional gain); got the string 'abc'"
#include <ros/node_handle.h>
#include <xmlrpcpp/XmlRpcValue.h>

#include <string>
#include <vector>

namespace sim_control {

// "<nh namespace>/<name>", the name error messages give.
std::string paramPath(const ros::NodeHandle& nh, const std::string& name);
// A value as a message shows it after "got": "the string 'x'", "3.5", "a list of 2 items", ...
std::string describeValue(XmlRpc::XmlRpcValue value);

// The two message shapes, for checks the helpers below do not cover.
std::string missingParamError(const ros::NodeHandle& nh, const std::string& name, const std::string& expected);
std::string badParamError(const ros::NodeHandle& nh, const std::string& name, const std::string& expected,
                          const std::string& got);

// Each returns false and fills `error` if the parameter is missing (when required) or has the
// wrong type; optional parameters that are absent leave `value` unchanged.
bool getRequiredString(const ros::NodeHandle& nh, const std::string& name, const std::string& expected,
                       std::string& value, std::string& error);
// Ints are accepted as numbers (yaml "p: 100"); NaN and infinity are not.
bool getNumber(const ros::NodeHandle& nh, const std::string& name, bool required, const std::string& expected,
               double& value, std::string& error);
bool getOptionalBool(const ros::NodeHandle& nh, const std::string& name, bool& value, std::string& error);
// A non-empty list of distinct joint names (ros_controllers' `joints`).
bool getJointNames(const ros::NodeHandle& nh, const std::string& name, std::vector<std::string>& names,
                   std::string& error);

}  // namespace sim_control
