// LaserScan -> base-frame points: beam angles, the laser's pose from tf, hector's filters, bad scans.
#include <cmath>
#include <limits>

#include <gtest/gtest.h>

#include "hector_style_mapping/ros/scan_conversion.h"

namespace hector_style_mapping {
namespace {

sensor_msgs::LaserScan scanOf(std::vector<float> ranges, double angle_min, double increment) {
  sensor_msgs::LaserScan scan;
  scan.angle_min = static_cast<float>(angle_min);
  scan.angle_increment = static_cast<float>(increment);
  scan.angle_max = static_cast<float>(angle_min + increment * (ranges.size() - 1));
  scan.range_min = 0.1f;
  scan.range_max = 10.0f;
  scan.ranges = std::move(ranges);
  return scan;
}

TEST(ScanToPoints, BeamIGoesAtAngleMinPlusITimesTheIncrement) {
  const auto scan = scanOf({1.0f, 2.0f, 3.0f}, -M_PI / 2, M_PI / 2);
  ScanPoints points;
  const auto report = scanToPoints(scan, Eigen::Isometry3d::Identity(), ScanFilter{}, &points);
  ASSERT_TRUE(report.error.empty());
  EXPECT_EQ(report.beams, 3);
  EXPECT_EQ(report.expected_beams, 3);
  ASSERT_EQ(points.points.size(), 3u);
  EXPECT_NEAR(points.points[0].x(), 0.0, 1e-6);
  EXPECT_NEAR(points.points[0].y(), -1.0, 1e-6);
  EXPECT_NEAR(points.points[1].x(), 2.0, 1e-6);
  EXPECT_NEAR(points.points[2].y(), 3.0, 1e-6);
}

TEST(ScanToPoints, UsesTheLasersPoseInTheBaseFrame) {
  // Laser 0.2 m ahead of the base, 0.3 m up, turned 90 degrees left: its +x is the base's +y.
  Eigen::Isometry3d laser = Eigen::Isometry3d::Identity();
  laser.translate(Eigen::Vector3d(0.2, 0.0, 0.3));
  laser.rotate(Eigen::AngleAxisd(M_PI / 2, Eigen::Vector3d::UnitZ()));
  ScanPoints points;
  scanToPoints(scanOf({1.0f}, 0.0, 0.1), laser, ScanFilter{}, &points);
  ASSERT_EQ(points.points.size(), 1u);
  EXPECT_NEAR(points.points[0].x(), 0.2, 1e-6);
  EXPECT_NEAR(points.points[0].y(), 1.0, 1e-6);
  EXPECT_NEAR(points.origin.x(), 0.2, 1e-9);
  EXPECT_NEAR(points.origin.y(), 0.0, 1e-9);
}

TEST(ScanToPoints, AnUpsideDownLaserMirrorsTheScan) {
  Eigen::Isometry3d laser(Eigen::AngleAxisd(M_PI, Eigen::Vector3d::UnitX()));
  ScanPoints points;
  scanToPoints(scanOf({1.0f}, M_PI / 2, 0.1), laser, ScanFilter{}, &points);
  ASSERT_EQ(points.points.size(), 1u);
  EXPECT_NEAR(points.points[0].y(), -1.0, 1e-6);
}

TEST(ScanToPoints, NanAndInfAreCountedAndSkipped) {
  const float nan = std::numeric_limits<float>::quiet_NaN(), inf = std::numeric_limits<float>::infinity();
  ScanPoints points;
  const auto report = scanToPoints(scanOf({nan, 1.0f, inf, -inf, 2.0f}, 0.0, 0.1), Eigen::Isometry3d::Identity(),
                                   ScanFilter{}, &points);
  EXPECT_EQ(report.nan, 1);
  EXPECT_EQ(report.infinite, 2);
  EXPECT_EQ(report.used, 2);
  EXPECT_EQ(points.points.size(), 2u);
}

TEST(ScanToPoints, RangesOutsideTheSensorsOrHectorsLimitsAreDropped) {
  ScanFilter filter;
  filter.laser_min_dist = 0.4;
  filter.laser_max_dist = 5.0;
  // 0.05 < range_min; 0.3 < laser_min_dist; 10 = range_max (no return); 6 > laser_max_dist.
  ScanPoints points;
  const auto report = scanToPoints(scanOf({0.05f, 0.3f, 1.0f, 10.0f, 6.0f, 4.9f}, 0.0, 0.1),
                                   Eigen::Isometry3d::Identity(), filter, &points);
  EXPECT_EQ(report.out_of_range, 4);
  EXPECT_EQ(report.used, 2);
}

TEST(ScanToPoints, EndPointsOutsideTheHeightBandAreDropped) {
  // Laser pitched 30 degrees down: a beam straight ahead at 3 m ends 1.5 m below the laser.
  Eigen::Isometry3d laser(Eigen::AngleAxisd(M_PI / 6, Eigen::Vector3d::UnitY()));
  ScanFilter filter;
  filter.laser_z_min_value = -1.0;
  ScanPoints points;
  const auto report = scanToPoints(scanOf({1.0f, 3.0f}, 0.0, 0.0001), laser, filter, &points);
  EXPECT_EQ(report.outside_height, 1);
  EXPECT_EQ(report.used, 1);
}

TEST(ScanToPoints, FewerRangesThanTheAnglesSayAreUsedAsFarAsTheyGo) {
  auto scan = scanOf({1.0f, 1.0f, 1.0f, 1.0f}, 0.0, 0.1);
  scan.ranges.resize(2);
  ScanPoints points;
  const auto report = scanToPoints(scan, Eigen::Isometry3d::Identity(), ScanFilter{}, &points);
  EXPECT_TRUE(report.error.empty());
  EXPECT_EQ(report.beams, 2);
  EXPECT_EQ(report.expected_beams, 4);
  EXPECT_EQ(points.points.size(), 2u);
}

TEST(ScanToPoints, AScanWithoutUsableAnglesIsAnErrorNotACrash) {
  for (float increment : {0.0f, std::numeric_limits<float>::quiet_NaN()}) {
    auto scan = scanOf({1.0f, 1.0f}, 0.0, 0.1);
    scan.angle_increment = increment;
    ScanPoints points;
    points.points.emplace_back(1.0, 1.0);  // stale content must go
    const auto report = scanToPoints(scan, Eigen::Isometry3d::Identity(), ScanFilter{}, &points);
    EXPECT_NE(report.error.find("angle_increment"), std::string::npos) << report.error;
    EXPECT_TRUE(points.points.empty());
  }
}

}  // namespace
}  // namespace hector_style_mapping
