#pragma once
// move_base's side of reading parameters. The planners, the recoveries and move_base itself read
// through ros_params::Reader and report with reportParams; costmap_ros still reads with param and
// searchParam below (upstream's untyped fallbacks), until its layers move into files of their own.
#include <ros/ros.h>

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

template <class T>
T param(const ros::NodeHandle& nh, const std::string& name, const T& fallback) {
  T value;
  return nh.getParam(name, value) ? value : fallback;
}

// ros::NodeHandle::searchParam: the nearest `name` from nh's namespace up to the root.
template <class T>
T searchParam(const ros::NodeHandle& nh, const std::string& name, const T& fallback) {
  std::string found;
  T value;
  if (nh.searchParam(name, found) && ros::param::get(found, value)) return value;
  return fallback;
}

}  // namespace move_base
