// Sparse pose adjustment: a drifting loop closed, a consistent graph left alone, the Jacobians, angles across
// +-pi, bad input, a wrong loop closure with and without a robust kernel, and a graph the size of a building.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <limits>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "hector_style_mapping_core/pose_graph.h"
#include "hector_style_mapping_core/testing/mentions.h"

namespace hector_style_mapping {
namespace {

using testing::mentions;

Eigen::Matrix3d informationOf(double sigma_xy, double sigma_theta) {
  return Eigen::Vector3d(1.0 / (sigma_xy * sigma_xy), 1.0 / (sigma_xy * sigma_xy), 1.0 / (sigma_theta * sigma_theta))
      .asDiagonal();
}

// A robot drives a 5 m square counter-clockwise, a pose every 0.2 m, 25 to a side; node 99 is one step short of
// node 0. The headings pass through pi on the third side.
constexpr int kSquarePoses = 100;
Pose2D squarePose(int k) {
  const int side = k / 25;
  const double along = 0.2 * (k % 25), heading = side * M_PI / 2;
  const Pose2D corners[] = {{0, 0, 0}, {5, 0, 0}, {5, 5, 0}, {0, 5, 0}};
  const Pose2D& corner = corners[side];
  return {corner.x + std::cos(heading) * along, corner.y + std::sin(heading) * along, normalizeAngle(heading)};
}

// Odometry as it comes from wheels: per 0.2 m step, a systematic heading error (a wheel base 1 % off turns
// 0.004 rad per step) and random errors (0.002 rad, 5 mm). The information matrix states 0.01 rad and 1 cm: the
// odometry model's budget for both. The loop closure, from scan matching, is good to about 1 cm and 0.005 rad
// and states 2 cm and 0.01 rad.
constexpr double kHeadingBias = 0.004;
const Eigen::Matrix3d kOdometryInformation = informationOf(0.01, 0.01);
const Eigen::Matrix3d kClosureInformation = informationOf(0.02, 0.01);

struct SquareRun {
  std::vector<Pose2D> truth;
  PoseGraph graph;  // nodes at the dead-reckoned poses, odometry constraints k -> k + 1, then 99 -> 0
  double end_drift = 0.0;  // m, dead-reckoned node 99 against its truth
};

SquareRun driveSquare(unsigned seed) {
  std::mt19937 rng(seed);
  std::normal_distribution<double> unit(0.0, 1.0);
  SquareRun run;
  for (int k = 0; k < kSquarePoses; ++k) run.truth.push_back(squarePose(k));
  Pose2D dead_reckoned = run.truth[0];
  run.graph.addNode(dead_reckoned);
  for (int k = 0; k + 1 < kSquarePoses; ++k) {
    Pose2D odometry = between(run.truth[k], run.truth[k + 1]);
    odometry.x += 0.005 * unit(rng);
    odometry.y += 0.005 * unit(rng);
    odometry.theta = normalizeAngle(odometry.theta + kHeadingBias + 0.002 * unit(rng));
    dead_reckoned = compose(dead_reckoned, odometry);
    run.graph.addNode(dead_reckoned);
    run.graph.addConstraint(k, k + 1, odometry, kOdometryInformation);
  }
  run.end_drift = std::hypot(dead_reckoned.x - run.truth.back().x, dead_reckoned.y - run.truth.back().y);
  Pose2D closure = between(run.truth.back(), run.truth.front());
  closure.x += 0.01 * unit(rng);
  closure.y += 0.01 * unit(rng);
  closure.theta += 0.005 * unit(rng);
  run.graph.addConstraint(kSquarePoses - 1, 0, closure, kClosureInformation);
  return run;
}

double rmsPositionError(const PoseGraph& graph, const std::vector<Pose2D>& truth) {
  double sum = 0.0;
  for (std::size_t k = 0; k < truth.size(); ++k) {
    const Pose2D& p = graph.pose(static_cast<int>(k));
    sum += std::pow(p.x - truth[k].x, 2) + std::pow(p.y - truth[k].y, 2);
  }
  return std::sqrt(sum / static_cast<double>(truth.size()));
}

// Node 0 is fixed at the truth, so no alignment is needed before comparing.
TEST(PoseGraph, ClosesASquareLoopWithOdometryDrift) {
  SquareRun run = driveSquare(1);
  ASSERT_GT(run.end_drift, 1.0);  // the premise: dead reckoning ends more than a metre off
  ASSERT_LT(run.end_drift, 2.0);
  EXPECT_GT(rmsPositionError(run.graph, run.truth), 0.5);

  const OptimizationSummary summary = run.graph.optimize();
  const double rms = rmsPositionError(run.graph, run.truth);
  std::printf("[          ] drift %.2f m, RMS after %.3f m, chi2 %.0f -> %.1f in %d iterations\n", run.end_drift, rms,
              summary.initial_chi2, summary.final_chi2, summary.iterations);
  EXPECT_TRUE(summary.converged);
  EXPECT_GE(summary.iterations, 2);
  EXPECT_LE(summary.iterations, 10);
  // The bound: spreading the misclosure evenly over the steps undoes a constant heading bias to first order
  // (the bias alone leaves 0.023 m RMS); the random errors leave what a single closure cannot see, 0.038 m RMS
  // on average over 1000 seeds of this model and 0.096 m at worst. The seed here gives about 0.045 m.
  EXPECT_LT(rms, 0.1);
  EXPECT_GT(rms, 0.005);
  // chi2 before: the closure alone, about (drift / 2 cm)^2 plus its heading misclosure. After: the bias is spread
  // over 99 steps, each then off by about 0.004 rad against its 0.01 rad, 99 * 0.4^2 = 15.8; the random errors
  // add a few tenths. 1000 seeds give 10.8 .. 21.0.
  EXPECT_GT(summary.initial_chi2, 2000.0);
  EXPECT_GT(summary.final_chi2, 8.0);
  EXPECT_LT(summary.final_chi2, 30.0);
  EXPECT_GT(summary.initial_chi2 / summary.final_chi2, 100.0);
  EXPECT_EQ(run.graph.pose(0).x, 0.0);  // the anchor did not move
  EXPECT_EQ(run.graph.pose(0).theta, 0.0);

  // Optimising again from the optimum changes nothing: the integrator may call it after every new closure.
  const OptimizationSummary again = run.graph.optimize();
  EXPECT_TRUE(again.converged);
  EXPECT_EQ(again.iterations, 1);
  EXPECT_NEAR(again.final_chi2, summary.final_chi2, 1e-6 * summary.final_chi2);
}

TEST(PoseGraph, AConsistentGraphStaysPutAndConvergesInOneIteration) {
  PoseGraph graph;
  for (int k = 0; k < kSquarePoses; ++k) graph.addNode(squarePose(k));
  for (int k = 0; k < kSquarePoses; ++k) {
    const int next = (k + 1) % kSquarePoses;
    graph.addConstraint(k, next, between(squarePose(k), squarePose(next)), kOdometryInformation);
  }
  const OptimizationSummary summary = graph.optimize();
  EXPECT_TRUE(summary.converged);
  EXPECT_EQ(summary.iterations, 1);
  EXPECT_LT(summary.initial_chi2, 1e-12);
  EXPECT_LE(summary.final_chi2, summary.initial_chi2);
  for (int k = 0; k < kSquarePoses; ++k) {
    const Pose2D truth = squarePose(k);
    EXPECT_NEAR(graph.pose(k).x, truth.x, 1e-9) << k;
    EXPECT_NEAR(graph.pose(k).y, truth.y, 1e-9) << k;
    EXPECT_NEAR(angleDifference(graph.pose(k).theta, truth.theta), 0.0, 1e-9) << k;
  }
}

TEST(PoseGraph, JacobiansMatchFiniteDifferences) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> coordinate(-5.0, 5.0), angle(-M_PI, M_PI), small(-0.3, 0.3);
  constexpr double kStep = 1e-6;
  for (int trial = 0; trial < 50; ++trial) {
    const Pose2D from{coordinate(rng), coordinate(rng), angle(rng)};
    const Pose2D to{coordinate(rng), coordinate(rng), angle(rng)};
    // A measurement near the current relative pose, so the error's angle stays away from the wrap at +-pi.
    const Pose2D relative = between(from, to);
    const Pose2D measured{relative.x + small(rng), relative.y + small(rng), relative.theta + small(rng)};
    const ConstraintLinearization lin = linearizeConstraint(from, to, measured);
    for (int column = 0; column < 3; ++column) {
      for (const bool moving_from : {true, false}) {
        Pose2D plus = moving_from ? from : to, minus = plus;
        double* const plus_field[] = {&plus.x, &plus.y, &plus.theta};
        double* const minus_field[] = {&minus.x, &minus.y, &minus.theta};
        *plus_field[column] += kStep;
        *minus_field[column] -= kStep;
        const Eigen::Vector3d numeric =
            moving_from ? (linearizeConstraint(plus, to, measured).error -
                           linearizeConstraint(minus, to, measured).error) / (2 * kStep)
                        : (linearizeConstraint(from, plus, measured).error -
                           linearizeConstraint(from, minus, measured).error) / (2 * kStep);
        const Eigen::Vector3d analytic = moving_from ? lin.d_from.col(column) : lin.d_to.col(column);
        EXPECT_LT((numeric - analytic).cwiseAbs().maxCoeff(), 1e-6)
            << "trial " << trial << (moving_from ? " d_from" : " d_to") << " column " << column;
      }
    }
  }
}

TEST(PoseGraph, AnglesWrapAcrossPlusMinusPi) {
  // Just either side of pi, 0.02 rad apart the short way: no error, not 2 pi.
  const Pose2D from{1.0, 2.0, M_PI - 0.01}, to{1.0, 2.0, -M_PI + 0.01};
  EXPECT_NEAR(linearizeConstraint(from, to, {0.0, 0.0, 0.02}).error.z(), 0.0, 1e-12);
  EXPECT_NEAR(linearizeConstraint(to, from, {0.0, 0.0, -0.02}).error.z(), 0.0, 1e-12);
  EXPECT_NEAR(linearizeConstraint(from, to, {0.0, 0.0, 0.0}).error.z(), 0.02, 1e-12);
  const double wrapped = linearizeConstraint(from, to, {0.0, 0.0, 0.02 + 2 * M_PI - 0.1}).error.z();
  EXPECT_NEAR(wrapped, 0.1, 1e-12);

  // A robot turning on the spot through pi, 0.1 rad a step, with exact measurements and a start up to 0.3 rad
  // off, some of it on the other side of pi: the optimum is the truth, every angle in (-pi, pi].
  PoseGraph graph;
  std::vector<Pose2D> truth;
  for (int k = 0; k < 12; ++k) truth.push_back({0.5, -0.5, normalizeAngle(M_PI - 0.55 + 0.1 * k)});
  const double start_offsets[] = {0.0, 0.3, -0.3, 0.2, -0.25, 0.3, -0.3, 0.1, 0.25, -0.2, 0.3, -0.1};
  for (int k = 0; k < 12; ++k) {
    const Pose2D& t = truth[static_cast<std::size_t>(k)];
    graph.addNode({t.x + 0.1 * start_offsets[k], t.y, t.theta + start_offsets[k]});
  }
  for (int k = 0; k + 1 < 12; ++k)
    graph.addConstraint(k, k + 1, between(truth[static_cast<std::size_t>(k)], truth[static_cast<std::size_t>(k + 1)]),
                        kOdometryInformation);
  const OptimizationSummary summary = graph.optimize();
  EXPECT_TRUE(summary.converged);
  EXPECT_LT(summary.final_chi2, 1e-12);
  // Quadratic convergence on a graph that can be satisfied exactly: chi2 2e4 to 2e-17 in 4 iterations, where
  // absolute_tolerance stops it rather than two more that only trade rounding errors.
  EXPECT_LE(summary.iterations, 5);
  for (int k = 0; k < 12; ++k) {
    const Pose2D& p = graph.pose(k);
    EXPECT_GT(p.theta, -M_PI);
    EXPECT_LE(p.theta, M_PI);
    EXPECT_NEAR(angleDifference(p.theta, truth[static_cast<std::size_t>(k)].theta), 0.0, 1e-7) << k;
    EXPECT_NEAR(p.x, 0.5, 1e-7) << k;
    EXPECT_NEAR(p.y, -0.5, 1e-7) << k;
  }
}

TEST(PoseGraph, FixedAndUnconstrainedNodesStayWhereTheyAre) {
  SquareRun run = driveSquare(1);
  const Pose2D pinned{2.0, 2.0, 1.0};  // nowhere near its truth
  const int loose = run.graph.addNode({9.0, 9.0, 0.5});
  const int fixed = run.graph.addNode(pinned, true);
  run.graph.addConstraint(fixed, 50, between(pinned, run.graph.pose(50)), kOdometryInformation);
  EXPECT_TRUE(run.graph.isFixed(0));  // the first node always
  EXPECT_TRUE(run.graph.isFixed(fixed));
  EXPECT_FALSE(run.graph.isFixed(loose));
  run.graph.optimize();
  EXPECT_EQ(run.graph.pose(fixed).x, pinned.x);
  EXPECT_EQ(run.graph.pose(fixed).y, pinned.y);
  EXPECT_EQ(run.graph.pose(fixed).theta, pinned.theta);
  EXPECT_EQ(run.graph.pose(loose).x, 9.0);
  EXPECT_EQ(run.graph.pose(0).x, 0.0);
}

TEST(PoseGraph, EmptyGraphsAndZeroIterationsOnlyEvaluate) {
  PoseGraph empty;
  const OptimizationSummary nothing = empty.optimize();
  EXPECT_EQ(nothing.iterations, 0);
  EXPECT_EQ(nothing.final_chi2, 0.0);
  SquareRun run = driveSquare(1);
  OptimizerOptions options;
  options.max_iterations = 0;
  const OptimizationSummary evaluated = run.graph.optimize(options);
  EXPECT_EQ(evaluated.iterations, 0);
  EXPECT_FALSE(evaluated.converged);
  EXPECT_EQ(evaluated.final_chi2, evaluated.initial_chi2);
  EXPECT_GT(rmsPositionError(run.graph, run.truth), 0.5);  // not moved
}

TEST(PoseGraph, RejectsBadInputNamingWhatIsWrong) {
  PoseGraph graph;
  for (int k = 0; k < 3; ++k) graph.addNode({static_cast<double>(k), 0.0, 0.0});
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const Pose2D step{1.0, 0.0, 0.0};
  auto messageOf = [](auto&& call) -> std::string {
    try {
      call();
    } catch (const std::invalid_argument& error) {
      return error.what();
    }
    return "(no exception)";
  };

  EXPECT_TRUE(mentions(messageOf([&] { graph.addConstraint(0, 5, step, kOdometryInformation); }), "to index 5"));
  EXPECT_TRUE(mentions(messageOf([&] { graph.addConstraint(-1, 1, step, kOdometryInformation); }), "from index -1"));
  EXPECT_TRUE(mentions(messageOf([&] { graph.pose(7); }), "index 7"));
  EXPECT_TRUE(mentions(messageOf([&] { graph.isFixed(3); }), "index 3"));
  EXPECT_TRUE(mentions(messageOf([&] { graph.constraintChi2(0); }), "index 0"));
  EXPECT_TRUE(mentions(messageOf([&] { graph.addConstraint(1, 1, step, kOdometryInformation); }), "two different"));
  EXPECT_TRUE(mentions(messageOf([&] { graph.addConstraint(0, 1, {nan, 0, 0}, kOdometryInformation); }), "finite"));
  EXPECT_TRUE(mentions(messageOf([&] { graph.addNode({0.0, nan, 0.0}); }), "finite"));

  const Eigen::Matrix3d singular = Eigen::Vector3d(1.0, 1.0, 0.0).asDiagonal();
  const Eigen::Matrix3d negative = Eigen::Vector3d(1.0, -1.0, 1.0).asDiagonal();
  Eigen::Matrix3d asymmetric = Eigen::Matrix3d::Identity();
  asymmetric(0, 1) = 0.5;
  Eigen::Matrix3d not_finite = Eigen::Matrix3d::Identity();
  not_finite(2, 2) = nan;
  for (const Eigen::Matrix3d& information : {singular, negative, asymmetric, not_finite}) {
    const std::string message = messageOf([&] { graph.addConstraint(0, 1, step, information); });
    EXPECT_TRUE(mentions(message, "0 -> 1") && mentions(message, "positive definite")) << message;
  }
  EXPECT_EQ(graph.constraintCount(), 0);  // nothing bad got in
  EXPECT_EQ(graph.nodeCount(), 3);

  graph.addConstraint(0, 1, step, kOdometryInformation);
  OptimizerOptions options;
  options.max_iterations = -1;
  EXPECT_TRUE(mentions(messageOf([&] { graph.optimize(options); }), "max_iterations must be >= 0 (got -1)"));
  options = OptimizerOptions{};
  options.relative_tolerance = nan;
  options.robust_kernel_width = 0.0;
  const std::string both = validate(options);
  EXPECT_TRUE(mentions(both, "relative_tolerance") && mentions(both, "robust_kernel_width")) << both;
  options = OptimizerOptions{};
  options.initial_damping = 0.0;
  options.absolute_tolerance = -1.0;
  const std::string damping = validate(options);
  EXPECT_TRUE(mentions(damping, "initial_damping") && mentions(damping, "absolute_tolerance")) << damping;
  EXPECT_EQ(validate(OptimizerOptions{}), "");
}

// The square again, plus a closure scan matching could well make: node 62, in the middle of the third side,
// matched to node 12 in the middle of the first, as if the two parallel corridors 5 m apart were one place.
TEST(PoseGraph, ARobustKernelSurvivesAWrongLoopClosure) {
  struct Outcome {
    double rms;
    double wrong_chi2;
    double right_chi2;
  };
  auto optimiseWith = [](RobustKernel kernel) {
    SquareRun run = driveSquare(1);
    run.graph.addConstraint(62, 12, {0.2, 0.0, M_PI}, kClosureInformation);
    OptimizerOptions options;
    options.robust_kernel = kernel;
    const OptimizationSummary summary = run.graph.optimize(options);
    EXPECT_TRUE(summary.converged);
    return Outcome{rmsPositionError(run.graph, run.truth), run.graph.constraintChi2(kSquarePoses),
                   run.graph.constraintChi2(kSquarePoses - 1)};
  };
  const Outcome plain = optimiseWith(RobustKernel::kNone);
  const Outcome huber = optimiseWith(RobustKernel::kHuber);
  const Outcome cauchy = optimiseWith(RobustKernel::kCauchy);
  std::printf("[          ] with a wrong closure, RMS: plain %.3f m, Huber %.3f m, Cauchy %.3f m\n", plain.rms,
              huber.rms, cauchy.rms);
  // Plain least squares folds the square: the two sides are pulled metres towards each other.
  EXPECT_GT(plain.rms, 1.0);
  // Huber caps the wrong closure's pull, not removes it: a pull of width / sigma stretches the loop's two halves
  // by decimetres (0.30 .. 0.43 m over 300 seeds).
  EXPECT_GT(huber.rms, 0.15);
  EXPECT_LT(huber.rms, 0.7);
  // Cauchy lets a pull 5 m / 2 cm = 250 standard deviations out fade to almost nothing: the result is that of
  // the square without the wrong closure (0.045 m), within the same bound.
  EXPECT_LT(cauchy.rms, 0.1);
  // And the overruled closure stands out for the integrator to drop, while the right one fits.
  EXPECT_GT(cauchy.wrong_chi2, 1e4);
  EXPECT_LT(cauchy.right_chi2, 16.3);  // 99.9th percentile of chi-square, 3 degrees of freedom
}

// A building-sized graph: 20 laps of a circle of 100 poses (2000 nodes), odometry as in the square between
// consecutive poses and 501 closures, each to the pose a lap earlier (2500 constraints). The heading bias turns
// the dead-reckoned laps 0.4 rad further each time, metres off: a hard, far from linear start. Wall time is
// printed and bounded only loosely, as the machine is shared.
TEST(PoseGraph, OptimisesTwoThousandNodesQuickly) {
  constexpr int kPerLap = 100, kNodes = 2000, kClosures = 501;
  auto truthAt = [](int k) {
    const double angle = 2 * M_PI * (k % kPerLap) / kPerLap;
    const double radius = 0.2 * kPerLap / (2 * M_PI);  // 0.2 m steps
    return Pose2D{radius * std::sin(angle), radius * (1 - std::cos(angle)), normalizeAngle(angle)};
  };
  std::mt19937 rng(3);
  std::normal_distribution<double> unit(0.0, 1.0);
  PoseGraph graph;
  std::vector<Pose2D> truth;
  Pose2D dead_reckoned = truthAt(0);
  truth.push_back(dead_reckoned);
  graph.addNode(dead_reckoned);
  for (int k = 1; k < kNodes; ++k) {
    truth.push_back(truthAt(k));
    Pose2D odometry = between(truth[static_cast<std::size_t>(k - 1)], truth.back());
    odometry.x += 0.005 * unit(rng);
    odometry.y += 0.005 * unit(rng);
    odometry.theta = normalizeAngle(odometry.theta + kHeadingBias + 0.002 * unit(rng));
    dead_reckoned = compose(dead_reckoned, odometry);
    graph.addNode(dead_reckoned);
    graph.addConstraint(k - 1, k, odometry, kOdometryInformation);
  }
  for (int c = 0; c < kClosures; ++c) {
    const int to = kPerLap + c * (kNodes - kPerLap) / kClosures;
    Pose2D closure = between(truth[static_cast<std::size_t>(to - kPerLap)], truth[static_cast<std::size_t>(to)]);
    closure.x += 0.01 * unit(rng);
    closure.y += 0.01 * unit(rng);
    closure.theta += 0.005 * unit(rng);
    graph.addConstraint(to - kPerLap, to, closure, kClosureInformation);
  }
  ASSERT_EQ(graph.nodeCount(), 2000);
  ASSERT_EQ(graph.constraintCount(), 2500);
  const double rms_before = rmsPositionError(graph, truth);

  const auto start = std::chrono::steady_clock::now();
  const OptimizationSummary summary = graph.optimize();
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const double rms_after = rmsPositionError(graph, truth);
  std::printf("[          ] 2000 nodes, 2500 constraints: %.1f ms, %d iterations, chi2 %.0f -> %.0f, "
              "RMS %.2f -> %.3f m\n", 1e3 * seconds, summary.iterations, summary.initial_chi2, summary.final_chi2,
              rms_before, rms_after);
  EXPECT_TRUE(summary.converged);
  EXPECT_LT(seconds, 2.0);
  EXPECT_GT(rms_before, 2.0);
  EXPECT_LT(rms_after, 0.1);
  // chi2 at the optimum, as in the square: the bias spread over 1999 steps, 1999 * 0.4^2 = 320, plus the random
  // errors over 7500 - 5997 = 1503 degrees of freedom, each worth their variance over the stated one (0.04 ..
  // 0.25), about 300.
  EXPECT_GT(summary.final_chi2, 400.0);
  EXPECT_LT(summary.final_chi2, 1000.0);
}

}  // namespace
}  // namespace hector_style_mapping
