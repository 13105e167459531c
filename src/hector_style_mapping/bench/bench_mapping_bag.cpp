// The mapper's cost per scan on a recorded bag, without the simulator or a ROS master: each scan of
// SCAN_TOPIC goes through the node's own steps (tf from the bag for the laser's pose, scanToPoints,
// SlamProcessor::update), timed as the node times them.
//
//   bench_mapping_bag BAG SCAN_TOPIC BASE_FRAME [--truth ODOM_TOPIC] [--poses CSV] [--map PGM]
//                     [_param:=value ...]
//
// With --truth, ODOM_TOPIC (nav_msgs/Odometry of the base in a fixed frame, e.g. a drive plugin's
// odometrySource world) is the ground truth: the mapper's poses are compared with it at their
// stamps, in the map frame (the truth at the first scan), and the errors are printed too:
//   accuracy: N poses, RMS X mm Y deg, max X mm Y deg, final X mm Y deg
// --poses writes each scan's stamp, the mapper's pose and the truth at that stamp (nan without one); with
//   _loop_closure:=true the poses are the final optimised trajectory (each scan's pose moved with the keyframe
//   it was matched after),
//   "t,x,y,theta,truth_x,truth_y,truth_theta", for other error measures (scripts/bench_radish.py);
// --map writes the final map's known part as a PGM (occupied 0, free 254, unknown 205, as map_server).
//
// The _param:=value pairs are the node's map and filter parameters (map_resolution, map_size,
// map_start_x, map_start_y, map_multi_res_levels, update_factor_free, update_factor_occupied,
// map_update_distance_thresh, map_update_angle_thresh, search_window_linear, search_window_angular,
// search_motion_weight, loop_closure (true/false),
// laser_min_dist, laser_max_dist,
// laser_z_min_value, laser_z_max_value). Prints one line scripts/bench_mapping.py reads:
//   bag: N scans of B beams: mean X ms, max Y ms per scan; final pose x y theta
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <limits>
#include <map>
#include <string>
#include <vector>

#include <rosbag/bag.h>
#include <rosbag/view.h>
#include <nav_msgs/Odometry.h>
#include <sensor_msgs/LaserScan.h>
#include <tf2/buffer_core.h>
#include <tf2/exceptions.h>
#include <tf2/utils.h>
#include <tf2_geometry_msgs/tf2_geometry_msgs.h>
#include <tf2_msgs/TFMessage.h>

#include "hector_style_mapping/ros/scan_conversion.h"
#include "hector_style_mapping_core/anchored_trajectory.h"
#include "hector_style_mapping_core/slam_processor.h"

using hector_style_mapping::MapperOptions;
using hector_style_mapping::ScanFilter;

namespace {

bool setParameter(const std::string& name, const std::string& value, MapperOptions* m, ScanFilter* f) {
  std::map<std::string, double*> doubles = {
      {"map_resolution", &m->map_resolution}, {"map_start_x", &m->map_start_x}, {"map_start_y", &m->map_start_y},
      {"update_factor_free", &m->update_factor_free}, {"update_factor_occupied", &m->update_factor_occupied},
      {"map_update_distance_thresh", &m->map_update_distance_thresh},
      {"map_update_angle_thresh", &m->map_update_angle_thresh},
      {"search_window_linear", &m->search_window_linear}, {"search_window_angular", &m->search_window_angular},
      {"search_motion_weight", &m->search_motion_weight},
      {"laser_min_dist", &f->laser_min_dist},
      {"laser_max_dist", &f->laser_max_dist}, {"laser_z_min_value", &f->laser_z_min_value},
      {"laser_z_max_value", &f->laser_z_max_value}};
  std::map<std::string, int*> ints = {{"map_size", &m->map_size}, {"map_multi_res_levels", &m->map_multi_res_levels}};
  if (name == "loop_closure") {
    m->loop_closure = value == "true" || value == "1";
    return value == "true" || value == "false" || value == "1" || value == "0";
  }
  try {
    if (doubles.count(name)) *doubles[name] = std::stod(value);
    else if (ints.count(name)) *ints[name] = std::stoi(value);
    else return false;
  } catch (const std::exception&) {
    return false;
  }
  return true;
}

struct StampedPose {
  double t;
  hector_style_mapping::Pose2D pose;
};

// The truth at time t: a sample at that stamp (a log's truth comes with each scan), else linearly
// interpolated; false outside the samples or across a gap > 0.1 s.
bool truthAt(const std::vector<StampedPose>& truth, double t, hector_style_mapping::Pose2D* out) {
  const auto after = std::lower_bound(truth.begin(), truth.end(), t,
                                      [](const StampedPose& s, double time) { return s.t < time; });
  if (after != truth.end() && std::abs(after->t - t) < 1e-6) {
    *out = after->pose;
    return true;
  }
  if (after == truth.begin() || after == truth.end()) return false;
  const StampedPose& a = *(after - 1);
  const StampedPose& b = *after;
  if (b.t - a.t > 0.1) return false;
  const double f = b.t > a.t ? (t - a.t) / (b.t - a.t) : 0.0;
  out->x = a.pose.x + f * (b.pose.x - a.pose.x);
  out->y = a.pose.y + f * (b.pose.y - a.pose.y);
  out->theta = a.pose.theta + f * hector_style_mapping::normalizeAngle(b.pose.theta - a.pose.theta);
  return true;
}

// Pose b in the frame of pose a.
hector_style_mapping::Pose2D relative(const hector_style_mapping::Pose2D& a, const hector_style_mapping::Pose2D& b) {
  const double c = std::cos(a.theta), s = std::sin(a.theta), dx = b.x - a.x, dy = b.y - a.y;
  return {c * dx + s * dy, -s * dx + c * dy, hector_style_mapping::normalizeAngle(b.theta - a.theta)};
}

void printAccuracy(const std::vector<StampedPose>& truth, const std::vector<StampedPose>& slam) {
  hector_style_mapping::Pose2D start;
  if (slam.empty() || !truthAt(truth, slam.front().t, &start)) {
    std::printf("accuracy: no ground truth at the first scan\n");
    return;
  }
  double sum_d = 0, sum_a = 0, max_d = 0, max_a = 0, last_d = 0, last_a = 0;
  long n = 0;
  for (const StampedPose& p : slam) {
    hector_style_mapping::Pose2D at;
    if (!truthAt(truth, p.t, &at)) continue;
    const hector_style_mapping::Pose2D expected = relative(start, at);
    last_d = std::hypot(p.pose.x - expected.x, p.pose.y - expected.y);
    last_a = std::abs(hector_style_mapping::normalizeAngle(p.pose.theta - expected.theta));
    if (std::getenv("BENCH_TRACE"))
      std::printf("trace %ld %.2f: %.3f m %.2f deg\n", n, p.t, last_d, (180.0 / M_PI) * last_a);
    sum_d += last_d * last_d;
    sum_a += last_a * last_a;
    max_d = std::max(max_d, last_d);
    max_a = std::max(max_a, last_a);
    ++n;
  }
  const double deg = 180.0 / M_PI;
  std::printf("accuracy: %ld poses, RMS %.1f mm %.2f deg, max %.1f mm %.2f deg, final %.1f mm %.2f deg\n", n,
              1e3 * std::sqrt(sum_d / std::max(n, 1L)), deg * std::sqrt(sum_a / std::max(n, 1L)), 1e3 * max_d,
              deg * max_a, 1e3 * last_d, deg * last_a);
}

// Each accepted loop closure against the logged poses of its two keyframes' scans: how far its relative pose is
// from the true one. A wrong closure bends the map; these say whether any was accepted.
void printClosureErrors(const std::vector<StampedPose>& truth, const std::vector<double>& keyframe_stamps,
                        const std::vector<hector_style_mapping::LoopClosure::Closure>& closures) {
  std::vector<double> errors;
  int wrong = 0;
  for (const auto& c : closures) {
    hector_style_mapping::Pose2D from, to;
    if (!truthAt(truth, keyframe_stamps[static_cast<std::size_t>(c.from)], &from) ||
        !truthAt(truth, keyframe_stamps[static_cast<std::size_t>(c.to)], &to))
      continue;
    const hector_style_mapping::Pose2D off = relative(relative(from, to), c.relative);
    const double d = std::hypot(off.x, off.y), a = std::abs(off.theta);
    errors.push_back(d);
    if (d > 0.3 || a > 3.0 * M_PI / 180.0) ++wrong;
    if (std::getenv("BENCH_TRACE"))
      std::printf("closure %d -> %d score %.3f elsewhere %.3f: %.3f m %.2f deg off\n", c.from, c.to, c.score,
                  c.elsewhere, d, a * 180.0 / M_PI);
  }
  if (errors.empty()) return;
  std::sort(errors.begin(), errors.end());
  std::printf("closures against the logged poses: %zu, median %.3f m, max %.3f m off; %d beyond 0.3 m or 3 deg\n",
              errors.size(), errors[errors.size() / 2], errors.back(), wrong);
}

void writePoses(const std::string& path, const std::vector<StampedPose>& truth, const std::vector<StampedPose>& slam) {
  std::ofstream out(path);
  out << "t,x,y,theta,truth_x,truth_y,truth_theta\n";
  const double nan = std::numeric_limits<double>::quiet_NaN();
  char line[256];
  for (const StampedPose& p : slam) {
    hector_style_mapping::Pose2D at{nan, nan, nan};
    truthAt(truth, p.t, &at);
    std::snprintf(line, sizeof line, "%.6f,%.5f,%.5f,%.6f,%.5f,%.5f,%.6f\n", p.t, p.pose.x, p.pose.y, p.pose.theta,
                  at.x, at.y, at.theta);
    out << line;
  }
  if (!out) std::fprintf(stderr, "bench_mapping_bag: could not write %s\n", path.c_str());
}

// The bounding box of the known cells, as a map_server PGM (top row = largest y).
void writeMap(const std::string& path, const hector_style_mapping::OccupancyGridMap& map) {
  int x0 = map.sizeX(), y0 = map.sizeY(), x1 = -1, y1 = -1;
  for (int y = 0; y < map.sizeY(); ++y)
    for (int x = 0; x < map.sizeX(); ++x)
      if (!map.isUnknown(x, y)) x0 = std::min(x0, x), y0 = std::min(y0, y), x1 = std::max(x1, x), y1 = std::max(y1, y);
  if (x1 < 0) x0 = y0 = x1 = y1 = 0;
  std::ofstream out(path, std::ios::binary);
  out << "P5\n" << (x1 - x0 + 1) << " " << (y1 - y0 + 1) << "\n255\n";
  for (int y = y1; y >= y0; --y)
    for (int x = x0; x <= x1; ++x)
      out.put(static_cast<char>(map.isUnknown(x, y) ? 205 : map.isOccupied(x, y) ? 0 : 254));
  if (!out) std::fprintf(stderr, "bench_mapping_bag: could not write %s\n", path.c_str());
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 4) {
    std::fprintf(stderr, "usage: bench_mapping_bag BAG SCAN_TOPIC BASE_FRAME [--truth ODOM_TOPIC] [--poses CSV] "
                         "[--map PGM] [_param:=value ...]\n");
    return 2;
  }
  const std::string bag_path = argv[1], scan_topic = argv[2], base_frame = argv[3];
  MapperOptions options;
  ScanFilter filter;
  std::string truth_topic, poses_path, map_path;
  for (int i = 4; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "--truth" && i + 1 < argc) {
      truth_topic = argv[++i];
      continue;
    }
    if (arg == "--poses" && i + 1 < argc) {
      poses_path = argv[++i];
      continue;
    }
    if (arg == "--map" && i + 1 < argc) {
      map_path = argv[++i];
      continue;
    }
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
  double last_stamp = 0.0;
  double total_ms = 0.0, max_ms = 0.0;
  std::vector<StampedPose> truth, slam_poses;
  hector_style_mapping::AnchoredTrajectory anchored;  // the poses, moving with their keyframes
  std::vector<double> keyframe_stamps;  // with loop closure: the stamp of each keyframe's scan
  std::vector<std::string> topics = {scan_topic, "/tf", "/tf_static"};
  if (!truth_topic.empty()) topics.push_back(truth_topic);
  rosbag::View view(bag, rosbag::TopicQuery(topics));
  for (const rosbag::MessageInstance& m : view) {
    if (!truth_topic.empty() && m.getTopic() == truth_topic) {
      const auto odometry = m.instantiate<nav_msgs::Odometry>();
      if (odometry)
        truth.push_back({odometry->header.stamp.toSec(),
                         {odometry->pose.pose.position.x, odometry->pose.pose.position.y,
                          tf2::getYaw(odometry->pose.pose.orientation)}});
      continue;
    }
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
    const double stamp = scan->header.stamp.toSec();
    slam.update(points, nullptr, last_stamp > 0.0 && stamp > last_stamp ? stamp - last_stamp : 0.0);
    last_stamp = stamp;
    const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    slam_poses.push_back({scan->header.stamp.toSec(), slam.pose()});
    if (slam.keyframePoses().size() > keyframe_stamps.size()) keyframe_stamps.push_back(stamp);
    anchored.append(slam.pose(), slam.keyframePoses());
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
  std::printf("search: %d of %ld scans matched by the correlative search\n", slam.searchCount(), scans);
  slam.finishLoopClosure();
  const hector_style_mapping::LoopClosureStats loops = slam.loopClosureStats();
  if (options.loop_closure)
    std::printf("loop closure: %d of %d tries closed a loop over %d keyframes (%d good matches refused by the chain "
                "check, %d as ambiguous)\n", static_cast<int>(loops.closures.size()), loops.attempts, loops.keyframes,
                loops.inconsistent, loops.ambiguous);
  std::sort(truth.begin(), truth.end(), [](const StampedPose& a, const StampedPose& b) { return a.t < b.t; });
  // With loop closure the trajectory is the optimised one: each pose moves with its keyframe.
  for (std::size_t i = 0; i < slam_poses.size(); ++i) slam_poses[i].pose = anchored.pose(i, slam.keyframePoses());
  if (!truth_topic.empty()) printAccuracy(truth, slam_poses);
  if (!truth_topic.empty() && options.loop_closure)
    printClosureErrors(truth, keyframe_stamps, loops.closures);
  if (!poses_path.empty()) writePoses(poses_path, truth, slam_poses);
  if (!map_path.empty()) writeMap(map_path, slam.map().finest());
  return 0;
}
