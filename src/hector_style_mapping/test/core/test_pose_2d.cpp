#include <cmath>

#include <gtest/gtest.h>

#include "hector_style_mapping/pose_2d.h"

namespace hector_style_mapping {
namespace {

TEST(Pose2D, DefaultIsTheMapOrigin) {
  const Pose2D pose;
  EXPECT_EQ(pose.x, 0.0);
  EXPECT_EQ(pose.y, 0.0);
  EXPECT_EQ(pose.theta, 0.0);
}

TEST(Pose2D, NormalizeAngleWrapsIntoHalfOpenInterval) {
  EXPECT_DOUBLE_EQ(normalizeAngle(0.5), 0.5);
  EXPECT_DOUBLE_EQ(normalizeAngle(-0.5), -0.5);
  EXPECT_DOUBLE_EQ(normalizeAngle(M_PI), M_PI);
  EXPECT_DOUBLE_EQ(normalizeAngle(-M_PI), M_PI);
  EXPECT_DOUBLE_EQ(normalizeAngle(3.0 * M_PI), M_PI);
  EXPECT_NEAR(normalizeAngle(2.0 * M_PI + 0.25), 0.25, 1e-12);
  EXPECT_NEAR(normalizeAngle(-2.0 * M_PI - 0.25), -0.25, 1e-12);
  EXPECT_NEAR(normalizeAngle(101.0 * M_PI + 0.1), -M_PI + 0.1, 1e-9);
  for (double angle = -20.0; angle <= 20.0; angle += 0.37) {
    const double wrapped = normalizeAngle(angle);
    EXPECT_GT(wrapped, -M_PI);
    EXPECT_LE(wrapped, M_PI);
    EXPECT_NEAR(std::cos(wrapped), std::cos(angle), 1e-12);
    EXPECT_NEAR(std::sin(wrapped), std::sin(angle), 1e-12);
  }
}

TEST(Pose2D, AngleDifferenceTakesTheShortWay) {
  EXPECT_NEAR(angleDifference(0.1, -0.1), 0.2, 1e-12);
  EXPECT_NEAR(angleDifference(M_PI - 0.1, -M_PI + 0.1), -0.2, 1e-12);
  EXPECT_NEAR(angleDifference(-M_PI + 0.1, M_PI - 0.1), 0.2, 1e-12);
}

TEST(Pose2D, TransformPointRotatesThenTranslates) {
  const Pose2D pose{1.0, 2.0, M_PI / 2};
  const Eigen::Vector2d p = transformPoint(pose, {1.0, 0.0});
  EXPECT_NEAR(p.x(), 1.0, 1e-12);
  EXPECT_NEAR(p.y(), 3.0, 1e-12);
  const Eigen::Vector2d q = transformPoint(pose, {0.0, 1.0});
  EXPECT_NEAR(q.x(), 0.0, 1e-12);
  EXPECT_NEAR(q.y(), 2.0, 1e-12);
}

}  // namespace
}  // namespace hector_style_mapping
