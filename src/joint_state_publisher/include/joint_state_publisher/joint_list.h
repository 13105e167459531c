#pragma once
// What joint_state_publisher publishes, without ROS: the moving joints of a URDF in document
// order, each free (its own value) or dependent (following another: a <mimic> tag or the
// dependent_joints parameter), and the JointState arrays built from them.
#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace joint_state_publisher {

struct JointListError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

struct Options {
  bool use_mimic_tags = true;
  bool use_smallest_joint_limits = true;  // <safety_controller> soft limits narrow <limit>
  bool publish_default_positions = true;
  bool publish_default_velocities = false;
  bool publish_default_efforts = false;
  std::map<std::string, double> zeros;    // joint -> its default position
  struct Dependent {
    std::string parent;
    double factor = 1.0, offset = 0.0;
  };
  std::map<std::string, Dependent> dependent_joints;
};

struct FreeJoint {
  double min = 0, max = 0, zero = 0;
  bool continuous = false;
  std::optional<double> position, velocity, effort;
  bool forward = true;  // the delta sweep's direction
};

struct JointStateArrays {
  std::vector<std::string> name;
  std::vector<double> position, velocity, effort;  // each empty or one per name
};

class JointList {
 public:
  // Throws JointListError when the XML is not a URDF <robot>, or a mimic chain loops.
  JointList(const std::string& urdf, const Options& options);

  // What was left out, and why, for the node to log once.
  const std::vector<std::string>& warnings() const { return warnings_; }
  const std::vector<std::string>& names() const { return order_; }
  bool isFree(const std::string& name) const { return free_.count(name) > 0; }

  // A source's values for the free joints it names (others are ignored, as upstream).
  void set(const std::string& name, std::optional<double> position, std::optional<double> velocity,
           std::optional<double> effort);
  // The `delta` parameter's sweep: every free joint moves `delta` towards its limit and turns
  // back there (a continuous joint wraps round instead).
  void sweep(double delta);
  JointStateArrays arrays() const;

 private:
  std::vector<std::string> order_;  // published joints, in the URDF's order
  std::map<std::string, FreeJoint> free_;
  std::map<std::string, Options::Dependent> dependent_;  // each resolved to a free joint
  std::vector<std::string> warnings_;
};

}  // namespace joint_state_publisher
