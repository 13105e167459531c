// The correlative search on its own: a scan put back where it was taken, from far off, and its branch and
// bound against the brute-force search it stands for.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

#include "hector_style_mapping_core/correlative_search.h"
#include "hector_style_mapping_core/likelihood_field.h"
#include "hector_style_mapping_core/testing/synthetic_world.h"

namespace hector_style_mapping {
namespace {

using testing::kDegree;

struct Scene {
  LikelihoodField field;
  ScanPoints scan;  // taken at the truth, after the field's scans
};

// The small maze's field from two scans at `truth`, and a third scan taken there.
Scene sceneAt(const Pose2D& truth) {
  const testing::SyntheticWorld world = testing::smallMaze();
  testing::LaserConfig laser;
  laser.range_noise_sigma = 0.01;
  std::mt19937 rng(21);
  std::vector<PlacedScan> recent = {{truth, world.scan(truth, laser, &rng)}, {truth, world.scan(truth, laser, &rng)}};
  return {LikelihoodField(recent), world.scan(truth, laser, &rng)};
}

double meanFieldValue(const LikelihoodField& field, const ScanPoints& scan, const Pose2D& pose) {
  double sum = 0.0;
  for (const Eigen::Vector2d& p : scan.points) {
    const Eigen::Vector2d c = field.toCell(transformPoint(pose, p));
    sum += field.value(static_cast<int>(std::floor(c.x() + 0.5)), static_cast<int>(std::floor(c.y() + 0.5)));
  }
  return sum / static_cast<double>(scan.points.size());
}

TEST(CorrelativeSearch, FindsAScanHalfAMetreAndTwentyDegreesOff) {
  const Pose2D truth{1.0, 0.2, 0.3};
  const Scene s = sceneAt(truth);
  const SearchResult found = correlativeSearch(s.field, s.scan, {1.4, -0.1, 0.3 + 20 * kDegree}, {0.6, 0.45});
  // The refinement reaches a tenth of a 5 cm cell; the scans' 1 cm noise leaves about that.
  EXPECT_LT(std::hypot(found.pose.x - truth.x, found.pose.y - truth.y), 0.01);
  EXPECT_LT(std::abs(angleDifference(found.pose.theta, truth.theta)), 0.2 * kDegree);
  // Nearly every point on a wall the field knows, none in its free space: the blur's value a few mm off.
  EXPECT_GT(found.score, 0.9);
  EXPECT_LE(found.score, 1.0);
  // Branch and bound scores far fewer poses than the 25 x 25 shifts times the rotations of brute force.
  const double rotations = 2.0 * std::ceil(0.45 / found.angle_step) + 1.0;
  EXPECT_LT(found.candidates, 0.1 * 25 * 25 * rotations);
}

// Branch and bound is exact: on random windows its grid winner scores as the brute-force one.
TEST(CorrelativeSearch, BranchAndBoundFindsTheBruteForceBest) {
  const Pose2D truth{1.0, 0.2, 0.3};
  const Scene s = sceneAt(truth);
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> offset(-0.4, 0.4), turn(-0.3, 0.3);
  for (int trial = 0; trial < 5; ++trial) {
    const Pose2D centre{truth.x + offset(rng), truth.y + offset(rng), truth.theta + turn(rng)};
    const SearchWindow window{0.3, 0.1};
    const SearchResult found = correlativeSearch(s.field, s.scan, centre, window);
    // Brute force over the same grid: translations one cell apart, rotations found.angle_step apart.
    const int shifts = static_cast<int>(std::ceil(window.linear / LikelihoodField::kResolution));
    const int angles = static_cast<int>(std::ceil(window.angular / found.angle_step));
    double best = -std::numeric_limits<double>::infinity();
    for (int a = -angles; a <= angles; ++a)
      for (int dy = -shifts; dy <= shifts; ++dy)
        for (int dx = -shifts; dx <= shifts; ++dx)
          best = std::max(best, meanFieldValue(s.field, s.scan,
                                               {centre.x + dx * LikelihoodField::kResolution,
                                                centre.y + dy * LikelihoodField::kResolution,
                                                centre.theta + a * found.angle_step}));
    // The refinement can only add to the grid winner's score, by at most what a fraction of a cell brings.
    EXPECT_GE(found.score, best - 0.02) << "trial " << trial;
    EXPECT_LE(found.score, best + 0.15) << "trial " << trial;
  }
}

// A field with fewer levels than the window would start from gives the same answer (branch and bound is exact),
// from more, finer blocks.
TEST(CorrelativeSearch, FewerLevelsTheSameAnswer) {
  const Pose2D truth{1.0, 0.2, 0.3};
  const testing::SyntheticWorld world = testing::smallMaze();
  testing::LaserConfig laser;
  laser.range_noise_sigma = 0.01;
  std::mt19937 rng(21);
  const std::vector<PlacedScan> recent = {{truth, world.scan(truth, laser, &rng)}};
  const ScanPoints scan = world.scan(truth, laser, &rng);
  const SearchWindow window{0.6, 0.45};
  EXPECT_EQ(searchLevels(window), 6);  // 25 cells across: blocks of 32
  EXPECT_EQ(searchLevels({0.2, 0.1}), 5);  // 9 cells across: blocks of 16
  LikelihoodField full(recent), few;
  few.build(recent, 2);
  const Pose2D centre{1.4, -0.1, 0.3 + 20 * kDegree};
  const SearchResult a = correlativeSearch(full, scan, centre, window);
  const SearchResult b = correlativeSearch(few, scan, centre, window);
  EXPECT_EQ(a.pose.x, b.pose.x);
  EXPECT_EQ(a.pose.y, b.pose.y);
  EXPECT_EQ(a.pose.theta, b.pose.theta);
  EXPECT_LT(std::hypot(b.pose.x - truth.x, b.pose.y - truth.y), 0.01);
  EXPECT_GT(b.candidates, a.candidates);  // from blocks of 2 cells, not 32
}

TEST(CorrelativeSearch, StaysInsideItsWindow) {
  const Pose2D truth{1.0, 0.2, 0.3};
  const Scene s = sceneAt(truth);
  const Pose2D centre{1.6, -0.4, 0.3};
  const SearchResult found = correlativeSearch(s.field, s.scan, centre, {0.2, 0.1});
  // The window plus the refinement's reach: two fifths of a cell twice, and its rotations.
  EXPECT_LE(std::abs(found.pose.x - centre.x), 0.2 + 0.8 * LikelihoodField::kResolution + 1e-9);
  EXPECT_LE(std::abs(found.pose.y - centre.y), 0.2 + 0.8 * LikelihoodField::kResolution + 1e-9);
  EXPECT_LE(std::abs(angleDifference(found.pose.theta, centre.theta)), 0.1 + found.angle_step);
}

// A featureless corridor 2 m wide along x, 100 m long, seen with a 6 m laser from the origin: the field of one
// scan, and a second scan taken there.
Scene corridorAtTheOrigin() {
  testing::SyntheticWorld corridor;
  corridor.addWall({-50.0, -1.03}, {50.0, -1.03});
  corridor.addWall({-50.0, 0.97}, {50.0, 0.97});
  testing::LaserConfig laser;
  laser.max_range = 6.0;
  const Pose2D origin{0.0, 0.0, 0.0};
  return {LikelihoodField({{origin, corridor.scan(origin, laser)}}), corridor.scan(origin, laser)};
}

// Along a corridor every position fits alike; the prior picks the expected one.
TEST(CorrelativeSearch, APriorDecidesAlongACorridor) {
  const Pose2D truth{0.0, 0.0, 0.0};
  const Scene s = corridorAtTheOrigin();
  const LikelihoodField& field = s.field;
  const ScanPoints& scan = s.scan;
  for (const double expected_x : {-0.6, 0.35}) {
    const SearchResult found =
        correlativeSearch(field, scan, truth, {1.0, 0.2}, TranslationPrior{{expected_x, 0.0}, 0.1});
    EXPECT_NEAR(found.pose.x, expected_x, LikelihoodField::kResolution);
    EXPECT_NEAR(found.pose.y, truth.y, 0.01);
    EXPECT_NEAR(found.pose.theta, truth.theta, 0.2 * kDegree);
  }
}

// The best fit elsewhere tells a place from a look-alike: in the maze nothing 0.3 m off fits nearly as well; along
// a corridor a fit 0.3 m further on is as good as the true one.
TEST(CorrelativeSearch, TheBestFitElsewhereIsFarWorseInAMazeThanAlongACorridor) {
  const Pose2D truth{1.0, 0.2, 0.3};
  const Scene maze = sceneAt(truth);
  const SearchResult here = correlativeSearch(maze.field, maze.scan, truth, {1.0, 0.2});
  const SearchResult there =
      correlativeSearchElsewhere(maze.field, maze.scan, truth, {1.0, 0.2}, {here.pose.x, here.pose.y}, 0.3);
  EXPECT_GT(std::max(std::abs(there.pose.x - here.pose.x), std::abs(there.pose.y - here.pose.y)), 0.3);
  EXPECT_LT(there.score, 0.6 * here.score);
  EXPECT_GT(there.score, -1.0);

  const Pose2D start{0.0, 0.0, 0.0};
  const Scene corridor = corridorAtTheOrigin();
  const SearchResult best = correlativeSearch(corridor.field, corridor.scan, start, {1.0, 0.2});
  const SearchResult elsewhere = correlativeSearchElsewhere(corridor.field, corridor.scan, start, {1.0, 0.2},
                                                            {best.pose.x, best.pose.y}, 0.3);
  EXPECT_GT(std::abs(elsewhere.pose.x - best.pose.x), 0.3);
  EXPECT_NEAR(elsewhere.pose.y, best.pose.y, 0.02);
  EXPECT_GT(elsewhere.score, 0.9 * best.score);
  EXPECT_LE(elsewhere.score, best.score + 1e-9);
}

TEST(CorrelativeSearch, NothingElsewhereInAWindowSmallerThanTheExclusion) {
  const Pose2D truth{1.0, 0.2, 0.3};
  const Scene s = sceneAt(truth);
  const SearchResult none = correlativeSearchElsewhere(s.field, s.scan, truth, {0.2, 0.1}, {truth.x, truth.y}, 0.3);
  EXPECT_EQ(none.score, -std::numeric_limits<double>::infinity());
}

TEST(CorrelativeSearch, AnEmptyScanReturnsTheCentre) {
  const Scene s = sceneAt({1.0, 0.2, 0.3});
  const Pose2D centre{1.3, 0.1, 0.2};
  const SearchResult none = correlativeSearch(s.field, ScanPoints{}, centre, {0.5, 0.5});
  EXPECT_EQ(none.candidates, 0);
  EXPECT_EQ(none.pose.x, centre.x);
  EXPECT_EQ(none.pose.theta, centre.theta);
}

}  // namespace
}  // namespace hector_style_mapping
