#ifndef HECTOR_STYLE_MAPPING_ROS_PARAMETER_READER_H
#define HECTOR_STYLE_MAPPING_ROS_PARAMETER_READER_H

#include <sstream>
#include <string>
#include <vector>

#include <ros/node_handle.h>
#include <xmlrpcpp/XmlRpcValue.h>

namespace hector_style_mapping {

// Reads typed private parameters, keeping their names (to find unknown ones) and the problems found: a
// parameter of the wrong type keeps its default and is reported with its full name, what was expected and
// what was given.
class ParameterReader {
 public:
  explicit ParameterReader(const ros::NodeHandle& nh) : nh_(nh) {}

  void read(const std::string& name, double* value);
  void read(const std::string& name, int* value);  // 200.0 is taken as 200
  void read(const std::string& name, bool* value);
  void read(const std::string& name, std::string* value);
  // True (and the value read) when the parameter is set, for parameters whose default depends on other input.
  bool readIfSet(const std::string& name, double* value);

  const std::vector<std::string>& names() const { return names_; }
  std::string problems() const { return problems_.str(); }
  void problem(const std::string& text) { problems_ << text << "\n"; }

  // The full names of the private parameters set on the server that are not in `known` (typos).
  std::vector<std::string> unknown(const std::vector<std::string>& known) const;

 private:
  bool fetch(const std::string& name, XmlRpc::XmlRpcValue* raw);
  void wrongType(const std::string& name, const char* expected, XmlRpc::XmlRpcValue& raw);

  const ros::NodeHandle& nh_;
  std::vector<std::string> names_;
  std::ostringstream problems_;
};

}  // namespace hector_style_mapping

#endif  // HECTOR_STYLE_MAPPING_ROS_PARAMETER_READER_H
