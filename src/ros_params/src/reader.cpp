#include "ros_params/reader.h"

#include <ros/console.h>
#include <ros/param.h>

#include <algorithm>
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

bool Reader::read(const std::string& name, double* value, const std::string& expected) {
  Value raw;
  if (!fetch(name, &raw)) return false;
  if (!isNumber(raw) || std::isnan(toDouble(raw))) return wrongType(name, expected, raw);
  *value = toDouble(raw);
  return true;
}

bool Reader::read(const std::string& name, int* value, const std::string& expected) {
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
  return wrongType(name, expected, raw);
}

bool Reader::read(const std::string& name, bool* value, const std::string& expected) {
  Value raw;
  if (!fetch(name, &raw)) return false;
  if (raw.getType() != Value::TypeBoolean) return wrongType(name, expected, raw);
  *value = static_cast<bool>(raw);
  return true;
}

bool Reader::read(const std::string& name, std::string* value, const std::string& expected) {
  Value raw;
  if (!fetch(name, &raw)) return false;
  if (raw.getType() != Value::TypeString) return wrongType(name, expected, raw);
  *value = static_cast<std::string>(raw);
  return true;
}

bool Reader::read(const std::string& name, std::vector<double>* value, const std::string& expected) {
  Value raw;
  if (!fetch(name, &raw)) return false;
  if (raw.getType() != Value::TypeArray) return wrongType(name, expected, raw);
  std::vector<double> numbers;
  for (int i = 0; i < raw.size(); ++i) {
    if (!isNumber(raw[i]) || std::isnan(toDouble(raw[i]))) {
      problem(path(name) + ": expected " + expected + ", got " + describe(raw[i]) + " at [" + std::to_string(i) + "]");
      return false;
    }
    numbers.push_back(toDouble(raw[i]));
  }
  *value = numbers;
  return true;
}

bool Reader::read(const std::string& name, std::vector<std::string>* value, const std::string& expected) {
  Value raw;
  if (!fetch(name, &raw)) return false;
  if (raw.getType() != Value::TypeArray) return wrongType(name, expected, raw);
  std::vector<std::string> strings;
  for (int i = 0; i < raw.size(); ++i) {
    if (raw[i].getType() != Value::TypeString) {
      problem(path(name) + ": expected " + expected + ", got " + describe(raw[i]) + " at [" + std::to_string(i) + "]");
      return false;
    }
    strings.push_back(static_cast<std::string>(raw[i]));
  }
  *value = strings;
  return true;
}

bool Reader::read(const std::string& name, Value* value) { return fetch(name, value); }

bool Reader::has(const std::string& name) {
  names_.push_back(name);
  return isSet(name);
}

bool Reader::isSet(const std::string& name) const {
  if (nh_) return nh_->hasParam(name);
  return find(name, nullptr) != nullptr;
}

std::string Reader::searchPath(const std::string& name) const {
  if (!nh_) return isSet(name) ? name : "";
  std::string found;
  return nh_->searchParam(name, found) ? found : "";
}

std::string Reader::path(const std::string& name) const {
  if (nh_) return nh_->resolveName(name);
  return (!ns_.empty() && ns_.back() == '/' ? ns_ : ns_ + "/") + name;
}

void Reader::problem(const std::string& text) {
  for (const std::string& p : problems_)
    if (p == text) return;
  problems_.push_back(text);
}

const Value* Reader::find(const std::string& name, std::string* blocked) const {
  const Value* node = &tree_;
  std::string where;
  std::size_t start = 0;
  while (true) {
    if (node->getType() == Value::TypeInvalid) return nullptr;  // nothing set
    if (node->getType() != Value::TypeStruct) {
      if (blocked) *blocked = (where.empty() ? ns_ : path(where)) + ": expected a dictionary, got " + describe(*node);
      return nullptr;
    }
    const std::size_t slash = name.find('/', start);
    const std::string key = name.substr(start, slash == std::string::npos ? std::string::npos : slash - start);
    if (!node->hasMember(key)) return nullptr;
    node = &(*node)[key];  // XmlRpcValue's const operator[] (it inserts nothing for a member it has)
    where += (where.empty() ? "" : "/") + key;
    if (slash == std::string::npos) return node;
    start = slash + 1;
  }
}

std::string Reader::problems() const {
  std::string text;
  for (const std::string& p : problems_) text += (text.empty() ? "" : "\n") + p;
  return text;
}

std::vector<std::string> Reader::unknown(const std::set<std::string>& also) const {
  std::set<std::string> known(names_.begin(), names_.end());
  known.insert(also.begin(), also.end());
  const std::vector<std::string> all = allNames();
  const std::string prefix = ns_.empty() || ns_.back() == '/' ? ns_ : ns_ + "/";
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
  if (nh_) return nh_->getParam(name, *raw);
  std::string blocked;
  const Value* found = find(name, &blocked);
  if (!blocked.empty()) problem(blocked);
  if (found) *raw = *found;
  return found != nullptr;
}

std::vector<std::string> Reader::allNames() const {
  std::vector<std::string> all;
  if (nh_) {
    ros::param::getParamNames(all);
    return all;
  }
  // The tree's leaves (and empty dictionaries), as the master lists a namespace's parameters.
  std::vector<std::pair<std::string, const Value*>> todo{{"", &tree_}};
  while (!todo.empty()) {
    const auto [name, node] = todo.back();
    todo.pop_back();
    if (node->getType() == Value::TypeStruct && node->size() > 0) {
      for (auto it = node->begin(); it != node->end(); ++it)
        todo.push_back({name + (name.empty() ? "" : "/") + it->first, &it->second});
    } else if (!name.empty()) {
      all.push_back(path(name));
    }
  }
  std::sort(all.begin(), all.end());
  return all;
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
