#include "ros_params/reader.h"

#include <ros/console.h>
#include <ros/param.h>

#include <cmath>
#include <sstream>

#include "ros_params/nearest_name.h"

namespace ros_params {
namespace {

using Value = XmlRpc::XmlRpcValue;

bool isNumber(const Value& v) { return v.getType() == Value::TypeDouble || v.getType() == Value::TypeInt; }

double toDouble(Value v) { return v.getType() == Value::TypeInt ? static_cast<int>(v) : static_cast<double>(v); }

}  // namespace

std::string describe(Value value) {
  std::ostringstream out;
  switch (value.getType()) {
    case Value::TypeBoolean: return static_cast<bool>(value) ? "true" : "false";
    case Value::TypeInt: return std::to_string(static_cast<int>(value));
    case Value::TypeDouble: {
      const double d = value;
      if (std::isnan(d)) return "NaN";
      out << d;
      return out.str();
    }
    case Value::TypeString: return "the string '" + static_cast<std::string>(value) + "'";
    case Value::TypeArray:
      out << "a list of " << value.size() << (value.size() == 1 ? " item" : " items");
      return out.str();
    case Value::TypeStruct: return "a dictionary";
    default: return "a value of another type";
  }
}

bool Reader::read(const std::string& name, double* value) {
  Value raw;
  if (!fetch(name, &raw)) return false;
  if (!isNumber(raw) || std::isnan(toDouble(raw))) return wrongType(name, "a number", raw);
  *value = toDouble(raw);
  return true;
}

bool Reader::read(const std::string& name, int* value) {
  Value raw;
  if (!fetch(name, &raw)) return false;
  if (raw.getType() == Value::TypeInt) {
    *value = static_cast<int>(raw);
    return true;
  }
  if (raw.getType() == Value::TypeDouble && static_cast<double>(raw) == std::floor(static_cast<double>(raw))) {
    *value = static_cast<int>(static_cast<double>(raw));
    return true;
  }
  return wrongType(name, "an integer", raw);
}

bool Reader::read(const std::string& name, bool* value) {
  Value raw;
  if (!fetch(name, &raw)) return false;
  if (raw.getType() != Value::TypeBoolean) return wrongType(name, "true or false", raw);
  *value = static_cast<bool>(raw);
  return true;
}

bool Reader::read(const std::string& name, std::string* value) {
  Value raw;
  if (!fetch(name, &raw)) return false;
  if (raw.getType() != Value::TypeString) return wrongType(name, "a string", raw);
  *value = static_cast<std::string>(raw);
  return true;
}

bool Reader::read(const std::string& name, std::vector<double>* value) {
  Value raw;
  if (!fetch(name, &raw)) return false;
  if (raw.getType() != Value::TypeArray) return wrongType(name, "a list of numbers", raw);
  std::vector<double> numbers;
  for (int i = 0; i < raw.size(); ++i) {
    if (!isNumber(raw[i]) || std::isnan(toDouble(raw[i]))) {
      problem(path(name) + ": expected a list of numbers, got " + describe(raw[i]) + " at [" + std::to_string(i) + "]");
      return false;
    }
    numbers.push_back(toDouble(raw[i]));
  }
  *value = numbers;
  return true;
}

bool Reader::read(const std::string& name, std::vector<std::string>* value) {
  Value raw;
  if (!fetch(name, &raw)) return false;
  if (raw.getType() != Value::TypeArray) return wrongType(name, "a list of strings", raw);
  std::vector<std::string> strings;
  for (int i = 0; i < raw.size(); ++i) {
    if (raw[i].getType() != Value::TypeString) {
      problem(path(name) + ": expected a list of strings, got " + describe(raw[i]) + " at [" + std::to_string(i) + "]");
      return false;
    }
    strings.push_back(static_cast<std::string>(raw[i]));
  }
  *value = strings;
  return true;
}

bool Reader::read(const std::string& name, Value* value) { return fetch(name, value); }

std::string Reader::problems() const {
  std::string text;
  for (const std::string& p : problems_) text += p + "\n";
  return text;
}

std::vector<std::string> Reader::unknown(const std::set<std::string>& also) const {
  std::set<std::string> known(names_.begin(), names_.end());
  known.insert(also.begin(), also.end());
  std::vector<std::string> all;
  if (!ros::param::getParamNames(all)) return {};
  const std::string prefix = nh_.getNamespace() == "/" ? "/" : nh_.getNamespace() + "/";
  std::vector<std::string> result;
  std::set<std::string> reported;
  for (const std::string& full : all) {
    if (full.compare(0, prefix.size(), prefix) != 0) continue;
    const std::string local = full.substr(prefix.size());
    // covered: asked for itself, or under a name asked for as a whole (a namespace read as a value)
    bool covered = known.count(local) > 0;
    for (std::size_t slash = local.find('/'); !covered && slash != std::string::npos; slash = local.find('/', slash + 1))
      covered = known.count(local.substr(0, slash)) > 0;
    if (covered || !reported.insert(local).second) continue;
    const std::string suggestion = nearestName(local, known);
    result.push_back(full + (suggestion.empty() ? "" : " (did you mean " + suggestion + "?)"));
  }
  return result;
}

bool Reader::fetch(const std::string& name, Value* raw) {
  names_.push_back(name);
  return nh_.getParam(name, *raw);
}

bool Reader::wrongType(const std::string& name, const std::string& expected, const Value& raw) {
  problem(path(name) + ": expected " + expected + ", got " + describe(raw));
  return false;
}

void Reader::warn(const std::string& text) {
  warnings_.push_back(text);
  ROS_WARN("%s", text.c_str());
}

}  // namespace ros_params
