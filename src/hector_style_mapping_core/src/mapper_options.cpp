#include "hector_style_mapping_core/mapper_options.h"

#include <cmath>
#include <sstream>
#include <vector>

namespace hector_style_mapping {

namespace {

// Collects "field must be ... (got value)" messages.
class Complaints {
 public:
  template <typename T>
  void add(const char* field, const char* expectation, T value) {
    std::ostringstream message;
    message << field << " must be " << expectation << " (got " << value << ")";
    messages_.push_back(message.str());
  }

  std::string joined() const {
    std::string result;
    for (const std::string& message : messages_) {
      if (!result.empty()) {
        result += "; ";
      }
      result += message;
    }
    return result;
  }

 private:
  std::vector<std::string> messages_;
};

}  // namespace

std::string validate(const MapperOptions& options) {
  Complaints complaints;

  // Written as !(good) so that NaN fails every check.
  if (!(options.map_resolution > 0.0 && std::isfinite(options.map_resolution))) {
    complaints.add("map_resolution", "> 0 and finite", options.map_resolution);
  }
  if (!(options.map_size >= 2 && options.map_size <= kMaxMapSize)) {
    complaints.add("map_size", ("in [2, " + std::to_string(kMaxMapSize) + "]").c_str(), options.map_size);
  }
  if (!(options.map_start_x >= 0.0 && options.map_start_x <= 1.0)) {
    complaints.add("map_start_x", "in [0, 1] (a fraction of the map's width)", options.map_start_x);
  }
  if (!(options.map_start_y >= 0.0 && options.map_start_y <= 1.0)) {
    complaints.add("map_start_y", "in [0, 1] (a fraction of the map's height)", options.map_start_y);
  }
  if (!(options.map_multi_res_levels >= 1 && options.map_multi_res_levels <= 8)) {
    complaints.add("map_multi_res_levels", "in [1, 8]", options.map_multi_res_levels);
  } else if (options.map_size >= 2 && options.map_size <= kMaxMapSize) {
    // Every level must cover exactly the finest level's area with whole cells, and keep at least two of them.
    const int coarsest_factor = 1 << (options.map_multi_res_levels - 1);
    if (options.map_size % coarsest_factor != 0 || options.map_size / coarsest_factor < 2) {
      std::ostringstream expectation;
      expectation << "a multiple of 2^(map_multi_res_levels - 1) = " << coarsest_factor
                  << " and at least twice that, so every level covers the same area with whole cells";
      complaints.add("map_size", expectation.str().c_str(), options.map_size);
    }
  }
  // The free factor must stand for "less likely occupied" and the hit factor for "more likely", or the map would
  // learn the opposite of what the laser saw.
  if (!(options.update_factor_free > 0.0 && options.update_factor_free < 0.5)) {
    complaints.add("update_factor_free", "in (0, 0.5)", options.update_factor_free);
  }
  if (!(options.update_factor_occupied > 0.5 && options.update_factor_occupied < 1.0)) {
    complaints.add("update_factor_occupied", "in (0.5, 1)", options.update_factor_occupied);
  }
  if (!(options.map_update_distance_thresh >= 0.0 && std::isfinite(options.map_update_distance_thresh))) {
    complaints.add("map_update_distance_thresh", ">= 0 and finite", options.map_update_distance_thresh);
  }
  if (!(options.map_update_angle_thresh >= 0.0 && std::isfinite(options.map_update_angle_thresh))) {
    complaints.add("map_update_angle_thresh", ">= 0 and finite", options.map_update_angle_thresh);
  }
  if (!(options.search_window_linear >= 0.0 && std::isfinite(options.search_window_linear))) {
    complaints.add("search_window_linear", ">= 0 and finite (m; 0 turns the search off)", options.search_window_linear);
  }
  if (!(options.search_window_angular >= 0.0 && options.search_window_angular <= M_PI)) {
    complaints.add("search_window_angular", "in [0, pi] (rad; 0 turns the search off)", options.search_window_angular);
  }
  if (!(options.search_motion_weight >= 0.0 && std::isfinite(options.search_motion_weight))) {
    complaints.add("search_motion_weight", ">= 0 and finite (per m; 0: no motion prior)", options.search_motion_weight);
  }
  return complaints.joined();
}

}  // namespace hector_style_mapping
