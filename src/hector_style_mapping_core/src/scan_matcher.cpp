#include "hector_style_mapping_core/scan_matcher.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include <Eigen/Eigenvalues>

namespace hector_style_mapping {

namespace {

constexpr double kNegligibleTranslationCells = 1e-3;
constexpr double kNegligibleRotation = 1e-4;  // rad
constexpr int kMaxStepHalvings = 2;
// Surface normals (surfaceNormalHessian): a line is fitted to at most kMaxNormalNeighboursPerSide neighbours on each
// side of a point, taking every stride-th beam (stride <= kMaxNormalStride, from the beam spacing measured over
// kSpacingSpan beams); the fit needs kMinNormalFitPoints points and counts as a straight surface when the variance
// across it is below kMaxNormalFitFlatness times the variance along it.
constexpr int kMaxNormalNeighboursPerSide = 6;
constexpr int kMaxNormalStride = 8;
constexpr int kSpacingSpan = 4;
constexpr int kMinNormalFitPoints = 3;
constexpr double kMaxNormalFitFlatness = 0.05;

// The normal equations of the cost at one pose.
struct NormalEquations {
  Eigen::Matrix3d hessian = Eigen::Matrix3d::Zero();  // sum J^T J
  Eigen::Vector3d gradient = Eigen::Vector3d::Zero();  // sum J^T (1 - M)
  double cost = 0.0;                                   // sum (1 - M)^2
  int point_count = 0;
};

NormalEquations evaluate(const OccupancyGridMap& map, const ScanPoints& scan, const Pose2D& pose) {
  const double c = std::cos(pose.theta);
  const double s = std::sin(pose.theta);
  // Accumulated in scalars: the upper triangle of H is all that is needed and the compiler keeps them in registers.
  double h_xx = 0.0, h_xy = 0.0, h_xt = 0.0, h_yy = 0.0, h_yt = 0.0, h_tt = 0.0;
  double g_x = 0.0, g_y = 0.0, g_t = 0.0;
  double cost = 0.0;
  int count = 0;
  Eigen::Vector2d map_gradient;
  for (const Eigen::Vector2d& point : scan.points) {
    if (!point.allFinite()) {
      continue;
    }
    // The point rotated into the map frame's orientation; dS/dtheta = (-sin*sx - cos*sy, cos*sx - sin*sy) is that
    // rotated point turned by 90 degrees.
    const double rotated_x = c * point.x() - s * point.y();
    const double rotated_y = s * point.x() + c * point.y();
    const double value = map.interpolate(Eigen::Vector2d(pose.x + rotated_x, pose.y + rotated_y), &map_gradient);
    const double residual = 1.0 - value;
    const double j_x = map_gradient.x();
    const double j_y = map_gradient.y();
    const double j_t = -rotated_y * j_x + rotated_x * j_y;
    h_xx += j_x * j_x;
    h_xy += j_x * j_y;
    h_xt += j_x * j_t;
    h_yy += j_y * j_y;
    h_yt += j_y * j_t;
    h_tt += j_t * j_t;
    g_x += j_x * residual;
    g_y += j_y * residual;
    g_t += j_t * residual;
    cost += residual * residual;
    ++count;
  }
  NormalEquations equations;
  equations.hessian << h_xx, h_xy, h_xt, h_xy, h_yy, h_yt, h_xt, h_yt, h_tt;
  equations.gradient << g_x, g_y, g_t;
  equations.cost = cost;
  equations.point_count = count;
  return equations;
}

// The scan's RMS distance from the base origin: the length that makes a rotation comparable to a translation.
double rotationLengthScale(const ScanPoints& scan) {
  double sum = 0.0;
  int count = 0;
  for (const Eigen::Vector2d& point : scan.points) {
    if (point.allFinite()) {
      sum += point.squaredNorm();
      ++count;
    }
  }
  return count == 0 ? 1.0 : std::max(std::sqrt(sum / count), 0.1);
}

// H^-1 g restricted to the directions H constrains, with rotation expressed as arc length at `length_scale` so the
// eigenvalues of translation and rotation are comparable.
Eigen::Vector3d gaussNewtonStep(const NormalEquations& equations, double length_scale) {
  const Eigen::Vector3d scale(1.0, 1.0, 1.0 / length_scale);
  const Eigen::Matrix3d scaled_hessian = scale.asDiagonal() * equations.hessian * scale.asDiagonal();
  const Eigen::Vector3d scaled_gradient = scale.cwiseProduct(equations.gradient);
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(scaled_hessian);
  const Eigen::Vector3d& eigenvalues = solver.eigenvalues();  // ascending
  const double largest = eigenvalues(2);
  Eigen::Vector3d scaled_step = Eigen::Vector3d::Zero();
  if (!(largest > 0.0) || !std::isfinite(largest)) {
    return scaled_step;
  }
  for (int k = 0; k < 3; ++k) {
    if (eigenvalues(k) > ScanMatcher::kRelativeEigenvalueFloor * largest) {
      const Eigen::Vector3d direction = solver.eigenvectors().col(k);
      scaled_step += direction * (direction.dot(scaled_gradient) / eigenvalues(k));
    }
  }
  return scale.cwiseProduct(scaled_step);
}

Eigen::Vector3d clampStep(Eigen::Vector3d step, double resolution) {
  const double max_translation = ScanMatcher::kMaxTranslationStepCells * resolution;
  const double translation = step.head<2>().norm();
  if (translation > max_translation) {
    step.head<2>() *= max_translation / translation;
  }
  step(2) = std::clamp(step(2), -ScanMatcher::kMaxRotationStep, ScanMatcher::kMaxRotationStep);
  return step;
}

Pose2D moved(const Pose2D& pose, const Eigen::Vector3d& step) {
  return {pose.x + step(0), pose.y + step(1), pose.theta + step(2)};
}

// Two consecutive beams around a point at `range` are taken to hit the same surface when their end points are
// closer than this (m): loose enough for a wall seen at a grazing angle, where consecutive hits lie far apart.
double sameSurfaceGap(double range) { return 0.05 + 0.15 * range; }

// The unit normal of the straight surface around point `index`, or zero if there is none. The fit takes, on each
// side, neighbours on the same surface: at least two where there are, then more while they lie within
// kNormalRadius. Where beams are dense (close to the laser) it takes every stride-th beam, so that the fit spans
// enough of the surface to see past range noise without visiting dozens of points.
Eigen::Vector2d surfaceNormalAt(const std::vector<Eigen::Vector2d>& points, int index) {
  const Eigen::Vector2d& centre = points[static_cast<std::size_t>(index)];
  const double radius_squared = ScanMatcher::kNormalRadius * ScanMatcher::kNormalRadius;
  const int size = static_cast<int>(points.size());
  // The beam spacing here, measured over a few beams so that range noise does not dominate it.
  const int span = std::min(kSpacingSpan, size - 1);
  const int other = index + span < size ? index + span : index - span;
  if (span < 1 || other < 0) {
    return Eigen::Vector2d::Zero();
  }
  const double spacing = (points[static_cast<std::size_t>(other)] - centre).norm() / span;
  const int stride =
      spacing > 0.0 && std::isfinite(spacing)
          ? std::clamp(static_cast<int>(ScanMatcher::kNormalRadius / (spacing * kMaxNormalNeighboursPerSide)), 1,
                       kMaxNormalStride)
          : 1;
  const double gap = sameSurfaceGap(centre.norm()) * stride;
  const double gap_squared = gap * gap;
  // Offsets from the centre point, for numerical stability of the scatter.
  Eigen::Vector2d sum = Eigen::Vector2d::Zero();
  Eigen::Matrix2d sum_of_squares = Eigen::Matrix2d::Zero();
  int count = 1;
  for (const int direction : {-1, 1}) {
    const Eigen::Vector2d* previous = &centre;
    for (int k = 1; k <= kMaxNormalNeighboursPerSide; ++k) {
      const int neighbour = index + direction * k * stride;
      if (neighbour < 0 || neighbour >= size) {
        break;
      }
      const Eigen::Vector2d& point = points[static_cast<std::size_t>(neighbour)];
      if (!point.allFinite() || (point - *previous).squaredNorm() > gap_squared) {
        break;
      }
      const Eigen::Vector2d offset = point - centre;
      if (k > 2 && offset.squaredNorm() > radius_squared) {
        break;
      }
      sum += offset;
      sum_of_squares += offset * offset.transpose();
      ++count;
      previous = &point;
    }
  }
  if (count < kMinNormalFitPoints) {
    return Eigen::Vector2d::Zero();
  }
  const Eigen::Vector2d mean = sum / count;
  const Eigen::Matrix2d scatter = sum_of_squares / count - mean * mean.transpose();
  // Closed-form eigen decomposition of the symmetric 2x2 scatter; this runs for every point of every scan.
  const double a = scatter(0, 0);
  const double b = scatter(0, 1);
  const double c = scatter(1, 1);
  const double half_trace = 0.5 * (a + c);
  const double spread = std::sqrt(0.25 * (a - c) * (a - c) + b * b);
  const double across = half_trace - spread;
  const double along = half_trace + spread;
  if (!(along > 0.0) || across > kMaxNormalFitFlatness * along) {
    return Eigen::Vector2d::Zero();
  }
  // Two candidate eigenvectors of the smaller eigenvalue; the longer one is the better conditioned.
  const Eigen::Vector2d first(b, across - a);
  const Eigen::Vector2d second(across - c, b);
  const Eigen::Vector2d& normal = first.squaredNorm() >= second.squaredNorm() ? first : second;
  const double length = normal.norm();
  return length > 0.0 ? Eigen::Vector2d(normal / length) : Eigen::Vector2d::Zero();
}

}  // namespace

Eigen::Matrix3d ScanMatcher::surfaceNormalHessian(const OccupancyGridMap& map, const ScanPoints& scan,
                                                  const Pose2D& pose) const {
  const double c = std::cos(pose.theta);
  const double s = std::sin(pose.theta);
  const Eigen::Matrix2d rotation = (Eigen::Matrix2d() << c, -s, s, c).finished();
  Eigen::Matrix3d hessian = Eigen::Matrix3d::Zero();
  Eigen::Vector2d map_gradient;
  for (int i = 0; i < static_cast<int>(scan.points.size()); ++i) {
    const Eigen::Vector2d& point = scan.points[static_cast<std::size_t>(i)];
    if (!point.allFinite()) {
      continue;
    }
    const Eigen::Vector2d rotated = rotation * point;
    map.interpolate(Eigen::Vector2d(pose.x, pose.y) + rotated, &map_gradient);
    const Eigen::Vector2d normal_in_base = surfaceNormalAt(scan.points, i);
    if (!normal_in_base.isZero()) {
      const Eigen::Vector2d normal = rotation * normal_in_base;
      map_gradient = normal * normal.dot(map_gradient);
    }
    const Eigen::Vector3d jacobian(map_gradient.x(), map_gradient.y(),
                                   -rotated.y() * map_gradient.x() + rotated.x() * map_gradient.y());
    hessian.noalias() += jacobian * jacobian.transpose();
  }
  return hessian;
}

Pose2D ScanMatcher::match(const OccupancyGridMap& map, const ScanPoints& scan, const Pose2D& guess, int iterations,
                          Eigen::Matrix3d* hessian) const {
  const ScanMatchResult result = matchWithDetails(map, scan, guess, iterations);
  if (hessian != nullptr) {
    *hessian = result.hessian;
  }
  return result.pose;
}

ScanMatchResult ScanMatcher::matchWithDetails(const OccupancyGridMap& map, const ScanPoints& scan,
                                              const Pose2D& guess, int iterations) const {
  const double length_scale = rotationLengthScale(scan);
  const double negligible_translation = kNegligibleTranslationCells * map.resolution();

  Pose2D pose = guess;
  NormalEquations current = evaluate(map, scan, pose);
  int accepted = 0;
  if (current.point_count > 0) {
    for (int iteration = 0; iteration < iterations; ++iteration) {
      Eigen::Vector3d step = clampStep(gaussNewtonStep(current, length_scale), map.resolution());
      if (step.head<2>().norm() < negligible_translation && std::abs(step(2)) < kNegligibleRotation) {
        break;
      }
      Pose2D candidate = moved(pose, step);
      NormalEquations at_candidate = evaluate(map, scan, candidate);
      // Bilinear maps have kinks at cell centres where a full step can overshoot; a shorter one usually does not.
      for (int halving = 0; halving < kMaxStepHalvings && !(at_candidate.cost < current.cost); ++halving) {
        step *= 0.5;
        candidate = moved(pose, step);
        at_candidate = evaluate(map, scan, candidate);
      }
      if (!(at_candidate.cost < current.cost)) {
        break;
      }
      pose = candidate;
      current = at_candidate;
      ++accepted;
    }
  }

  ScanMatchResult result;
  result.pose = {pose.x, pose.y, normalizeAngle(pose.theta)};
  result.hessian = current.hessian;
  result.squared_residual_sum = current.cost;
  result.point_count = current.point_count;
  result.iterations = accepted;
  return result;
}

}  // namespace hector_style_mapping
