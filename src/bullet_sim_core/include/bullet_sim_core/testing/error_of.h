#pragma once
// For tests of what bad input says: the message of the DescriptionError that f() throws.
#include <string>

#include "bullet_sim_core/description_error.h"

namespace bullet_sim {

// The DescriptionError's message, or "" when f() throws none.
template <class F>
std::string errorOf(F f) {
  try {
    f();
  } catch (const DescriptionError& e) {
    return e.what();
  }
  return "";
}

}  // namespace bullet_sim
