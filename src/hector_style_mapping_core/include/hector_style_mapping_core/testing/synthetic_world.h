#ifndef HECTOR_STYLE_MAPPING_CORE_TESTING_SYNTHETIC_WORLD_H
#define HECTOR_STYLE_MAPPING_CORE_TESTING_SYNTHETIC_WORLD_H

// A 2D world of wall segments and a laser that ray-casts against it, so the SLAM core can be tested against
// ground truth without a simulator.

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include <Eigen/Core>

#include "hector_style_mapping_core/mapper_options.h"
#include "hector_style_mapping_core/pose_2d.h"
#include "hector_style_mapping_core/scan_points.h"

namespace hector_style_mapping {
namespace testing {

constexpr double kDegree = M_PI / 180.0;

// The lecture's m_robot setting: 5 cm cells, 2 levels.
inline MapperOptions robotOptions() {
  MapperOptions options;
  options.map_resolution = 0.05;
  options.map_size = 512;
  options.map_multi_res_levels = 2;
  return options;
}

struct Segment {
  Eigen::Vector2d a;
  Eigen::Vector2d b;
};

struct LaserConfig {
  int beams = 720;                        // spread evenly over the full circle
  double min_range = 0.1;                 // m; shorter hits are dropped, as the node's range filter would
  double max_range = 10.0;                // m; beams hitting nothing closer are dropped
  double range_noise_sigma = 0.0;         // m, gaussian, added to every range
  Eigen::Vector2d mount{0.0, 0.0};        // laser position in the base frame (not rotated)
};

class SyntheticWorld {
 public:
  void addWall(const Eigen::Vector2d& a, const Eigen::Vector2d& b) { walls_.push_back({a, b}); }

  // The four walls of an axis-aligned rectangle.
  void addBox(const Eigen::Vector2d& min, const Eigen::Vector2d& max) {
    addWall({min.x(), min.y()}, {max.x(), min.y()});
    addWall({max.x(), min.y()}, {max.x(), max.y()});
    addWall({max.x(), max.y()}, {min.x(), max.y()});
    addWall({min.x(), max.y()}, {min.x(), min.y()});
  }

  // Every wall turned by `angle` about the world origin.
  SyntheticWorld rotated(double angle) const {
    SyntheticWorld result;
    const Pose2D turn{0.0, 0.0, angle};
    for (const Segment& wall : walls_) {
      result.addWall(transformPoint(turn, wall.a), transformPoint(turn, wall.b));
    }
    return result;
  }

  const std::vector<Segment>& walls() const { return walls_; }

  // Distance from `from` along unit direction `direction` to the nearest wall, infinity if none.
  double castRay(const Eigen::Vector2d& from, const Eigen::Vector2d& direction) const {
    double nearest = std::numeric_limits<double>::infinity();
    for (const Segment& wall : walls_) {
      const Eigen::Vector2d edge = wall.b - wall.a;
      const double denominator = cross(direction, edge);
      if (std::abs(denominator) < 1e-12) {
        continue;  // parallel
      }
      const Eigen::Vector2d to_wall = wall.a - from;
      const double distance = cross(to_wall, edge) / denominator;
      const double along_wall = cross(to_wall, direction) / denominator;
      if (distance > 0.0 && along_wall >= 0.0 && along_wall <= 1.0) {
        nearest = std::min(nearest, distance);
      }
    }
    return nearest;
  }

  // A scan taken with the robot's base at `pose` (world = map frame), points in the base frame. Noise comes from
  // `rng` when the config asks for it.
  ScanPoints scan(const Pose2D& pose, const LaserConfig& config, std::mt19937* rng = nullptr) const {
    ScanPoints result;
    result.origin = config.mount;
    result.points.reserve(static_cast<std::size_t>(config.beams));
    const Eigen::Vector2d laser_in_world = transformPoint(pose, config.mount);
    std::normal_distribution<double> noise(0.0, config.range_noise_sigma);
    for (int beam = 0; beam < config.beams; ++beam) {
      const double angle_in_base = -M_PI + 2.0 * M_PI * beam / config.beams;
      const double angle_in_world = pose.theta + angle_in_base;
      double range = castRay(laser_in_world, {std::cos(angle_in_world), std::sin(angle_in_world)});
      if (config.range_noise_sigma > 0.0 && rng != nullptr && std::isfinite(range)) {
        range += noise(*rng);
      }
      if (!(range >= config.min_range && range <= config.max_range)) {
        continue;
      }
      result.points.push_back(config.mount +
                              range * Eigen::Vector2d(std::cos(angle_in_base), std::sin(angle_in_base)));
    }
    return result;
  }

 private:
  static double cross(const Eigen::Vector2d& a, const Eigen::Vector2d& b) { return a.x() * b.y() - a.y() * b.x(); }

  std::vector<Segment> walls_;
};

// A 6 m x 5 m room (x in [-1.5, 4.5], y in [-2, 3]) with a few interior walls, like a small maze. The map frame's
// origin, where the robot starts, is in free space. Wall coordinates avoid round numbers so walls do not line up
// with cell boundaries or centres.
inline SyntheticWorld smallMaze() {
  SyntheticWorld world;
  world.addBox({-1.53, -2.07}, {4.46, 3.04});
  world.addWall({1.21, -2.07}, {1.21, -0.83});   // stub from the south wall
  world.addWall({-1.53, 1.13}, {0.52, 1.13});    // shelf from the west wall
  world.addWall({2.37, 0.71}, {2.37, 3.04});     // stub from the north wall
  world.addWall({3.12, -0.64}, {4.46, -0.64});   // shelf from the east wall
  world.addBox({1.55, 1.47}, {1.83, 1.79});      // a pillar
  world.addWall({-0.91, -1.42}, {-0.28, -0.97}); // a slanted board
  return world;
}

// A straight corridor along +x, `width` wide, centred on the x axis, much longer than the laser's range and with
// nothing in it.
// Robot poses along `waypoints` as a unicycle would drive them from `start`: each step turns towards the next
// waypoint by at most `max_turn` and, unless it is still facing more than 0.5 rad away (then it turns on the
// spot), moves `step_length` forward. The start pose is the first element.
inline std::vector<Pose2D> driveThrough(const Pose2D& start, const std::vector<Eigen::Vector2d>& waypoints,
                                        double step_length, double max_turn) {
  std::vector<Pose2D> poses{start};
  Pose2D pose = start;
  for (const Eigen::Vector2d& waypoint : waypoints) {
    while (std::hypot(waypoint.x() - pose.x, waypoint.y() - pose.y) > step_length) {
      const double heading = std::atan2(waypoint.y() - pose.y, waypoint.x() - pose.x);
      const double error = angleDifference(heading, pose.theta);
      pose.theta = normalizeAngle(pose.theta + std::clamp(error, -max_turn, max_turn));
      const double forward = std::abs(error) > 0.5 ? 0.0 : step_length;
      pose.x += forward * std::cos(pose.theta);
      pose.y += forward * std::sin(pose.theta);
      poses.push_back(pose);
    }
  }
  return poses;
}

inline SyntheticWorld longCorridor(double length = 60.0, double width = 2.0) {
  SyntheticWorld world;
  world.addWall({-length / 2, -width / 2}, {length / 2, -width / 2});
  world.addWall({-length / 2, width / 2}, {length / 2, width / 2});
  return world;
}

}  // namespace testing
}  // namespace hector_style_mapping

#endif  // HECTOR_STYLE_MAPPING_CORE_TESTING_SYNTHETIC_WORLD_H
