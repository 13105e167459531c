// The mapper's cost per scan on a recorded bag, without the simulator or a ROS master: each scan of
// SCAN_TOPIC goes through the node's own steps (tf from the bag for the laser's pose, scanToPoints,
// SlamProcessor::update), timed as the node times them.
//
//   bench_mapping_bag BAG SCAN_TOPIC BASE_FRAME [_param:=value ...]
//
// The _param:=value pairs are the node's map and filter parameters (map_resolution, map_size,
// map_start_x, map_start_y, map_multi_res_levels, update_factor_free, update_factor_occupied,
// map_update_distance_thresh, map_update_angle_thresh, laser_min_dist, laser_max_dist,
// laser_z_min_value, laser_z_max_value). Prints one line scripts/bench_mapping.py reads:
//   bag: N scans of B beams: mean X ms, max Y ms per scan; final pose x y theta
#include <chrono>
#include <cstdio>
#include <map>
#include <string>

#include <rosbag/bag.h>
#include <rosbag/view.h>
#include <sensor_msgs/LaserScan.h>
#include <tf2/buffer_core.h>
#include <tf2/exceptions.h>
#include <tf2_msgs/TFMessage.h>

#include "hector_style_mapping/ros/scan_conversion.h"
#include "hector_style_mapping/slam_processor.h"

using hector_style_mapping::MapperOptions;
using hector_style_mapping::ScanFilter;

namespace {

bool setParameter(const std::string& name, const std::string& value, MapperOptions* m, ScanFilter* f) {
  std::map<std::string, double*> doubles = {
      {"map_resolution", &m->map_resolution}, {"map_start_x", &m->map_start_x}, {"map_start_y", &m->map_start_y},
      {"update_factor_free", &m->update_factor_free}, {"update_factor_occupied", &m->update_factor_occupied},
      {"map_update_distance_thresh", &m->map_update_distance_thresh},
      {"map_update_angle_thresh", &m->map_update_angle_thresh}, {"laser_min_dist", &f->laser_min_dist},
      {"laser_max_dist", &f->laser_max_dist}, {"laser_z_min_value", &f->laser_z_min_value},
      {"laser_z_max_value", &f->laser_z_max_value}};
  std::map<std::string, int*> ints = {{"map_size", &m->map_size}, {"map_multi_res_levels", &m->map_multi_res_levels}};
  try {
    if (doubles.count(name)) *doubles[name] = std::stod(value);
    else if (ints.count(name)) *ints[name] = std::stoi(value);
    else return false;
  } catch (const std::exception&) {
    return false;
  }
  return true;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 4) {
    std::fprintf(stderr, "usage: bench_mapping_bag BAG SCAN_TOPIC BASE_FRAME [_param:=value ...]\n");
    return 2;
  }
  const std::string bag_path = argv[1], scan_topic = argv[2], base_frame = argv[3];
  MapperOptions options;
  ScanFilter filter;
  for (int i = 4; i < argc; ++i) {
    const std::string arg = argv[i];
    const auto sep = arg.find(":=");
    if (arg.empty() || arg[0] != '_' || sep == std::string::npos ||
        !setParameter(arg.substr(1, sep - 1), arg.substr(sep + 2), &options, &filter)) {
      std::fprintf(stderr, "bench_mapping_bag: '%s': expected _name:=number with a map or filter parameter\n",
                   arg.c_str());
      return 2;
    }
  }
  const std::string problems = hector_style_mapping::validate(options);
  if (!problems.empty()) {
    std::fprintf(stderr, "bench_mapping_bag: %s\n", problems.c_str());
    return 2;
  }

  rosbag::Bag bag;
  try {
    bag.open(bag_path, rosbag::bagmode::Read);
  } catch (const rosbag::BagException& e) {
    std::fprintf(stderr, "bench_mapping_bag: cannot read %s: %s\n", bag_path.c_str(), e.what());
    return 1;
  }
  tf2::BufferCore tf(ros::Duration(600.0));
  hector_style_mapping::SlamProcessor slam(options);
  hector_style_mapping::ScanPoints points;
  long scans = 0, beams = 0, no_tf = 0;
  double total_ms = 0.0, max_ms = 0.0;
  rosbag::View view(bag, rosbag::TopicQuery({scan_topic, "/tf", "/tf_static"}));
  for (const rosbag::MessageInstance& m : view) {
    if (m.getTopic() == "/tf" || m.getTopic() == "/tf_static") {
      const auto transforms = m.instantiate<tf2_msgs::TFMessage>();
      for (const auto& t : transforms->transforms) tf.setTransform(t, "bag", m.getTopic() == "/tf_static");
      continue;
    }
    const auto scan = m.instantiate<sensor_msgs::LaserScan>();
    if (!scan) continue;
    Eigen::Isometry3d laser_in_base = Eigen::Isometry3d::Identity();
    try {
      const auto t = tf.lookupTransform(base_frame, scan->header.frame_id, scan->header.stamp);
      const auto& r = t.transform.rotation;
      laser_in_base.linear() = Eigen::Quaterniond(r.w, r.x, r.y, r.z).normalized().toRotationMatrix();
      laser_in_base.translation() << t.transform.translation.x, t.transform.translation.y, t.transform.translation.z;
    } catch (const tf2::TransformException&) {
      ++no_tf;
      continue;
    }
    const auto start = std::chrono::steady_clock::now();
    hector_style_mapping::scanToPoints(*scan, laser_in_base, filter, &points);
    slam.update(points);
    const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    ++scans;
    beams = static_cast<long>(scan->ranges.size());
    total_ms += ms;
    max_ms = std::max(max_ms, ms);
  }
  if (scans == 0) {
    std::fprintf(stderr, "bench_mapping_bag: no scan of %s in %s could be used (%ld without tf to %s)\n",
                 scan_topic.c_str(), bag_path.c_str(), no_tf, base_frame.c_str());
    return 1;
  }
  std::printf("bag: %ld scans of %ld beams: mean %.3f ms, max %.3f ms per scan; final pose %.3f %.3f %.4f\n", scans,
              beams, total_ms / scans, max_ms, slam.pose().x, slam.pose().y, slam.pose().theta);
  return 0;
}
