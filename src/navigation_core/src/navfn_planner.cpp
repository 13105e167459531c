#include "navigation_core/navfn_planner.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

#include "navigation_core/cost_values.h"

namespace navigation_core {
namespace {

constexpr float kCostFactor = 0.8f;
constexpr double kStep = 0.5;  // cells per gradient-descent step, as navfn
constexpr float kDiagonal = static_cast<float>(M_SQRT1_2);
// An obstacle's cost: no potential plus it is below kUnreached, so the wavefront never enters one.
constexpr float kBlocked = std::numeric_limits<float>::infinity();
constexpr std::uint16_t kPending = 0x100;  // in cell_, beside the costmap value
// How many cells ahead in a round the spreading asks for the memory that a cell will read: on a
// big map its rows are far apart, and the cache would miss them.
constexpr std::size_t kPrefetchAhead = 8;

}  // namespace

void NavfnPlanner::loadCosts(const Costmap& costmap) {
  nx_ = costmap.sizeX();
  ny_ = costmap.sizeY();
  for (unsigned v = 0; v < 256; ++v) {
    float cost = kBlocked;
    if (v < kInscribedInflatedObstacle)
      cost = std::min(kNeutral + kCostFactor * v, kObstacle - 1);
    else if (v == kNoInformation && options_.allow_unknown)
      cost = kObstacle - 1;
    cost_of_[v] = cost_of_[v | kPending] = cost;
    diagonal_cost_of_[v] = cost * kDiagonal;
    diagonal_cost_of_[v | kPending] = kBlocked;  // a pending cell is not pushed again
  }
  // The costmap values themselves, costed through cost_of_: two bytes a cell where float costs
  // would take four, as the spreading reads cells all over the map.
  const std::size_t size = costmap.costs().size();
  cell_.resize(size);
  std::uint16_t* const cell = cell_.data();
  std::copy(costmap.costs().begin(), costmap.costs().end(), cell);
  // The map's outermost cells are obstacles, so that a cell's four neighbours are always on the map.
  std::fill(cell, cell + nx_, kLethalObstacle);
  std::fill(cell + size - nx_, cell + size, kLethalObstacle);
  for (std::size_t row = nx_; row < size; row += nx_) cell[row - 1] = cell[row] = kLethalObstacle;
}

void NavfnPlanner::spread(unsigned source, unsigned target) {
  // navfn's wavefront: cells whose potential falls below a threshold are expanded in rounds; the
  // others wait in an overflow list until the threshold rises by kThresholdStep. Not exactly
  // Dijkstra's order (a cell may be updated twice) but linear in the map, where a heap is not.
  constexpr float kThresholdStep = 2 * kNeutral;
  const std::size_t size = cell_.size(), nx = nx_;
  potential_.assign(size, kUnreached);
  float* const potential = potential_.data();
  std::uint16_t* const cell = cell_.data();
  const float* const cost_of = cost_of_;
  const float* const diagonal_cost_of = diagonal_cost_of_;
  // Room for `more` cells after the first `count` of `list`.
  const auto makeRoom = [](CellList& list, std::size_t more) {
    if (list.count + more > list.cells.size()) list.cells.resize(list.count + more);
  };
  current_.count = next_.count = overflow_.count = 0;

  potential[source] = 0.0f;
  makeRoom(current_, 4);
  const std::size_t s = source;
  for (const std::size_t m : {s - 1, s + 1, s - nx, s + nx}) {
    if (cost_of[cell[m]] < kBlocked) {
      cell[m] |= kPending;
      current_.cells[current_.count++] = static_cast<unsigned>(m);
    }
  }
  float threshold = kObstacle;
  while (current_.count != 0 || overflow_.count != 0) {
    const unsigned* const cells = current_.cells.data();
    const std::size_t cells_count = current_.count;
    for (std::size_t k = 0; k < cells_count; ++k) cell[cells[k]] &= ~kPending;
    // A cell writes four slots at most (below).
    makeRoom(next_, 4 * cells_count);
    makeRoom(overflow_, 4 * cells_count);
    // [0]: overflow, [1]: next, chosen by index, not by a branch: a cell goes either way about as
    // often.
    unsigned* const lists[2] = {overflow_.cells.data(), next_.cells.data()};
    std::size_t counts[2] = {overflow_.count, next_.count};
    for (std::size_t k = 0; k < cells_count; ++k) {
      if (k + kPrefetchAhead < cells_count) {
        const std::size_t ahead = cells[k + kPrefetchAhead];
        for (const std::size_t row : {ahead - nx, ahead, ahead + nx}) {
          __builtin_prefetch(potential + row);
          __builtin_prefetch(cell + row);
        }
      }
      const std::size_t n = cells[k];
      // navfn's quadratic interpolation from the lower neighbour on each axis.
      const float left = potential[n - 1], right = potential[n + 1], up = potential[n - nx], down = potential[n + nx];
      const float a = std::min(left, right), b = std::min(up, down);
      const float ta = std::min(a, b), tc = std::max(a, b);
      const float hf = cost_of[cell[n]];
      const float dc = tc - ta;
      const float t = dc / hf;
      // dc >= hf: only one neighbour counts, a straight step.
      const float candidate = dc >= hf ? ta + hf : ta + hf * (-0.2301f * t * t + 0.5307f * t + 0.7040f);
      if (!(candidate < potential[n])) continue;
      potential[n] = candidate;
      // Neighbours that this cell could improve go to the next round, or wait for a higher
      // threshold. Appended without branches (the slot is written either way, kept only if
      // pushed): whether a neighbour goes is data that branch prediction cannot guess.
      const int low = candidate < threshold;
      unsigned* const out = lists[low];
      std::size_t count = counts[low];
      const auto push = [&](std::size_t m, float pm) {
        const bool go = pm > candidate + diagonal_cost_of[cell[m]];
        out[count] = static_cast<unsigned>(m);
        count += go;
        cell[m] |= go ? kPending : 0;
      };
      push(n - 1, left);
      push(n + 1, right);
      push(n - nx, up);
      push(n + nx, down);
      counts[low] = count;
    }
    overflow_.count = counts[0];
    next_.count = counts[1];
    std::swap(current_, next_);
    next_.count = 0;
    if (current_.count == 0) {
      threshold += kThresholdStep;
      std::swap(current_, overflow_);
    }
    if (target < size && potential[target] < kUnreached) break;  // reached: navfn stops here too
  }
  // Cells left pending keep their flag: the next plan loads cell_ afresh.
}

void NavfnPlanner::gradientAt(unsigned n, double& gx, double& gy) const {
  // Central differences over the neighbours that were reached; towards the reached side from an
  // unreached cell.
  gx = gy = 0.0;
  const float here = potential_[n];
  const auto reached = [&](unsigned m) { return potential_[m] < kUnreached; };
  if (here >= kUnreached) {
    if (reached(n - 1)) gx = kObstacle;
    else if (reached(n + 1)) gx = -kObstacle;
    if (reached(n - nx_)) gy = kObstacle;
    else if (reached(n + nx_)) gy = -kObstacle;
  } else {
    if (reached(n - 1)) gx += here - potential_[n - 1];
    if (reached(n + 1)) gx += potential_[n + 1] - here;
    if (reached(n - nx_)) gy += here - potential_[n - nx_];
    if (reached(n + nx_)) gy += potential_[n + nx_] - here;
  }
  const double norm = std::hypot(gx, gy);
  if (norm > 0) {
    gx /= norm;
    gy /= norm;
  }
}

bool NavfnPlanner::descend(double sx, double sy, std::vector<Point2>& samples) const {
  // (sx, sy): sample coordinates, sample (i, j) being cell (i, j)'s centre.
  const std::size_t max_steps = 4 * (static_cast<std::size_t>(nx_) + ny_) * 4;
  for (std::size_t step = 0; step < max_steps; ++step) {
    const int i = static_cast<int>(std::floor(sx)), j = static_cast<int>(std::floor(sy));
    if (i < 1 || j < 1 || i + 2 >= static_cast<int>(nx_) || j + 2 >= static_cast<int>(ny_)) return false;
    // The nearest sample decides whether we have arrived.
    const unsigned near = static_cast<unsigned>(std::lround(sy)) * nx_ + static_cast<unsigned>(std::lround(sx));
    if (potential_[near] < kNeutral) return true;
    const unsigned n = static_cast<unsigned>(j) * nx_ + static_cast<unsigned>(i);
    bool blocked = false;
    for (const unsigned m : {n, n + 1, n + nx_, n + nx_ + 1}) blocked = blocked || potential_[m] >= kUnreached;
    const std::size_t count = samples.size();
    const bool oscillating = count >= 3 && std::hypot(samples[count - 1].x - samples[count - 3].x,
                                                      samples[count - 1].y - samples[count - 3].y) < 1e-6;
    if (blocked || oscillating) {
      // Next to an obstacle (or going back and forth): step to the lowest of the nearest
      // sample's eight neighbours, as navfn does.
      unsigned best = near;
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
          const unsigned m = static_cast<unsigned>(static_cast<int>(near) + dy * static_cast<int>(nx_) + dx);
          if (potential_[m] < potential_[best]) best = m;
        }
      if (best == near) return false;  // a pit: nowhere lower to go
      sx = best % nx_;
      sy = best / nx_;
    } else {
      // The gradient interpolated bilinearly between the four samples around the point.
      const double fx = sx - i, fy = sy - j;
      double g[4][2];
      gradientAt(n, g[0][0], g[0][1]);
      gradientAt(n + 1, g[1][0], g[1][1]);
      gradientAt(n + nx_, g[2][0], g[2][1]);
      gradientAt(n + nx_ + 1, g[3][0], g[3][1]);
      double gx = (1 - fy) * ((1 - fx) * g[0][0] + fx * g[1][0]) + fy * ((1 - fx) * g[2][0] + fx * g[3][0]);
      double gy = (1 - fy) * ((1 - fx) * g[0][1] + fx * g[1][1]) + fy * ((1 - fx) * g[2][1] + fx * g[3][1]);
      const double norm = std::hypot(gx, gy);
      if (!(norm > 0)) return false;
      sx -= kStep * gx / norm;
      sy -= kStep * gy / norm;
    }
    samples.push_back({sx, sy});
  }
  return false;
}

std::vector<Point2> NavfnPlanner::makePlan(const Costmap& costmap, const Point2& start, const Point2& goal,
                                           double tolerance, std::string* why) {
  const auto fail = [&](const std::string& reason) {
    if (why) *why = reason;
    return std::vector<Point2>();
  };
  unsigned sx, sy, gx, gy;
  if (!costmap.worldToMap(start.x, start.y, sx, sy)) return fail("the robot's position is off the costmap");
  if (!costmap.worldToMap(goal.x, goal.y, gx, gy)) return fail("the goal is off the global costmap");
  loadCosts(costmap);
  const unsigned source = sy * nx_ + sx, target = gy * nx_ + gx;
  // The robot's own cell is passable whatever the costmap says (NavfnROS clears it), unless it is
  // on the map's edge.
  if (sx == 0 || sy == 0 || sx + 1 >= nx_ || sy + 1 >= ny_) return fail("the robot is on the costmap's edge");
  cell_[source] = kFreeSpace;  // costs kNeutral
  spread(source, target);

  const double res = costmap.resolution();
  Point2 end = goal;
  unsigned end_cell = target;
  if (potential_[target] >= kUnreached) {
    if (tolerance < 0) tolerance = options_.default_tolerance;
    // The reached cell nearest to the goal within the tolerance (NavfnROS searches the same way).
    double best = std::numeric_limits<double>::infinity();
    const int reach = static_cast<int>(std::ceil(tolerance / res));
    for (int dy = -reach; dy <= reach; ++dy) {
      for (int dx = -reach; dx <= reach; ++dx) {
        const int x = static_cast<int>(gx) + dx, y = static_cast<int>(gy) + dy;
        if (x < 0 || y < 0 || x >= static_cast<int>(nx_) || y >= static_cast<int>(ny_)) continue;
        const unsigned m = static_cast<unsigned>(y) * nx_ + static_cast<unsigned>(x);
        Point2 centre;
        costmap.mapToWorld(static_cast<unsigned>(x), static_cast<unsigned>(y), centre.x, centre.y);
        const double d = std::hypot(centre.x - goal.x, centre.y - goal.y);
        if (potential_[m] < kUnreached && d <= tolerance && d < best) {
          best = d;
          end = centre;
          end_cell = m;
        }
      }
    }
    if (!std::isfinite(best)) return fail("no path to the goal: it is in an obstacle or walled off");
  }

  // Descend from the end to the robot in sample coordinates (sample (i, j) = cell (i, j)'s centre).
  std::vector<Point2> samples;
  const double ex = (end.x - costmap.originX()) / res - 0.5, ey = (end.y - costmap.originY()) / res - 0.5;
  if (end_cell != source && !descend(ex, ey, samples))
    return fail("a potential was found but no path could be traced down it");
  std::vector<Point2> path{start};
  for (auto it = samples.rbegin(); it != samples.rend(); ++it)
    path.push_back({costmap.originX() + (it->x + 0.5) * res, costmap.originY() + (it->y + 0.5) * res});
  path.push_back(end);
  if (why) why->clear();
  return path;
}

}  // namespace navigation_core
