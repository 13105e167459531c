#include "pioneer_ros/controller_params.h"

#include <cmath>
#include <optional>
#include <sstream>
#include <vector>

namespace pioneer_ros {
namespace {

using XmlRpc::XmlRpcValue;

// "<ns>/<name>" without doubling the slash of the root namespace "/".
std::string join(const std::string& ns, const std::string& name) {
  return (!ns.empty() && ns.back() == '/' ? ns : ns + "/") + name;
}

// A value as a message shows it after "got": "the string 'fast'", "true", "a list of 2 items".
std::string describe(XmlRpcValue value) {  // by value: XmlRpcValue's casts are not const
  std::ostringstream out;
  switch (value.getType()) {
    case XmlRpcValue::TypeString: out << "the string '" << static_cast<std::string&>(value) << "'"; break;
    case XmlRpcValue::TypeInt: out << static_cast<int>(value); break;
    case XmlRpcValue::TypeDouble: out << static_cast<double>(value); break;
    case XmlRpcValue::TypeBoolean: out << (static_cast<bool>(value) ? "true" : "false"); break;
    case XmlRpcValue::TypeArray: out << "a list of " << value.size() << " items"; break;
    case XmlRpcValue::TypeStruct: out << "a dictionary"; break;
    default: out << "a value of another type"; break;
  }
  return out.str();
}

class TreeReader {
 public:
  TreeReader(const XmlRpcValue& tree, const std::string& ns) : tree_(tree), ns_(ns) {}

  // Sets `value` from the number at `path` when there is one.
  void read(const std::vector<std::string>& path, double& value) const {
    std::optional<double> found;
    read(path, found);
    if (found) value = *found;
  }

  void read(const std::vector<std::string>& path, std::optional<double>& value) const {
    const XmlRpcValue* node = &tree_;
    std::string where = ns_;
    for (const std::string& key : path) {
      if (node->getType() != XmlRpcValue::TypeStruct)
        throw BadParameter(where + ": expected a dictionary, got " + describe(*node));
      if (!node->hasMember(key)) return;
      node = &(*node)[key];
      where = join(where, key);
    }
    XmlRpcValue leaf = *node;
    double number;
    // An int is a number (yaml "rate: 20"); a bool or a string is not, whatever Python would make of it.
    if (leaf.getType() == XmlRpcValue::TypeInt) number = static_cast<int>(leaf);
    else if (leaf.getType() == XmlRpcValue::TypeDouble) number = static_cast<double>(leaf);
    else throw BadParameter(where + ": expected a number, got " + describe(leaf));
    if (std::isnan(number)) throw BadParameter(where + ": expected a number, got NaN");
    value = number;
  }

 private:
  const XmlRpcValue& tree_;
  const std::string& ns_;
};

void readAxis(const TreeReader& reader, const std::string& axis, AxisConfig& config) {
  reader.read({"controller_gains", "body", axis, "p"}, config.p);
  reader.read({"controller_gains", "body", axis, "i"}, config.i);
  reader.read({"controller_gains", "body", axis, "d"}, config.d);
  reader.read({"controller_gains", "body", axis, "i_clamp"}, config.i_clamp);
  reader.read({"feedforward", axis}, config.feedforward);
  reader.read({"limits", axis}, config.limit);
}

}  // namespace

ControllerConfig configFromParams(const XmlRpc::XmlRpcValue& tree, const std::string& ns) {
  ControllerConfig config;
  // Nothing set at all: ros::param::get leaves the value invalid; that is an empty tree.
  if (tree.getType() != XmlRpcValue::TypeInvalid) {
    const TreeReader reader(tree, ns);
    readAxis(reader, "linear", config.linear);
    readAxis(reader, "angular", config.angular);
    reader.read({"derivative_filter_time"}, config.derivative_filter_time);
    reader.read({"rate"}, config.rate);
    reader.read({"cmd_timeout"}, config.cmd_timeout);
    reader.read({"odom_timeout"}, config.odom_timeout);
  }
  const std::string problem = validate(config);
  if (!problem.empty()) throw BadParameter(join(ns, problem));
  return config;
}

}  // namespace pioneer_ros
