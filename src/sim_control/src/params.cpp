#include "sim_control/params.h"

#include <cmath>
#include <set>
#include <sstream>

namespace sim_control {

std::string paramPath(const ros::NodeHandle& nh, const std::string& name) {
  std::string ns = nh.getNamespace();
  if (ns.empty() || ns.back() != '/') ns += '/';  // the root namespace is "/" already
  return ns + name;
}

std::string describeValue(XmlRpc::XmlRpcValue value) {  // by value: XmlRpcValue's casts are non-const
  std::ostringstream out;
  switch (value.getType()) {
    case XmlRpc::XmlRpcValue::TypeString: out << "the string '" << static_cast<std::string&>(value) << "'"; break;
    case XmlRpc::XmlRpcValue::TypeInt: out << static_cast<int>(value); break;
    case XmlRpc::XmlRpcValue::TypeDouble: out << static_cast<double>(value); break;
    case XmlRpc::XmlRpcValue::TypeBoolean: out << (static_cast<bool>(value) ? "true" : "false"); break;
    case XmlRpc::XmlRpcValue::TypeArray: out << "a list of " << value.size() << " items"; break;
    case XmlRpc::XmlRpcValue::TypeStruct: out << "a dictionary"; break;
    default: out << "a value of another type"; break;
  }
  return out.str();
}

std::string missingParamError(const ros::NodeHandle& nh, const std::string& name, const std::string& expected) {
  return paramPath(nh, name) + ": required parameter missing; expected " + expected;
}

std::string badParamError(const ros::NodeHandle& nh, const std::string& name, const std::string& expected,
                          const std::string& got) {
  return paramPath(nh, name) + ": expected " + expected + "; got " + got;
}

bool getRequiredString(const ros::NodeHandle& nh, const std::string& name, const std::string& expected,
                       std::string& value, std::string& error) {
  XmlRpc::XmlRpcValue v;
  if (!nh.getParam(name, v)) {
    error = missingParamError(nh, name, expected);
    return false;
  }
  if (v.getType() != XmlRpc::XmlRpcValue::TypeString || static_cast<std::string&>(v).empty()) {
    error = badParamError(nh, name, expected, v.getType() == XmlRpc::XmlRpcValue::TypeString ? "an empty string"
                                                                                              : describeValue(v));
    return false;
  }
  value = static_cast<std::string&>(v);
  return true;
}

bool getNumber(const ros::NodeHandle& nh, const std::string& name, bool required, const std::string& expected,
               double& value, std::string& error) {
  XmlRpc::XmlRpcValue v;
  if (!nh.getParam(name, v)) {
    if (!required) return true;
    error = missingParamError(nh, name, expected);
    return false;
  }
  double number;
  if (v.getType() == XmlRpc::XmlRpcValue::TypeInt) number = static_cast<int>(v);
  else if (v.getType() == XmlRpc::XmlRpcValue::TypeDouble) number = static_cast<double>(v);
  else {
    error = badParamError(nh, name, expected, describeValue(v));
    return false;
  }
  if (!std::isfinite(number)) {
    error = badParamError(nh, name, expected + " (finite)", describeValue(v));
    return false;
  }
  value = number;
  return true;
}

bool getOptionalBool(const ros::NodeHandle& nh, const std::string& name, bool& value, std::string& error) {
  XmlRpc::XmlRpcValue v;
  if (!nh.getParam(name, v)) return true;
  if (v.getType() != XmlRpc::XmlRpcValue::TypeBoolean) {
    error = badParamError(nh, name, "true or false", describeValue(v));
    return false;
  }
  value = static_cast<bool>(v);
  return true;
}

bool getJointNames(const ros::NodeHandle& nh, const std::string& name, std::vector<std::string>& names,
                   std::string& error) {
  const std::string expected = "a list of joint names, e.g. [joint1, joint2]";
  XmlRpc::XmlRpcValue v;
  if (!nh.getParam(name, v)) {
    error = missingParamError(nh, name, expected);
    return false;
  }
  if (v.getType() != XmlRpc::XmlRpcValue::TypeArray || v.size() == 0) {
    error = badParamError(nh, name, expected, v.getType() == XmlRpc::XmlRpcValue::TypeArray ? "an empty list"
                                                                                             : describeValue(v));
    return false;
  }
  names.clear();
  std::set<std::string> seen;
  for (int k = 0; k < v.size(); ++k) {
    if (v[k].getType() != XmlRpc::XmlRpcValue::TypeString) {
      error = badParamError(nh, name, expected, "item " + std::to_string(k) + " = " + describeValue(v[k]));
      return false;
    }
    const std::string joint = static_cast<std::string&>(v[k]);
    // A joint listed twice would be commanded twice per update and claimed twice.
    if (!seen.insert(joint).second) {
      error = badParamError(nh, name, "distinct joint names", "'" + joint + "' more than once");
      return false;
    }
    names.push_back(joint);
  }
  return true;
}

}  // namespace sim_control
