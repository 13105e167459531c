// Loop closure on a synthetic loop with known drift: the front end's poses (each step's motion 3 % too long and
// turned 0.1 degree too far) drift by 0.8 m round a 28 m ring corridor; when the robot is back where it
// started, its keyframes match the first ones and the graph spreads the drift back over the loop.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "hector_style_mapping_core/anchored_trajectory.h"
#include "hector_style_mapping_core/loop_closure.h"
#include "hector_style_mapping_core/loop_closure_worker.h"
#include "hector_style_mapping_core/slam_processor.h"
#include "hector_style_mapping_core/testing/synthetic_world.h"

namespace hector_style_mapping {
namespace {

using testing::kDegree;

// A ring corridor 2 m wide round a 6 x 4 m block, with pillars and notches so that no stretch is featureless.
testing::SyntheticWorld ring() {
  testing::SyntheticWorld world;
  world.addBox({-1.03, -1.02}, {9.04, 7.01});
  world.addBox({0.98, 1.01}, {7.02, 4.97});
  world.addBox({2.51, -1.02}, {2.83, -0.71});  // notches in the outer wall
  world.addBox({9.04 - 0.3, 2.47}, {9.04, 2.91});
  world.addBox({5.12, 6.71}, {5.6, 7.01});
  world.addBox({-1.03, 3.33}, {-0.69, 3.71});
  world.addBox({4.4, 0.98 - 0.25}, {4.7, 0.98});  // pillars against the block
  world.addBox({0.73, 2.2}, {0.98, 2.6});
  return world;
}

// Poses along the corridor's centre line, 0.4 m apart, facing the way they go, once round and a quarter more.
std::vector<Pose2D> tour() {
  const std::vector<Eigen::Vector2d> corners = {{0, 0}, {8, 0}, {8, 6}, {0, 6}, {0, 0}, {8, 0}};
  std::vector<Pose2D> poses;
  for (std::size_t i = 0; i + 1 < corners.size(); ++i) {
    const Eigen::Vector2d a = corners[i], b = corners[i + 1];
    const double heading = std::atan2(b.y() - a.y(), b.x() - a.x());
    const int steps = static_cast<int>(std::round((b - a).norm() / 0.4));
    for (int s = 0; s < steps; ++s) {
      const Eigen::Vector2d p = a + (b - a) * s / steps;
      poses.push_back({p.x(), p.y(), heading});
    }
  }
  return poses;
}

// The front end's view of a step: 3 % too long and turned 0.1 degree too far.
Pose2D drifted(const Pose2D& step) { return {1.03 * step.x, 1.03 * step.y, step.theta + 0.1 * kDegree}; }

// The laser every ring test scans with: 360 beams, 1 cm range noise.
testing::LaserConfig ringLaser() {
  testing::LaserConfig laser;
  laser.beams = 360;
  laser.range_noise_sigma = 0.01;
  return laser;
}

double distance(const Pose2D& a, const Pose2D& b) { return std::hypot(a.x - b.x, a.y - b.y); }

std::vector<Pose2D> posesOf(const LoopClosure& loop) {
  std::vector<Pose2D> poses;
  for (int i = 0; i < loop.keyframes(); ++i) poses.push_back(loop.pose(i));
  return poses;
}

// A pose graph cannot tell where along the loop a drift this even came from: it spreads it over the loop, so
// the keyframes are right where the loop closes and off by less than half the drift in between.
TEST(LoopClosure, SpreadsTheDriftOfARingBackOverIt) {
  const testing::SyntheticWorld world = ring();
  const std::vector<Pose2D> truth = tour();
  const testing::LaserConfig laser = ringLaser();
  std::mt19937 rng(7);

  LoopClosure loop;
  std::vector<Pose2D> dead_reckoned = {truth[0]};  // the same drift with nothing to correct it
  int closed_at = -1;
  for (std::size_t k = 0; k < truth.size(); ++k) {
    Pose2D matched = truth[0];
    if (k > 0) {
      const Pose2D step = drifted(between(truth[k - 1], truth[k]));
      matched = compose(loop.pose(static_cast<int>(k) - 1), step);
      dead_reckoned.push_back(compose(dead_reckoned.back(), step));
    }
    if (loop.addKeyframe(world.scan(truth[k], laser, &rng), matched) && closed_at < 0)
      closed_at = static_cast<int>(k);
  }
  ASSERT_EQ(loop.keyframes(), static_cast<int>(truth.size()));
  const auto error = [&](int k) { return distance(loop.pose(k), truth[static_cast<std::size_t>(k)]); };
  const auto drift = [&](int k) {
    return distance(dead_reckoned[static_cast<std::size_t>(k)], truth[static_cast<std::size_t>(k)]);
  };
  // Round the ring is 70 keyframes; the first closure comes within kCandidateRadius of the start.
  constexpr int kRound = 70;
  EXPECT_GE(closed_at, kRound - 8);
  EXPECT_LE(closed_at, kRound);
  EXPECT_GE(loop.closures(), 3);
  EXPECT_GT(drift(kRound), 0.5);  // what there is to correct
  for (int k = kRound - 5; k <= kRound + 2; ++k) EXPECT_LT(error(k), 0.05) << "keyframe " << k;
  double worst = 0.0;
  for (int k = 0; k <= kRound; ++k) worst = std::max(worst, error(k));
  EXPECT_LT(worst, 0.5 * drift(kRound));
  const int last = loop.keyframes() - 1;
  EXPECT_LT(error(last), 0.5 * drift(last));
  EXPECT_LT(std::abs(angleDifference(loop.pose(kRound).theta, truth[kRound].theta)), 1.0 * kDegree);
}

// The path between keyframes moves with them: round the ring, a pose halfway to the next keyframe (as the front
// end saw it, after the newest keyframe) ends as close to the truth as the keyframes do, where as appended it is
// off by the drift.
TEST(LoopClosure, AnchoredTrajectoryFollowsTheClosedLoop) {
  const testing::SyntheticWorld world = ring();
  const std::vector<Pose2D> truth = tour();
  const testing::LaserConfig laser = ringLaser();
  std::mt19937 rng(7);

  LoopClosure loop;
  AnchoredTrajectory path;
  std::vector<Pose2D> halfway_truth, as_appended;
  for (std::size_t k = 0; k + 1 < truth.size(); ++k) {
    const Pose2D matched =
        k == 0 ? truth[0] : compose(loop.pose(static_cast<int>(k) - 1), drifted(between(truth[k - 1], truth[k])));
    loop.addKeyframe(world.scan(truth[k], laser, &rng), matched);
    const Pose2D half_step = between(truth[k], truth[k + 1]);
    const Pose2D seen = compose(loop.pose(static_cast<int>(k)), drifted({0.5 * half_step.x, 0.5 * half_step.y, 0.0}));
    path.append(seen, posesOf(loop));
    as_appended.push_back(seen);
    halfway_truth.push_back(compose(truth[k], {0.5 * half_step.x, 0.5 * half_step.y, 0.0}));
  }
  ASSERT_GE(loop.closures(), 3);
  ASSERT_EQ(path.size(), as_appended.size());
  const std::vector<Pose2D> keyframes = posesOf(loop);
  double worst_as_appended = 0.0;
  for (std::size_t i = 0; i < path.size(); ++i) {
    worst_as_appended = std::max(worst_as_appended, distance(as_appended[i], halfway_truth[i]));
    // Its keyframe's error, and 2 cm for the half step's own 3 % and the keyframe's heading error over it.
    const double keyframe_error = distance(loop.pose(static_cast<int>(i)), truth[i]);
    EXPECT_LT(distance(path.pose(i, keyframes), halfway_truth[i]), keyframe_error + 0.02) << "pose " << i;
  }
  EXPECT_GT(worst_as_appended, 0.3);  // what the closures corrected (0.44 m)
}

// Without keyframes (loop closure off) the path is kept as given.
TEST(LoopClosure, AnchoredTrajectoryWithoutKeyframesKeepsThePoses) {
  const std::vector<Pose2D> none;
  AnchoredTrajectory path;
  path.append({1.0, 2.0, 0.5}, none);
  path.append({-3.0, 0.25, -2.0}, none);
  ASSERT_EQ(path.size(), 2u);
  EXPECT_DOUBLE_EQ(path.pose(1, none).x, -3.0);
  EXPECT_DOUBLE_EQ(path.pose(1, none).y, 0.25);
  EXPECT_DOUBLE_EQ(path.pose(1, none).theta, -2.0);
  path.clear();
  EXPECT_EQ(path.size(), 0u);
}

// Keyframes less than kMinKeyframeGap apart are the front end's business: nothing is tried against them.
TEST(LoopClosure, NothingIsTriedAgainstRecentKeyframes) {
  const testing::SyntheticWorld world = ring();
  const std::vector<Pose2D> truth = tour();
  testing::LaserConfig laser;
  laser.beams = 360;
  LoopClosure loop;
  for (std::size_t k = 0; k < 30; ++k) loop.addKeyframe(world.scan(truth[k], laser), truth[k]);
  // Keyframes 20 and 25 have keyframes 0 .. 5 older than the gap, but 8 m and more away.
  EXPECT_EQ(loop.attempts(), 0);
  EXPECT_EQ(loop.closures(), 0);
  for (std::size_t k = 0; k < 30; ++k) EXPECT_NEAR(distance(loop.pose(static_cast<int>(k)), truth[k]), 0.0, 1e-9);
}

// Out 4 m along the ring's bottom corridor, a half turn on the spot, and back: keyframe 25 is at the start again,
// after a chain of 25 steps.
std::vector<Pose2D> outAndBack() {
  std::vector<Pose2D> poses;
  for (int k = 0; k <= 10; ++k) poses.push_back({0.4 * k, 0.0, 0.0});
  for (int k = 1; k <= 5; ++k) poses.push_back({4.0, 0.0, normalizeAngle(k * M_PI / 5.0)});
  for (int k = 1; k <= 10; ++k) poses.push_back({4.0 - 0.4 * k, 0.0, M_PI});
  return poses;
}

// Keyframe 25's scan, taken `shift` m further along the corridor than the front end (right all along) says.
LoopClosure outAndBackSeenFrom(double shift) {
  const testing::SyntheticWorld world = ring();
  testing::LaserConfig laser;
  laser.beams = 360;
  LoopClosure loop;
  const std::vector<Pose2D> truth = outAndBack();
  for (std::size_t k = 0; k < truth.size(); ++k) {
    Pose2D seen_from = truth[k];
    if (k + 1 == truth.size()) seen_from.x += shift;
    loop.addKeyframe(world.scan(seen_from, laser), truth[k]);
  }
  return loop;
}

// A match that puts a keyframe further from its estimate than the chain of steps since the candidate can have
// drifted (a look-alike place) is refused; one that agrees is taken.
TEST(LoopClosure, AMatchTheChainCannotExplainIsRefused) {
  // Keyframes 20 (2 m from the start) and 25 are both tried against keyframe 0.
  const LoopClosure agrees = outAndBackSeenFrom(0.0);
  EXPECT_EQ(agrees.closures(), 2);
  EXPECT_EQ(agrees.inconsistent(), 0);
  EXPECT_NEAR(agrees.pose(25).x, 0.0, 0.02);

  const LoopClosure far = outAndBackSeenFrom(1.6);
  EXPECT_EQ(far.closures(), 1);
  EXPECT_EQ(far.inconsistent(), 1);
  ASSERT_EQ(far.acceptedClosures().size(), 1u);
  EXPECT_EQ(far.acceptedClosures()[0].to, 20);
  EXPECT_NEAR(far.pose(25).x, 0.0, 0.02);  // not pulled 1.6 m along
}

// The worker in its own thread does the same work as inline: the same keyframes give the same closures and the
// same optimised poses, to the last bit.
TEST(LoopClosureWorker, InTheBackgroundFindsWhatInlineFinds) {
  const testing::SyntheticWorld world = ring();
  const std::vector<Pose2D> truth = tour();
  const testing::LaserConfig laser = ringLaser();
  std::mt19937 rng(7);
  const MapperOptions options;
  LoopClosureWorker inline_worker(options, LoopClosureThreading::kInline);
  LoopClosureWorker background(options, LoopClosureThreading::kBackground);
  std::optional<LoopClosureUpdate> last_inline;
  std::vector<Pose2D> dead_reckoned;  // the same drift with nothing to correct it
  for (std::size_t k = 0; k < truth.size(); ++k) {
    const Pose2D step = k == 0 ? truth[0] : drifted(between(truth[k - 1], truth[k]));
    dead_reckoned.push_back(k == 0 ? step : compose(dead_reckoned.back(), step));
    const ScanPoints scan = world.scan(truth[k], laser, &rng);
    inline_worker.submit(scan, step);
    background.submit(scan, step);
    if (std::optional<LoopClosureUpdate> update = inline_worker.take()) {
      EXPECT_TRUE(update->map);  // inline too, the map comes redrawn
      last_inline = std::move(update);
    }
  }
  background.waitUntilIdle();
  const std::optional<LoopClosureUpdate> last_background = background.take();
  ASSERT_TRUE(last_inline);
  ASSERT_TRUE(last_background);
  EXPECT_FALSE(background.take());  // taken
  const LoopClosureStats a = inline_worker.stats(), b = background.stats();
  EXPECT_EQ(a.keyframes, static_cast<int>(truth.size()));
  EXPECT_EQ(b.keyframes, a.keyframes);
  EXPECT_GE(a.closures.size(), 3u);
  EXPECT_EQ(b.closures.size(), a.closures.size());
  EXPECT_EQ(b.attempts, a.attempts);
  ASSERT_EQ(last_background->poses.size(), last_inline->poses.size());
  double worst_error = 0.0, worst_drift = 0.0;
  for (std::size_t i = 0; i < last_inline->poses.size(); ++i) {
    EXPECT_EQ(last_background->poses[i].x, last_inline->poses[i].x) << i;
    EXPECT_EQ(last_background->poses[i].theta, last_inline->poses[i].theta) << i;
    worst_error = std::max(worst_error, distance(last_background->poses[i], truth[i]));
    worst_drift = std::max(worst_drift, distance(dead_reckoned[i], truth[i]));
  }
  EXPECT_GT(worst_drift, 0.5);  // what there was to correct
  EXPECT_LT(worst_error, 0.5 * worst_drift);  // the drift spread over the loop
  // The map comes redrawn from the optimised keyframes, the same cell for cell either way.
  ASSERT_TRUE(last_background->map);
  ASSERT_TRUE(last_inline->map);
  const OccupancyGridMap& inline_map = last_inline->map->finest();
  const OccupancyGridMap& background_map = last_background->map->finest();
  int differing = 0;
  for (int y = 0; y < inline_map.sizeY(); ++y)
    for (int x = 0; x < inline_map.sizeX(); ++x) differing += inline_map.logOdds(x, y) != background_map.logOdds(x, y);
  EXPECT_EQ(differing, 0);
  EXPECT_GT(last_background->map->finest().logOdds(
                static_cast<int>((truth[0].x - last_background->map->finest().origin().x()) / options.map_resolution),
                static_cast<int>((truth[0].y - 1.02 - last_background->map->finest().origin().y()) /
                                 options.map_resolution)), 0.0);  // the outer wall below the start
}

// A SlamProcessor's settings for the ring: the search and loop closure on.
MapperOptions ringMapperOptions() {
  MapperOptions options;
  options.map_resolution = 0.05;
  options.map_size = 512;
  options.search_window_linear = 1.0;
  options.search_window_angular = 1.7;  // the tour turns its corners in one step
  options.loop_closure = true;
  options.map_update_distance_thresh = 0.3;  // every scan of the tour a keyframe
  return options;
}

// A SlamProcessor round the ring with loop closure in the background: the closures it adopts along the way
// leave its map exactly as a redraw of its keyframes at their final poses (nothing missing, nothing drawn
// twice, nothing half-written), and its keyframes as near the truth as inline.
TEST(LoopClosureWorker, SlamProcessorInTheBackgroundKeepsItsMapTheRedrawOfItsKeyframes) {
  const testing::SyntheticWorld world = ring();
  const std::vector<Pose2D> truth = tour();
  const testing::LaserConfig laser = ringLaser();
  const MapperOptions options = ringMapperOptions();
  for (const LoopClosureThreading threading : {LoopClosureThreading::kInline, LoopClosureThreading::kBackground}) {
    std::mt19937 rng(11);
    SlamProcessor slam(options, threading);
    slam.reset(truth[0]);
    std::vector<ScanPoints> mapped;
    std::vector<Pose2D> mapped_truth;
    double worst = 0.0;
    for (const Pose2D& pose : truth) {
      const ScanPoints scan = world.scan(pose, laser, &rng);
      slam.update(scan);
      if (slam.mapUpdatedByLastScan()) {
        mapped.push_back(scan);
        mapped_truth.push_back(pose);
      }
      slam.map();  // read between scans, as a node's map publisher does
    }
    slam.finishLoopClosure();
    const std::vector<Pose2D>& keyframes = slam.keyframePoses();
    ASSERT_EQ(keyframes.size(), mapped.size());
    EXPECT_EQ(slam.loopClosureStats().keyframes, static_cast<int>(keyframes.size()));
    EXPECT_GE(slam.loopClosureAdoptions(), 1);
    MultiResolutionMap redrawn(options);
    for (std::size_t i = 0; i < keyframes.size(); ++i) {
      redrawn.updateByScan(mapped[i], keyframes[i]);
      worst = std::max(worst, distance(keyframes[i], mapped_truth[i]));
    }
    const OccupancyGridMap& a = slam.map().finest();
    const OccupancyGridMap& b = redrawn.finest();
    int differing = 0, occupied = 0;
    for (int y = 0; y < a.sizeY(); ++y)
      for (int x = 0; x < a.sizeX(); ++x) {
        differing += a.logOdds(x, y) != b.logOdds(x, y);
        occupied += b.isOccupied(x, y);
      }
    EXPECT_EQ(differing, 0) << (threading == LoopClosureThreading::kInline ? "inline" : "background");
    EXPECT_GT(occupied, 400);  // the ring's walls: 56 m of them, 0.05 m cells
    EXPECT_LT(worst, 0.15);
  }
}

// Inline (benchmarks, offline runs), a closed loop's scans are matched against the redrawn map at once, whether
// or not anyone reads the map: reading it changes nothing. (The map used to be redrawn only when read, and until
// then the scans after a closure went unrefined and unmapped: offline, where nothing reads it, a different
// mapper from the node's.)
TEST(LoopClosureWorker, InlineReadingTheMapChangesNothing) {
  const testing::SyntheticWorld world = ring();
  const std::vector<Pose2D> truth = tour();
  const testing::LaserConfig laser = ringLaser();
  const MapperOptions options = ringMapperOptions();
  std::vector<Pose2D> keyframes[2];
  Pose2D last_pose[2];
  for (const bool read : {false, true}) {
    std::mt19937 rng(11);
    SlamProcessor slam(options, LoopClosureThreading::kInline);
    slam.reset(truth[0]);
    for (const Pose2D& pose : truth) {
      slam.update(world.scan(pose, laser, &rng));
      if (read) slam.map();
    }
    EXPECT_GE(slam.loopClosureAdoptions(), 1);
    keyframes[read] = slam.keyframePoses();
    last_pose[read] = slam.pose();
  }
  ASSERT_EQ(keyframes[0].size(), keyframes[1].size());
  for (std::size_t i = 0; i < keyframes[0].size(); ++i) {
    EXPECT_EQ(keyframes[0][i].x, keyframes[1][i].x) << i;
    EXPECT_EQ(keyframes[0][i].y, keyframes[1][i].y) << i;
    EXPECT_EQ(keyframes[0][i].theta, keyframes[1][i].theta) << i;
  }
  EXPECT_EQ(last_pose[0].x, last_pose[1].x);
  EXPECT_EQ(last_pose[0].y, last_pose[1].y);
}

}  // namespace
}  // namespace hector_style_mapping
