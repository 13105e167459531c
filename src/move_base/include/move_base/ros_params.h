#pragma once
// Reading parameters as the navigation stack does, plus what it lacks: frame ids written with a
// leading '/' (as ROS 1 tutorials have them) are accepted, renamed parameters are honoured with a
// warning naming the new name, and names no component reads are reported with the nearest known one.
#include <ros/ros.h>

#include <set>
#include <string>

namespace move_base {

// "/map" -> "map" (tf2 refuses frame ids with a leading slash).
std::string frameId(const std::string& frame);

template <class T>
T param(const ros::NodeHandle& nh, const std::string& name, const T& fallback) {
  T value;
  return nh.getParam(name, value) ? value : fallback;
}

// The value of `name`, else of its former name `old_name` (with a warning naming the new one),
// else `fallback`.
template <class T>
T renamedParam(const ros::NodeHandle& nh, const std::string& name, const std::string& old_name, const T& fallback) {
  T value;
  if (nh.getParam(name, value)) return value;
  if (nh.getParam(old_name, value)) {
    ROS_WARN("Parameter %s/%s has been renamed to %s: using its value (%s is honoured for now; rename it).",
             nh.getNamespace().c_str(), old_name.c_str(), name.c_str(), old_name.c_str());
    return value;
  }
  return fallback;
}

// ros::NodeHandle::searchParam: the nearest `name` from nh's namespace up to the root.
template <class T>
T searchParam(const ros::NodeHandle& nh, const std::string& name, const T& fallback) {
  std::string found;
  T value;
  if (nh.searchParam(name, found) && ros::param::get(found, value)) return value;
  return fallback;
}

// Warns of each parameter directly in nh's namespace whose name is not in `known` and of each
// sub-namespace not in `namespaces`, suggesting the nearest known name.
void warnUnknownParams(const ros::NodeHandle& nh, const std::set<std::string>& known,
                       const std::set<std::string>& namespaces);

}  // namespace move_base
