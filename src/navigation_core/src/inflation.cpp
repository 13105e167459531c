#include "navigation_core/inflation.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <map>
#include <stdexcept>
#include <string>

#include "navigation_core/cost_values.h"

namespace navigation_core {
namespace {

void requireNonNegative(double value, const char* name) {
  if (!(value >= 0) || !std::isfinite(value))
    throw std::invalid_argument(std::string("inflation: ") + name + ": expected a number >= 0, got " +
                                std::to_string(value));
}

// The rank of an offset beyond inflation_radius: never queued.
constexpr unsigned kBeyondRadius = ~0u;

struct FrontCell {
  unsigned index, x, y, source_x, source_y;
};

}  // namespace

Inflation::Inflation(const InflationOptions& options, double inscribed_radius, double resolution)
    : options_(options), inscribed_radius_(inscribed_radius), resolution_(resolution) {
  requireNonNegative(options.inflation_radius, "inflation_radius");
  requireNonNegative(options.cost_scaling_factor, "cost_scaling_factor");
  requireNonNegative(inscribed_radius, "the footprint's inscribed radius");
  if (!(resolution > 0) || !std::isfinite(resolution))
    throw std::invalid_argument("inflation: resolution: expected a positive number, got " + std::to_string(resolution));
  cell_radius_ = static_cast<unsigned>(std::max(0.0, std::ceil(options.inflation_radius / resolution)));
  const unsigned n = cell_radius_ + 2;
  cost_table_.resize(n * n);
  rank_table_.resize(n * n);
  std::map<double, unsigned> ranks;
  for (unsigned dy = 0; dy < n; ++dy)
    for (unsigned dx = 0; dx < n; ++dx) ranks.emplace(std::hypot(dx, dy), 0);
  for (auto& [distance, rank] : ranks) rank = ranks_++;
  for (unsigned dy = 0; dy < n; ++dy) {
    for (unsigned dx = 0; dx < n; ++dx) {
      const double d = std::hypot(dx, dy);
      cost_table_[dy * n + dx] = costAt(d);
      rank_table_[dy * n + dx] = d > cell_radius_ ? kBeyondRadius : ranks.at(d);
    }
  }
}

std::uint8_t Inflation::costAt(double distance_cells) const {
  if (distance_cells == 0) return kLethalObstacle;
  const double distance = distance_cells * resolution_;
  if (distance <= inscribed_radius_) return kInscribedInflatedObstacle;
  const double factor = std::exp(-options_.cost_scaling_factor * (distance - inscribed_radius_));
  return static_cast<std::uint8_t>((kInscribedInflatedObstacle - 1) * factor);
}

void Inflation::apply(Costmap& map) const {
  const unsigned size_x = map.sizeX(), size_y = map.sizeY();
  if (size_x == 0 || size_y == 0) return;
  std::vector<std::uint8_t>& costs = map.costs();
  std::vector<bool> seen(costs.size(), false);
  std::vector<std::vector<FrontCell>> buckets(ranks_);
  for (unsigned y = 0; y < size_y; ++y)
    for (unsigned x = 0; x < size_x; ++x)
      if (costs[map.index(x, y)] == kLethalObstacle) buckets[0].push_back({map.index(x, y), x, y, x, y});

  const unsigned n = cell_radius_ + 2;
  const auto enqueue = [&](unsigned x, unsigned y, unsigned source_x, unsigned source_y) {
    const unsigned index = map.index(x, y);
    if (seen[index]) return;
    const unsigned dx = x > source_x ? x - source_x : source_x - x;
    const unsigned dy = y > source_y ? y - source_y : source_y - y;
    if (dx >= n || dy >= n) return;
    const unsigned rank = rank_table_[dy * n + dx];
    if (rank == kBeyondRadius) return;
    buckets[rank].push_back({index, x, y, source_x, source_y});
  };
  for (auto& bucket : buckets) {
    // A bucket may grow while it is read (neighbours at the same distance from their source).
    for (std::size_t k = 0; k < bucket.size(); ++k) {
      const FrontCell c = bucket[k];
      if (seen[c.index]) continue;
      seen[c.index] = true;
      const unsigned dx = c.x > c.source_x ? c.x - c.source_x : c.source_x - c.x;
      const unsigned dy = c.y > c.source_y ? c.y - c.source_y : c.source_y - c.y;
      const std::uint8_t cost = cost_table_[dy * n + dx];
      std::uint8_t& old = costs[c.index];
      const bool unknown_takes_it =
          old == kNoInformation && (options_.inflate_unknown ? cost > kFreeSpace : cost >= kInscribedInflatedObstacle);
      old = unknown_takes_it ? cost : std::max(old, cost);
      if (c.x > 0) enqueue(c.x - 1, c.y, c.source_x, c.source_y);
      if (c.y > 0) enqueue(c.x, c.y - 1, c.source_x, c.source_y);
      if (c.x + 1 < size_x) enqueue(c.x + 1, c.y, c.source_x, c.source_y);
      if (c.y + 1 < size_y) enqueue(c.x, c.y + 1, c.source_x, c.source_y);
    }
    bucket.clear();
    bucket.shrink_to_fit();
  }
}

}  // namespace navigation_core
