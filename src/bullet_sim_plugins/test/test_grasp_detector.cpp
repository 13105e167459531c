// The grasp fix's decisions (grasp_detector.h): opposing pushes, grip counts, attach, release.
#include <gtest/gtest.h>

#include <cmath>

#include "bullet_sim_plugins/grasp_detector.h"

namespace bullet_sim {
namespace {

using Touch = GraspDetector::Touch;

// Two fingers pushing on `object` from either side, the second turned by `angle` (rad) from opposing.
std::vector<Touch> pinch(const std::string& object, double angle = 0.0) {
  return {{object, 0, Eigen::Vector3d(1, 0, 0)}, {object, 1, Eigen::Vector3d(-std::cos(angle), std::sin(angle), 0)}};
}

TEST(GraspDetector, OpposingMeansAtLeast180MinusTheToleranceApart) {
  const double deg = M_PI / 180;
  EXPECT_TRUE(GraspDetector::opposing(pinch("can"), 0.0));              // exactly opposite
  EXPECT_TRUE(GraspDetector::opposing(pinch("can", 99 * deg), 100.0));  // 81 degrees apart >= 80
  EXPECT_FALSE(GraspDetector::opposing(pinch("can", 101 * deg), 100.0));
  EXPECT_FALSE(GraspDetector::opposing(pinch("can", 10 * deg), 5.0));
  // One finger, however many contacts, never grips; contacts of one link are summed first.
  EXPECT_FALSE(GraspDetector::opposing({{"can", 0, Eigen::Vector3d(1, 0, 0)}, {"can", 0, Eigen::Vector3d(-1, 0, 0.1)}},
                                       180.0));
}

TEST(GraspDetector, AttachesAtTheThresholdCheckAndOnlyOnce) {
  GraspFixOptions o;
  o.grip_count_threshold = 4;
  o.max_grip_count = 8;
  GraspDetector d(o);
  for (int check = 1; check <= 3; ++check) {
    EXPECT_TRUE(d.update(pinch("can"), 0.07).empty()) << check;
    EXPECT_EQ(d.gripCount("can"), check);
  }
  const auto events = d.update(pinch("can"), 0.07);
  ASSERT_EQ(events.size(), 1u);
  EXPECT_EQ(events[0].object, "can");
  EXPECT_TRUE(events[0].attached);
  EXPECT_TRUE(d.isAttached("can"));
  for (int check = 0; check < 10; ++check) EXPECT_TRUE(d.update(pinch("can"), 0.07).empty());
  EXPECT_EQ(d.gripCount("can"), 8);  // capped at max_grip_count
}

TEST(GraspDetector, ACountFallsWhileNotGrippedAndOneFingerNeverAttaches) {
  GraspFixOptions o;
  o.grip_count_threshold = 4;
  GraspDetector d(o);
  for (int i = 0; i < 3; ++i) d.update(pinch("can"), 0.07);
  d.update({}, 0.07);
  d.update({{"can", 0, Eigen::Vector3d(1, 0, 0)}}, 0.07);  // one finger: not a grip
  EXPECT_EQ(d.gripCount("can"), 1);
  EXPECT_TRUE(d.update(pinch("can"), 0.07).empty());
  EXPECT_TRUE(d.update(pinch("can"), 0.07).empty());
  EXPECT_EQ(d.update(pinch("can"), 0.07).size(), 1u);  // 4 again
  GraspDetector lonely(o);
  for (int i = 0; i < 20; ++i) EXPECT_TRUE(lonely.update({{"can", 1, Eigen::Vector3d(0, 1, 0)}}, 0.07).empty());
}

// A detector (attach after 2 checks, release_tolerance 5 mm) that has just attached "can",
// pinched at the gripper spread `spread`.
GraspDetector holdingTheCan(double spread) {
  GraspFixOptions o;
  o.grip_count_threshold = 2;
  o.release_tolerance = 0.005;
  GraspDetector d(o);
  d.update(pinch("can"), spread);
  d.update(pinch("can"), spread);
  return d;
}

TEST(GraspDetector, ReleasesWhenTheGripperOpensBeyondTheToleranceFromItsTightest) {
  GraspDetector d = holdingTheCan(0.070);
  ASSERT_TRUE(d.isAttached("can"));
  d.update(pinch("can"), 0.066);                      // squeezed 4 mm tighter after the attach
  EXPECT_TRUE(d.update(pinch("can"), 0.070).empty());  // 4 mm open from the tightest: still held
  EXPECT_TRUE(d.isAttached("can"));
  const auto events = d.update({}, 0.0715);  // 5.5 mm open from the tightest: let go
  ASSERT_EQ(events.size(), 1u);
  EXPECT_FALSE(events[0].attached);
  EXPECT_FALSE(d.isAttached("can"));
  EXPECT_EQ(d.gripCount("can"), 0);
}

TEST(GraspDetector, AnObjectNoFingerTouchesIsLetGoOnceTheGripperOpensAFifthOfTheTolerance) {
  GraspDetector d = holdingTheCan(0.0319);
  ASSERT_TRUE(d.isAttached("can"));
  // The fingers off the can but the gripper no wider (they jitter): held.
  EXPECT_TRUE(d.update({}, 0.0319 + 1e-6).empty());
  EXPECT_TRUE(d.update({}, 0.0319 + 0.0009).empty());
  // Opened 1.5 mm with both fingers still on it: held (less than the tolerance).
  EXPECT_TRUE(d.update(pinch("can"), 0.0334).empty());
  EXPECT_TRUE(d.isAttached("can"));
  // Opened 4.2 mm and off it (the can deep in the Katana's gripper): let go.
  const auto events = d.update({}, 0.0361);
  ASSERT_EQ(events.size(), 1u);
  EXPECT_FALSE(events[0].attached);
  EXPECT_FALSE(d.isAttached("can"));
}

TEST(GraspDetector, AnObjectOneFingerStillTouchesIsLetGoOnceTheGripperOpensAFifthOfTheTolerance) {
  // Old-band seed 14: the right finger opened off the can, the left one stuck on its rim; the
  // spread grew 3.5 mm, under the 5 mm tolerance, and the can stayed in the open gripper.
  GraspDetector d = holdingTheCan(0.0350);
  const std::vector<Touch> one_finger{{"can", 1, Eigen::Vector3d(0.93, -0.36, 0)}};
  EXPECT_TRUE(d.update(one_finger, 0.0350 + 0.0009).empty());  // not yet opened a fifth: held
  EXPECT_TRUE(d.isAttached("can"));
  const auto events = d.update(one_finger, 0.0385);
  ASSERT_EQ(events.size(), 1u);
  EXPECT_FALSE(events[0].attached);
  EXPECT_FALSE(d.isAttached("can"));
  // The stuck finger still touches it: not gripped again until the gripper closes.
  for (int i = 0; i < 10; ++i) EXPECT_TRUE(d.update(one_finger, 0.0385).empty()) << i;
}

TEST(GraspDetector, AReleasedObjectIsNotGrippedAgainByFingersThatOpenedAndStillTouchIt) {
  GraspFixOptions o;
  o.grip_count_threshold = 3;
  o.release_tolerance = 0.005;
  GraspDetector d(o);
  for (int i = 0; i < 3; ++i) d.update(pinch("can"), 0.07);
  ASSERT_TRUE(d.isAttached("can"));
  ASSERT_EQ(d.update(pinch("can"), 0.08).size(), 1u);  // opened while the fingers still touch
  // Open and resting on it, however long, with the spread's jitter: never held again.
  for (int i = 0; i < 20; ++i) {
    EXPECT_TRUE(d.update(pinch("can"), 0.08 - (i % 2) * 1e-6).empty()) << i;
    EXPECT_EQ(d.gripCount("can"), 0);
  }
  // Closed on it anew (by more than a fifth of the tolerance): counted from 0, attached at 3.
  EXPECT_TRUE(d.update(pinch("can"), 0.0785).empty());
  EXPECT_EQ(d.gripCount("can"), 1);
  EXPECT_TRUE(d.update(pinch("can"), 0.072).empty());
  const auto again = d.update(pinch("can"), 0.07);
  ASSERT_EQ(again.size(), 1u);
  EXPECT_TRUE(again[0].attached);
}

TEST(GraspDetector, AReleasedObjectTheOpenFingersCameOffAndTouchAgainIsNotGripped) {
  // The arm, rid of the can's weight, springs back and brings the open fingers onto it again.
  GraspFixOptions o;
  o.grip_count_threshold = 2;
  GraspDetector d(o);
  for (int i = 0; i < 2; ++i) d.update(pinch("can"), 0.07);
  ASSERT_EQ(d.update({}, 0.08).size(), 1u);  // let go, the fingers off it
  for (int i = 0; i < 10; ++i) EXPECT_TRUE(d.update(pinch("can"), 0.08).empty()) << i;
  EXPECT_FALSE(d.isAttached("can"));
  // Opened wider still, then closed on it: a new grasp.
  d.update({}, 0.09);
  EXPECT_TRUE(d.update(pinch("can"), 0.0885).empty());
  EXPECT_EQ(d.update(pinch("can"), 0.0885).size(), 1u);
}

TEST(GraspDetector, ObjectsAreCountedApartAndForgetting) {
  GraspFixOptions o;
  o.grip_count_threshold = 2;
  GraspDetector d(o);
  auto both = pinch("can_1");
  const auto other = pinch("can_2", 2.0);  // pushes 65 degrees apart: no grip at tolerance 100
  both.insert(both.end(), other.begin(), other.end());
  d.update(both, 0.07);
  const auto events = d.update(both, 0.07);
  ASSERT_EQ(events.size(), 1u);
  EXPECT_EQ(events[0].object, "can_1");
  EXPECT_FALSE(d.isAttached("can_2"));
  d.forget("can_1");
  EXPECT_FALSE(d.isAttached("can_1"));
  EXPECT_EQ(d.gripCount("can_1"), 0);
}

TEST(GraspDetector, OptionsAreValidatedByName) {
  EXPECT_EQ(validate(GraspFixOptions{}), "");
  GraspFixOptions o;
  o.update_rate = 0;
  o.grip_count_threshold = 11;
  o.forces_angle_tolerance = 200;
  const std::string problems = validate(o);
  for (const char* field : {"update_rate", "grip_count_threshold", "forces_angle_tolerance"})
    EXPECT_NE(problems.find(field), std::string::npos) << field << " not in: " << problems;
  EXPECT_EQ(problems.find("release_tolerance"), std::string::npos);
}

}  // namespace
}  // namespace bullet_sim
