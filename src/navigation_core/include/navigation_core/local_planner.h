#pragma once
// A local planner after base_local_planner's trajectory rollout and DWA: sample velocities the
// robot can reach, simulate each for sim_time, drop those whose footprint would touch an obstacle,
// or pass a cell cut off from the path or the local goal, and score the rest by how far they end
// from the global path and from the local goal and by the costs they pass over; the cheapest is the
// command. No way to the local goal at all (the plan blocked): no command.
//
//   score = path_distance_bias * path distance + goal_distance_bias * goal distance
//           + occdist_scale * highest footprint cost
//
// Distances are counted in cells over the costmap around obstacles (in metres with meter_scoring),
// 8-connected where base_local_planner's map grid is 4-connected (local_planner.cpp says why).
#include <cmath>
#include <string>
#include <vector>

#include "navigation_core/costmap.h"
#include "navigation_core/footprint.h"

namespace navigation_core {

struct Velocity2 {
  double x = 0.0, y = 0.0, theta = 0.0;  // in the robot's frame
};

struct LocalPlannerOptions {  // base_local_planner's TrajectoryPlannerROS parameters and defaults
  double max_vel_x = 0.5, min_vel_x = 0.1;
  double max_vel_theta = 1.0, min_vel_theta = -1.0;
  double min_in_place_vel_theta = 0.4;
  // dwa_local_planner's min_vel_trans: a sample slower than this that also turns slower than
  // min_in_place_vel_theta is no move at all and is not considered (standing still would otherwise
  // beat turning towards a path behind the robot). 0: TrajectoryPlannerROS, whose min_vel_x does it.
  double min_vel_trans = 0.0;
  double heading_lookahead = 0.325;  // m: turning in place, look this far ahead along the heading
  double acc_lim_x = 2.5, acc_lim_theta = 3.2;
  double escape_vel = -0.1;  // backing out when nothing else is safe
  double sim_time = 1.0, sim_granularity = 0.025, angular_sim_granularity = 0.025;
  int vx_samples = 3, vtheta_samples = 20;
  bool dwa = true;           // the window is what the accelerations reach in one control period
  double sim_period = 0.05;  // s: 1 / move_base's controller_frequency
  double path_distance_bias = 0.6, goal_distance_bias = 0.8, occdist_scale = 0.01;
  bool meter_scoring = false;
};

struct Trajectory {
  Velocity2 velocity;
  std::vector<Pose2> poses;
  // Negative: the footprint would touch an obstacle somewhere along it (-1), or it passes a free
  // cell from which no way leads round the obstacles to the path or the goal (-2).
  double cost = -1.0;
};

class LocalPlanner {
 public:
  explicit LocalPlanner(const LocalPlannerOptions& options);

  // The command for the robot at `pose` moving at `velocity`, following `plan` (world points in
  // the costmap's frame, robot first). False, with the reason, when no sampled trajectory is safe
  // or no way leads to the local goal.
  bool computeVelocity(const Costmap& costmap, const Footprint& footprint, const Pose2& pose,
                       const Velocity2& velocity, const std::vector<Point2>& plan, Trajectory& best,
                       std::string* why);

  // One trajectory at a constant command from `pose`, scored against the distance grids of the
  // last computeVelocity (for tests and the local_plan topic).
  Trajectory simulate(const Costmap& costmap, const Footprint& footprint, const Pose2& pose,
                      const Velocity2& command) const;

  // The highest cost under the footprint's outline and centre at `pose`, or -1 if they touch an
  // obstacle (lethal or unknown cells, off the map), as base_local_planner checks a polygon.
  static double footprintCost(const Costmap& costmap, const Footprint& footprint, const Pose2& pose);
  // The same with the heading's cosine and sine given (the trajectory simulation has them).
  static double footprintCost(const Costmap& costmap, const Footprint& footprint, const Pose2& pose, double cos_theta,
                              double sin_theta);

 private:
  // One constant command's poses over sim_time, with each pose's heading cosine and sine.
  struct Rollout {
    Velocity2 command;
    std::vector<Pose2> poses;
    std::vector<double> cos_theta, sin_theta;
  };

  void distanceGrid(const Costmap& costmap, const std::vector<unsigned>& seeds, std::vector<double>& out) const;
  // A command worth a trajectory: not slower than min_vel_trans and min_in_place_vel_theta both.
  bool isAMove(double vx, double vtheta) const {
    return !(std::abs(vx) < options_.min_vel_trans && std::abs(vtheta) < options_.min_in_place_vel_theta);
  }
  Rollout rollout(const Pose2& pose, const Velocity2& command) const;
  // The rollout's footprints checked in turn: the trajectory as far as it is safe, and its cost.
  Trajectory check(const Costmap& costmap, const Footprint& footprint, const Rollout& rollout) const;
  // Whether the distance grids are this costmap's (computeVelocity made them).
  bool scored(const Costmap& costmap) const;
  double score(const Costmap& costmap, unsigned end_cell, double highest_cost) const;
  // The least the rollout can score from a few of its footprints' cells (check() looks at them
  // all); infinity when those already make it invalid.
  double lowestScore(const Costmap& costmap, const Footprint& footprint, const Rollout& rollout) const;

  LocalPlannerOptions options_;
  std::vector<double> path_distance_, goal_distance_;
  // distanceGrid's working memory, kept from call to call: its distances in integer steps, and its
  // bucket queue (one bucket per distance modulo the longest step + 1).
  static constexpr unsigned kDistanceBuckets = 8;
  mutable std::vector<unsigned> scratch_distance_;
  mutable std::vector<unsigned> scratch_buckets_[kDistanceBuckets];
};

}  // namespace navigation_core
