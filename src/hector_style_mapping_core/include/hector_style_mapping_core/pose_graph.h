#ifndef HECTOR_STYLE_MAPPING_CORE_POSE_GRAPH_H
#define HECTOR_STYLE_MAPPING_CORE_POSE_GRAPH_H

#include <string>
#include <vector>

#include <Eigen/Core>

#include "hector_style_mapping_core/pose_2d.h"

namespace hector_style_mapping {

// How much a constraint far from agreeing with the others may pull. Loop closures come from scan matching
// against an earlier submap, and in a building of look-alike corridors and doors a match can be confident and
// wrong (perceptual aliasing). Under plain least squares its pull grows with its error, so one such closure
// bends the whole loop towards it; a kernel caps that pull (Huber) or lets it fade as the error grows (Cauchy).
// Constraints that agree with the rest stay in the kernel's quadratic part and are weighed as before.
enum class RobustKernel {
  kNone,    // plain least squares
  kHuber,   // quadratic up to the width, then linear: bounded pull, still convex
  kCauchy,  // log(1 + r^2 / width^2): the pull of a gross outlier fades, but the cost is not convex
};

// The Levenberg-Marquardt loop's settings, checked by validate() and by PoseGraph::optimize().
struct OptimizerOptions {
  int max_iterations = 50;  // linearisations; 0 only evaluates chi2
  // Stop once an iteration lowers chi2 by no more than this fraction of it ...
  double relative_tolerance = 1e-6;
  // ... or chi2 is at most this: every error a millionth of its standard deviation, an exactly consistent graph.
  double absolute_tolerance = 1e-12;
  // The first damping lambda, relative to the diagonal of the normal equations (Marquardt's scaling).
  double initial_damping = 1e-4;
  RobustKernel robust_kernel = RobustKernel::kNone;
  // Where the kernel leaves its quadratic part, in standard deviations: on r = sqrt(e^T Omega e). The default,
  // sqrt(7.81), is the 95th percentile of a chi-square with 3 degrees of freedom, so a constraint whose noise
  // matches its information matrix is down-weighted only 1 time in 20.
  double robust_kernel_width = 2.7955;
};

// "" when `options` can be used; otherwise one message per bad field, joined by "; ", each naming the field, what
// was expected and what was given, e.g. "max_iterations must be >= 0 (got -1)".
std::string validate(const OptimizerOptions& options);

struct OptimizationSummary {
  int iterations = 0;         // linearisations done
  double initial_chi2 = 0.0;  // the objective before: sum over constraints of rho(e^T Omega e) ...
  double final_chi2 = 0.0;    // ... and after; rho is the identity without a robust kernel
  bool converged = false;     // a tolerance was met, or no step lowered chi2 (a minimum to rounding)
};

// A constraint's error at two poses and its derivatives with respect to each (x, y, theta): what optimize()
// linearises. Public so that tests can check the analytic Jacobians against finite differences.
struct ConstraintLinearization {
  Eigen::Vector3d error;
  Eigen::Matrix3d d_from;  // d error / d (x, y, theta) of `from`
  Eigen::Matrix3d d_to;    // d error / d (x, y, theta) of `to`
};

// error = h(from, to) - measured, with h(from, to) = (R(from)^T (t_to - t_from), theta_to - theta_from): the
// current pose of `to` in the frame of `from`, compared component-wise with the measurement (Konolige et al.
// 2010, eq. 1 to 3), the angle wrapped to (-pi, pi].
ConstraintLinearization linearizeConstraint(const Pose2D& from, const Pose2D& to, const Pose2D& measured);

// Sparse pose adjustment (Konolige, Grisetti, Kuemmerle, Burgard, Limketkai, Vincent: "Efficient sparse pose
// adjustment for 2D mapping", IROS 2010): nodes are planar poses, constraints the measured pose of one node in
// another's frame with an information matrix (inverse covariance, in the `from` node's frame: x, y, theta).
// optimize() minimises sum rho(e^T Omega e) by Levenberg-Marquardt, the normal equations sparse and solved by
// sparse LDL^T. The first node, and every node added as fixed, stays where it is: without an anchor the whole
// graph could slide and turn freely. Nodes no constraint touches are left alone too.
class PoseGraph {
 public:
  // Adds a node and returns its index (0, 1, ...). Throws std::invalid_argument if a field is not finite.
  int addNode(const Pose2D& initial, bool fixed = false);

  // Adds the measurement of node `to`'s pose in node `from`'s frame. Throws std::invalid_argument naming what is
  // wrong: an index that is no node, from == to, a non-finite measurement, or an information matrix that is not
  // finite, symmetric and positive definite.
  void addConstraint(int from, int to, const Pose2D& measured, const Eigen::Matrix3d& information);

  // Throws std::invalid_argument naming the index if there is no such node.
  const Pose2D& pose(int node) const;
  bool isFixed(int node) const;
  int nodeCount() const { return static_cast<int>(nodes_.size()); }
  int constraintCount() const { return static_cast<int>(constraints_.size()); }

  // e^T Omega e of one constraint (in the order added) at the current poses, without any kernel: after a robust
  // optimisation, the closures the kernel overruled stand out with large values. Throws std::invalid_argument
  // if there is no such constraint.
  double constraintChi2(int constraint) const;

  // Moves the free nodes to minimise chi2. Throws std::invalid_argument with validate()'s message if the options
  // are not valid. Can be called again after adding nodes and constraints; it starts from the current poses.
  OptimizationSummary optimize(const OptimizerOptions& options = OptimizerOptions{});

 private:
  struct Node {
    Pose2D pose;
    bool fixed = false;
  };
  struct Constraint {
    int from = 0;
    int to = 0;
    Pose2D measured;
    Eigen::Matrix3d information;
  };

  void checkNode(int node, const char* role) const;
  // sum rho(e^T Omega e) over all constraints at `poses`.
  double objective(const std::vector<Pose2D>& poses, const OptimizerOptions& options) const;

  std::vector<Node> nodes_;
  std::vector<Constraint> constraints_;
};

}  // namespace hector_style_mapping

#endif  // HECTOR_STYLE_MAPPING_CORE_POSE_GRAPH_H
