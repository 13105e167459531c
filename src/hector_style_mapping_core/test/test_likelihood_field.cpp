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

}  // namespace
}  // namespace hector_style_mapping
