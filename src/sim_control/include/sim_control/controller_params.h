#pragma once
// What controllers check of their parameters beyond the type, which ros_params::Reader (the
// workspace's one reader) checks; a wrong yaml file says which line to fix:
//   "/rrbot/joint1_position_controller/joint: required parameter missing; expected the name of a joint"
//   "/rrbot/joint1_position_controller/pid/p: expected a number (the proportional gain), got the string 'abc'"
#include <string>
#include <vector>

#include "ros_params/reader.h"

namespace sim_control {

// `name` as a finite number (an infinite gain or rate would reach the physics as inf and NaN).
bool readFinite(ros_params::Reader& params, const std::string& name, double* value, const std::string& expected,
                bool required = false);
// `joint`: the name of one joint.
bool readJointName(ros_params::Reader& params, std::string* joint);
// `joints`: a non-empty list of distinct joint names (ros_controllers' `joints`).
bool readJointNames(ros_params::Reader& params, std::vector<std::string>* joints);
// The reader's problems as a controller's init error, one a line; false when there are some.
bool noProblems(const ros_params::Reader& params, std::string& error);

}  // namespace sim_control
