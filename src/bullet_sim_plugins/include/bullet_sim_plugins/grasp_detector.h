#pragma once
// The grasp fix's decision, without ROS or physics (libgazebo_grasp_fix.so's semantics, our own
// rules where upstream's hurt): when is an object held by the gripper, and when is it let go.
//
// Every check (update_rate times a second of sim time) brings the touches between the gripper's
// links and other objects. An object is gripped in a check when two gripper links push on it in
// roughly opposing directions: the angle between their pushes is at least
// 180 - forces_angle_tolerance degrees. Its grip count goes up by one in a check where it is
// gripped (up to max_grip_count) and down by one where it is not; at grip_count_threshold it is
// attached. It is released when the gripper opens: the gripper links' spread (the plugin passes
// the mean distance of their centres of mass from their centroid) grows by more than
// release_tolerance beyond the tightest it has been since the attach, or it has opened by a fifth
// of that and is no longer gripped (one gripper link on it at most). Measuring from the tightest
// spread, not from the spread at the attach, means a gripper that closes further after the attach
// still lets go as soon as it opens (upstream compares with the attach and can hold for ever).
// The second rule lets go of an object held near the fingers' hinges, where opening moves the
// fingers off it by less than the tolerance: a can deep in the Katana's gripper, fingers stalled
// at 0.18 rad, spread only 4.2 mm on opening to katana_driver's open 0.30 rad, under the
// tutorial's 5 mm, and stayed in the open gripper. It also lets go when one finger opens and the
// other stays on the object: a finger whose edge rests on a held can's side is pinned there, as
// the can fixed to the palm cannot give way (old-band seed 14: 3.5 mm, and the back-away pulled
// the tower over). While held, the fingers press on the object; only an opening leaves them off it.
// A released object starts again from a count of 0, and is not counted at all until the gripper
// closes again (its spread falls a fifth of release_tolerance below its widest since the
// release). Upstream counts it at once, so open fingers that rest on it grip it again
// (gazebo-pkgs issue 52: "still sticking for 1-2 seconds"): a steep Katana grasp leaves the can's
// rim between the open fingers' roots, touching both at 0.1 N once the arm, rid of the can's
// weight, springs back 1 cm, and the can set down was attached again after 1 s and dragged by the
// back-away. Every new grasp closes the fingers, so none is lost.
#include <Eigen/Core>

#include <map>
#include <string>
#include <vector>

namespace bullet_sim {

struct GraspFixOptions {
  double forces_angle_tolerance = 100.0;  // degrees
  double update_rate = 5.0;               // checks per second of sim time
  int grip_count_threshold = 5;
  int max_grip_count = 10;
  double release_tolerance = 0.005;  // m
  // The part of release_tolerance the gripper must have opened by to let go of an object that no
  // gripper link touches any more, and closed by to grip again an object it let go of while still
  // touching it (the spread's jitter is about 1e-6 m).
  static constexpr double kOpenedOffFraction = 0.2;
  bool disable_collisions_on_attach = false;
};

// "" if usable, else what is wrong, naming the field.
std::string validate(const GraspFixOptions& options);

class GraspDetector {
 public:
  struct Touch {
    std::string object;           // what is touched (the plugin's key: model and link)
    int gripper_link = 0;         // which gripper link touches it (index)
    Eigen::Vector3d push;         // direction of the gripper link's push on the object (any length > 0)
  };
  struct Event {
    std::string object;
    bool attached = false;  // true: attach it now; false: release it now
  };

  explicit GraspDetector(const GraspFixOptions& options) : options_(options) {}

  // One check: this check's touches and the gripper's spread (m). Returns what changes.
  std::vector<Event> update(const std::vector<Touch>& touches, double spread);
  // Forgets an object (e.g. it was deleted), attached or not; no event.
  void forget(const std::string& object);
  bool isAttached(const std::string& object) const;
  int gripCount(const std::string& object) const;

  // Whether two gripper links push on an object in roughly opposing directions.
  static bool opposing(const std::vector<Touch>& touches_of_one_object, double tolerance_degrees);

 private:
  struct State {
    int count = 0;
    bool attached = false;
    double tightest = 0.0;  // the smallest spread since the attach
    bool let_go = false;    // released, and the gripper not closed since
    double widest = 0.0;    // the largest spread since the release
  };
  GraspFixOptions options_;
  std::map<std::string, State> objects_;
};

}  // namespace bullet_sim
