#pragma once
// move_base's side of reading parameters: every component (move_base, the planners, the
// recoveries, each costmap layer) reads through a ros_params::Reader on its namespace and reports
// what it read with reportParams.
#include <set>
#include <string>

#include "ros_params/reader.h"

namespace move_base {

// "/map" -> "map" (tf2 refuses frame ids with a leading slash).
std::string frameId(const std::string& frame);

// A component's parameters as read: each problem an error (the default is used instead: a
// navigation stack keeps going), each parameter in its namespace it never read a warning with the
// nearest name it reads. `also`: names in that namespace read elsewhere or accepted without effect.
void reportParams(const ros_params::Reader& params, const std::set<std::string>& also = {});

}  // namespace move_base
