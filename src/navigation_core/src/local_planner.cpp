#include "navigation_core/local_planner.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <stdexcept>
#include <utility>

#include "navigation_core/cost_values.h"
#include "navigation_core/outline_cells.h"

namespace navigation_core {
namespace {

constexpr double kUnreachable = 1e9;  // cells: no way round the obstacles to the path or goal

bool blocksTheGrid(std::uint8_t cost) { return cost >= kInscribedInflatedObstacle; }

// Whether the free cells nearest to cell (mx, my) (itself if free, else the nearest ring of cells
// round it that holds a free one) include one with a way to the goal.
bool aWayOutFrom(const Costmap& costmap, const std::vector<double>& goal_distance, unsigned mx, unsigned my) {
  const int nx = static_cast<int>(costmap.sizeX()), ny = static_cast<int>(costmap.sizeY());
  const std::vector<std::uint8_t>& costs = costmap.costs();
  for (int r = 0; r < std::max(nx, ny); ++r) {
    bool any_free = false;
    for (int y = static_cast<int>(my) - r; y <= static_cast<int>(my) + r; ++y) {
      for (int x = static_cast<int>(mx) - r; x <= static_cast<int>(mx) + r; ++x) {
        const bool on_ring = std::abs(x - static_cast<int>(mx)) == r || std::abs(y - static_cast<int>(my)) == r;
        if (!on_ring || x < 0 || y < 0 || x >= nx || y >= ny) continue;
        const std::size_t i = costmap.index(static_cast<unsigned>(x), static_cast<unsigned>(y));
        if (blocksTheGrid(costs[i])) continue;
        if (goal_distance[i] < kUnreachable) return true;
        any_free = true;
      }
    }
    if (any_free) return false;
  }
  return true;  // no free cell at all: the footprint checks decide
}

void requirePositive(double value, const char* name) {
  if (!(value > 0) || !std::isfinite(value))
    throw std::invalid_argument(std::string("local planner: ") + name + ": expected a number > 0, got " +
                                std::to_string(value));
}

}  // namespace

LocalPlanner::LocalPlanner(const LocalPlannerOptions& options) : options_(options) {
  requirePositive(options.sim_time, "sim_time");
  requirePositive(options.sim_granularity, "sim_granularity");
  requirePositive(options.angular_sim_granularity, "angular_sim_granularity");
  requirePositive(options.sim_period, "the control period (controller_frequency)");
  if (options.vx_samples < 1 || options.vtheta_samples < 1)
    throw std::invalid_argument("local planner: vx_samples and vtheta_samples: expected at least 1");
  if (options.min_vel_x > options.max_vel_x || options.min_vel_theta > options.max_vel_theta)
    throw std::invalid_argument("local planner: a minimum velocity is above its maximum");
}

void LocalPlanner::distanceGrid(const Costmap& costmap, const std::vector<unsigned>& seeds,
                                std::vector<double>& out) const {
  // Shortest paths over 8-connected cells around obstacles, straight steps 5 and diagonal ones 7
  // (1.4, within 1 % of sqrt 2): within 8 % of the Euclidean distance, where base_local_planner's
  // 4-connected count is the Manhattan one and makes a robot heading diagonally to its goal look as
  // well placed as one heading straight at it. Integer weights let a bucket queue (Dial's
  // algorithm) replace a heap: linear in the window.
  constexpr unsigned kStraight = 5, kDiagonal = 7;
  constexpr unsigned kNone = std::numeric_limits<unsigned>::max();
  const unsigned nx = costmap.sizeX(), ny = costmap.sizeY();
  const std::vector<std::uint8_t>& costs = costmap.costs();
  std::vector<unsigned>& distance = scratch_distance_;  // kept between calls: no allocation per cycle
  distance.assign(costs.size(), kNone);
  for (std::vector<unsigned>& bucket : scratch_buckets_) bucket.clear();
  for (const unsigned s : seeds) {
    if (distance[s] == 0) continue;
    distance[s] = 0;
    scratch_buckets_[0].push_back(s);
  }
  const int row = static_cast<int>(nx);
  const int offsets[8] = {-1, 1, -row, row, -row - 1, -row + 1, row - 1, row + 1};
  const unsigned steps[8] = {kStraight, kStraight, kStraight, kStraight, kDiagonal, kDiagonal, kDiagonal, kDiagonal};
  const auto relax = [&](unsigned m, unsigned next) {
    if (blocksTheGrid(costs[m]) || next >= distance[m]) return;
    distance[m] = next;
    scratch_buckets_[next % kDistanceBuckets].push_back(m);
  };
  std::size_t waiting = scratch_buckets_[0].size();
  for (unsigned d = 0; waiting > 0; ++d) {
    std::vector<unsigned>& bucket = scratch_buckets_[d % kDistanceBuckets];
    for (std::size_t k = 0; k < bucket.size(); ++k) {
      const unsigned n = bucket[k];
      if (distance[n] != d) continue;  // reached more cheaply since
      const unsigned x = n % nx, y = n / nx;
      if (x > 0 && y > 0 && x + 1 < nx && y + 1 < ny) {  // inside the border: all eight neighbours
        for (int i = 0; i < 8; ++i) relax(static_cast<unsigned>(static_cast<int>(n) + offsets[i]), d + steps[i]);
      } else {
        for (int dy = -1; dy <= 1; ++dy) {
          for (int dx = -1; dx <= 1; ++dx) {
            if ((dx == 0 && dy == 0) || (dx < 0 && x == 0) || (dy < 0 && y == 0) || (dx > 0 && x + 1 == nx) ||
                (dy > 0 && y + 1 == ny))
              continue;
            relax(static_cast<unsigned>(static_cast<int>(n) + dy * row + dx), d + (dx != 0 && dy != 0 ? kDiagonal : kStraight));
          }
        }
      }
    }
    waiting = 0;
    bucket.clear();
    for (const std::vector<unsigned>& b : scratch_buckets_) waiting += b.size();
  }
  out.resize(costs.size());
  for (std::size_t i = 0; i < costs.size(); ++i)
    out[i] = distance[i] == kNone ? kUnreachable : static_cast<double>(distance[i]) / kStraight;
}

double LocalPlanner::footprintCost(const Costmap& costmap, const Footprint& footprint, const Pose2& pose) {
  return footprintCost(costmap, footprint, pose, std::cos(pose.theta), std::sin(pose.theta));
}

double LocalPlanner::footprintCost(const Costmap& costmap, const Footprint& footprint, const Pose2& pose,
                                   double cos_theta, double sin_theta) {
  unsigned cx, cy;
  if (!costmap.worldToMap(pose.x, pose.y, cx, cy)) return -1.0;
  const std::vector<std::uint8_t>& costs = costmap.costs();
  const std::uint8_t centre = costs[costmap.index(cx, cy)];
  // As base_local_planner's polygon check: lethal or unknown under the centre or the outline. An
  // inscribed centre alone (the robot pushed near a wall, e.g. by slip) does not forbid a move,
  // else nothing could get it out again.
  if (centre == kLethalObstacle || centre == kNoInformation) return -1.0;
  std::uint8_t highest = centre;
  const bool clear = forEachOutlineCell(costmap, footprint, pose, cos_theta, sin_theta, [&](unsigned cell) {
    const std::uint8_t cost = costs[cell];
    if (cost == kLethalObstacle || cost == kNoInformation) return false;
    highest = std::max(highest, cost);
    return true;
  });
  return clear ? highest : -1.0;
}

LocalPlanner::Rollout LocalPlanner::rollout(const Pose2& pose, const Velocity2& command) const {
  Rollout r;
  r.command = command;
  const double distance = std::abs(command.x) * options_.sim_time;
  const double angle = std::abs(command.theta) * options_.sim_time;
  const int steps = std::max(1, static_cast<int>(std::ceil(std::max(distance / options_.sim_granularity,
                                                                    angle / options_.angular_sim_granularity))));
  const double dt = options_.sim_time / steps;
  r.poses.reserve(steps);
  r.cos_theta.reserve(steps);
  r.sin_theta.reserve(steps);
  Pose2 p = pose;
  double c = std::cos(p.theta), s = std::sin(p.theta);
  for (int k = 0; k < steps; ++k) {
    p.x += command.x * c * dt;
    p.y += command.x * s * dt;
    p.theta += command.theta * dt;
    if (command.theta != 0.0) c = std::cos(p.theta), s = std::sin(p.theta);
    r.poses.push_back(p);
    r.cos_theta.push_back(c);
    r.sin_theta.push_back(s);
  }
  return r;
}

bool LocalPlanner::scored(const Costmap& costmap) const { return path_distance_.size() == costmap.costs().size(); }

double LocalPlanner::score(const Costmap& costmap, unsigned end_cell, double highest) const {
  const double scale = options_.meter_scoring ? costmap.resolution() : 1.0;
  return options_.path_distance_bias * scale * path_distance_[end_cell] +
         options_.goal_distance_bias * scale * goal_distance_[end_cell] + options_.occdist_scale * highest;
}

double LocalPlanner::lowestScore(const Costmap& costmap, const Footprint& footprint, const Rollout& r) const {
  constexpr double kNever = std::numeric_limits<double>::infinity();
  unsigned end_x, end_y;
  if (!scored(costmap) || r.poses.empty() || !costmap.worldToMap(r.poses.back().x, r.poses.back().y, end_x, end_y))
    return kNever;
  // The cells under each pose's centre and corners: a few of the outline's, checked as check()
  // does. One that fails there fails there too (or earlier); the highest of their costs is at
  // most the footprints' highest.
  const std::vector<std::uint8_t>& costs = costmap.costs();
  const auto fails = [](std::uint8_t cost) { return cost == kLethalObstacle || cost == kNoInformation; };
  std::uint8_t highest = 0;
  for (std::size_t k = 0; k < r.poses.size(); ++k) {
    const Pose2& p = r.poses[k];
    unsigned cx, cy;
    if (!costmap.worldToMap(p.x, p.y, cx, cy)) return kNever;
    const unsigned centre = costmap.index(cx, cy);
    if (fails(costs[centre])) return kNever;
    if (!blocksTheGrid(costs[centre]) && (path_distance_[centre] >= kUnreachable || goal_distance_[centre] >= kUnreachable))
      return kNever;
    highest = std::max(highest, costs[centre]);
    for (const Point2& v : footprint) {
      int vx, vy;
      if (!outlineVertexCell(costmap, p, r.cos_theta[k], r.sin_theta[k], v, vx, vy)) return kNever;
      const std::uint8_t cost = costs[costmap.index(static_cast<unsigned>(vx), static_cast<unsigned>(vy))];
      if (fails(cost)) return kNever;
      highest = std::max(highest, cost);
    }
  }
  // With occdist_scale >= 0 the rest of the outline can only add to the score (and adding a
  // non-negative number never rounds below the sum without it).
  if (options_.occdist_scale < 0) return -kNever;
  return score(costmap, costmap.index(end_x, end_y), highest);
}

Trajectory LocalPlanner::check(const Costmap& costmap, const Footprint& footprint, const Rollout& r) const {
  Trajectory t;
  t.velocity = r.command;
  const bool with_scores = scored(costmap);
  double highest = 0.0;
  for (std::size_t k = 0; k < r.poses.size(); ++k) {
    const Pose2& p = r.poses[k];
    const double cost = footprintCost(costmap, footprint, p, r.cos_theta[k], r.sin_theta[k]);
    if (cost < 0) return t;  // cost stays -1: unsafe
    unsigned cx, cy;
    if (with_scores && costmap.worldToMap(p.x, p.y, cx, cy)) {
      // As base_local_planner: a free cell with no way round the obstacles to the path or the
      // goal makes the trajectory invalid (inscribed cells are let through: see footprintCost).
      const unsigned i = costmap.index(cx, cy);
      if (!blocksTheGrid(costmap.costs()[i]) && (path_distance_[i] >= kUnreachable || goal_distance_[i] >= kUnreachable)) {
        t.cost = -2.0;
        return t;
      }
    }
    highest = std::max(highest, cost);
    t.poses.push_back(p);
  }
  unsigned mx, my;
  if (!with_scores || r.poses.empty() || !costmap.worldToMap(r.poses.back().x, r.poses.back().y, mx, my)) return t;
  t.cost = score(costmap, costmap.index(mx, my), highest);
  return t;
}

Trajectory LocalPlanner::simulate(const Costmap& costmap, const Footprint& footprint, const Pose2& pose,
                                  const Velocity2& command) const {
  return check(costmap, footprint, rollout(pose, command));
}

bool LocalPlanner::computeVelocity(const Costmap& costmap, const Footprint& footprint, const Pose2& pose,
                                   const Velocity2& velocity, const std::vector<Point2>& plan, Trajectory& best,
                                   std::string* why) {
  const auto fail = [&](const std::string& reason) {
    if (why) *why = reason;
    return false;
  };
  // The path's cells (every half cell along it) and the local goal: as base_local_planner's map
  // grid, the path as far as it first leaves the costmap, and its last cell there. (A plan that
  // leaves the window round a wall's end and comes back in beyond the wall would otherwise put the
  // local goal where no way inside the window leads.)
  std::vector<unsigned> path_cells;
  unsigned goal_cell = 0;
  bool has_goal = false, left = false;
  for (std::size_t k = 0; k < plan.size() && !left; ++k) {
    const Point2& b = plan[k];
    const Point2& a = k > 0 ? plan[k - 1] : b;
    const int n = std::max(1, static_cast<int>(std::ceil(std::hypot(b.x - a.x, b.y - a.y) / (0.5 * costmap.resolution()))));
    for (int i = 1; i <= n && !left; ++i) {
      const double t = static_cast<double>(i) / n;
      unsigned mx, my;
      if (!costmap.worldToMap(a.x + t * (b.x - a.x), a.y + t * (b.y - a.y), mx, my)) {
        left = has_goal;
        continue;
      }
      path_cells.push_back(costmap.index(mx, my));
      goal_cell = path_cells.back();
      has_goal = true;
    }
  }
  if (!has_goal) return fail("the global plan does not cross the local costmap");
  distanceGrid(costmap, path_cells, path_distance_);
  distanceGrid(costmap, {goal_cell}, goal_distance_);
  // A plan blocked after it was made (a door shut, a box dropped in a corridor) leaves no way to the
  // local goal: fail, as base_local_planner does, so that move_base plans again and, failing that,
  // recovers and aborts, rather than roaming on the least bad of hopeless trajectories.
  unsigned rx, ry;
  if (costmap.worldToMap(pose.x, pose.y, rx, ry) && !aWayOutFrom(costmap, goal_distance_, rx, ry))
    return fail("the plan is blocked: no way round the obstacles in the local costmap to the local goal");

  // The dynamic window: what the accelerations reach in one control period (dwa) or in sim_time.
  const double horizon = options_.dwa ? options_.sim_period : options_.sim_time;
  double max_vx = std::min(options_.max_vel_x, velocity.x + options_.acc_lim_x * horizon);
  double min_vx = std::max(options_.min_vel_x, velocity.x - options_.acc_lim_x * horizon);
  double max_vth = std::min(options_.max_vel_theta, velocity.theta + options_.acc_lim_theta * horizon);
  double min_vth = std::max(options_.min_vel_theta, velocity.theta - options_.acc_lim_theta * horizon);
  if (min_vx > max_vx) min_vx = max_vx;
  if (min_vth > max_vth) min_vth = max_vth;

  // Every sampled command is rolled out first (no footprints: cheap); where it ends and the cells
  // under its poses' centres and corners bound its score from below, and rule out most commands
  // that touch an obstacle. Whole footprints, nearly all of the work, are then checked in order of
  // that bound, and no more once a bound is above the best score found: the command checking them
  // all would choose (the lowest score, the first sampled among equals), at a fraction of the cost.
  struct Candidate {
    Rollout rollout;
    double lowest;
    int order;  // sampling order, which breaks ties as checking them in turn would
  };
  std::vector<Candidate> candidates;
  const int nvx = options_.vx_samples, nvth = options_.vtheta_samples;
  candidates.reserve(static_cast<std::size_t>(nvx) * nvth);
  for (int i = 0; i < nvx; ++i) {
    const double vx = nvx == 1 ? max_vx : min_vx + i * (max_vx - min_vx) / (nvx - 1);
    for (int j = 0; j < nvth; ++j) {
      const double vth = nvth == 1 ? 0.0 : min_vth + j * (max_vth - min_vth) / (nvth - 1);
      if (!isAMove(vx, vth)) continue;
      Velocity2 command;
      command.x = vx;
      command.theta = vth;
      Rollout r = rollout(pose, command);
      const double lowest = lowestScore(costmap, footprint, r);
      if (lowest < std::numeric_limits<double>::infinity())
        candidates.push_back({std::move(r), lowest, static_cast<int>(candidates.size())});
    }
  }
  std::sort(candidates.begin(), candidates.end(), [](const Candidate& a, const Candidate& b) {
    return a.lowest < b.lowest || (a.lowest == b.lowest && a.order < b.order);
  });
  best = Trajectory();
  int best_order = -1;
  for (const Candidate& c : candidates) {
    if (best.cost >= 0 && (c.lowest > best.cost || (c.lowest == best.cost && c.order > best_order))) break;
    Trajectory t = check(costmap, footprint, c.rollout);
    if (t.cost >= 0 && (best.cost < 0 || t.cost < best.cost || (t.cost == best.cost && c.order < best_order))) {
      best = std::move(t);
      best_order = c.order;
    }
  }
  // Turning in place, at least min_in_place_vel_theta. A turn ends where it began, so all turns
  // score alike; as base_local_planner, the one whose heading then points at the cell nearest to
  // the goal (heading_lookahead ahead) is taken, if it scores no worse than the best move.
  double best_ahead = std::numeric_limits<double>::infinity();
  for (int j = 0; j < nvth; ++j) {
    double vth = nvth == 1 ? 0.0 : min_vth + j * (max_vth - min_vth) / (nvth - 1);
    if (vth == 0.0) continue;
    vth = vth > 0 ? std::max(vth, options_.min_in_place_vel_theta) : std::min(vth, -options_.min_in_place_vel_theta);
    Velocity2 command;
    command.theta = vth;
    const Rollout r = rollout(pose, command);
    if (best.cost >= 0 && lowestScore(costmap, footprint, r) > best.cost) continue;  // cannot score as well
    Trajectory t = check(costmap, footprint, r);
    if (t.cost < 0 || t.poses.empty() || (best.cost >= 0 && t.cost > best.cost)) continue;
    const Pose2& end = t.poses.back();
    unsigned mx, my;
    if (!costmap.worldToMap(end.x + options_.heading_lookahead * std::cos(end.theta),
                            end.y + options_.heading_lookahead * std::sin(end.theta), mx, my))
      continue;
    const double ahead = goal_distance_[costmap.index(mx, my)];
    if (ahead < best_ahead) {
      best_ahead = ahead;
      best = std::move(t);
    }
  }
  if (best.cost >= 0) return true;
  Velocity2 back;  // back out
  back.x = options_.escape_vel;
  if (isAMove(back.x, 0.0)) {
    Trajectory t = simulate(costmap, footprint, pose, back);
    if (t.cost >= 0) best = std::move(t);
  }
  if (best.cost >= 0) return true;
  return fail("no valid trajectory: every sampled command would bring the footprint onto an obstacle within sim_time");
}

}  // namespace navigation_core
