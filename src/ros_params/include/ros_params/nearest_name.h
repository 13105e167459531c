#pragma once
// The nearest of a set of names to a misspelt one, for "did you mean ...?". ROS-free.
#include <cstddef>
#include <set>
#include <string>

namespace ros_params {

// Levenshtein distance: insertions, deletions and substitutions of one character.
std::size_t editDistance(const std::string& a, const std::string& b);

// The name in `known` fewest edits from `name`, if at most `max_edits` (else ""); ties go to the
// first in order.
std::string nearestName(const std::string& name, const std::set<std::string>& known, std::size_t max_edits = 3);

}  // namespace ros_params
