#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "hector_style_mapping_core/testing/synthetic_world.h"
#include "odometry_slam/odometry_slam.h"

namespace odometry_slam {
namespace {

namespace hsm = hector_style_mapping;
using hsm::testing::LaserConfig;
using hsm::testing::SyntheticWorld;

// A small map round the 6 x 5 m maze: 20 x 20 m.
OdometrySlamOptions mazeOptions() {
  OdometrySlamOptions options;
  options.xmin = options.ymin = -10.0;
  options.xmax = options.ymax = 10.0;
  return options;
}

double distance(const Pose2D& a, const Pose2D& b) { return std::hypot(a.x - b.x, a.y - b.y); }

// Odometry that drifts as wheel odometry does: 4 % long on every step and 0.03 rad per metre to the left.
std::vector<Pose2D> driftingOdometry(const std::vector<Pose2D>& truth) {
  std::vector<Pose2D> odometry{truth.front()};
  for (std::size_t i = 1; i < truth.size(); ++i) {
    Pose2D step = hsm::between(truth[i - 1], truth[i]);
    const double length = std::hypot(step.x, step.y);
    step.x *= 1.04;
    step.y *= 1.04;
    step.theta += 0.03 * length;
    odometry.push_back(hsm::compose(odometry.back(), step));
  }
  return odometry;
}

std::vector<Pose2D> mazeTour() {
  return hsm::testing::driveThrough(Pose2D{}, {{3.6, 0.0}, {3.6, 2.3}, {0.0, 2.3}, {-0.9, -0.3}, {0.3, -1.5}},
                                    0.05, 0.15);
}

TEST(OdometrySlam, ValidationNamesEveryBadField) {
  OdometrySlamOptions options;
  options.delta = 0.0;
  options.xmin = 5.0;
  options.srr = -0.1;
  options.occ_thresh = 1.5;
  const std::string problems = validate(options);
  for (const char* field : {"delta", "xmin", "srr", "occ_thresh"})
    EXPECT_NE(problems.find(field), std::string::npos) << field << " not in: " << problems;
  EXPECT_THROW(OdometrySlam{options}, std::invalid_argument);
  EXPECT_EQ(validate(OdometrySlamOptions{}), "");
}

TEST(OdometrySlam, MapCoversTheAreaWithTheMapFrameAtTheOdomOrigin) {
  OdometrySlamOptions options = mazeOptions();
  options.xmin = -4.0;  // the longer side (y, 20 m) makes the square
  OdometrySlam slam(options);
  const hsm::OccupancyGridMap& finest = slam.map().finest();
  EXPECT_EQ(finest.sizeX(), 400);
  EXPECT_NEAR(finest.origin().x(), -4.0, 1e-9);
  EXPECT_NEAR(finest.origin().y(), -10.0, 1e-9);
}

TEST(OdometrySlam, FirstScanStartsTheMapAtTheOdometry) {
  const SyntheticWorld world = hsm::testing::smallMaze();
  OdometrySlam slam(mazeOptions());
  const Pose2D odometry{0.3, -0.2, 0.4};  // the odom frame is the world here
  EXPECT_EQ(slam.addScan(world.scan(odometry, LaserConfig{}), odometry, 0.0), OdometrySlam::Outcome::kFirst);
  EXPECT_NEAR(distance(slam.pose(), odometry), 0.0, 1e-12);
  EXPECT_NEAR(distance(slam.mapToOdom(), Pose2D{}), 0.0, 1e-12);
  EXPECT_EQ(slam.processedScans(), 1);
  EXPECT_FALSE(slam.hitCounts().seenBox().empty());
}

TEST(OdometrySlam, ScansAreProcessedAfterLinearOrAngularUpdateOfTravelOrTemporalUpdate) {
  const SyntheticWorld world = hsm::testing::smallMaze();
  OdometrySlamOptions options = mazeOptions();
  options.linear_update = 0.5;
  options.angular_update = 0.3;
  options.temporal_update = 10.0;
  OdometrySlam slam(options);
  const auto add = [&](const Pose2D& pose, double time) {
    return slam.addScan(world.scan(pose, LaserConfig{}), pose, time);
  };
  ASSERT_EQ(add({0.0, 0.0, 0.0}, 0.0), OdometrySlam::Outcome::kFirst);
  // Back and forth by 0.2 m: the net motion stays small, the travel adds up (as gmapping sums it).
  EXPECT_EQ(add({0.2, 0.0, 0.0}, 1.0), OdometrySlam::Outcome::kSkipped);
  EXPECT_NEAR(slam.pose().x, 0.2, 1e-12);  // the pose follows the odometry between processed scans
  EXPECT_EQ(add({0.0, 0.0, 0.0}, 2.0), OdometrySlam::Outcome::kSkipped);
  EXPECT_EQ(add({0.2, 0.0, 0.0}, 3.0), OdometrySlam::Outcome::kMatched);  // 0.6 m travelled
  EXPECT_EQ(add({0.2, 0.0, 0.2}, 4.0), OdometrySlam::Outcome::kSkipped);
  EXPECT_EQ(add({0.2, 0.0, 0.35}, 5.0), OdometrySlam::Outcome::kMatched);  // 0.35 rad turned
  EXPECT_EQ(add({0.2, 0.0, 0.35}, 14.0), OdometrySlam::Outcome::kSkipped);
  EXPECT_EQ(add({0.2, 0.0, 0.35}, 15.5), OdometrySlam::Outcome::kMatched);  // 10.5 s at rest
  EXPECT_EQ(slam.processedScans(), 4);
  EXPECT_EQ(slam.refusedMatches(), 0);
}

TEST(OdometrySlam, CorrectsDriftingOdometryThroughTheMaze) {
  const SyntheticWorld world = hsm::testing::smallMaze();
  const std::vector<Pose2D> truth = mazeTour();
  const std::vector<Pose2D> odometry = driftingOdometry(truth);
  OdometrySlamOptions options = mazeOptions();
  options.linear_update = 0.25;
  options.angular_update = 0.25;
  OdometrySlam slam(options);
  double worst = 0.0;
  for (std::size_t i = 0; i < truth.size(); ++i) {
    slam.addScan(world.scan(truth[i], LaserConfig{}), odometry[i], 0.1 * i);
    worst = std::max(worst, distance(slam.pose(), truth[i]));
  }
  const double odometry_error = distance(odometry.back(), truth.back());
  const double error = distance(slam.pose(), truth.back());
  const double angle_error = std::abs(hsm::angleDifference(slam.pose().theta, truth.back().theta));
  std::printf("%zu poses, %d scans mapped: odometry off by %.3f m, SLAM by %.4f m / %.3f deg (worst %.3f m)\n",
              truth.size(), slam.processedScans(), odometry_error, error, angle_error * 180.0 / M_PI, worst);
  EXPECT_GT(odometry_error, 0.4);  // the drift is worth correcting ...
  EXPECT_LT(error, 0.03);          // ... and the matcher removes it
  EXPECT_LT(angle_error, 1.0 * hsm::testing::kDegree);
  // Between processed scans the odometry drifts for up to 0.25 m of travel: 4 % + the turn of 0.0075 rad.
  EXPECT_LT(worst, 0.06);
  EXPECT_EQ(slam.refusedMatches(), 0);
  EXPECT_TRUE(std::isfinite(slam.poseEntropy()));
}

TEST(OdometrySlam, MapOfTheMazeHasItsWallsOccupiedAndItsRoomFree) {
  const SyntheticWorld world = hsm::testing::smallMaze();
  OdometrySlamOptions options = mazeOptions();
  options.linear_update = 0.25;
  options.angular_update = 0.25;
  OdometrySlam slam(options);
  const std::vector<Pose2D> truth = mazeTour();
  for (std::size_t i = 0; i < truth.size(); ++i) slam.addScan(world.scan(truth[i], LaserConfig{}), truth[i], 0.1 * i);
  const hsm::OccupancyGridMap& finest = slam.map().finest();
  const HitCounts& counts = slam.hitCounts();
  const auto stateAt = [&](double x, double y) {
    const Eigen::Vector2i cell = finest.cellOf({x, y});
    return counts.state(cell.x(), cell.y(), slam.occThresh());
  };
  EXPECT_EQ(stateAt(4.46, 1.0), 100);   // east wall
  EXPECT_EQ(stateAt(1.0, -2.07), 100);  // south wall
  EXPECT_EQ(stateAt(0.5, 0.0), 0);      // the room
  EXPECT_EQ(stateAt(3.0, 2.0), 0);
  EXPECT_EQ(stateAt(6.0, 0.0), -1);     // beyond the walls
  // What was seen lies within the maze (1 cell of rounding).
  const CellBox& seen = counts.seenBox();
  const Eigen::Vector2d low = finest.cellCenter(seen.x0, seen.y0), high = finest.cellCenter(seen.x1 - 1, seen.y1 - 1);
  EXPECT_NEAR(low.x(), -1.53, 0.05);
  EXPECT_NEAR(low.y(), -2.07, 0.05);
  EXPECT_NEAR(high.x(), 4.46, 0.05);
  EXPECT_NEAR(high.y(), 3.04, 0.05);
}

// The same 0.15 m odometry error at a processed scan after 1 m of travel: within 3 sigma of the default error
// model (srr 0.1 per m: 0.3 m + a cell) it is corrected; with the odometry trusted (all noise 0: one cell)
// the match is refused and the odometry kept.
TEST(OdometrySlam, MatchesFurtherFromTheOdometryThanItsErrorModelAreRefused) {
  const SyntheticWorld world = hsm::testing::smallMaze();
  for (const bool trusted : {false, true}) {
    OdometrySlamOptions options = mazeOptions();
    if (trusted) options.srr = options.srt = options.str = options.stt = 0.0;
    OdometrySlam slam(options);
    slam.addScan(world.scan(Pose2D{}, LaserConfig{}), Pose2D{}, 0.0);
    const Pose2D truth{1.0, 0.0, 0.0};
    const Pose2D odometry{1.15, 0.0, 0.0};
    EXPECT_EQ(slam.addScan(world.scan(truth, LaserConfig{}), odometry, 1.0),
              trusted ? OdometrySlam::Outcome::kMatchRefused : OdometrySlam::Outcome::kMatched);
    if (trusted) {
      EXPECT_NEAR(distance(slam.pose(), odometry), 0.0, 1e-9);
      EXPECT_EQ(slam.refusedMatches(), 1);
      EXPECT_NEAR(slam.covariance()(0, 0), options.delta * options.delta, 1e-12);
    } else {
      EXPECT_LT(distance(slam.pose(), truth), 0.02);
      EXPECT_NEAR(slam.mapToOdom().x, -0.15, 0.02);  // map -> odom takes the odometry's error out
      EXPECT_LT(slam.covariance()(0, 0), 1e-3);
    }
  }
}

TEST(OdometrySlam, ScanWithoutPointsChangesNothingAndResetStartsOver) {
  const SyntheticWorld world = hsm::testing::smallMaze();
  OdometrySlam slam(mazeOptions());
  EXPECT_EQ(slam.addScan(ScanPoints{}, Pose2D{}, 0.0), OdometrySlam::Outcome::kNoPoints);
  EXPECT_EQ(slam.processedScans(), 0);
  EXPECT_EQ(slam.addScan(world.scan(Pose2D{}, LaserConfig{}), Pose2D{}, 0.0), OdometrySlam::Outcome::kFirst);
  ScanPoints empty;
  empty.points = {{std::nan(""), 0.0}};
  EXPECT_EQ(slam.addScan(empty, Pose2D{2.0, 0.0, 0.0}, 1.0), OdometrySlam::Outcome::kNoPoints);
  EXPECT_EQ(slam.processedScans(), 1);
  slam.reset();
  EXPECT_EQ(slam.processedScans(), 0);
  EXPECT_TRUE(slam.hitCounts().seenBox().empty());
  EXPECT_EQ(slam.addScan(world.scan(Pose2D{}, LaserConfig{}), Pose2D{}, 2.0), OdometrySlam::Outcome::kFirst);
}

}  // namespace
}  // namespace odometry_slam
