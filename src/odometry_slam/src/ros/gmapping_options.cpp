#include "odometry_slam/ros/gmapping_options.h"

#include <cmath>

#include "ros_params/reader.h"

namespace odometry_slam {
namespace {


// gmapping's particle filter and likelihood field, which this node does not have (README.md says why).
const char* const kParticleFilterParameters[] = {
    "particles", "resampleThreshold", "sigma", "kernelSize", "lstep", "astep", "iterations", "lsigma", "ogain",
    "lskip", "minimumScore", "llsamplerange", "llsamplestep", "lasamplerange", "lasamplestep"};
// Accepted and ignored: removed upstream too (the laser's orientation comes from tf).
const char* const kObsoleteParameters[] = {"inverted_laser"};

void readAll(ros_params::Reader& r, GmappingOptions* o) {
  r.read("base_frame", &o->base_frame);
  r.read("map_frame", &o->map_frame);
  r.read("odom_frame", &o->odom_frame);
  r.read("throttle_scans", &o->throttle_scans);
  r.read("map_update_interval", &o->map_update_interval);
  r.read("transform_publish_period", &o->transform_publish_period);
  o->tf_delay = o->transform_publish_period;
  r.read("tf_delay", &o->tf_delay);
  double value = 0.0;
  if (r.read("maxRange", &value)) o->max_range = value;
  if (r.read("maxUrange", &value)) o->max_usable_range = value;
  OdometrySlamOptions& s = o->slam;
  r.read("delta", &s.delta);
  r.read("xmin", &s.xmin);
  r.read("ymin", &s.ymin);
  r.read("xmax", &s.xmax);
  r.read("ymax", &s.ymax);
  r.read("linearUpdate", &s.linear_update);
  r.read("angularUpdate", &s.angular_update);
  r.read("temporalUpdate", &s.temporal_update);
  r.read("srr", &s.srr);
  r.read("srt", &s.srt);
  r.read("str", &s.str);
  r.read("stt", &s.stt);
  r.read("occ_thresh", &s.occ_thresh);
}

}  // namespace

std::string loadGmappingOptions(const ros::NodeHandle& private_nh, GmappingOptions* options) {
  ros_params::Reader reader(private_nh);
  readAll(reader, options);
  for (const char* name : kParticleFilterParameters)
    if (private_nh.hasParam(name)) options->particle_filter_parameters_set.push_back(name);
  if (options->throttle_scans < 1)
    reader.problem("throttle_scans: expected an integer >= 1, got " + std::to_string(options->throttle_scans));
  if (!(options->map_update_interval >= 0.0))
    reader.problem("map_update_interval: expected >= 0 s, got " + std::to_string(options->map_update_interval));
  if (!(options->transform_publish_period >= 0.0))
    reader.problem("transform_publish_period: expected >= 0 s (0: no map -> odom), got " +
                   std::to_string(options->transform_publish_period));
  if (!std::isfinite(options->tf_delay))
    reader.problem("tf_delay: expected a number of seconds, got " + std::to_string(options->tf_delay));
  if (options->max_range && !(*options->max_range > 0.0))
    reader.problem("maxRange: expected > 0 m, got " + std::to_string(*options->max_range));
  if (options->max_usable_range && !(*options->max_usable_range > 0.0))
    reader.problem("maxUrange: expected > 0 m, got " + std::to_string(*options->max_usable_range));
  if (options->base_frame.empty() || options->map_frame.empty() || options->odom_frame.empty())
    reader.problem("base_frame, map_frame, odom_frame: expected frame names, got an empty one");
  if (options->odom_frame == options->base_frame || options->map_frame == options->odom_frame)
    reader.problem("map_frame '" + options->map_frame + "', odom_frame '" + options->odom_frame +
                   "', base_frame '" + options->base_frame + "': expected three different frames (slam_gmapping "
                   "publishes map -> odom and reads odom -> base)");
  const std::string core = validate(options->slam);
  if (!core.empty()) reader.problem(core);
  return reader.problems();
}

std::vector<std::string> unknownGmappingParameters(const ros::NodeHandle& private_nh) {
  ros_params::Reader reader(private_nh);
  GmappingOptions scratch;
  readAll(reader, &scratch);
  std::set<std::string> also(std::begin(kParticleFilterParameters), std::end(kParticleFilterParameters));
  also.insert(std::begin(kObsoleteParameters), std::end(kObsoleteParameters));
  return reader.unknown(also);
}

}  // namespace odometry_slam
