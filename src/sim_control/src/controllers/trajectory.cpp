#include "sim_control/trajectory.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace sim_control {
namespace trajectory {
namespace {

constexpr double kPi = 3.14159265358979323846;

std::string num(double value) {
  char buffer[32];
  std::snprintf(buffer, sizeof(buffer), "%.4g", value);
  return buffer;
}

std::string quoted(const std::vector<std::string>& names) {
  std::string out;
  for (std::size_t k = 0; k < names.size(); ++k) out += (k ? ", '" : "'") + names[k] + "'";
  return out;
}

std::string list(const std::vector<std::string>& names) {
  std::string out;
  for (std::size_t k = 0; k < names.size(); ++k) out += (k ? ", " : "") + names[k];
  return out;
}

// ros_controllers reads a point as: no velocities -> positions only (linear), velocities but no
// accelerations -> cubic, both -> quintic.
Order pointOrder(const Waypoint& point) {
  if (point.velocities.empty()) return Order::Linear;
  if (point.accelerations.empty()) return Order::Cubic;
  return Order::Quintic;
}

State pointState(const Waypoint& point, std::size_t k, double position_offset) {
  State state;
  state.position = point.positions[k] + position_offset;
  if (!point.velocities.empty()) state.velocity = point.velocities[k];
  if (!point.accelerations.empty()) state.acceleration = point.accelerations[k];
  return state;
}

// Which component of `error` exceeds `tolerance` first: 0 position, 1 velocity, 2 acceleration; -1 none.
int firstViolation(const State& error, const StateTolerance& tolerance) {
  const double e[3] = {error.position, error.velocity, error.acceleration};
  const double t[3] = {tolerance.position, tolerance.velocity, tolerance.acceleration};
  for (int c = 0; c < 3; ++c)
    if (t[c] > 0.0 && !(std::abs(e[c]) <= t[c])) return c;  // NaN errors violate too
  return -1;
}

const char* const kComponent[3] = {"position", "velocity", "acceleration"};

std::string describeViolation(const State& error, const StateTolerance& tolerance, int c, const std::string& kind) {
  const double e[3] = {error.position, error.velocity, error.acceleration};
  const double t[3] = {tolerance.position, tolerance.velocity, tolerance.acceleration};
  return std::string(kComponent[c]) + " error " + num(e[c]) + " exceeds the " + kind + (kind.empty() ? "" : " ") +
         "tolerance " + num(t[c]) + " by " + num(std::abs(e[c]) - t[c]);
}

}  // namespace

// ---------------------------------------------------------------------------------------------
// Segments

Segment::Segment(double start_time, const State& start, double end_time, const State& end, Order order)
    : start_time_(start_time), duration_(std::max(0.0, end_time - start_time)), order_(order),
      end_position_(end.position) {
  const double T = duration_;
  const double h = end.position - start.position;
  const double v0 = start.velocity, v1 = end.velocity;
  const double a0 = start.acceleration, a1 = end.acceleration;
  c_.fill(0.0);
  c_[0] = start.position;
  switch (order) {
    case Order::Linear:
      c_[1] = T > 0.0 ? h / T : 0.0;
      break;
    case Order::Cubic:
      c_[1] = v0;
      if (T > 0.0) {
        c_[2] = (3.0 * h - (2.0 * v0 + v1) * T) / (T * T);
        c_[3] = (-2.0 * h + (v0 + v1) * T) / (T * T * T);
      }
      break;
    case Order::Quintic:
      c_[1] = v0;
      c_[2] = 0.5 * a0;
      if (T > 0.0) {
        const double T2 = T * T, T3 = T2 * T;
        c_[3] = (20.0 * h - (12.0 * v0 + 8.0 * v1) * T - (3.0 * a0 - a1) * T2) / (2.0 * T3);
        c_[4] = (-30.0 * h + (16.0 * v0 + 14.0 * v1) * T + (3.0 * a0 - 2.0 * a1) * T2) / (2.0 * T3 * T);
        c_[5] = (12.0 * h - 6.0 * (v0 + v1) * T - (a0 - a1) * T2) / (2.0 * T3 * T2);
      }
      break;
  }
}

State Segment::sample(double time) const {
  State s;
  const double x = time - start_time_;
  if (x < 0.0) {
    s.position = c_[0];
    return s;
  }
  // After the end (and for a zero-length segment, which ros_controllers would leave at its start
  // position) the end position is held exactly.
  if (x > duration_ || duration_ == 0.0) {
    s.position = end_position_;
    return s;
  }
  s.position = ((((c_[5] * x + c_[4]) * x + c_[3]) * x + c_[2]) * x + c_[1]) * x + c_[0];
  s.velocity = (((5.0 * c_[5] * x + 4.0 * c_[4]) * x + 3.0 * c_[3]) * x + 2.0 * c_[2]) * x + c_[1];
  s.acceleration = ((20.0 * c_[5] * x + 12.0 * c_[4]) * x + 6.0 * c_[3]) * x + 2.0 * c_[2];
  return s;
}

int findSegment(const JointTrajectory& trajectory, double time) {
  const auto it = std::upper_bound(trajectory.begin(), trajectory.end(), time,
                                   [](double t, const Segment& segment) { return t < segment.startTime(); });
  return static_cast<int>(it - trajectory.begin()) - 1;
}

int sample(const JointTrajectory& trajectory, double time, State& state) {
  const int index = findSegment(trajectory, time);
  if (index >= 0) state = trajectory[index].sample(time);
  else if (!trajectory.empty()) state = trajectory.front().sample(time);
  return index;
}

JointTrajectory holdTrajectory(double time, double position, int goal_id) {
  State state;
  state.position = position;
  Segment segment(time, state, time, state, Order::Quintic);
  segment.goal_id = goal_id;
  return {segment};
}

JointTrajectory stopTrajectory(double time, const State& from, double duration, int goal_id) {
  if (!(duration > 0.0)) return holdTrajectory(time, from.position, goal_id);
  State start = from, mirrored = from;
  start.acceleration = 0.0;
  mirrored.velocity = -from.velocity;
  mirrored.acceleration = 0.0;
  // Symmetric about its midpoint, so the velocity there is zero.
  const Segment symmetric(time, start, time + 2.0 * duration, mirrored, Order::Quintic);
  State rest = symmetric.sample(time + duration);
  rest.velocity = 0.0;
  Segment segment(time, start, time + duration, rest, Order::Quintic);
  segment.goal_id = goal_id;
  return {segment};
}

double shortestAngularDistance(double from, double to) {
  // angles::normalize_angle(to - from): into (-pi, pi].
  const double r = std::fmod(to - from + kPi, 2.0 * kPi);
  return r <= 0.0 ? r + kPi : r - kPi;
}

double wraparoundOffset(double previous, double next) {
  double distance = shortestAngularDistance(previous, next);
  if (std::abs(std::abs(distance) - kPi) < 1e-9) distance = next > previous ? std::abs(distance) : -std::abs(distance);
  return previous + distance - next;
}

// ---------------------------------------------------------------------------------------------
// Commands

int validateJoints(const Command& command, const std::vector<std::string>& joints, bool allow_partial,
                   std::vector<std::size_t>& mapping, std::string& error) {
  mapping.clear();
  if (command.joint_names.empty()) {
    error = "joint_names is empty; expected the controller's joints (" + list(joints) + ")";
    return kInvalidJoints;
  }
  std::vector<bool> named(joints.size(), false);
  std::vector<std::string> unknown, repeated;
  for (const auto& name : command.joint_names) {
    const auto it = std::find(joints.begin(), joints.end(), name);
    if (it == joints.end()) {
      unknown.push_back(name);
      continue;
    }
    const std::size_t index = static_cast<std::size_t>(it - joints.begin());
    if (named[index]) {
      repeated.push_back(name);
      continue;
    }
    named[index] = true;
    mapping.push_back(index);
  }
  if (!unknown.empty()) {
    error = (unknown.size() == 1 ? "joint " + quoted(unknown) + " is not a joint" : "joints " + quoted(unknown) +
                                                                                       " are not joints") +
            " of this controller (its joints: " + list(joints) + ")";
    return kInvalidJoints;
  }
  if (!repeated.empty()) {
    error = "joint_names lists " + quoted(repeated) + " more than once";
    return kInvalidJoints;
  }
  if (!allow_partial && mapping.size() != joints.size()) {
    std::vector<std::string> missing;
    for (std::size_t j = 0; j < joints.size(); ++j)
      if (!named[j]) missing.push_back(joints[j]);
    error = "missing joint" + std::string(missing.size() == 1 ? " " : "s ") + quoted(missing) +
            ": a trajectory must name all of the controller's joints (" + list(joints) +
            ") unless allow_partial_joints_goal is true";
    return kInvalidJoints;
  }
  return kSuccessful;
}

int validatePoints(const Command& command, std::string& error) {
  const std::size_t n = command.joint_names.size();
  const std::string per_joint = std::to_string(n) + ", one per joint in joint_names";
  for (std::size_t i = 0; i < command.points.size(); ++i) {
    const Waypoint& p = command.points[i];
    const std::string point = "point " + std::to_string(i);
    if (p.positions.size() != n) {
      error = point + " has " + std::to_string(p.positions.size()) + " positions; expected " + per_joint;
      return kInvalidGoal;
    }
    if (!p.velocities.empty() && p.velocities.size() != n) {
      error = point + " has " + std::to_string(p.velocities.size()) + " velocities; expected none or " + per_joint;
      return kInvalidGoal;
    }
    if (!p.accelerations.empty() && p.accelerations.size() != n) {
      error = point + " has " + std::to_string(p.accelerations.size()) + " accelerations; expected none or " +
              per_joint;
      return kInvalidGoal;
    }
    const std::vector<double>* fields[3] = {&p.positions, &p.velocities, &p.accelerations};
    const char* const field_names[3] = {"positions", "velocities", "accelerations"};
    for (int f = 0; f < 3; ++f) {
      for (std::size_t k = 0; k < fields[f]->size(); ++k) {
        if (!std::isfinite((*fields[f])[k])) {
          error = point + ": " + field_names[f] + "[" + std::to_string(k) + "] (joint '" + command.joint_names[k] +
                  "') is " + num((*fields[f])[k]) + "; expected a finite number";
          return kInvalidGoal;
        }
      }
    }
    if (!std::isfinite(p.time_from_start)) {
      error = point + ": time_from_start is not a finite number";
      return kInvalidGoal;
    }
    if (i > 0 && !(p.time_from_start > command.points[i - 1].time_from_start)) {
      error = point + "'s time_from_start " + num(p.time_from_start) + " s is not after point " +
              std::to_string(i - 1) + "'s " + num(command.points[i - 1].time_from_start) +
              " s; times must increase strictly";
      return kInvalidGoal;
    }
  }
  return kSuccessful;
}

MergeResult merge(const Trajectory& current, const Command& command, double start_time, double now,
                  const MergeOptions& options) {
  MergeResult result;
  std::vector<std::size_t> mapping;
  result.error_code = validateJoints(command, options.joints, options.allow_partial, mapping, result.error);
  if (result.error_code != kSuccessful) return result;
  result.error_code = validatePoints(command, result.error);
  if (result.error_code != kSuccessful) return result;
  const auto& points = command.points;
  if (points.empty()) {
    result.error_code = kInvalidGoal;
    result.error = "the trajectory has no points";
    return result;
  }
  if (current.size() != options.joints.size()) {
    result.error_code = kInvalidGoal;
    result.error = "internal error: the current trajectory has " + std::to_string(current.size()) +
                   " joints, the controller " + std::to_string(options.joints.size());
    return result;
  }

  // The first point after `now`; those at or before it are dropped.
  std::size_t first = 0;
  while (first < points.size() && start_time + points[first].time_from_start <= now) ++first;
  result.dropped_points = first;
  if (first == points.size()) {
    result.error_code = kInvalidGoal;
    result.error = "all " + std::to_string(points.size()) +
                   " trajectory points are in the past: the last one is " +
                   num(now - (start_time + points.back().time_from_start)) +
                   " s before the next control update (check header.stamp; zero means start now)";
    return result;
  }

  result.trajectory.resize(options.joints.size());
  std::vector<bool> commanded(options.joints.size(), false);
  for (std::size_t k = 0; k < mapping.size(); ++k) {
    const std::size_t j = mapping[k];
    commanded[j] = true;
    const JointTrajectory& old = current[j];
    JointTrajectory& out = result.trajectory[j];
    double offset = 0.0;

    if (!old.empty()) {
      // Keep the current trajectory until the new one starts, then bridge from its state there
      // to the first remaining point.
      const double bridge_start = std::max(start_time, now);
      State from;
      sample(old, bridge_start, from);
      State to = pointState(points[first], k, 0.0);
      if (j < options.wraparound.size() && options.wraparound[j]) offset = wraparoundOffset(from.position, to.position);
      to.position += offset;
      const int keep_from = std::max(0, findSegment(old, now));
      const int keep_to = findSegment(old, bridge_start);
      for (int s = keep_from; s <= keep_to; ++s) {
        out.push_back(old[s]);
        out.back().goal_id = options.goal_id;
      }
      Segment bridge(bridge_start, from, start_time + points[first].time_from_start, to, pointOrder(points[first]));
      bridge.goal_id = options.goal_id;
      out.push_back(bridge);
    } else if (first + 1 == points.size()) {
      // Nothing to bridge from: just be at the single point from its time on.
      out = holdTrajectory(start_time + points[first].time_from_start, points[first].positions[k], options.goal_id);
    }

    for (std::size_t p = first; p + 1 < points.size(); ++p) {
      const Order order = std::min(pointOrder(points[p]), pointOrder(points[p + 1]));
      Segment segment(start_time + points[p].time_from_start, pointState(points[p], k, offset),
                      start_time + points[p + 1].time_from_start, pointState(points[p + 1], k, offset), order);
      segment.goal_id = options.goal_id;
      out.push_back(segment);
    }
  }

  // Joints a partial command leaves out carry on, now as part of the new goal.
  for (std::size_t j = 0; j < options.joints.size(); ++j) {
    if (commanded[j]) continue;
    const JointTrajectory& old = current[j];
    const int keep_from = std::max(0, findSegment(old, now));
    for (std::size_t s = static_cast<std::size_t>(keep_from); s < old.size(); ++s) {
      result.trajectory[j].push_back(old[s]);
      result.trajectory[j].back().goal_id = options.goal_id;
    }
  }
  return result;
}

// ---------------------------------------------------------------------------------------------
// Tolerances

void applyOverrides(const std::vector<ToleranceOverride>& overrides, const std::vector<std::string>& joints,
                    std::vector<StateTolerance>& tolerances) {
  auto apply = [](double given, double& tolerance) {
    if (given > 0.0) tolerance = given;
    else if (given < 0.0) tolerance = 0.0;  // no check
  };
  for (const auto& o : overrides) {
    const auto it = std::find(joints.begin(), joints.end(), o.name);
    if (it == joints.end()) continue;
    const std::size_t j = static_cast<std::size_t>(it - joints.begin());
    if (j >= tolerances.size()) continue;
    apply(o.position, tolerances[j].position);
    apply(o.velocity, tolerances[j].velocity);
    apply(o.acceleration, tolerances[j].acceleration);
  }
}

double applyGoalTimeOverride(double goal_time, double default_goal_time) {
  if (goal_time > 0.0) return goal_time;
  if (goal_time < 0.0) return 0.0;
  return default_goal_time;
}

bool withinTolerance(const State& error, const StateTolerance& tolerance, std::string* violation) {
  const int c = firstViolation(error, tolerance);
  if (c < 0) return true;
  if (violation) *violation = describeViolation(error, tolerance, c, "");
  return false;
}

void GoalMonitor::start(int goal_id, const Tolerances& tolerances, const std::vector<std::string>& joints,
                        double start_time) {
  goal_id_ = goal_id;
  tolerances_ = tolerances;
  joints_ = joints;
  tolerances_.path.resize(joints.size());
  tolerances_.goal.resize(joints.size());
  reached_.assign(joints.size(), false);
  start_time_ = start_time;
}

GoalMonitor::Result GoalMonitor::check(double now, const Trajectory& trajectory, const std::vector<int>& segments,
                                       const std::vector<State>& errors) {
  Result result;
  if (!active()) return result;
  const std::size_t n = std::min({joints_.size(), trajectory.size(), segments.size(), errors.size()});
  for (std::size_t i = 0; i < n; ++i) {
    if (segments[i] < 0 || static_cast<std::size_t>(segments[i]) >= trajectory[i].size()) continue;
    const Segment& segment = trajectory[i][segments[i]];
    if (segment.goal_id != goal_id_) continue;
    if (now < segment.endTime()) {
      // Executing: path tolerance.
      const int c = firstViolation(errors[i], tolerances_.path[i]);
      if (c >= 0) {
        result.done = true;
        result.error_code = kPathToleranceViolated;
        result.message = "joint '" + joints_[i] + "' left its path: " +
                         describeViolation(errors[i], tolerances_.path[i], c, "path") + ", " +
                         num(now - start_time_) + " s into the trajectory";
        clear();
        return result;
      }
    } else if (static_cast<std::size_t>(segments[i]) + 1 == trajectory[i].size()) {
      // Past the last point: goal tolerance, with goal_time to get there.
      const int c = firstViolation(errors[i], tolerances_.goal[i]);
      if (c < 0) {
        reached_[i] = true;
      } else if (now < segment.endTime() + tolerances_.goal_time) {
        // Still time to settle.
      } else {
        result.done = true;
        result.error_code = kGoalToleranceViolated;
        result.message = "joint '" + joints_[i] + "' " + (c == 1 ? "was still moving" : "missed its goal") + ": " +
                         describeViolation(errors[i], tolerances_.goal[i], c, c == 1 ? "stopped velocity" : "goal") +
                         ", " +
                         num(now - segment.endTime()) + " s after the trajectory's end (goal_time tolerance " +
                         num(tolerances_.goal_time) + " s)";
        clear();
        return result;
      }
    }
  }
  if (!reached_.empty() && std::all_of(reached_.begin(), reached_.end(), [](bool r) { return r; })) {
    result.done = true;
    result.error_code = kSuccessful;
    clear();
  }
  return result;
}

}  // namespace trajectory
}  // namespace sim_control
