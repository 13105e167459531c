#pragma once
// Reading a node's ROS parameters, one way for every C++ node of the workspace:
//   ros_params::Reader params(ros::NodeHandle("~"));
//   params.read("map_resolution", &options.resolution);      // set: read; absent: default kept
//   options.rate = params.get("rate", 20.0);                   // the same, returning the value
//   params.readRenamed("max_vel_trans", "max_trans_vel", &v);  // the old name honoured, with a warning
//   params.require("joint", &joint, "the name of a joint");    // absent is a problem too
//   if (!params.ok()) ROS_FATAL("%s", params.problems().c_str());
//   for (const auto& line : params.unknown()) ROS_WARN("%s: no parameter of this node", line.c_str());
// A parameter of the wrong type is a problem naming its full path, what was expected and what was
// found ("/hector_mapping/map_size: expected an integer, got the string 'big'"), and the value keeps
// its default; never a silent fallback. Every name asked for is recorded, so unknown() reports the
// parameters the node never reads from what it reads, not from a list kept by hand.
#include <ros/node_handle.h>
#include <xmlrpcpp/XmlRpcValue.h>

#include <set>
#include <string>
#include <vector>

namespace ros_params {

// A value as an error message shows it after "got": "the string 'x'", "3.5", "true", "NaN",
// "a list of 2 items", "a dictionary".
std::string describe(XmlRpc::XmlRpcValue value);

class Reader {
 public:
  explicit Reader(const ros::NodeHandle& nh) : nh_(nh) {}

  // Each reads `name` (relative to the node handle) into *value when it is set and of the right
  // type, and says whether it did.
  bool read(const std::string& name, double* value);  // an int is a number too; NaN is refused
  bool read(const std::string& name, int* value);     // 200.0 is taken as 200
  bool read(const std::string& name, bool* value);
  bool read(const std::string& name, std::string* value);
  bool read(const std::string& name, std::vector<double>* value);
  bool read(const std::string& name, std::vector<std::string>* value);
  bool read(const std::string& name, XmlRpc::XmlRpcValue* value);  // any type: checked by the caller

  // The value of `name`, else `fallback` (not set, or of the wrong type: a problem).
  template <class T>
  T get(const std::string& name, const T& fallback) {
    T value = fallback;
    read(name, &value);
    return value;
  }

  // `name`, else its former name `old_name` (with a warning naming the new one).
  template <class T>
  bool readRenamed(const std::string& name, const std::string& old_name, T* value) {
    if (read(name, value)) return true;
    if (!read(old_name, value)) return false;
    warn(path(old_name) + " has been renamed to " + name + ": its value is used (rename it)");
    return true;
  }

  template <class T>
  T getRenamed(const std::string& name, const std::string& old_name, const T& fallback) {
    T value = fallback;
    readRenamed(name, old_name, &value);
    return value;
  }

  // Like read, and a problem when the parameter is not set: "<path>: required parameter missing; expected <what>".
  template <class T>
  bool require(const std::string& name, T* value, const std::string& expected) {
    if (read(name, value)) return true;
    if (!nh_.hasParam(name)) problem(path(name) + ": required parameter missing; expected " + expected);
    return false;
  }

  std::string path(const std::string& name) const { return nh_.resolveName(name); }
  const std::vector<std::string>& names() const { return names_; }  // every name asked for

  void problem(const std::string& text) { problems_.push_back(text); }
  bool ok() const { return problems_.empty(); }
  // The problems, one a line.
  std::string problems() const;
  const std::vector<std::string>& problemList() const { return problems_; }
  const std::vector<std::string>& warnings() const { return warnings_; }

  // The full names of the parameters set under the node handle's namespace that were never asked
  // for, each followed by " (did you mean <nearest name asked for>?)" when one is close. A name
  // asked for that is itself a namespace (read as XmlRpcValue) covers what is under it; `also`
  // adds names read elsewhere (another reader, a plugin).
  std::vector<std::string> unknown(const std::set<std::string>& also = {}) const;

 private:
  bool fetch(const std::string& name, XmlRpc::XmlRpcValue* raw);
  bool wrongType(const std::string& name, const std::string& expected, const XmlRpc::XmlRpcValue& raw);
  void warn(const std::string& text);

  ros::NodeHandle nh_;
  std::vector<std::string> names_;
  std::vector<std::string> problems_;
  std::vector<std::string> warnings_;
};

}  // namespace ros_params
