#pragma once
// A global planner after navfn (NavfnROS): a potential spreads from the robot over the costmap in
// navfn's wavefront order (Dijkstra's, in bands), each cell's value interpolated quadratically from
// its two lowest neighbours (navfn's approximation of the Eikonal equation, so paths cut across
// open space like straight lines rather than staircases); the path descends the potential's
// gradient from the goal back to the robot.
//
// Costs as navfn reads a costmap: a free cell costs kNeutral (50), a cell of cost c costs
// 50 + 0.8 c; lethal and inscribed cells (and unknown ones unless allow_unknown) are obstacles,
// unknown ones with allow_unknown cost what the dearest passable cell does. The map's outermost
// cells are obstacles, as navfn makes them.
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "navigation_core/costmap.h"
#include "navigation_core/footprint.h"

namespace navigation_core {

struct NavfnOptions {  // NavfnROS's parameters and defaults
  bool allow_unknown = true;
  double default_tolerance = 0.0;  // m: a goal that cannot be reached may be replaced by the
                                   // nearest reachable point within this distance
};

class NavfnPlanner {
 public:
  explicit NavfnPlanner(const NavfnOptions& options = NavfnOptions()) : options_(options) {}

  // A path of world points from `start` to `goal` (or, when the goal cannot be reached, to the
  // reachable point nearest to it within `tolerance`, or options' default_tolerance if negative).
  // Empty, with the reason in `why`, when there is none: start or goal off the map, start in an
  // obstacle, no way through.
  std::vector<Point2> makePlan(const Costmap& costmap, const Point2& start, const Point2& goal, double tolerance,
                               std::string* why);

  // The last potential (for ~potential and tests): one float per cell, kUnreached where the
  // spreading did not get to.
  const std::vector<float>& potential() const { return potential_; }
  static constexpr float kUnreached = 1e10f;
  static constexpr float kNeutral = 50.0f;
  static constexpr float kObstacle = 254.0f;

 private:
  // A list of cells whose storage lasts from plan to plan: the first `count` of `cells` are in it.
  struct CellList {
    std::vector<unsigned> cells;
    std::size_t count = 0;
  };

  void loadCosts(const Costmap& costmap);
  // Spreads the potential from cell `source` until cell `target` is reached (or everywhere: pass
  // a target past the end).
  void spread(unsigned source, unsigned target);
  // Gradient descent from continuous cell coordinates (x, y) to the source; false if stuck.
  bool descend(double x, double y, std::vector<Point2>& cells) const;
  void gradientAt(unsigned index, double& gx, double& gy) const;

  NavfnOptions options_;
  unsigned nx_ = 0, ny_ = 0;
  // Per cell: its costmap value (lethal on the map's border), with kPending (0x100) set while the
  // cell waits in next_ or overflow_.
  std::vector<std::uint16_t> cell_;
  // navfn's cost of a cell_ entry (infinite for an obstacle), and that times sqrt(1/2): a
  // neighbour is worth pushing when its potential exceeds a cell's by more (never when pending).
  float cost_of_[512], diagonal_cost_of_[512];
  std::vector<float> potential_;
  // The wavefront's lists, kept from plan to plan so that a plan need not allocate.
  CellList current_, next_, overflow_;
};

}  // namespace navigation_core
