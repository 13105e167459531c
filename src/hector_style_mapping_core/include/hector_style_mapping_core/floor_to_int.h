#ifndef HECTOR_STYLE_MAPPING_CORE_FLOOR_TO_INT_H
#define HECTOR_STYLE_MAPPING_CORE_FLOOR_TO_INT_H

namespace hector_style_mapping {

// static_cast<int>(std::floor(v)) without the library call that x86-64's baseline (no SSE4.1 rounding
// instruction) makes of std::floor; the same result for every v within int's range. The grids' cell lookups
// are the mapper's innermost loops.
inline int floorToInt(double v) {
  const int truncated = static_cast<int>(v);
  return truncated - (v < truncated);
}

}  // namespace hector_style_mapping

#endif  // HECTOR_STYLE_MAPPING_CORE_FLOOR_TO_INT_H
