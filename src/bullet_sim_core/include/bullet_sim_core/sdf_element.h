#pragma once
// One reader for SDF: the elements of .world and model.sdf files, and the SDF that URDF carries in
// its <gazebo> blocks (sensors, plugins, materials, friction). Every parser, sensor and plugin reads
// through it, so numbers, vectors, poses and booleans are parsed one way (strictly, whatever the C
// locale) and every mistake is reported in one wording:
//
//   <source>: <element path>: expected <form>, got '<text>'
//   m_robot.urdf: <gazebo reference='laser'>/<sensor name='lidar'>/<ray>/<range>/<max>:
//       expected a number > <min> (0.1), got 'far'
//
// An SdfElement is a cheap handle: it shares the parsed document, so it can be kept in a
// ModelDescription and read later by the plugin that owns the element. A handle may be "absent"
// (a child that is not there): reading values from it gives the fallbacks, and its path still names
// where it would be.
#include <tinyxml2.h>

#include <Eigen/Geometry>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace bullet_sim {

// A condition a number must meet and the words that say it, e.g. {v > 0, "> 0"}.
struct NumberCheck {
  std::function<bool(double)> ok;  // empty: any finite number
  std::string expectation;         // "> 0", "in (0, pi) radians", "> <min> (0.1)"
};
NumberCheck positive();                                      // > 0
NumberCheck nonNegative();                                   // >= 0
NumberCheck greaterThan(double bound, const std::string& what);  // > <what> (bound)
NumberCheck atLeast(double bound, const std::string& what);      // >= <what> (bound)

class SdfElement {
 public:
  SdfElement() = default;  // absent, nowhere

  // The root element of `xml`. Throws DescriptionError "<source>: malformed XML at line N: ..."
  // or "<source>: no XML element found".
  static SdfElement parse(const std::string& xml, const std::string& source);

  explicit operator bool() const { return element_ != nullptr; }
  const std::string& source() const { return source_; }
  std::string tag() const;  // "sensor"
  // Where the element is, from the document's top (a <robot> or <sdf> root is left out):
  // "<gazebo reference='laser'>/<sensor name='lidar'>/<ray>".
  std::string path() const;

  std::string attribute(const char* name, const std::string& fallback = "") const;
  bool hasAttribute(const char* name) const;
  std::string text() const;  // trimmed; "" when absent or empty

  SdfElement child(const char* tag) const;  // absent if there is none
  // Throws "<path>: missing required element <tag>" when there is none.
  SdfElement requiredChild(const char* tag) const;
  std::vector<SdfElement> children(const char* tag = nullptr) const;  // all, or those with `tag`
  SdfElement parent() const;
  std::string xml() const;  // the element printed back

  // This element's text as a value. Each throws DescriptionError in the wording above.
  double asNumber(const NumberCheck& check = {}) const;
  std::vector<double> asNumbers(size_t min_count, size_t max_count) const;
  long asInteger(long min, long max) const;
  bool asBoolean() const;  // true/false (any case), 1/0
  Eigen::Vector3d asVector3() const;
  // "x y z roll pitch yaw", fixed-axis RPY (R = Rz(yaw) Ry(pitch) Rx(roll)); degrees='true' honoured.
  Eigen::Isometry3d asPose() const;

  // A child's value, or `fallback` when the child is absent. A fallback that fails `check` is an
  // error too: it may contradict a value given elsewhere (a <far> default below a given <near>).
  double number(const char* tag, double fallback, const NumberCheck& check = {}) const;
  long integer(const char* tag, long fallback, long min, long max) const;
  bool boolean(const char* tag, bool fallback) const;
  std::string string(const char* tag, const std::string& fallback) const;
  // Like string(), but a present child must not be empty (a topic or frame name).
  std::string name(const char* tag, const std::string& fallback) const;
  Eigen::Vector3d vector3(const char* tag, const Eigen::Vector3d& fallback) const;
  Eigen::Isometry3d pose(const char* tag = "pose") const;  // identity when absent

  // Throws DescriptionError "<source>: <path>: <what>".
  [[noreturn]] void fail(const std::string& what) const;

 private:
  SdfElement(std::shared_ptr<const tinyxml2::XMLDocument> doc, const tinyxml2::XMLElement* element,
             const tinyxml2::XMLElement* parent, std::string missing_tag, std::string source);
  [[noreturn]] void expected(const std::string& form) const;  // "expected <form>, got '<text>'"

  std::shared_ptr<const tinyxml2::XMLDocument> doc_;
  const tinyxml2::XMLElement* element_ = nullptr;
  // For an absent child: the element it would be in, and its tag, so that its path is known.
  const tinyxml2::XMLElement* parent_ = nullptr;
  std::string missing_tag_;
  std::string source_;
};

// The plugin library a filename names, without a folder: "/opt/x/libfoo.so" -> "libfoo.so".
std::string pluginLibraryName(const std::string& filename);

// A number for messages, in the C locale with up to 6 significant digits.
std::string formatNumber(double v);

}  // namespace bullet_sim
