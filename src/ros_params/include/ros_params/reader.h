#pragma once
// Reading a node's ROS parameters, one way for every C++ node of the workspace:
//   ros_params::Reader params(ros::NodeHandle("~"));
//   params.read("map_resolution", &options.resolution);      // set: read; absent: default kept
//   options.rate = params.get("rate", 20.0);                   // the same, returning the value
//   params.readRenamed("max_vel_trans", "max_trans_vel", &v);  // the old name honoured, with a warning
//   params.require("joint", &joint, "the name of a joint");    // absent is a problem too
//   params.search("robot_radius", &radius);                    // the nearest up the namespaces
//   if (!params.ok()) ROS_FATAL("%s", params.problems().c_str());
//   for (const auto& line : params.unknown()) ROS_WARN("%s: no parameter of this node", line.c_str());
// A parameter of the wrong type is a problem naming its full path, what was expected and what was
// found ("/hector_mapping/map_size: expected an integer, got the string 'big'"), and the value keeps
// its default; never a silent fallback. Every name asked for is recorded, so unknown() reports the
// parameters the node never reads from what it reads, not from a list kept by hand.
// A Reader can also read a tree already fetched (ros::param::get of a namespace), the same way and
// with the same messages, which needs no master: a test reads a yaml file's tree with it.
#include <ros/node_handle.h>
#include <xmlrpcpp/XmlRpcValue.h>

#include <optional>
#include <set>
#include <string>
#include <vector>

namespace ros_params {

// A value as an error message shows it after "got": "the string 'x'", "3.5", "true", "NaN",
// "a list of 2 items", "a dictionary".
std::string describe(XmlRpc::XmlRpcValue value);

class Reader {
 public:
  explicit Reader(const ros::NodeHandle& nh) : nh_(nh), ns_(nh.getNamespace()) {}
  // The parameters in `tree`, as fetched from namespace `ns` (an invalid tree: nothing set).
  Reader(const XmlRpc::XmlRpcValue& tree, const std::string& ns) : tree_(tree), ns_(ns) {}

  // Each reads `name` (relative to the node handle) into *value when it is set and of the right
  // type, and says whether it did. `expected` is what a problem says was expected ("a rate in Hz").
  bool read(const std::string& name, double* value,  // an int is a number too; NaN is refused
            const std::string& expected = "a number");
  bool read(const std::string& name, int* value, const std::string& expected = "an integer");  // 200.0 is 200
  bool read(const std::string& name, bool* value, const std::string& expected = "true or false");
  bool read(const std::string& name, std::string* value, const std::string& expected = "a string");
  bool read(const std::string& name, std::vector<double>* value, const std::string& expected = "a list of numbers");
  bool read(const std::string& name, std::vector<std::string>* value,
            const std::string& expected = "a list of strings");
  bool read(const std::string& name, XmlRpc::XmlRpcValue* value);  // any type: checked by the caller
  // Whether `name` is set (counted as asked for).
  bool has(const std::string& name);

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

  // ros::NodeHandle::searchParam's reading: the nearest `name` from the namespace up to the root
  // ("~global_costmap/robot_radius", then "~robot_radius", then "/robot_radius"), read as read()
  // reads it, with the path where it was found in problems. A tree holds only its own namespace.
  template <class T>
  bool search(const std::string& name, T* value) {
    const std::string found = searchPath(name);
    const std::size_t asked = names_.size();
    const bool got = !found.empty() && read(found, value);
    names_.resize(asked);  // recorded as asked for, not by where it was found
    names_.push_back(name);
    return got;
  }
  // Where search finds `name` (a full path), or "" when nothing up the namespaces sets it.
  std::string searchPath(const std::string& name) const;

  // Like read, and a problem when the parameter is not set: "<path>: required parameter missing; expected <what>".
  template <class T>
  bool require(const std::string& name, T* value, const std::string& expected) {
    if (read(name, value, expected)) return true;
    if (!isSet(name)) problem(path(name) + ": required parameter missing; expected " + expected);
    return false;
  }

  // The full name of `name`, as messages give it.
  std::string path(const std::string& name) const;
  const std::vector<std::string>& names() const { return names_; }  // every name asked for

  void problem(const std::string& text);  // the same problem twice is recorded once
  // A problem with `name`'s value: "<path>: <what>"; false, to return.
  bool fail(const std::string& name, const std::string& what) {
    problem(path(name) + ": " + what);
    return false;
  }
  bool ok() const { return problems_.empty(); }
  // The problems, one a line (no newline after the last).
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
  bool isSet(const std::string& name) const;
  // In tree mode: the value at `name` ('/'-separated), if set; *blocked says so when a level above
  // it is not a dictionary.
  const XmlRpc::XmlRpcValue* find(const std::string& name, std::string* blocked) const;
  std::vector<std::string> allNames() const;  // the full names of everything set
  bool wrongType(const std::string& name, const std::string& expected, const XmlRpc::XmlRpcValue& raw);
  void warn(const std::string& text);

  std::optional<ros::NodeHandle> nh_;  // reading the parameter server; else tree_
  XmlRpc::XmlRpcValue tree_;
  std::string ns_;
  std::vector<std::string> names_;
  std::vector<std::string> problems_;
  std::vector<std::string> warnings_;
};

}  // namespace ros_params
