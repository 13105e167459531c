#include "navigation_core/layered_costmap.h"

#include <cmath>
#include <stdexcept>
#include <string>

#include "navigation_core/cost_values.h"

namespace navigation_core {
namespace {

unsigned cellsFor(double metres, double resolution) {
  if (!(metres > 0) || !std::isfinite(metres))
    throw std::invalid_argument("costmap width and height: expected positive numbers of metres, got " +
                                std::to_string(metres));
  return static_cast<unsigned>(std::lround(metres / resolution));
}

}  // namespace

LayeredCostmap::LayeredCostmap(const LayeredCostmapOptions& options, const Footprint& footprint)
    : options_(options),
      footprint_(footprint),
      inflation_(options.inflation, footprintRadii(footprint).inscribed, options.resolution) {
  master_ = Costmap(cellsFor(options.width, options.resolution), cellsFor(options.height, options.resolution),
                    options.resolution, options.origin_x, options.origin_y, defaultCost());
  obstacles_ = Costmap(master_.sizeX(), master_.sizeY(), options.resolution, options.origin_x, options.origin_y,
                       unseenObstacleCost());
}

std::uint8_t LayeredCostmap::defaultCost() const {
  return options_.track_unknown_space ? kNoInformation : kFreeSpace;
}

std::uint8_t LayeredCostmap::unseenObstacleCost() const {
  return options_.obstacle_track_unknown_space ? kNoInformation : kFreeSpace;
}

void LayeredCostmap::setStaticMap(const Costmap& static_costs) {
  const bool same_geometry = static_ && static_->sizeX() == static_costs.sizeX() &&
                             static_->sizeY() == static_costs.sizeY() &&
                             static_->resolution() == static_costs.resolution() &&
                             static_->originX() == static_costs.originX() && static_->originY() == static_costs.originY();
  static_ = static_costs;
  if (!options_.rolling_window && !same_geometry) {
    // A new size: every layer starts again on the map's grid, as costmap_2d resizes them.
    master_ = Costmap(static_costs.sizeX(), static_costs.sizeY(), static_costs.resolution(), static_costs.originX(),
                      static_costs.originY(), defaultCost());
    obstacles_ = Costmap(master_.sizeX(), master_.sizeY(), master_.resolution(), master_.originX(), master_.originY(),
                         unseenObstacleCost());
    inflation_ = Inflation(options_.inflation, footprintRadii(footprint_).inscribed, static_costs.resolution());
  }
  // The master at once: a planner reading it before the next update must not find it blank.
  update();
}

void LayeredCostmap::addObservation(const Observation& observation) {
  applyObservation(obstacles_, observation, options_.obstacles);
}

void LayeredCostmap::addObservation(const Observation& observation, const ObstacleLayerOptions& source) {
  applyObservation(obstacles_, observation, source);
}

void LayeredCostmap::updateOrigin(double robot_x, double robot_y) {
  if (!options_.rolling_window) return;
  const double res = master_.resolution();
  // The new corner, on the same cell grid as the old one, so that kept cells move by whole cells.
  const double want_x = robot_x - master_.sizeX() * res / 2, want_y = robot_y - master_.sizeY() * res / 2;
  const long shift_x = std::lround((want_x - obstacles_.originX()) / res);
  const long shift_y = std::lround((want_y - obstacles_.originY()) / res);
  if (shift_x == 0 && shift_y == 0) return;
  Costmap moved(obstacles_.sizeX(), obstacles_.sizeY(), res, obstacles_.originX() + shift_x * res,
                obstacles_.originY() + shift_y * res, unseenObstacleCost());
  for (unsigned y = 0; y < moved.sizeY(); ++y) {
    for (unsigned x = 0; x < moved.sizeX(); ++x) {
      const long ox = static_cast<long>(x) + shift_x, oy = static_cast<long>(y) + shift_y;
      if (ox >= 0 && oy >= 0 && ox < static_cast<long>(obstacles_.sizeX()) && oy < static_cast<long>(obstacles_.sizeY()))
        moved.setCost(x, y, obstacles_.cost(static_cast<unsigned>(ox), static_cast<unsigned>(oy)));
    }
  }
  obstacles_ = std::move(moved);
  master_ = Costmap(obstacles_.sizeX(), obstacles_.sizeY(), res, obstacles_.originX(), obstacles_.originY(),
                    defaultCost());
}

void LayeredCostmap::resetObstacles() { obstacles_.reset(unseenObstacleCost()); }

void LayeredCostmap::resetObstaclesOutside(double x, double y, double size) {
  const double res = obstacles_.resolution();
  // The kept square in cells (cells whose centres lie inside it).
  const double x0 = (x - size / 2 - obstacles_.originX()) / res - 0.5, x1 = (x + size / 2 - obstacles_.originX()) / res - 0.5;
  const double y0 = (y - size / 2 - obstacles_.originY()) / res - 0.5, y1 = (y + size / 2 - obstacles_.originY()) / res - 0.5;
  const std::uint8_t unseen = unseenObstacleCost();
  for (unsigned my = 0; my < obstacles_.sizeY(); ++my) {
    for (unsigned mx = 0; mx < obstacles_.sizeX(); ++mx) {
      if (mx >= x0 && mx <= x1 && my >= y0 && my <= y1) continue;
      obstacles_.setCost(mx, my, unseen);
    }
  }
}

const Costmap& LayeredCostmap::update(const std::optional<Pose2>& robot) {
  if (robot && options_.footprint_clearing_enabled) clearFootprint(obstacles_, footprint_, *robot);
  if (static_ && !options_.rolling_window) {
    master_.costs() = static_->costs();  // the same grid: setStaticMap gave the master its geometry
  } else {
    master_.reset(defaultCost());
    // A rolling window: the static map written over it where it covers it (unknown included), by
    // world position.
    for (unsigned y = 0; static_ && y < master_.sizeY(); ++y) {
      for (unsigned x = 0; x < master_.sizeX(); ++x) {
        double wx, wy;
        master_.mapToWorld(x, y, wx, wy);
        unsigned sx, sy;
        if (static_->worldToMap(wx, wy, sx, sy)) master_.setCost(x, y, static_->cost(sx, sy));
      }
    }
  }
  // The obstacle grid's known cells, by maximum; an unknown master cell takes them.
  std::vector<std::uint8_t>& master = master_.costs();
  const std::vector<std::uint8_t>& obstacles = obstacles_.costs();
  for (std::size_t i = 0; i < master.size(); ++i) {
    if (obstacles[i] == kNoInformation) continue;
    if (master[i] == kNoInformation || master[i] < obstacles[i]) master[i] = obstacles[i];
  }
  if (options_.inflate) inflation_.apply(master_);
  return master_;
}

}  // namespace navigation_core
