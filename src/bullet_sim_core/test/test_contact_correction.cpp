// Overlaps corrected as Gazebo limits it (contact_solver.cpp, "Interpenetration"): a body spawned
// into the ground or into another rises out of it no faster than the contact's max_vel, keeps
// min_depth of it, and gains no kinetic energy from it. Runs without ROS.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>
#include <string>

#include "bullet_sim_core/description_error.h"
#include "bullet_sim_core/physics_world.h"
#include "bullet_sim_core/urdf_parser.h"
#include "ground_plane.h"

using namespace bullet_sim;

namespace {

constexpr double kStep = 0.001;  // s, PhysicsSettings' default
constexpr double kHalf = 0.1;    // m, half the test box's size: its centre's height at rest
// How much faster than its limit a contact may seem to push. The pass aims at exactly the limit and
// stops once a sweep changes no contact's speed by more than 1e-6 m/s; the velocity rows (stopped at
// the world's solver tolerance, 1e-5 m/s) let the box drift no faster than that on top of it.
constexpr double kRateTolerance = 2e-5;  // m/s
// Steps before a box in the ground has its four corners in contact: Bullet's box-plane contact finds
// one corner a step, so in the first it tips on one and moves at up to g * dt (10 mm/s), from its
// weight, not from the overlap.
constexpr int kSettling = 10;

ModelDescription parse(const std::string& xml) { return parseUrdf(xml, "test.urdf", ResourceResolver()); }

// A 0.2 m cube of 1 kg; `gazebo` goes into a <gazebo reference="body"> block.
std::string boxUrdf(const std::string& name, const std::string& gazebo = "") {
  return R"(<robot name=")" + name + R"("><link name="body">
    <inertial><mass value="1"/><inertia ixx="0.00667" ixy="0" ixz="0" iyy="0.00667" iyz="0" izz="0.00667"/></inertial>
    <collision><geometry><box size="0.2 0.2 0.2"/></geometry></collision></link>
    <gazebo reference="body">)" + gazebo + R"(</gazebo></robot>)";
}

Eigen::Isometry3d at(double x, double y, double z) {
  Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
  t.translation() = Eigen::Vector3d(x, y, z);
  return t;
}

// A box `depth` into the ground, stepped for `seconds`: how fast and how far it rose, how fast it
// moved (what it gained in kinetic energy), when it came within 1 mm of `rest` (its centre's height
// at rest) and where it ended.
struct Rise {
  double fastest_rise = 0;  // m/s, from its height step to step
  double highest = -1e9;    // m, its centre
  double rising = 0;        // m/s, its centre's upward velocity
  double fastest = 0;       // m/s, its velocity (and rad/s of its rotation, times its half size) after kSettling
  double arrived = -1;      // s, first within 1 mm of rest; -1: never
  double end_height = 0;
  double end_speed = 0;
};

Rise riseOutOfTheGround(const PhysicsSettings& settings, const std::string& gazebo, double depth, double seconds,
                        double rest = kHalf) {
  PhysicsWorld world(settings);
  world.addModel(groundPlane(), Eigen::Isometry3d::Identity());
  PhysicsModel& box = world.addModel(parse(boxUrdf("box", gazebo)), at(0, 0, kHalf - depth));
  Rise r;
  double z = box.pose().translation().z();
  for (int i = 1; i <= static_cast<int>(seconds / kStep); ++i) {
    world.step();
    const double next = box.pose().translation().z();
    r.fastest_rise = std::max(r.fastest_rise, (next - z) / kStep);
    z = next;
    r.highest = std::max(r.highest, z);
    const Twist t = box.twist();
    r.rising = std::max(r.rising, t.linear.z());
    if (i > kSettling) r.fastest = std::max(r.fastest, t.linear.norm() + t.angular.norm() * kHalf);
    if (r.arrived < 0 && z > rest - 1e-3) r.arrived = i * kStep;
  }
  r.end_height = z;
  r.end_speed = box.twist().linear.norm() + box.twist().angular.norm() * kHalf;
  return r;
}

}  // namespace

// Bullet's own correction (erp * depth / dt as velocity) threw this box out of the ground at
// metres per second. SDF's max_vel of 0.01 m/s: it rises 0.1 m in 10 s and stands there.
TEST(ContactCorrection, ABoxSpawnedIntoTheGroundRisesAtMaxVelToRest) {
  const Rise r = riseOutOfTheGround(PhysicsSettings(), "", 0.1, 12);
  EXPECT_LE(r.fastest_rise, 0.01 + kRateTolerance);
  EXPECT_GT(r.fastest_rise, 0.01 - kRateTolerance);  // and at the limit, not slower
  EXPECT_LT(r.highest, kHalf + 2e-3);                 // never above where it rests
  // 0.099 m at 0.01 m/s; the last steps, where erp * depth / dt is below the limit, take ms.
  EXPECT_NEAR(r.arrived, 9.9, 0.02);
  EXPECT_NEAR(r.end_height, kHalf, 1e-4);
  EXPECT_LT(r.end_speed, 1e-4);
  // The push moves positions only: the box itself never moved up, nor at more than a tenth of the
  // limit once it stood on its four corners.
  EXPECT_LT(r.rising, 1e-4);
  EXPECT_LT(r.fastest, 1e-3);
}

// Both boxes move: the contact's limit is their speed apart, 0.01 m/s, 5 mm/s each.
TEST(ContactCorrection, TwoBoxesSpawnedOverlappingPartAtMaxVel) {
  PhysicsSettings weightless;
  weightless.gravity.setZero();
  PhysicsWorld world(weightless);
  PhysicsModel& a = world.addModel(parse(boxUrdf("a")), at(0, 0, 1));
  PhysicsModel& b = world.addModel(parse(boxUrdf("b")), at(0.15, 0, 1));  // 0.05 m into each other
  double gap = 0.15, fastest_parting = 0, fastest = 0, touching = -1;
  for (int i = 1; i <= 7000; ++i) {
    world.step();
    const double next = (b.pose().translation() - a.pose().translation()).norm();
    fastest_parting = std::max(fastest_parting, (next - gap) / kStep);
    gap = next;
    for (const PhysicsModel* m : {&a, &b}) fastest = std::max(fastest, m->twist().linear.norm());
    if (touching < 0 && gap > 0.2 - 1e-3) touching = i * kStep;
  }
  EXPECT_LE(fastest_parting, 0.01 + kRateTolerance);
  EXPECT_GT(fastest_parting, 0.01 - kRateTolerance);
  EXPECT_NEAR(touching, 4.9, 0.02);  // 0.049 m at 0.01 m/s
  EXPECT_NEAR(gap, 0.2, 1e-4);       // touching, not apart
  EXPECT_LT(fastest, 1e-3);
  // Neither was pushed more than the other: they part about their middle.
  EXPECT_NEAR(a.pose().translation().x() + b.pose().translation().x(), 0.15, 1e-3);
}

TEST(ContactCorrection, ASurfaceMaxVelOfTenTimesTheDefaultIsTenTimesFaster) {
  const Rise slow = riseOutOfTheGround(PhysicsSettings(), "", 0.05, 6);
  const Rise fast = riseOutOfTheGround(PhysicsSettings(), "<maxVel>0.1</maxVel>", 0.05, 1);
  EXPECT_NEAR(fast.fastest_rise, 0.1, 10 * kRateTolerance);
  EXPECT_NEAR(slow.arrived, 4.9, 0.02);
  EXPECT_NEAR(fast.arrived, 0.49, 0.01);
  EXPECT_NEAR(slow.arrived / fast.arrived, 10, 0.3);
  EXPECT_NEAR(fast.end_height, kHalf, 1e-4);
  EXPECT_LT(fast.rising, 1e-4);
  EXPECT_LT(fast.fastest, 1e-3);
}

// contact_max_correcting_vel caps every contact's max_vel; a negative max_vel leaves only it.
TEST(ContactCorrection, TheWorldsCorrectingVelocityCapsTheSurfaces) {
  PhysicsSettings slow_world;
  slow_world.contact_max_correcting_vel = 0.005;
  const Rise capped = riseOutOfTheGround(slow_world, "", 0.02, 5);  // the surface says 0.01
  EXPECT_LE(capped.fastest_rise, 0.005 + kRateTolerance);
  EXPECT_NEAR(capped.arrived, 3.8, 0.02);  // 0.019 m at 0.005 m/s
  PhysicsSettings world;
  world.contact_max_correcting_vel = 0.02;
  const Rise only_world = riseOutOfTheGround(world, "<maxVel>-1</maxVel>", 0.02, 2);
  EXPECT_NEAR(only_world.fastest_rise, 0.02, kRateTolerance);
  EXPECT_NEAR(only_world.arrived, 0.95, 0.01);
}

// min_depth is the overlap a contact leaves: the box rests that deep. The world's
// contact_surface_layer would be it only for bodies without surfaces of their own; every link has
// them (min_depth 0 by default), so as in Gazebo the layer does not sink the box.
TEST(ContactCorrection, MinDepthIsLeftAndTheSurfaceLayerGivesWayToIt) {
  const Rise kept = riseOutOfTheGround(PhysicsSettings(), "<minDepth>0.005</minDepth>", 0.02, 3, kHalf - 0.005);
  EXPECT_NEAR(kept.end_height, kHalf - 0.005, 1e-4);
  EXPECT_NEAR(kept.arrived, 1.4, 0.02);  // 0.014 m at 0.01 m/s
  EXPECT_LT(kept.highest, kHalf - 0.005 + 1e-4);
  PhysicsSettings layered;
  layered.contact_surface_layer = 0.005;
  const Rise layer = riseOutOfTheGround(layered, "", 0.02, 3);
  EXPECT_NEAR(layer.end_height, kHalf, 1e-4);
  // A box dropped onto the ground stops at its surface, min_depth or not (nothing pushes it in).
  PhysicsWorld world;
  world.addModel(groundPlane(), Eigen::Isometry3d::Identity());
  PhysicsModel& box = world.addModel(parse(boxUrdf("box", "<minDepth>0.005</minDepth>")), at(0, 0, 0.3));
  for (int i = 0; i < 2000; ++i) world.step();
  EXPECT_GT(box.pose().translation().z(), kHalf - 0.005 - 1e-4);
  EXPECT_LT(box.pose().translation().z(), kHalf + 1e-4);
}

TEST(ContactCorrection, BadWorldValuesAreRejected) {
  PhysicsWorld world;
  PhysicsSettings s;
  s.contact_max_correcting_vel = -1;
  try {
    world.setSettings(s);
    FAIL() << "accepted";
  } catch (const DescriptionError& e) {
    EXPECT_NE(std::string(e.what()).find("contact_max_correcting_vel: expected a velocity >= 0"), std::string::npos)
        << e.what();
  }
  s = PhysicsSettings();
  s.contact_surface_layer = std::nan("");
  EXPECT_THROW(world.setSettings(s), DescriptionError);
  EXPECT_DOUBLE_EQ(world.settings().contact_max_correcting_vel, 100);  // unchanged
}

// The Capstone lecture's m_robot (test/data/m_robot.urdf, xacro-expanded) spawned without -z: its
// base at 0, so its wheels (r 0.05, 0.05 below the base) are 0.1 m and its base plate 0.01 m in the
// ground. In Gazebo it ends up on its wheels; Bullet's correction threw it metres into the air.
TEST(ContactCorrection, MRobotSpawnedIntoTheGroundRisesOntoItsWheels) {
  std::ifstream file(std::string(BULLET_SIM_TEST_DATA_DIR) + "/m_robot.urdf");
  std::stringstream urdf;
  urdf << file.rdbuf();
  PhysicsWorld world;
  world.addModel(groundPlane(), Eigen::Isometry3d::Identity());
  PhysicsModel& robot = world.addModel(parseUrdf(urdf.str(), "m_robot.urdf", ResourceResolver()), at(0, 0, 0));
  const double rest = 0.1;  // the base on its wheels
  double highest = 0, fastest = 0, arrived = -1;
  for (int i = 1; i <= 15000; ++i) {
    world.step();
    const double z = robot.pose().translation().z();
    highest = std::max(highest, z);
    fastest = std::max(fastest, robot.twist().linear.norm());
    if (arrived < 0 && z > rest - 1e-3) arrived = i * kStep;
  }
  const Eigen::Isometry3d pose = robot.pose();
  EXPECT_LT(highest, rest + 0.05);  // what the issue asks
  EXPECT_LT(highest, rest + 2e-3);  // what it does
  EXPECT_NEAR(arrived, 9.9, 0.1);
  EXPECT_NEAR(pose.translation().z(), rest, 5e-4);
  EXPECT_LT(pose.translation().head<2>().norm(), 1e-3);  // straight up
  EXPECT_GT(pose.linear()(2, 2), std::cos(0.01));        // level
  EXPECT_LT(robot.twist().linear.norm() + robot.twist().angular.norm(), 1e-3);
  EXPECT_LT(fastest, 1e-2);
}
