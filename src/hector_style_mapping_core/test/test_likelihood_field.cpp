// The correlative search's field: blurred hits, free space where rays passed, block maxima that bound.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "hector_style_mapping_core/likelihood_field.h"

namespace hector_style_mapping {
namespace {

Eigen::Vector2i cellOf(const LikelihoodField& field, const Eigen::Vector2d& p) {
  const Eigen::Vector2d c = field.toCell(p);
  return {static_cast<int>(std::floor(c.x() + 0.5)), static_cast<int>(std::floor(c.y() + 0.5))};
}

// One beam from a laser 0.2 m ahead of a base at (1, 2), turned 90 degrees: it hits (1, 5).
LikelihoodField oneBeam() {
  ScanPoints scan;
  scan.origin = {0.2, 0.0};
  scan.points = {{3.0, 0.0}};  // in the base frame
  return LikelihoodField({{Pose2D{1.0, 2.0, M_PI / 2}, scan}});
}

TEST(LikelihoodField, HitsAreBlurredAsAGaussian) {
  const LikelihoodField field = oneBeam();
  for (const double d : {0.0, 0.1, 0.2}) {
    // Sideways from the hit (x), where no ray passed.
    const Eigen::Vector2d at{1.0 + d, 5.0};
    const Eigen::Vector2i c = cellOf(field, at);
    // From the cell's centre to the hit.
    const double distance = ((c.cast<double>() - field.toCell({1.0, 5.0})) * LikelihoodField::kResolution).norm();
    const double sigma = LikelihoodField::kSigma;
    EXPECT_NEAR(field.value(c.x(), c.y()), std::exp(-distance * distance / (2 * sigma * sigma)), 1e-6) << d;
  }
  // Beyond 3 sigma: nothing.
  const Eigen::Vector2i far = cellOf(field, {1.0 + 0.35, 5.0});
  EXPECT_EQ(field.value(far.x(), far.y()), 0.0f);
}

TEST(LikelihoodField, WhereTheRayPassedIsFree) {
  const LikelihoodField field = oneBeam();
  for (const double y : {2.3, 3.5, 4.7}) {  // from the laser at (1, 2.2) up to 2 sigma before the hit
    const Eigen::Vector2i c = cellOf(field, {1.0, y});
    EXPECT_EQ(field.value(c.x(), c.y()), LikelihoodField::kFreeValue) << y;
  }
  // Near the hit the blur wins; beside the ray nothing was seen; outside the grid, 0.
  const Eigen::Vector2i near_hit = cellOf(field, {1.0, 4.95});
  EXPECT_GT(field.value(near_hit.x(), near_hit.y()), 0.8f);
  const Eigen::Vector2i beside = cellOf(field, {1.3, 3.5});
  EXPECT_EQ(field.value(beside.x(), beside.y()), 0.0f);
  EXPECT_EQ(field.value(-1, 0), 0.0f);
  EXPECT_EQ(field.value(field.sizeX(), 0), 0.0f);
}

// blockMax(l, x, y) is the largest value over its 2^l x 2^l cells, counting cells outside the grid as 0: exactly,
// unless the block reaches over the grid's low edge, where it may be more (still a bound).
TEST(LikelihoodField, BlockMaximaBoundTheirCells) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> range(0.5, 4.0);
  ScanPoints scan;
  for (int i = 0; i < 90; ++i) {
    const double angle = -M_PI + 2 * M_PI * i / 90.0, r = range(rng);
    scan.points.emplace_back(r * std::cos(angle), r * std::sin(angle));
  }
  const LikelihoodField field({{Pose2D{0.3, -0.2, 0.4}, scan}});
  std::uniform_int_distribution<int> x(-40, field.sizeX() + 8), y(-40, field.sizeY() + 8);
  for (int level = 0; level < LikelihoodField::kLevels; ++level) {
    for (int trial = 0; trial < 300; ++trial) {
      const int bx = x(rng), by = y(rng), size = 1 << level;
      float expected = -2.0f;
      for (int cy = by; cy < by + size; ++cy)
        for (int cx = bx; cx < bx + size; ++cx) expected = std::max(expected, field.value(cx, cy));
      if (bx >= 0 && by >= 0)
        ASSERT_EQ(field.blockMax(level, bx, by), expected) << "level " << level << " at " << bx << ", " << by;
      else
        ASSERT_GE(field.blockMax(level, bx, by), expected) << "level " << level << " at " << bx << ", " << by;
    }
  }
}

TEST(LikelihoodField, NoPointsNoGrid) {
  ScanPoints scan;
  scan.points = {{NAN, 1.0}};
  const LikelihoodField field({{Pose2D{}, scan}});
  EXPECT_EQ(field.sizeX(), 0);
  EXPECT_EQ(field.value(0, 0), 0.0f);
  EXPECT_EQ(field.blockMax(3, -2, -2), 0.0f);
  EXPECT_EQ(field.interpolate({0.0, 0.0}), 0.0);
}

// A scan of `beams` beams over a full turn, ranges 0.5-`far` m, every fifth beam a free ray (no return).
ScanPoints randomScan(std::mt19937* rng, int beams, double far) {
  std::uniform_real_distribution<double> range(0.5, far);
  ScanPoints scan;
  scan.origin = {0.1, 0.0};
  for (int i = 0; i < beams; ++i) {
    const double angle = -M_PI + 2 * M_PI * i / beams, r = range(*rng);
    (i % 5 == 0 ? scan.free_rays : scan.points).emplace_back(r * std::cos(angle), r * std::sin(angle));
  }
  return scan;
}

// Every level of `a` and `b`, cell for cell, over the same grid in the map frame.
void expectSameField(const LikelihoodField& a, const LikelihoodField& b, const char* what) {
  ASSERT_EQ(a.sizeX(), b.sizeX()) << what;
  ASSERT_EQ(a.sizeY(), b.sizeY()) << what;
  const Eigen::Vector2d somewhere{0.37, -1.21};
  EXPECT_EQ(a.toCell(somewhere), b.toCell(somewhere)) << what;
  long differing = 0, free = 0, hit = 0;
  for (int level = 0; level < LikelihoodField::kLevels; ++level)
    for (int y = 0; y < a.sizeY(); ++y)
      for (int x = 0; x < a.sizeX(); ++x) {
        differing += a.blockMax(level, x, y) != b.blockMax(level, x, y);
        if (level == 0) free += a.value(x, y) == LikelihoodField::kFreeValue, hit += a.value(x, y) > 0.5f;
      }
  EXPECT_EQ(differing, 0) << what;
  EXPECT_GT(free, 100) << what;  // not vacuous: rays and hits of every kind
  EXPECT_GT(hit, 100) << what;
}

// A mapper searches each scan against the same recent scans and the last one: the field built on top of the
// recent scans' is the field of them all on its lattice, whether the last scan lies inside their grid or reaches
// past it (the grid grows), and with a scan or a base that has no point.
TEST(LikelihoodField, BuiltOnTopItIsTheFieldOfAllTheScans) {
  std::mt19937 rng(5);
  std::vector<PlacedScan> recent;
  for (int i = 0; i < 3; ++i) recent.push_back({Pose2D{0.3 * i, 0.1 * i, 0.2 * i}, randomScan(&rng, 180, 4.0)});
  const LikelihoodField base(recent);
  ScanPoints nothing;
  nothing.points = {{NAN, 1.0}};
  const PlacedScan empty{Pose2D{5.0, 5.0, 0.0}, nothing};  // its laser far off: the grid takes it in too
  for (const PlacedScan& last : {PlacedScan{Pose2D{0.5, 0.2, 0.7}, randomScan(&rng, 180, 3.0)},   // inside
                                 PlacedScan{Pose2D{2.0, -1.0, -0.4}, randomScan(&rng, 180, 6.0)},  // past
                                 empty}) {
    std::vector<PlacedScan> all = recent;
    all.push_back(last);
    LikelihoodField on_top, all_at_once;
    on_top.buildOnTop(base, last);
    all_at_once.build(all, base.latticePoint());
    expectSameField(on_top, all_at_once, "on top");
  }
  LikelihoodField on_top;
  on_top.buildOnTop(LikelihoodField({empty}), recent[1]);
  expectSameField(on_top, LikelihoodField({recent[1]}), "on an empty base");
}

// A search reads only the levels its window needs; those built later are the ones a full build makes.
TEST(LikelihoodField, LevelsBuiltLaterAreThoseOfAFullBuild) {
  std::mt19937 rng(9);
  const std::vector<PlacedScan> scans = {{Pose2D{0.2, -0.1, 0.3}, randomScan(&rng, 180, 5.0)}};
  LikelihoodField partial;
  partial.build(scans, 2);
  EXPECT_EQ(partial.levels(), 2);
  partial.ensureLevels(LikelihoodField::kLevels);
  EXPECT_EQ(partial.levels(), LikelihoodField::kLevels);
  expectSameField(partial, LikelihoodField(scans), "levels built later");
}

}  // namespace
}  // namespace hector_style_mapping
