#include "odometry_slam/odometry_slam.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>

#include <Eigen/LU>

#include "hector_style_mapping_core/slam_processor.h"

namespace odometry_slam {

namespace hsm = hector_style_mapping;

namespace {

// The matcher's map: a square of the longer side of the options' area, three levels as hector_mapping.
hsm::MapperOptions mapperOptions(const OdometrySlamOptions& options) {
  const std::string problems = validate(options);
  if (!problems.empty()) throw std::invalid_argument(problems);
  hsm::MapperOptions m;
  m.map_resolution = options.delta;
  const double side = std::max(options.xmax - options.xmin, options.ymax - options.ymin);
  constexpr int kLevels = 3;
  // Whole cells, a multiple of 2^(levels - 1) so every level halves exactly.
  const int multiple = 1 << (kLevels - 1);
  m.map_size = multiple * static_cast<int>(std::ceil(side / options.delta / multiple - 1e-9));
  m.map_start_x = -options.xmin / (m.map_size * options.delta);
  m.map_start_y = -options.ymin / (m.map_size * options.delta);
  m.map_multi_res_levels = kLevels;
  return m;
}

bool hasFinitePoint(const ScanPoints& scan) {
  return std::any_of(scan.points.begin(), scan.points.end(), [](const Eigen::Vector2d& p) { return p.allFinite(); });
}

}  // namespace

std::string validate(const OdometrySlamOptions& o) {
  std::ostringstream out;
  const char* separator = "";
  const auto complain = [&](const char* field, const char* expected, double value) {
    out << separator << field << " must be " << expected << " (got " << value << ")";
    separator = "; ";
  };
  if (!(o.delta > 0.0 && std::isfinite(o.delta))) complain("delta", "> 0", o.delta);
  // The map frame's origin (the odom frame's) must lie in the map.
  if (!(std::isfinite(o.xmin) && o.xmin <= 0.0)) complain("xmin", "finite and <= 0", o.xmin);
  if (!(std::isfinite(o.xmax) && o.xmax > 0.0)) complain("xmax", "finite and > 0", o.xmax);
  if (!(std::isfinite(o.ymin) && o.ymin <= 0.0)) complain("ymin", "finite and <= 0", o.ymin);
  if (!(std::isfinite(o.ymax) && o.ymax > 0.0)) complain("ymax", "finite and > 0", o.ymax);
  if (o.delta > 0.0 && std::isfinite(o.delta)) {
    const double side = std::max(o.xmax - o.xmin, o.ymax - o.ymin) / o.delta;
    if (side > hsm::kMaxMapSize)
      complain("the map", "at most 16384 cells a side ((xmax - xmin) / delta); cells", side);
  }
  if (!(o.linear_update >= 0.0 && std::isfinite(o.linear_update))) complain("linearUpdate", ">= 0", o.linear_update);
  if (!(o.angular_update >= 0.0 && std::isfinite(o.angular_update)))
    complain("angularUpdate", ">= 0", o.angular_update);
  if (std::isnan(o.temporal_update)) complain("temporalUpdate", "a number", o.temporal_update);
  const std::pair<const char*, double> noises[] = {{"srr", o.srr}, {"srt", o.srt}, {"str", o.str}, {"stt", o.stt}};
  for (const auto& [name, value] : noises)
    if (!(value >= 0.0 && std::isfinite(value))) complain(name, ">= 0", value);
  if (!(o.occ_thresh >= 0.0 && o.occ_thresh < 1.0)) complain("occ_thresh", "in [0, 1)", o.occ_thresh);
  return out.str();
}

OdometrySlam::OdometrySlam(const OdometrySlamOptions& options)
    : options_(options), map_(mapperOptions(options)), counts_(map_.finest().sizeX(), map_.finest().sizeY()) {}

void OdometrySlam::reset() {
  map_.clear();
  counts_.clear();
  pose_ = map_to_odom_ = last_odometry_ = processed_odometry_ = Pose2D{};
  covariance_.setZero();
  processed_ = refused_ = 0;
  processed_time_ = travelled_ = turned_ = 0.0;
}

double OdometrySlam::poseEntropy() const {
  const double determinant = covariance_.determinant();
  if (!(determinant > 0.0)) return -std::numeric_limits<double>::infinity();
  return 0.5 * std::log(std::pow(2.0 * M_PI * M_E, 3) * determinant);
}

bool OdometrySlam::due(const Pose2D& odometry, double time) {
  const Pose2D step = hsm::between(last_odometry_, odometry);
  travelled_ += std::hypot(step.x, step.y);
  turned_ += std::abs(step.theta);
  last_odometry_ = odometry;
  return travelled_ >= options_.linear_update || turned_ >= options_.angular_update ||
         (options_.temporal_update >= 0.0 && time - processed_time_ > options_.temporal_update);
}

void OdometrySlam::insert(const ScanPoints& scan, const Pose2D& odometry, double time) {
  map_.updateByScan(scan, pose_);
  counts_.addLastUpdate(map_.finest());
  map_to_odom_ = hsm::compose(pose_, hsm::between(odometry, Pose2D{}));
  processed_odometry_ = odometry;
  processed_time_ = time;
  travelled_ = turned_ = 0.0;
  ++processed_;
}

OdometrySlam::Outcome OdometrySlam::addScan(const ScanPoints& scan, const Pose2D& odometry, double time) {
  if (processed_ == 0) {
    last_odometry_ = odometry;
    pose_ = odometry;  // map frame = odom frame, as gmapping's initial pose
    if (!hasFinitePoint(scan)) return Outcome::kNoPoints;
    insert(scan, odometry, time);
    return Outcome::kFirst;
  }
  const bool process = due(odometry, time);
  pose_ = hsm::compose(map_to_odom_, odometry);
  if (!process) return Outcome::kSkipped;
  if (!hasFinitePoint(scan)) return Outcome::kNoPoints;

  // The odometry's error since the last processed scan, by its error model.
  const Pose2D motion = hsm::between(processed_odometry_, odometry);
  const double distance = std::hypot(motion.x, motion.y);
  const double rotation = std::abs(motion.theta);
  const double translation_sigma = options_.srr * distance + options_.srt * rotation;
  const double rotation_sigma = options_.stt * rotation + options_.str * distance;

  const Pose2D predicted = pose_;
  const hsm::ScanMatchResult matched = hsm::matchThroughLevels(matcher_, map_, scan, predicted);
  const Pose2D correction = hsm::between(predicted, matched.pose);
  const bool accepted =
      matched.point_count > 0 &&
      std::hypot(correction.x, correction.y) <= kGateSigmas * translation_sigma + options_.delta &&
      std::abs(correction.theta) <= kGateSigmas * rotation_sigma + kMinAngleGate;
  if (accepted) {
    pose_ = matched.pose;
    covariance_ = hsm::matchCovariance(matched, matcher_.surfaceNormalHessian(map_.finest(), scan, pose_));
  } else {
    ++refused_;
    const double t2 = std::max(translation_sigma * translation_sigma, options_.delta * options_.delta);
    const double r2 = std::max(rotation_sigma * rotation_sigma, kMinAngleGate * kMinAngleGate);
    covariance_ = Eigen::Vector3d(t2, t2, r2).asDiagonal();
  }
  insert(scan, odometry, time);
  return accepted ? Outcome::kMatched : Outcome::kMatchRefused;
}

}  // namespace odometry_slam
