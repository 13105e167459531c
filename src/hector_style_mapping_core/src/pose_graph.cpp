#include "hector_style_mapping_core/pose_graph.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include <Eigen/Cholesky>
#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>

namespace hector_style_mapping {

namespace {

// Bounds on the damping lambda. Past kMaxDamping the step is a vanishing gradient step: if even that does not
// lower chi2, we are at a minimum.
constexpr double kMinDamping = 1e-12;
constexpr double kMaxDamping = 1e12;

bool isFinite(const Pose2D& pose) {
  return std::isfinite(pose.x) && std::isfinite(pose.y) && std::isfinite(pose.theta);
}

std::string describe(const Pose2D& pose) {
  std::ostringstream text;
  text << "(" << pose.x << ", " << pose.y << ", " << pose.theta << ")";
  return text.str();
}

// rho(s) and its slope w = rho'(s) at s = e^T Omega e. The slope is the weight of the constraint in the normal
// equations (iteratively reweighted least squares; rho's curvature is left out, as Gauss-Newton leaves out the
// error's).
struct Robustified {
  double cost;
  double weight;
};

Robustified robustify(double s, const OptimizerOptions& options) {
  const double k = options.robust_kernel_width;
  switch (options.robust_kernel) {
    case RobustKernel::kHuber: {
      if (s <= k * k) return {s, 1.0};
      const double r = std::sqrt(s);
      return {2.0 * k * r - k * k, k / r};
    }
    case RobustKernel::kCauchy:
      return {k * k * std::log1p(s / (k * k)), 1.0 / (1.0 + s / (k * k))};
    case RobustKernel::kNone:
      break;
  }
  return {s, 1.0};
}

Eigen::Vector3d constraintError(const Pose2D& from, const Pose2D& to, const Pose2D& measured) {
  const double c = std::cos(from.theta), s = std::sin(from.theta);
  const double dx = to.x - from.x, dy = to.y - from.y;
  return {c * dx + s * dy - measured.x, -s * dx + c * dy - measured.y,
          normalizeAngle(to.theta - from.theta - measured.theta)};
}

// Adds `block` at block row `row`, block column `col` of the lower triangle the solver reads: an upper block is
// stored as its transpose, and only the lower half of a diagonal block.
void addBlock(int row, int col, const Eigen::Matrix3d& block, std::vector<Eigen::Triplet<double>>* triplets) {
  if (row < col) {
    addBlock(col, row, block.transpose(), triplets);
    return;
  }
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c)
      if (row != col || c <= r) triplets->emplace_back(3 * row + r, 3 * col + c, block(r, c));
}

}  // namespace

std::string validate(const OptimizerOptions& options) {
  std::vector<std::string> complaints;
  auto complain = [&complaints](const char* field, const char* expectation, double value) {
    std::ostringstream message;
    message << field << " must be " << expectation << " (got " << value << ")";
    complaints.push_back(message.str());
  };
  // Written as !(good) so that NaN fails every check.
  if (!(options.max_iterations >= 0)) complain("max_iterations", ">= 0", options.max_iterations);
  if (!(options.relative_tolerance >= 0.0 && options.relative_tolerance < 1.0))
    complain("relative_tolerance", "in [0, 1)", options.relative_tolerance);
  if (!(options.absolute_tolerance >= 0.0 && std::isfinite(options.absolute_tolerance)))
    complain("absolute_tolerance", ">= 0 and finite", options.absolute_tolerance);
  if (!(options.initial_damping >= kMinDamping && options.initial_damping <= kMaxDamping))
    complain("initial_damping", "in [1e-12, 1e12]", options.initial_damping);
  const int kernel = static_cast<int>(options.robust_kernel);
  if (!(kernel >= static_cast<int>(RobustKernel::kNone) && kernel <= static_cast<int>(RobustKernel::kCauchy)))
    complain("robust_kernel", "kNone, kHuber or kCauchy", kernel);
  if (!(options.robust_kernel_width > 0.0 && std::isfinite(options.robust_kernel_width)))
    complain("robust_kernel_width", "> 0 and finite (standard deviations)", options.robust_kernel_width);

  std::string joined;
  for (const std::string& complaint : complaints) joined += (joined.empty() ? "" : "; ") + complaint;
  return joined;
}

ConstraintLinearization linearizeConstraint(const Pose2D& from, const Pose2D& to, const Pose2D& measured) {
  const double c = std::cos(from.theta), s = std::sin(from.theta);
  const double dx = to.x - from.x, dy = to.y - from.y;
  ConstraintLinearization result;
  result.error = constraintError(from, to, measured);
  // d/d from: -R^T on the translation, dR^T/dtheta (t_to - t_from) from the turn of the frame, -1 on the angle.
  result.d_from << -c, -s, -s * dx + c * dy,  //
      s, -c, -c * dx - s * dy,                //
      0.0, 0.0, -1.0;
  // d/d to: R^T on the translation, +1 on the angle.
  result.d_to << c, s, 0.0,  //
      -s, c, 0.0,            //
      0.0, 0.0, 1.0;
  return result;
}

int PoseGraph::addNode(const Pose2D& initial, bool fixed) {
  if (!isFinite(initial))
    throw std::invalid_argument("PoseGraph::addNode: the initial pose must be finite (got " + describe(initial) + ")");
  nodes_.push_back({{initial.x, initial.y, normalizeAngle(initial.theta)}, fixed});
  return nodeCount() - 1;
}

void PoseGraph::checkNode(int node, const char* role) const {
  if (node < 0 || node >= nodeCount()) {
    std::ostringstream message;
    message << "PoseGraph: " << role << " index " << node << " is not a node (the graph has " << nodeCount()
            << (nodeCount() == 0 ? " nodes)" : " nodes, 0 to " + std::to_string(nodeCount() - 1) + ")");
    throw std::invalid_argument(message.str());
  }
}

void PoseGraph::addConstraint(int from, int to, const Pose2D& measured, const Eigen::Matrix3d& information) {
  checkNode(from, "from");
  checkNode(to, "to");
  const std::string name = "PoseGraph::addConstraint " + std::to_string(from) + " -> " + std::to_string(to) + ": ";
  if (from == to) throw std::invalid_argument(name + "a constraint needs two different nodes");
  if (!isFinite(measured))
    throw std::invalid_argument(name + "the measured pose must be finite (got " + describe(measured) + ")");
  // Symmetric to rounding, and positive definite: otherwise some direction would count as negative or no error,
  // and the normal equations could not be solved.
  const bool symmetric =
      information.allFinite() &&
      (information - information.transpose()).cwiseAbs().maxCoeff() <= 1e-9 * information.cwiseAbs().maxCoeff();
  if (!symmetric || Eigen::LLT<Eigen::Matrix3d>(information).info() != Eigen::Success) {
    std::ostringstream message;
    const Eigen::IOFormat row_by_row(Eigen::StreamPrecision, 0, ", ", "; ", "", "", "[", "]");
    message << name << "the information matrix must be finite, symmetric and positive definite (got "
            << information.format(row_by_row) << ")";
    throw std::invalid_argument(message.str());
  }
  constraints_.push_back({from, to, measured, information});
}

const Pose2D& PoseGraph::pose(int node) const {
  checkNode(node, "node");
  return nodes_[static_cast<std::size_t>(node)].pose;
}

bool PoseGraph::isFixed(int node) const {
  checkNode(node, "node");
  return node == 0 || nodes_[static_cast<std::size_t>(node)].fixed;
}

double PoseGraph::constraintChi2(int constraint) const {
  if (constraint < 0 || constraint >= constraintCount())
    throw std::invalid_argument("PoseGraph::constraintChi2: index " + std::to_string(constraint) +
                                " is not a constraint (the graph has " + std::to_string(constraintCount()) + ")");
  const Constraint& c = constraints_[static_cast<std::size_t>(constraint)];
  const Eigen::Vector3d e = constraintError(nodes_[static_cast<std::size_t>(c.from)].pose,
                                            nodes_[static_cast<std::size_t>(c.to)].pose, c.measured);
  return e.dot(c.information * e);
}

double PoseGraph::objective(const std::vector<Pose2D>& poses, const OptimizerOptions& options) const {
  double sum = 0.0;
  for (const Constraint& c : constraints_) {
    const Eigen::Vector3d e = constraintError(poses[static_cast<std::size_t>(c.from)],
                                              poses[static_cast<std::size_t>(c.to)], c.measured);
    sum += robustify(e.dot(c.information * e), options).cost;
  }
  return sum;
}

OptimizationSummary PoseGraph::optimize(const OptimizerOptions& options) {
  const std::string complaints = validate(options);
  if (!complaints.empty()) throw std::invalid_argument("PoseGraph::optimize: " + complaints);

  // The unknowns: free nodes that some constraint touches, three columns each.
  std::vector<int> variable(nodes_.size(), -1);
  int variables = 0;
  for (const Constraint& c : constraints_)
    for (const int node : {c.from, c.to})
      if (!isFixed(node) && variable[static_cast<std::size_t>(node)] < 0)
        variable[static_cast<std::size_t>(node)] = variables++;

  std::vector<Pose2D> poses;
  poses.reserve(nodes_.size());
  for (const Node& node : nodes_) poses.push_back(node.pose);

  OptimizationSummary summary;
  double chi2 = objective(poses, options);
  summary.initial_chi2 = summary.final_chi2 = chi2;
  if (variables == 0) {
    summary.converged = true;
    return summary;
  }

  const int dimension = 3 * variables;
  std::vector<Eigen::Triplet<double>> triplets;
  triplets.reserve(constraints_.size() * 4 * 9);
  Eigen::SparseMatrix<double> hessian(dimension, dimension);
  Eigen::VectorXd gradient(dimension);
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>, Eigen::Lower> solver;
  bool pattern_analysed = false;
  double damping = options.initial_damping;

  for (int iteration = 0; iteration < options.max_iterations; ++iteration) {
    summary.iterations = iteration + 1;
    // Normal equations H dx = -g with H = sum w J^T Omega J and g = sum w J^T Omega e; fixed nodes contribute
    // to the error but have no columns.
    triplets.clear();
    gradient.setZero();
    for (const Constraint& c : constraints_) {
      const ConstraintLinearization lin = linearizeConstraint(poses[static_cast<std::size_t>(c.from)],
                                                              poses[static_cast<std::size_t>(c.to)], c.measured);
      const double w = robustify(lin.error.dot(c.information * lin.error), options).weight;
      const Eigen::Matrix3d omega = w * c.information;
      const int a = variable[static_cast<std::size_t>(c.from)], b = variable[static_cast<std::size_t>(c.to)];
      if (a >= 0) {
        addBlock(a, a, lin.d_from.transpose() * omega * lin.d_from, &triplets);
        gradient.segment<3>(3 * a) += lin.d_from.transpose() * omega * lin.error;
      }
      if (b >= 0) {
        addBlock(b, b, lin.d_to.transpose() * omega * lin.d_to, &triplets);
        gradient.segment<3>(3 * b) += lin.d_to.transpose() * omega * lin.error;
      }
      if (a >= 0 && b >= 0) addBlock(a, b, lin.d_from.transpose() * omega * lin.d_to, &triplets);
    }
    hessian.setFromTriplets(triplets.begin(), triplets.end());  // sums the blocks that share a place
    const Eigen::VectorXd diagonal = hessian.diagonal();
    if (!pattern_analysed) {
      // The sparsity pattern depends only on which nodes the constraints join: order and analyse it once.
      solver.analyzePattern(hessian);
      pattern_analysed = true;
    }

    // Levenberg-Marquardt: solve (H + lambda diag(H)) dx = -g, raising lambda until chi2 drops.
    bool stepped = false;
    double new_chi2 = chi2;
    double growth = 2.0;
    std::vector<Pose2D> trial = poses;
    while (damping <= kMaxDamping) {
      Eigen::SparseMatrix<double> damped = hessian;
      for (int i = 0; i < dimension; ++i) damped.coeffRef(i, i) += damping * diagonal[i];
      solver.factorize(damped);
      if (solver.info() == Eigen::Success) {
        const Eigen::VectorXd step = solver.solve(-gradient);
        for (std::size_t node = 0; node < nodes_.size(); ++node) {
          const int v = variable[node];
          if (v < 0) continue;
          trial[node] = {poses[node].x + step[3 * v], poses[node].y + step[3 * v + 1],
                         normalizeAngle(poses[node].theta + step[3 * v + 2])};
        }
        new_chi2 = objective(trial, options);
        if (new_chi2 < chi2) {
          stepped = true;
          // Nielsen's update: shrink lambda (down to a third) as far as the linear model predicted the drop well
          // (gain ratio near 1), keep or grow it where it did not. The plain tenfold up and down makes lambda
          // oscillate far from the optimum, a rejected step every other iteration.
          const Eigen::VectorXd curvature = hessian.selfadjointView<Eigen::Lower>() * step;
          const double predicted = -(2.0 * gradient.dot(step) + step.dot(curvature));  // by the linear model
          const double gain = predicted > 0.0 ? (chi2 - new_chi2) / predicted : 1.0;
          damping = std::max(damping * std::max(1.0 / 3.0, 1.0 - std::pow(2.0 * gain - 1.0, 3)), kMinDamping);
          break;
        }
      }
      damping *= growth;
      growth *= 2.0;
    }
    if (!stepped) {  // no step lowers chi2: a minimum, to rounding
      summary.converged = true;
      break;
    }
    const double drop = chi2 - new_chi2;
    poses.swap(trial);
    chi2 = new_chi2;
    if (drop <= options.relative_tolerance * (chi2 + drop) || chi2 <= options.absolute_tolerance) {
      summary.converged = true;
      break;
    }
  }

  for (std::size_t node = 0; node < nodes_.size(); ++node) nodes_[node].pose = poses[node];
  summary.final_chi2 = chi2;
  return summary;
}

}  // namespace hector_style_mapping
