#include "sim_control/controller_params.h"

#include <cmath>
#include <set>
#include <sstream>

namespace sim_control {

bool readFinite(ros_params::Reader& params, const std::string& name, double* value, const std::string& expected,
                bool required) {
  double number = *value;
  if (!(required ? params.require(name, &number, expected) : params.read(name, &number, expected))) return false;
  if (!std::isfinite(number)) {
    std::ostringstream got;
    got << number;
    return params.fail(name, "expected " + expected + " (finite), got " + got.str());
  }
  *value = number;
  return true;
}

bool readJointName(ros_params::Reader& params, std::string* joint) {
  const std::string expected = "the name of a joint";
  std::string name;
  if (!params.require("joint", &name, expected)) return false;
  if (name.empty()) return params.fail("joint", "expected " + expected + ", got an empty string");
  *joint = name;
  return true;
}

bool readJointNames(ros_params::Reader& params, std::vector<std::string>* joints) {
  const std::string expected = "a list of joint names, e.g. [joint1, joint2]";
  std::vector<std::string> names;
  if (!params.require("joints", &names, expected)) return false;
  if (names.empty()) return params.fail("joints", "expected " + expected + ", got an empty list");
  std::set<std::string> seen;
  for (const std::string& name : names) {
    // A joint listed twice would be commanded twice per update and claimed twice.
    if (!seen.insert(name).second)
      return params.fail("joints", "expected distinct joint names, got '" + name + "' more than once");
  }
  *joints = names;
  return true;
}

bool noProblems(const ros_params::Reader& params, std::string& error) {
  if (params.ok()) return true;
  error = params.problems();
  return false;
}

}  // namespace sim_control
