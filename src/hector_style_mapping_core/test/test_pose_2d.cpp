#include <cmath>

#include <gtest/gtest.h>

#include "hector_style_mapping_core/pose_2d.h"

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

TEST(Pose2D, BetweenIsTheMotionThatComposeAppliesAgain) {
  // Odometry says the robot went from a to b; the mapper moves its last match m by that motion.
  const Pose2D a{1.0, 2.0, M_PI / 2}, b{1.0, 3.0, M_PI};  // 1 m ahead, then a left quarter turn
  const Pose2D motion = between(a, b);
  EXPECT_NEAR(motion.x, 1.0, 1e-12);
  EXPECT_NEAR(motion.y, 0.0, 1e-12);
  EXPECT_NEAR(motion.theta, M_PI / 2, 1e-12);
  const Pose2D m{-2.0, 0.5, 0.0};  // the same motion from a pose facing +x
  const Pose2D predicted = compose(m, motion);
  EXPECT_NEAR(predicted.x, -1.0, 1e-12);
  EXPECT_NEAR(predicted.y, 0.5, 1e-12);
  EXPECT_NEAR(predicted.theta, M_PI / 2, 1e-12);
  const Pose2D back = compose(a, between(a, b));
  EXPECT_NEAR(back.x, b.x, 1e-12);
  EXPECT_NEAR(back.y, b.y, 1e-12);
  EXPECT_NEAR(std::abs(angleDifference(back.theta, b.theta)), 0.0, 1e-12);
}

}  // namespace
}  // namespace hector_style_mapping
