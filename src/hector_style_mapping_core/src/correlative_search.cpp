#include "hector_style_mapping_core/correlative_search.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "hector_style_mapping_core/floor_to_int.h"

namespace hector_style_mapping {

namespace {

// The rotation step: the farthest points (the 95th percentile of ranges, so that a few stray far returns do
// not make the step needlessly fine) move by the field's blur.
double angularStep(const std::vector<Eigen::Vector2d>& points) {
  std::vector<double> ranges;
  ranges.reserve(points.size());
  for (const Eigen::Vector2d& p : points) ranges.push_back(p.norm());
  const std::size_t k = std::min(ranges.size() - 1, static_cast<std::size_t>(0.95 * ranges.size()));
  std::nth_element(ranges.begin(), ranges.begin() + static_cast<long>(k), ranges.end());
  return LikelihoodField::kSigma / std::max(ranges[k], 1.0);
}

// Translations (x, y) .. (x + 2^level - 1, y + 2^level - 1) cells from the centre at one rotation, and the
// bound on their score (the exact score at level 0).
struct Candidate {
  int rotation;
  int x;
  int y;
  int level;
  double score;
};

class BranchAndBound {
 public:
  // `expected`: the prior's translation from the centre in cells; `weight`: its cost per cell.
  BranchAndBound(const LikelihoodField& field, const std::vector<std::vector<Eigen::Vector2i>>& rotated, int shifts,
                 int centre_rotation, const Eigen::Vector2d& expected, double weight)
      : field_(field), rotated_(rotated), shifts_(shifts), centre_rotation_(centre_rotation), expected_(expected),
        weight_(weight) {}

  // Translations within `radius` cells of `centre` (along x and along y) are not candidates.
  void exclude(const Eigen::Vector2i& centre, int radius) { excluded_ = centre, excluded_radius_ = radius; }

  // The block's bound: the mean of its points' block maxima, less the prior's cost at the block's point
  // nearest the expected translation (for a single cell, the score less its cost).
  double score(int rotation, int x, int y, int level) {
    ++evaluated_;
    double sum = 0.0;
    for (const Eigen::Vector2i& cell : rotated_[static_cast<std::size_t>(rotation)])
      sum += field_.blockMax(level, cell.x() + x, cell.y() + y);
    const int last = (1 << level) - 1;
    const double dx = std::max({x - expected_.x(), expected_.x() - (x + last), 0.0});
    const double dy = std::max({y - expected_.y(), expected_.y() - (y + last), 0.0});
    return sum / static_cast<double>(rotated_[static_cast<std::size_t>(rotation)].size()) -
           weight_ * std::hypot(dx, dy);
  }

  // Depth first, best bound first; a branch whose bound is below the best leaf so far cannot hold a better one.
  void descend(Candidate* candidates, std::size_t count) {
    std::sort(candidates, candidates + count, [](const Candidate& a, const Candidate& b) { return a.score > b.score; });
    for (const Candidate* it = candidates; it != candidates + count; ++it) {
      const Candidate& c = *it;
      if (c.score < best_.score) break;
      if (c.level == 0) {
        if (std::abs(c.x - excluded_.x()) <= excluded_radius_ && std::abs(c.y - excluded_.y()) <= excluded_radius_)
          continue;
        const double distance = std::hypot(c.x, c.y) + std::abs(c.rotation - centre_rotation_);
        if (c.score > best_.score || distance < best_distance_) best_ = c, best_distance_ = distance;
        continue;
      }
      const int half = 1 << (c.level - 1);
      Candidate children[4];  // on the stack: a search descends through tens of thousands of blocks
      std::size_t count = 0;
      for (int dy = 0; dy <= half; dy += half)
        for (int dx = 0; dx <= half; dx += half)
          if (c.x + dx <= shifts_ && c.y + dy <= shifts_)
            children[count++] = {c.rotation, c.x + dx, c.y + dy, c.level - 1,
                                 score(c.rotation, c.x + dx, c.y + dy, c.level - 1)};
      descend(children, count);
    }
  }

  const Candidate& best() const { return best_; }
  long evaluated() const { return evaluated_; }

 private:
  const LikelihoodField& field_;
  const std::vector<std::vector<Eigen::Vector2i>>& rotated_;
  const int shifts_;
  const int centre_rotation_;
  const Eigen::Vector2d expected_;
  const double weight_;
  Eigen::Vector2i excluded_{0, 0};
  int excluded_radius_ = -1;
  Candidate best_{0, 0, 0, 0, -std::numeric_limits<double>::infinity()};
  double best_distance_ = std::numeric_limits<double>::infinity();
  long evaluated_ = 0;
};

std::vector<Eigen::Vector2d> rotatedBy(const std::vector<Eigen::Vector2d>& points, double theta) {
  const double c = std::cos(theta), s = std::sin(theta);
  std::vector<Eigen::Vector2d> rotated;
  rotated.reserve(points.size());
  for (const Eigen::Vector2d& p : points) rotated.emplace_back(c * p.x() - s * p.y(), s * p.x() + c * p.y());
  return rotated;
}

// Mean interpolated field value of `points` (already rotated) moved by (x, y). When it can no longer beat
// `to_beat` (each point adds at most 1, a cell's largest value), -infinity at once: refine() only wants a better
// candidate, and most are not.
double interpolatedScore(const LikelihoodField& field, const std::vector<Eigen::Vector2d>& points, double x,
                         double y, double to_beat = -std::numeric_limits<double>::infinity()) {
  const double n = static_cast<double>(points.size());
  // A margin for rounding: a candidate given up on is below to_beat by far more than the sum's rounding.
  const double needed = to_beat * n - 1e-9 * n;
  double sum = 0.0;
  double left = n;
  for (const Eigen::Vector2d& p : points) {
    sum += field.interpolate({p.x() + x, p.y() + y});
    left -= 1.0;
    if (sum + left < needed) return -std::numeric_limits<double>::infinity();
  }
  return sum / n;
}

// The best pose within +-2 steps of `pose` in x and y and +-(rotations / 2) steps in theta, on the
// interpolated field: `score` is pose's own, and stays with it on ties.
Pose2D refine(const LikelihoodField& field, const std::vector<Eigen::Vector2d>& points, const Pose2D& pose,
              double linear_step, double angular_step, int rotations, double* score, long* candidates) {
  Pose2D best = pose;
  for (int a = -rotations / 2; a <= rotations / 2; ++a) {
    const double theta = pose.theta + a * angular_step;
    const std::vector<Eigen::Vector2d> rotated = rotatedBy(points, theta);
    for (int dy = -2; dy <= 2; ++dy) {
      for (int dx = -2; dx <= 2; ++dx) {
        const double x = pose.x + dx * linear_step, y = pose.y + dy * linear_step;
        const double value = interpolatedScore(field, rotated, x, y, *score);
        ++*candidates;
        if (value > *score) *score = value, best = {x, y, theta};
      }
    }
  }
  return best;
}

// The window's half-width in cells. Less a hair: 0.2 / 0.05 is 4.000000000000001, and a window of 0.2 m is 4
// cells, not 5.
int windowCells(const SearchWindow& window) {
  return static_cast<int>(std::ceil(std::max(window.linear, 0.0) / LikelihoodField::kResolution - 1e-9));
}

}  // namespace

int searchLevels(const SearchWindow& window) {
  // The branch and bound starts from the finest blocks as wide as the window.
  const int width = 2 * windowCells(window) + 1;
  int level = 0;
  while (level + 1 < LikelihoodField::kLevels && (1 << level) < width) ++level;
  return level + 1;
}

namespace {

// correlativeSearch, leaving out translations within `excluded_radius` (m, along x and along y; < 0: none) of
// `excluded`.
SearchResult search(const LikelihoodField& field, const ScanPoints& scan, const Pose2D& centre,
                    const SearchWindow& window, const TranslationPrior& prior, const Eigen::Vector2d& excluded,
                    double excluded_radius) {
  SearchResult result;
  result.pose = centre;
  std::vector<Eigen::Vector2d> points;
  points.reserve(scan.points.size());
  for (const Eigen::Vector2d& p : scan.points)
    if (p.allFinite()) points.push_back(p);
  if (points.empty()) return result;

  const double resolution = LikelihoodField::kResolution;
  const double angle_step = angularStep(points);
  result.angle_step = angle_step;
  const int angles = static_cast<int>(std::ceil(std::max(window.angular, 0.0) / angle_step));
  const int shifts = windowCells(window);

  // Each rotation's points as cells, the translation at the centre. The buffers are kept from one search to the
  // next (a search per scan, a hundred rotations or more each on a dense log).
  thread_local std::vector<std::vector<Eigen::Vector2i>> rotated;
  rotated.resize(static_cast<std::size_t>(2 * angles + 1));
  for (int a = -angles; a <= angles; ++a) {
    const PoseTransform to_map(Pose2D{centre.x, centre.y, centre.theta + a * angle_step});
    std::vector<Eigen::Vector2i>& cells = rotated[static_cast<std::size_t>(a + angles)];
    cells.resize(points.size());  // written by index, not appended: the loop vectorises
    for (std::size_t i = 0; i < points.size(); ++i) {
      const Eigen::Vector2d c = field.toCell(to_map(points[i]));
      cells[i] = Eigen::Vector2i(floorToInt(c.x() + 0.5), floorToInt(c.y() + 0.5));
    }
  }

  // Fewer levels built than the window would start from: the same answer from finer blocks, more of them.
  const int level = std::min(searchLevels(window), field.levels()) - 1;
  const Eigen::Vector2d expected_cells = (prior.expected - Eigen::Vector2d(centre.x, centre.y)) / resolution;
  BranchAndBound bnb(field, rotated, shifts, angles, expected_cells, std::max(prior.weight, 0.0) * resolution);
  if (excluded_radius >= 0.0) {
    const Eigen::Vector2d cells = (excluded - Eigen::Vector2d(centre.x, centre.y)) / resolution;
    bnb.exclude(Eigen::Vector2i(static_cast<int>(std::lround(cells.x())), static_cast<int>(std::lround(cells.y()))),
                // Beyond the rounding of the excluded cell and the refinement's reach (a cell), so that the result
                // still lies more than excluded_radius away.
                static_cast<int>(std::ceil(excluded_radius / resolution + 1.5)));
  }
  std::vector<Candidate> top;
  for (int r = 0; r <= 2 * angles; ++r)
    for (int y = -shifts; y <= shifts; y += 1 << level)
      for (int x = -shifts; x <= shifts; x += 1 << level) top.push_back({r, x, y, level, bnb.score(r, x, y, level)});
  bnb.descend(top.data(), top.size());
  const Candidate& best = bnb.best();
  result.candidates = bnb.evaluated();
  if (!std::isfinite(best.score)) {  // everything excluded
    result.score = -std::numeric_limits<double>::infinity();
    return result;
  }

  // Finer than the grid, on the interpolated field: down to a tenth of a cell and an eighth of a rotation step.
  Pose2D refined{centre.x + best.x * resolution, centre.y + best.y * resolution,
                 centre.theta + (best.rotation - angles) * angle_step};
  double refined_score = interpolatedScore(field, rotatedBy(points, refined.theta), refined.x, refined.y);
  refined = refine(field, points, refined, 0.4 * resolution, 0.25 * angle_step, 5, &refined_score,
                   &result.candidates);
  refined = refine(field, points, refined, 0.1 * resolution, 0.125 * angle_step, 3, &refined_score,
                   &result.candidates);
  result.pose = {refined.x, refined.y, normalizeAngle(refined.theta)};
  result.score = refined_score;
  return result;
}

}  // namespace

SearchResult correlativeSearch(const LikelihoodField& field, const ScanPoints& scan, const Pose2D& centre,
                               const SearchWindow& window, const TranslationPrior& prior) {
  return search(field, scan, centre, window, prior, Eigen::Vector2d::Zero(), -1.0);
}

SearchResult correlativeSearchElsewhere(const LikelihoodField& field, const ScanPoints& scan, const Pose2D& centre,
                                        const SearchWindow& window, const Eigen::Vector2d& excluded,
                                        double excluded_radius) {
  return search(field, scan, centre, window, TranslationPrior{}, excluded, std::max(excluded_radius, 0.0));
}

}  // namespace hector_style_mapping
