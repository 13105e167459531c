#pragma once
// The one error type every parser and builder throws for bad input. The message names the
// file (or service request), the element or field, and what was expected, e.g.
//   "/tmp/bad.world: <model name='box'>/<link>/<collision>/<geometry>: expected one of box, cylinder, sphere, plane, mesh".
#include <stdexcept>
#include <string>

namespace bullet_sim {

class DescriptionError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace bullet_sim
