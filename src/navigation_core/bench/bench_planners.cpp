// bench_planners: the navigation core's planning times (issue 11; figures in docs/PERFORMANCE.md).
//
//   bench_planners [--seed 1] [--plans 20]
//
// 1. Global plans (NavfnPlanner::makePlan) on 200 x 200, 512 x 512 and 2048 x 2048 grids of
//    0.05 m cells: a maze-like map (walls of random length on a 1 m lattice, inflated as
//    costmap_2d would for a 0.24 x 0.18 m robot), PLANS seeded random start/goal pairs in free
//    space at least half the map apart; mean and worst milliseconds per plan, and how many found one.
// 2. The local planner's cycle (LocalPlanner::computeVelocity) on a 4 x 4 m rolling window: in the
//    maze, following a path across it from its start, with base_local_planner's default sampling
//    (3 x 20 velocities, 1 s at 0.025 m); and the Pioneer as pioneer_2dnav sets it up (its padded
//    footprint, 6 x 20 velocities over 1.5 s in metres, inflation 0.6 m at scaling 3) in a 1.2 m
//    corridor that turns left, from 40 poses along its centre line: mean and worst microseconds.
// 3. Inflating the whole 512 x 512 map once: milliseconds.
// 4. A local costmap's update per laser scan (LayeredCostmap: the 4 x 4 m rolling window moved,
//    one 720-beam scan cleared and marked, footprint cleared, inflated), the robot driving through
//    a room whose walls the scan sees: mean and worst microseconds.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <random>
#include <string>
#include <vector>

#include "navigation_core/cost_values.h"
#include "navigation_core/inflation.h"
#include "navigation_core/layered_costmap.h"
#include "navigation_core/local_planner.h"
#include "navigation_core/navfn_planner.h"

using namespace navigation_core;

namespace {

const Footprint kFootprint = {{-0.12, -0.09}, {-0.12, 0.09}, {0.12, 0.09}, {0.12, -0.09}};
constexpr double kRes = 0.05;

double millisecondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

Costmap maze(unsigned cells, std::mt19937& rng) {
  Costmap map(cells, cells, kRes, 0, 0);
  const unsigned lattice = 20;  // 1 m
  std::uniform_int_distribution<int> coin(0, 2);
  for (unsigned y = 0; y < cells; y += lattice) {
    for (unsigned x = 0; x < cells; x += lattice) {
      const int kind = coin(rng);  // none, a horizontal or a vertical wall of 1 m
      for (unsigned k = 0; k < lattice && kind != 0; ++k) {
        const unsigned wx = kind == 1 ? x + k : x, wy = kind == 1 ? y : y + k;
        if (wx < cells && wy < cells) map.setCost(wx, wy, kLethalObstacle);
      }
    }
  }
  InflationOptions inflation;
  Inflation(inflation, footprintRadii(kFootprint).inscribed, kRes).apply(map);
  return map;
}

Point2 freePoint(const Costmap& map, std::mt19937& rng) {
  std::uniform_real_distribution<double> u(0.1, map.sizeX() * kRes - 0.1);
  for (;;) {
    const Point2 p{u(rng), u(rng)};
    unsigned mx, my;
    if (map.worldToMap(p.x, p.y, mx, my) && map.cost(mx, my) < 128) return p;
  }
}

struct LocalCase {
  Pose2 pose;
  std::vector<Point2> plan;  // from the robot on
};

// 200 local planner cycles, the cases in turn, the robot moving at `speed`: mean and worst times.
void timeLocalPlanner(const char* what, LocalPlanner& planner, const Costmap& window, const Footprint& footprint,
                      const std::vector<LocalCase>& cases, double speed) {
  double total = 0, worst = 0;
  const int cycles = 200;
  for (int k = 0; k < cycles; ++k) {
    const LocalCase& c = cases[static_cast<std::size_t>(k) % cases.size()];
    Trajectory best;
    std::string why;
    Velocity2 v;
    v.x = speed;
    const auto start = std::chrono::steady_clock::now();
    planner.computeVelocity(window, footprint, c.pose, v, c.plan, best, &why);
    const double us = 1000 * millisecondsSince(start);
    total += us;
    worst = std::max(worst, us);
  }
  std::printf("local planner cycle 80x80 window%s: %.0f us mean, %.0f us worst\n", what, total / cycles, worst);
}

}  // namespace

int main(int argc, char** argv) {
  unsigned seed = 1;
  int plans = 20;
  for (int i = 1; i + 1 < argc; i += 2) {
    if (!std::strcmp(argv[i], "--seed")) seed = static_cast<unsigned>(std::atoi(argv[i + 1]));
    else if (!std::strcmp(argv[i], "--plans")) plans = std::atoi(argv[i + 1]);
  }
  std::printf("bench_planners --seed %u --plans %d\n", seed, plans);
  for (const unsigned cells : {200u, 512u, 2048u}) {
    std::mt19937 rng(seed);
    const Costmap map = maze(cells, rng);
    NavfnPlanner planner;
    double total = 0, worst = 0;
    int found = 0;
    for (int k = 0; k < plans; ++k) {
      Point2 a = freePoint(map, rng), b = freePoint(map, rng);
      while (std::hypot(a.x - b.x, a.y - b.y) < 0.5 * cells * kRes) b = freePoint(map, rng);
      const auto start = std::chrono::steady_clock::now();
      std::string why;
      found += !planner.makePlan(map, a, b, 0.0, &why).empty();
      const double ms = millisecondsSince(start);
      total += ms;
      worst = std::max(worst, ms);
    }
    std::printf("global plan %ux%u: %.2f ms mean, %.2f ms worst, %d of %d found\n", cells, cells, total / plans, worst,
                found, plans);
  }
  {
    std::mt19937 rng(seed);
    const Costmap window = maze(80, rng);
    LocalPlanner planner{LocalPlannerOptions()};
    std::vector<Point2> plan;
    for (int k = 0; k <= 80; ++k) plan.push_back({0.2 + 3.6 * k / 80, 2.0 + 1.5 * std::sin(k * 0.08)});
    timeLocalPlanner("", planner, window, kFootprint, {{{0.2, 2.0, 0.0}, plan}}, 0.2);
  }
  {
    const Footprint pioneer_footprint = {{-0.29, -0.22}, {-0.29, 0.22}, {0.20, 0.22}, {0.20, -0.22}};
    Costmap window(80, 80, kRes, 0, 0);
    const auto wall = [&](double x0, double y0, double x1, double y1) {
      for (double t = 0; t <= 1.0; t += 0.005) {
        unsigned mx, my;
        if (window.worldToMap(x0 + t * (x1 - x0), y0 + t * (y1 - y0), mx, my)) window.setCost(mx, my, kLethalObstacle);
      }
    };
    wall(0.0, 1.4, 3.2, 1.4), wall(3.2, 1.4, 3.2, 4.0), wall(0.0, 2.6, 2.0, 2.6), wall(2.0, 2.6, 2.0, 4.0);
    InflationOptions inflation;
    inflation.inflation_radius = 0.6, inflation.cost_scaling_factor = 3.0;
    Inflation(inflation, footprintRadii(pioneer_footprint).inscribed, kRes).apply(window);
    std::vector<Point2> plan;
    for (int k = 0; k <= 48; ++k) plan.push_back({0.2 + 0.05 * k, 2.0});
    for (int k = 1; k <= 36; ++k) plan.push_back({2.6, 2.0 + 0.05 * k});
    LocalPlannerOptions o;
    o.max_vel_x = 0.5, o.acc_lim_x = 1.0, o.acc_lim_theta = 2.0, o.sim_time = 1.5, o.vx_samples = 6;
    o.meter_scoring = true, o.min_in_place_vel_theta = 0.5;
    LocalPlanner planner(o);
    std::vector<LocalCase> along;  // on the path, heading along it
    for (std::size_t at = 0; at < 80; at += 2) {
      const Point2& p = plan[at];
      along.push_back({{p.x, p.y, std::atan2(plan[at + 1].y - p.y, plan[at + 1].x - p.x)},
                       std::vector<Point2>(plan.begin() + static_cast<std::ptrdiff_t>(at), plan.end())});
    }
    timeLocalPlanner(", the Pioneer in a corridor", planner, window, pioneer_footprint, along, 0.25);  // half speed
  }
  {
    std::mt19937 rng(seed);
    Costmap map = maze(512, rng);
    const auto start = std::chrono::steady_clock::now();
    Inflation(InflationOptions(), footprintRadii(kFootprint).inscribed, kRes).apply(map);
    std::printf("inflation 512x512: %.2f ms\n", millisecondsSince(start));
  }
  {
    LayeredCostmapOptions o;
    o.width = o.height = 4.0;
    o.rolling_window = true;
    o.obstacles.obstacle_range = 2.5;
    o.obstacles.raytrace_range = 3.0;
    LayeredCostmap costmap(o, kFootprint);
    std::mt19937 rng(seed);
    std::normal_distribution<double> noise(0.0, 0.01);
    double total = 0, worst = 0;
    const int scans = 200;
    for (int k = 0; k < scans; ++k) {
      // The robot crosses a 6 x 3 m room (walls at x = 0, 6 and y = 0, 3); 720 beams over 270 degrees.
      const Pose2 robot{1.0 + 4.0 * k / scans, 1.5, 0.3 * std::sin(k * 0.05)};
      Observation scan;
      scan.origin = {robot.x, robot.y, 0.2};
      for (int b = 0; b < 720; ++b) {
        const double a = robot.theta - 2.356 + 4.712 * b / 719, c = std::cos(a), s = std::sin(a);
        double range = 30.0;
        if (c > 1e-9) range = std::min(range, (6.0 - robot.x) / c);
        if (c < -1e-9) range = std::min(range, -robot.x / c);
        if (s > 1e-9) range = std::min(range, (3.0 - robot.y) / s);
        if (s < -1e-9) range = std::min(range, -robot.y / s);
        range += noise(rng);
        scan.points.push_back({robot.x + range * c, robot.y + range * s, 0.2});
      }
      const auto start = std::chrono::steady_clock::now();
      costmap.updateOrigin(robot.x, robot.y);
      costmap.addObservation(scan);
      costmap.update(robot);
      const double us = 1000 * millisecondsSince(start);
      total += us;
      worst = std::max(worst, us);
    }
    std::printf("local costmap update per 720-beam scan, 80x80 window: %.0f us mean, %.0f us worst\n",
                total / scans, worst);
  }
  return 0;
}
