#include "bullet_sim_plugins/grasp_detector.h"

#include <algorithm>
#include <cmath>
#include <set>

namespace bullet_sim {

std::string validate(const GraspFixOptions& o) {
  std::string problems;
  const auto add = [&](const std::string& p) { problems += (problems.empty() ? "" : "; ") + p; };
  if (!(o.forces_angle_tolerance >= 0 && o.forces_angle_tolerance <= 180))
    add("forces_angle_tolerance: expected degrees in [0, 180], got " + std::to_string(o.forces_angle_tolerance));
  if (!(o.update_rate > 0 && std::isfinite(o.update_rate)))
    add("update_rate: expected checks per second > 0, got " + std::to_string(o.update_rate));
  if (o.max_grip_count < 1) add("max_grip_count: expected at least 1, got " + std::to_string(o.max_grip_count));
  if (o.grip_count_threshold < 1 || o.grip_count_threshold > o.max_grip_count)
    add("grip_count_threshold: expected 1 to max_grip_count (" + std::to_string(o.max_grip_count) + "), got " +
        std::to_string(o.grip_count_threshold));
  if (!(o.release_tolerance >= 0 && std::isfinite(o.release_tolerance)))
    add("release_tolerance: expected a distance >= 0 m, got " + std::to_string(o.release_tolerance));
  return problems;
}

bool GraspDetector::opposing(const std::vector<Touch>& touches, double tolerance_degrees) {
  // One push per gripper link: the sum of its contacts' pushes.
  std::map<int, Eigen::Vector3d> pushes;
  for (const Touch& t : touches) {
    auto [it, fresh] = pushes.emplace(t.gripper_link, Eigen::Vector3d::Zero());
    it->second += t.push.normalized();
  }
  const double min_angle = (180.0 - tolerance_degrees) * M_PI / 180.0;
  for (auto a = pushes.begin(); a != pushes.end(); ++a) {
    for (auto b = std::next(a); b != pushes.end(); ++b) {
      if (a->second.norm() < 1e-9 || b->second.norm() < 1e-9) continue;
      const double cosine = a->second.normalized().dot(b->second.normalized());
      if (std::acos(std::clamp(cosine, -1.0, 1.0)) >= min_angle - 1e-12) return true;
    }
  }
  return false;
}

std::vector<GraspDetector::Event> GraspDetector::update(const std::vector<Touch>& touches, double spread) {
  std::map<std::string, std::vector<Touch>> by_object;
  for (const Touch& t : touches) by_object[t.object].push_back(t);
  std::set<std::string> seen;
  for (const auto& [object, state] : objects_) seen.insert(object);
  for (const auto& [object, list] : by_object) seen.insert(object);

  std::vector<Event> events;
  for (const std::string& object : seen) {
    State& s = objects_[object];
    const auto it = by_object.find(object);
    const bool untouched = it == by_object.end();
    if (s.let_go) {
      // Not counted until the fingers close anew: fingers that opened grip nothing.
      s.widest = std::max(s.widest, spread);
      if (s.widest - spread <= GraspFixOptions::kOpenedOffFraction * options_.release_tolerance) continue;
      s.let_go = false;
    }
    const bool gripped = !untouched && opposing(it->second, options_.forces_angle_tolerance);
    s.count = gripped ? std::min(s.count + 1, options_.max_grip_count) : std::max(s.count - 1, 0);
    if (s.attached) {
      s.tightest = std::min(s.tightest, spread);
      const double opened = spread - s.tightest;
      if (opened > options_.release_tolerance ||
          (!gripped && opened > GraspFixOptions::kOpenedOffFraction * options_.release_tolerance)) {
        s = State{};  // released: start again from nothing
        s.let_go = true;
        s.widest = spread;
        events.push_back({object, false});
      }
    } else if (s.count >= options_.grip_count_threshold) {
      s.attached = true;
      s.tightest = spread;
      events.push_back({object, true});
    }
  }
  // Objects neither touched nor held are forgotten, so the map stays small.
  for (auto it = objects_.begin(); it != objects_.end();)
    it = (!it->second.attached && !it->second.let_go && it->second.count == 0) ? objects_.erase(it) : std::next(it);
  return events;
}

void GraspDetector::forget(const std::string& object) { objects_.erase(object); }

bool GraspDetector::isAttached(const std::string& object) const {
  const auto it = objects_.find(object);
  return it != objects_.end() && it->second.attached;
}

int GraspDetector::gripCount(const std::string& object) const {
  const auto it = objects_.find(object);
  return it == objects_.end() ? 0 : it->second.count;
}

}  // namespace bullet_sim
