#ifndef PIONEER_ROS_SRC_NUMBERS_H
#define PIONEER_ROS_SRC_NUMBERS_H

// Small number helpers the controllers share (private to the library's sources).
#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>

namespace pioneer_ros {
namespace numbers {

// Not std::clamp: its behaviour is undefined for low > high and for NaN bounds.
inline double clampTo(double value, double low, double high) { return std::max(low, std::min(high, value)); }

// A value as an error message prints it.
inline std::string number(double value) {
  if (std::isnan(value)) return "nan";  // not glibc's "-nan" for a NaN with its sign bit set
  std::ostringstream out;
  out << value;
  return out.str();
}

}  // namespace numbers
}  // namespace pioneer_ros

#endif  // PIONEER_ROS_SRC_NUMBERS_H
