#include "hector_style_mapping/ros/parameter_reader.h"

#include <algorithm>
#include <cmath>

namespace hector_style_mapping {
namespace {

const char* typeName(const XmlRpc::XmlRpcValue& value) {
  switch (value.getType()) {
    case XmlRpc::XmlRpcValue::TypeBoolean: return "a bool";
    case XmlRpc::XmlRpcValue::TypeInt: return "an int";
    case XmlRpc::XmlRpcValue::TypeDouble: return "a double";
    case XmlRpc::XmlRpcValue::TypeString: return "a string";
    case XmlRpc::XmlRpcValue::TypeArray: return "a list";
    case XmlRpc::XmlRpcValue::TypeStruct: return "a dictionary";
    default: return "something else";
  }
}

}  // namespace

void ParameterReader::read(const std::string& name, double* value) { readIfSet(name, value); }

bool ParameterReader::readIfSet(const std::string& name, double* value) {
  XmlRpc::XmlRpcValue raw;
  if (!fetch(name, &raw)) return false;
  if (raw.getType() == XmlRpc::XmlRpcValue::TypeDouble) *value = static_cast<double>(raw);
  else if (raw.getType() == XmlRpc::XmlRpcValue::TypeInt) *value = static_cast<int>(raw);
  else {
    wrongType(name, "a number", raw);
    return false;
  }
  return true;
}

void ParameterReader::read(const std::string& name, int* value) {
  XmlRpc::XmlRpcValue raw;
  if (!fetch(name, &raw)) return;
  if (raw.getType() == XmlRpc::XmlRpcValue::TypeInt) {
    *value = static_cast<int>(raw);
  } else if (raw.getType() == XmlRpc::XmlRpcValue::TypeDouble &&
             static_cast<double>(raw) == std::floor(static_cast<double>(raw))) {
    *value = static_cast<int>(static_cast<double>(raw));
  } else {
    wrongType(name, "an integer", raw);
  }
}

void ParameterReader::read(const std::string& name, bool* value) {
  XmlRpc::XmlRpcValue raw;
  if (!fetch(name, &raw)) return;
  if (raw.getType() == XmlRpc::XmlRpcValue::TypeBoolean) *value = static_cast<bool>(raw);
  else wrongType(name, "true or false", raw);
}

void ParameterReader::read(const std::string& name, std::string* value) {
  XmlRpc::XmlRpcValue raw;
  if (!fetch(name, &raw)) return;
  if (raw.getType() == XmlRpc::XmlRpcValue::TypeString) *value = static_cast<std::string>(raw);
  else wrongType(name, "a string", raw);
}

std::vector<std::string> ParameterReader::unknown(const std::vector<std::string>& known) const {
  std::vector<std::string> all;
  ros::NodeHandle("~").getParamNames(all);  // every parameter on the server
  const std::string prefix = nh_.getNamespace() + "/";
  std::vector<std::string> result;
  for (const std::string& name : all) {
    if (name.compare(0, prefix.size(), prefix) != 0) continue;
    const std::string local = name.substr(prefix.size());
    if (std::find(known.begin(), known.end(), local) == known.end()) result.push_back(name);
  }
  return result;
}

bool ParameterReader::fetch(const std::string& name, XmlRpc::XmlRpcValue* raw) {
  names_.push_back(name);
  return nh_.getParam(name, *raw);
}

void ParameterReader::wrongType(const std::string& name, const char* expected, XmlRpc::XmlRpcValue& raw) {
  problems_ << nh_.resolveName(name) << ": expected " << expected << ", got " << typeName(raw) << " ("
            << raw.toXml() << ")\n";
}

}  // namespace hector_style_mapping
