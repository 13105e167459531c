// The physics core against analytic mechanics: pendulum period, free fall, kinematic frames,
// limits, determinism. Runs without ROS.
#include <BulletCollision/NarrowPhaseCollision/btPersistentManifold.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <tuple>
#include <vector>

#include "bullet_sim_core/description_error.h"
#include "bullet_sim_core/physics_world.h"
#include "bullet_sim_core/urdf_parser.h"
#include "ground_plane.h"

using namespace bullet_sim;

namespace {

constexpr double kG = 9.8;

// A bob of mass m on a massless rod of length L (COM below the pivot), swinging about y.
// The inertial frame is rotated on purpose: principal axes must not change the dynamics.
std::string pendulumUrdf(double length, double mass, double inertia) {
  const std::string L = std::to_string(length), m = std::to_string(mass), I = std::to_string(inertia);
  return R"(<robot name="pendulum">
    <link name="world"/>
    <joint name="anchor" type="fixed"><parent link="world"/><child link="base"/><origin xyz="0 0 2"/></joint>
    <link name="base"><inertial><mass value="1"/><inertia ixx="1" ixy="0" ixz="0" iyy="1" iyz="0" izz="1"/></inertial></link>
    <joint name="hinge" type="continuous"><parent link="base"/><child link="rod"/><axis xyz="0 1 0"/></joint>
    <link name="rod"><inertial><origin xyz="0 0 -)" + L + R"(" rpy="0.3 0.2 0.1"/><mass value=")" + m +
         R"("/><inertia ixx=")" + I + R"(" ixy="0" ixz="0" iyy=")" + I + R"(" iyz="0" izz=")" + I +
         R"("/></inertial></link>
  </robot>)";
}

const char* kBox = R"(<robot name="box"><link name="body">
  <inertial><mass value="1"/><inertia ixx="0.01" ixy="0" ixz="0" iyy="0.01" iyz="0" izz="0.01"/></inertial>
  <collision><geometry><box size="0.2 0.2 0.2"/></geometry></collision></link></robot>)";

// Two revolute joints with rotated origins, a fixed tool, and off-centre inertials.
const char* kTwoLink = R"(<robot name="two">
  <link name="world"/>
  <joint name="j0" type="fixed"><parent link="world"/><child link="base"/><origin xyz="0.1 0.2 0.3" rpy="0 0 0.4"/></joint>
  <link name="base"><inertial><origin xyz="0.05 0 0"/><mass value="3"/><inertia ixx="0.1" ixy="0" ixz="0" iyy="0.1" iyz="0" izz="0.1"/></inertial></link>
  <joint name="j1" type="revolute"><parent link="base"/><child link="l1"/><origin xyz="0 0 0.2" rpy="0.3 0 0"/>
    <axis xyz="0 0 1"/><limit lower="-3" upper="3" effort="100" velocity="10"/></joint>
  <link name="l1"><inertial><origin xyz="0.2 0.01 0" rpy="0.5 0.1 0"/><mass value="1"/><inertia ixx="0.01" ixy="0.001" ixz="0" iyy="0.02" iyz="0" izz="0.03"/></inertial></link>
  <joint name="j2" type="prismatic"><parent link="l1"/><child link="l2"/><origin xyz="0.4 0 0" rpy="0 0.2 0"/>
    <axis xyz="1 0 0"/><limit lower="-0.5" upper="0.5" effort="100" velocity="1"/></joint>
  <link name="l2"><inertial><origin xyz="0 0 0.1"/><mass value="0.5"/><inertia ixx="0.01" ixy="0" ixz="0" iyy="0.01" iyz="0" izz="0.01"/></inertial></link>
  <joint name="tool_joint" type="fixed"><parent link="l2"/><child link="tool"/><origin xyz="0 0.1 0" rpy="0 0 1.0"/></joint>
  <link name="tool"><inertial><mass value="0.1"/><inertia ixx="0.001" ixy="0" ixz="0" iyy="0.001" iyz="0" izz="0.001"/></inertial></link>
</robot>)";

Eigen::Isometry3d xyzRpy(double x, double y, double z, double r, double p, double yaw) {
  Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
  t.translation() = Eigen::Vector3d(x, y, z);
  t.linear() = (Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()) * Eigen::AngleAxisd(p, Eigen::Vector3d::UnitY()) *
                Eigen::AngleAxisd(r, Eigen::Vector3d::UnitX()))
                   .toRotationMatrix();
  return t;
}

ModelDescription parse(const std::string& xml) { return parseUrdf(xml, "test.urdf", ResourceResolver()); }

PhysicsSettings noGround() {
  PhysicsSettings s;
  s.gravity = Eigen::Vector3d(0, 0, -kG);
  return s;
}

// Period from the times the joint velocity changes sign (every half period).
double measurePeriod(PhysicsWorld& world, PhysicsModel& model, int joint, double seconds) {
  std::vector<double> crossings;
  double previous = model.jointVelocity(joint);
  const int steps = static_cast<int>(seconds / world.settings().max_step_size);
  for (int i = 0; i < steps; ++i) {
    world.step();
    const double v = model.jointVelocity(joint);
    if ((previous < 0) != (v < 0) && previous != 0) {
      // Linear interpolation of the crossing inside the step.
      crossings.push_back(world.time() - world.settings().max_step_size * v / (v - previous));
    }
    previous = v;
  }
  EXPECT_GE(crossings.size(), 4u);
  return 2.0 * (crossings.back() - crossings.front()) / (crossings.size() - 1);
}

}  // namespace

class PendulumPeriod : public ::testing::TestWithParam<std::tuple<double, double, double>> {};

TEST_P(PendulumPeriod, MatchesSmallAngleTheory) {
  const auto [L, m, I] = GetParam();
  PhysicsWorld world(noGround());
  PhysicsModel& model = world.addModel(parse(pendulumUrdf(L, m, I)), Eigen::Isometry3d::Identity());
  ASSERT_EQ(model.joints().size(), 1u);
  model.setJointState(0, 0.05, 0.0);
  const double expected = 2 * M_PI * std::sqrt((I + m * L * L) / (m * kG * L));
  const double period = measurePeriod(world, model, 0, 10.0);
  RecordProperty("period", std::to_string(period));
  EXPECT_NEAR(period, expected, 0.001 * expected) << "expected " << expected;
}

INSTANTIATE_TEST_SUITE_P(PhysicsWorld, PendulumPeriod,
                         ::testing::Values(std::make_tuple(0.8, 1.5, 2e-3), std::make_tuple(0.25, 1.0, 1e-4),
                                           std::make_tuple(0.05, 0.1, 1e-6)));

TEST(PhysicsWorld, DampingDecaysTheSwing) {
  std::string xml = pendulumUrdf(0.5, 1.0, 1e-3);
  xml.replace(xml.find("<axis xyz=\"0 1 0\"/>"), 19, "<axis xyz=\"0 1 0\"/><dynamics damping=\"0.5\"/>");
  PhysicsWorld world(noGround());
  PhysicsModel& model = world.addModel(parse(xml), Eigen::Isometry3d::Identity());
  model.setJointState(0, 0.3, 0.0);
  for (int i = 0; i < 5000; ++i) world.step();
  EXPECT_LT(std::abs(model.jointPosition(0)), 0.05);
}

TEST(PhysicsWorld, FreeFallDropMatchesHalfGTSquared) {
  PhysicsWorld world(noGround());
  PhysicsModel& box = world.addModel(parse(kBox), xyzRpy(0, 0, 10, 0, 0, 0));
  for (int i = 0; i < 1000; ++i) world.step();
  EXPECT_NEAR(world.time(), 1.0, 1e-9);
  const double drop = 10.0 - box.pose().translation().z();
  EXPECT_NEAR(drop, 0.5 * kG, 0.002 * 0.5 * kG);
  EXPECT_NEAR(box.twist().linear.z(), -kG, 0.002 * kG);
}

// <turnGravityOff> (Gazebo's URDF extension) and <gravity>false</gravity>: the link floats while
// the world's gravity still acts on everything else.
TEST(PhysicsWorld, ALinkWithGravityTurnedOffDoesNotFall) {
  std::string weightless = kBox;
  weightless.replace(weightless.find("</robot>"), 8, R"(<gazebo reference="body"><turnGravityOff>true</turnGravityOff></gazebo></robot>)");
  weightless.replace(weightless.find("name=\"box\""), 10, "name=\"floating\"");
  PhysicsWorld world(noGround());
  PhysicsModel& falling = world.addModel(parse(kBox), xyzRpy(0, 0, 10, 0, 0, 0));
  PhysicsModel& floating = world.addModel(parse(weightless), xyzRpy(2, 0, 10, 0.3, 0.2, 0.1));
  for (int i = 0; i < 1000; ++i) world.step();
  EXPECT_NEAR(10.0 - falling.pose().translation().z(), 0.5 * kG, 0.002 * 0.5 * kG);
  EXPECT_NEAR(floating.pose().translation().z(), 10.0, 1e-6);
  EXPECT_LT(floating.twist().angular.norm(), 1e-6);  // held at its centre of mass: no spin either
}

// A pendulum whose rod has no gravity stays where it is put; with gravity it swings down. The
// rod's mass sits 0.5 m off the hinge, so a force in the wrong place would turn it.
TEST(PhysicsWorld, APendulumWithAWeightlessRodStaysPut) {
  const std::string swinging = pendulumUrdf(0.5, 1.0, 1e-3);
  std::string weightless = swinging;
  weightless.replace(weightless.find("</robot>"), 8, R"(<gazebo reference="rod"><gravity>false</gravity></gazebo></robot>)");
  for (const bool gravity_on : {true, false}) {
    PhysicsWorld world(noGround());
    PhysicsModel& model = world.addModel(parse(gravity_on ? swinging : weightless), Eigen::Isometry3d::Identity());
    model.setJointState(0, 1.0, 0.0);
    for (int i = 0; i < 300; ++i) world.step();
    if (gravity_on)
      EXPECT_LT(model.jointPosition(0), 0.8);  // falling back towards 0 under g
    else
      EXPECT_NEAR(model.jointPosition(0), 1.0, 1e-6);
  }
}

// In a body merged from links by fixed joints, only the links with gravity off are held up: a
// 1 kg weightless link beside a 1 kg heavy one makes the pair fall as if it weighed 1 kg and had 2.
TEST(PhysicsWorld, GravityOffActsPerLinkInAMergedBody) {
  const char* pair = R"(<robot name="pair">
    <link name="heavy"><inertial><mass value="1"/><inertia ixx="0.01" ixy="0" ixz="0" iyy="0.01" iyz="0" izz="0.01"/></inertial></link>
    <joint name="glue" type="fixed"><parent link="heavy"/><child link="light"/><origin xyz="0 0 0.5"/></joint>
    <link name="light"><inertial><mass value="1"/><inertia ixx="0.01" ixy="0" ixz="0" iyy="0.01" iyz="0" izz="0.01"/></inertial></link>
    <gazebo reference="light"><turnGravityOff>true</turnGravityOff></gazebo></robot>)";
  PhysicsWorld world(noGround());
  PhysicsModel& model = world.addModel(parse(pair), xyzRpy(0, 0, 10, 0, 0, 0));
  for (int i = 0; i < 1000; ++i) world.step();
  EXPECT_NEAR(10.0 - model.pose().translation().z(), 0.25 * kG, 0.005 * 0.25 * kG);
  EXPECT_LT(model.twist().angular.norm(), 1e-6);  // the lift acts on the line of the fall: no spin
}

TEST(PhysicsWorld, LinkFramesFollowTheJointChain) {
  PhysicsWorld world(noGround());
  const Eigen::Isometry3d spawn = xyzRpy(1, -2, 0.5, 0, 0, 0.7);
  PhysicsModel& model = world.addModel(parse(kTwoLink), spawn);
  ASSERT_EQ(model.joints().size(), 2u);
  const double q1 = 0.6, q2 = 0.25;
  model.setJointState(model.jointIndex("j1"), q1, 0);
  model.setJointState(model.jointIndex("j2"), q2, 0);
  const Eigen::Isometry3d base = spawn * xyzRpy(0.1, 0.2, 0.3, 0, 0, 0.4);
  const Eigen::Isometry3d l1 = base * xyzRpy(0, 0, 0.2, 0.3, 0, 0) * Eigen::AngleAxisd(q1, Eigen::Vector3d::UnitZ());
  Eigen::Isometry3d l2 = l1 * xyzRpy(0.4, 0, 0, 0, 0.2, 0);
  l2.translation() += l2.linear() * Eigen::Vector3d(q2, 0, 0);
  const Eigen::Isometry3d tool = l2 * xyzRpy(0, 0.1, 0, 0, 0, 1.0);
  EXPECT_TRUE(model.linkPose("base").isApprox(base, 1e-9));
  EXPECT_TRUE(model.linkPose("l1").isApprox(l1, 1e-9)) << model.linkPose("l1").matrix() << "\n" << l1.matrix();
  EXPECT_TRUE(model.linkPose("l2").isApprox(l2, 1e-9));
  EXPECT_TRUE(model.linkPose("tool").isApprox(tool, 1e-9));
  EXPECT_TRUE(model.pose().isApprox(spawn, 1e-9));  // a fixed robot's model frame is its spawn pose
  const auto names = model.linkNames();
  EXPECT_EQ(std::count(names.begin(), names.end(), "world"), 0);
}

TEST(PhysicsWorld, LinkTwistMatchesFiniteDifference) {
  PhysicsWorld world(noGround());
  PhysicsModel& model = world.addModel(parse(kTwoLink), Eigen::Isometry3d::Identity());
  model.setJointState(0, 0.0, 1.5);
  model.setJointState(1, 0.0, 0.3);
  const Eigen::Isometry3d before = model.linkPose("tool");
  const Twist twist = model.linkTwist("tool");
  world.step();
  const Eigen::Vector3d velocity = (model.linkPose("tool").translation() - before.translation()) / 0.001;
  EXPECT_NEAR((velocity - twist.linear).norm(), 0.0, 0.02 * twist.linear.norm());
}

TEST(PhysicsWorld, JointLimitStopsTheJoint) {
  PhysicsWorld world(noGround());
  PhysicsModel& model = world.addModel(parse(kTwoLink), Eigen::Isometry3d::Identity());
  const int j2 = model.jointIndex("j2");
  for (int i = 0; i < 2000; ++i) {
    model.addJointEffort(j2, 50.0);
    world.step();
  }
  EXPECT_NEAR(model.jointPosition(j2), 0.5, 0.01);
  EXPECT_NEAR(model.jointEffort(j2), 50.0, 1e-12);
}

// A limit joins the solver only when its joint comes near it (PhysicsModel::updateLimits). Thrown
// at its limit from the far end at 8 m/s, a joint must stop as it does with the limit always in
// the solver: Bullet's limit acts once the joint has crossed it, so at most one step's travel past
// it (8 mm at 8 m/s; 6.9 mm here, the same with the limit always in).
TEST(PhysicsWorld, AJointThrownAtItsLimitStopsThere) {
  PhysicsWorld world(noGround());
  PhysicsModel& model = world.addModel(parse(kTwoLink), Eigen::Isometry3d::Identity());
  const int j2 = model.jointIndex("j2");
  model.setJointState(j2, -0.45, 8.0);  // 0.95 m from the upper limit: about 120 steps away
  double highest = -1.0, fastest = 0.0;
  for (int i = 0; i < 500; ++i) {
    world.step();
    highest = std::max(highest, model.jointPosition(j2));
    fastest = std::max(fastest, model.jointVelocity(j2));
  }
  EXPECT_GT(fastest, 7.0);  // it really came at speed
  EXPECT_GT(highest, 0.5);  // reached the limit
  EXPECT_LT(highest, 0.5 + 0.008) << "went through the limit";
  EXPECT_LT(model.jointPosition(j2), 0.5 + 0.001);  // and was pushed back
}

TEST(PhysicsWorld, SameCommandsGiveTheSameTrajectory) {
  auto run = [] {
    PhysicsWorld world(noGround());
    PhysicsModel& model = world.addModel(parse(kTwoLink), Eigen::Isometry3d::Identity());
    for (int i = 0; i < 3000; ++i) {
      model.addJointEffort(0, std::sin(i * 0.01));
      world.step();
    }
    return std::make_pair(model.jointPosition(0), Eigen::Vector3d(model.linkPose("tool").translation()));
  };
  const auto a = run(), b = run();
  EXPECT_EQ(a.first, b.first);
  EXPECT_EQ(a.second, b.second);
}

TEST(PhysicsWorld, BoxRestsOnTheGround) {
  PhysicsWorld world(noGround());
  ModelDescription ground;
  ground.name = "ground_plane";
  ground.is_static = true;
  ground.links.emplace_back();
  ground.links[0].name = "link";
  ground.links[0].collisions.emplace_back();
  ground.links[0].collisions[0].geometry.type = GeometryType::Plane;
  world.addModel(ground, Eigen::Isometry3d::Identity());
  PhysicsModel& box = world.addModel(parse(kBox), xyzRpy(0, 0, 0.5, 0, 0, 0));
  for (int i = 0; i < 2000; ++i) world.step();
  EXPECT_NEAR(box.pose().translation().z(), 0.1, 0.003);
  EXPECT_LT(box.twist().linear.norm(), 0.01);
}

TEST(PhysicsWorld, DuplicateNameAndBadPoseAreRejected) {
  PhysicsWorld world(noGround());
  world.addModel(parse(kBox), Eigen::Isometry3d::Identity());
  try {
    world.addModel(parse(kBox), Eigen::Isometry3d::Identity());
    FAIL() << "duplicate accepted";
  } catch (const DescriptionError& e) {
    EXPECT_NE(std::string(e.what()).find("a model named 'box' already exists"), std::string::npos);
  }
  ModelDescription other = parse(kBox);
  other.name = "other";
  Eigen::Isometry3d bad = Eigen::Isometry3d::Identity();
  bad.translation().x() = std::nan("");
  EXPECT_THROW(world.addModel(other, bad), DescriptionError);
  EXPECT_EQ(world.modelNames().size(), 1u);
}

TEST(PhysicsWorld, RemoveAndResetModels) {
  PhysicsWorld world(noGround());
  PhysicsModel& box = world.addModel(parse(kBox), xyzRpy(0, 0, 3, 0, 0, 0));
  for (int i = 0; i < 500; ++i) world.step();
  EXPECT_LT(box.pose().translation().z(), 2.0);
  world.resetModels();
  EXPECT_NEAR(box.pose().translation().z(), 3.0, 1e-12);
  EXPECT_NEAR(box.twist().linear.norm(), 0.0, 1e-12);
  EXPECT_TRUE(world.removeModel("box"));
  EXPECT_FALSE(world.removeModel("box"));
  EXPECT_EQ(world.findModel("box"), nullptr);
}

namespace {

std::string meshBoxUrdf(const std::string& name, double scale) {
  const std::string s = std::to_string(scale);
  return R"(<robot name=")" + name + R"("><link name="body">
    <inertial><mass value="1"/><inertia ixx="0.01" ixy="0" ixz="0" iyy="0.01" iyz="0" izz="0.01"/></inertial>
    <collision><geometry><mesh filename=")" BULLET_SIM_TEST_DATA_DIR R"(/meshes/cube.stl" scale=")" + s + " " + s +
         " " + s + R"("/></geometry></collision></link></robot>)";
}

}  // namespace

// The floor's bounding box ends at its surface: a body high above it is not even paired with it
// (Bullet's own plane pairs with everything, every step), and one that falls onto it lands.
TEST(PhysicsWorld, TheFloorPairsOnlyWithBodiesThatReachIt) {
  PhysicsWorld world(noGround());
  world.addModel(groundPlane(), Eigen::Isometry3d::Identity());
  const Eigen::Isometry3d tilted = xyzRpy(0, 50, -5, 0.3, 0, 0);  // far below, and with no axis to bound
  world.addModel([] { ModelDescription m = groundPlane(); m.name = "ramp"; return m; }(), tilted);
  PhysicsModel& box = world.addModel(parse(kBox), xyzRpy(0, 0, 0.5, 0, 0, 0));
  world.step();
  // The box (0.2 m, 0.4 m above the floor) overlaps the tilted plane's unbounded box only.
  EXPECT_EQ(world.bulletWorld().getPairCache()->getNumOverlappingPairs(), 1);
  for (int i = 0; i < 2000; ++i) world.step();
  EXPECT_EQ(world.bulletWorld().getPairCache()->getNumOverlappingPairs(), 2);
  EXPECT_NEAR(box.pose().translation().z(), 0.1, 0.003);
}

TEST(PhysicsWorld, MovingMeshIsAConvexHullThatRestsAtItsSize) {
  PhysicsWorld world(noGround());
  world.addModel(groundPlane(), Eigen::Isometry3d::Identity());
  PhysicsModel& cube = world.addModel(parse(meshBoxUrdf("cube", 0.3)), xyzRpy(0, 0, 1, 0, 0, 0));
  for (int i = 0; i < 2000; ++i) world.step();
  EXPECT_NEAR(cube.pose().translation().z(), 0.15, 0.004);  // hull margin is 1 mm
}

TEST(PhysicsWorld, StaticMeshIsATriangleMeshThatHoldsABox) {
  PhysicsWorld world(noGround());
  ModelDescription slab = parse(meshBoxUrdf("slab", 2.0));
  slab.is_static = true;
  world.addModel(slab, Eigen::Isometry3d::Identity());  // top face at z = 1
  PhysicsModel& box = world.addModel(parse(kBox), xyzRpy(0.2, 0.1, 1.5, 0, 0, 0));
  for (int i = 0; i < 2000; ++i) world.step();
  EXPECT_NEAR(box.pose().translation().z(), 1.1, 0.004);
}

TEST(PhysicsWorld, ContactFrictionComesFromMu) {
  // A 1 kg box pushed sideways with 3 N: it holds with mu 1 and slides with mu 0.1. The ground
  // has mu 100 like Gazebo's ground_plane: contacts take the smaller coefficient, as in ODE.
  auto slide = [](double mu) {
    PhysicsWorld world(noGround());
    ModelDescription ground = groundPlane();
    ground.links[0].mu1 = 100;
    ground.links[0].mu2 = 100;
    world.addModel(ground, Eigen::Isometry3d::Identity());
    ModelDescription box = parse(kBox);
    box.links[0].mu1 = box.links[0].mu2 = mu;
    PhysicsModel& model = world.addModel(box, xyzRpy(0, 0, 0.1, 0, 0, 0));
    for (int i = 0; i < 300; ++i) world.step();  // settle
    const double x0 = model.pose().translation().x();
    for (int i = 0; i < 1000; ++i) {
      model.addLinkWrench("body", Eigen::Vector3d(3, 0, 0), Eigen::Vector3d::Zero(), model.pose().translation());
      world.step();
    }
    return model.pose().translation().x() - x0;
  };
  EXPECT_LT(slide(1.0), 0.005);
  // (3 - 0.1 * 9.8) / 1 kg = 2.02 m/s^2 for 1 s: about 1 m.
  EXPECT_NEAR(slide(0.1), 0.5 * 2.02, 0.1);
}

// Wheeled vehicles on the ground plane: how cylinders touch it and how contact friction acts.
namespace {

// A wheel: a full-width cylinder r x width about the link's y axis (rolled from z, as URDFs
// do), on a continuous joint about +y at (x, y, z) of base_link.
std::string wheelUrdf(const std::string& name, double x, double y, double z, double r, double width, double mass) {
  const std::string R = std::to_string(r), W = std::to_string(width), m = std::to_string(mass);
  const std::string across = std::to_string(mass * (3 * r * r + width * width) / 12), axle = std::to_string(mass * r * r / 2);
  return R"(<link name=")" + name + R"("><inertial><origin rpy="-1.5707963267948966 0 0"/><mass value=")" + m +
         R"("/><inertia ixx=")" + across + R"(" ixy="0" ixz="0" iyy=")" + across + R"(" iyz="0" izz=")" + axle +
         R"("/></inertial><collision><origin rpy="-1.5707963267948966 0 0"/><geometry><cylinder radius=")" + R +
         R"(" length=")" + W + R"("/></geometry></collision></link>
    <joint name=")" + name + R"(_joint" type="continuous"><parent link="base_link"/><child link=")" + name +
         R"("/><origin xyz=")" + std::to_string(x) + " " + std::to_string(y) + " " + std::to_string(z) +
         R"("/><axis xyz="0 1 0"/></joint>)";
}

// src/bullet_sim/bench/skid4.urdf: 12 kg body, four 0.5 kg wheels r 0.1 x 0.06 wide at
// x +-0.2, y +-0.25 (separation 0.5), base_link on the ground.
std::string skid4Urdf() {
  std::string xml = R"(<robot name="skid4"><link name="base_link">
    <inertial><origin xyz="0 0 0.15"/><mass value="12"/><inertia ixx="0.1825" ixy="0" ixz="0" iyy="0.3825" iyz="0" izz="0.52"/></inertial>
    <collision><origin xyz="0 0 0.15"/><geometry><box size="0.6 0.4 0.15"/></geometry></collision></link>)";
  for (const auto& [name, x, y] : {std::make_tuple("front_left", 0.2, 0.25), std::make_tuple("front_right", 0.2, -0.25),
                                   std::make_tuple("back_left", -0.2, 0.25), std::make_tuple("back_right", -0.2, -0.25)})
    xml += wheelUrdf(name, x, y, 0.1, 0.1, 0.06, 0.5);
  return xml + "</robot>";
}

// Two drive wheels r 0.1 x 0.04 wide, 0.4 m apart, on full-width cylinders, and a frictionless
// caster ball in front: test/urdf/diffbot.urdf's numbers.
std::string diffbotUrdf() {
  std::string xml = R"(<robot name="diffbot"><link name="base_link">
    <inertial><origin xyz="0 0 0.1"/><mass value="4"/><inertia ixx="0.05" ixy="0" ixz="0" iyy="0.08" iyz="0" izz="0.1"/></inertial>
    <collision><origin xyz="0 0 0.12"/><geometry><box size="0.4 0.3 0.08"/></geometry></collision></link>
    <joint name="caster_joint" type="fixed"><parent link="base_link"/><child link="caster"/><origin xyz="0.16 0 0.04"/></joint>
    <link name="caster"><inertial><mass value="0.1"/><inertia ixx="1e-4" ixy="0" ixz="0" iyy="1e-4" iyz="0" izz="1e-4"/></inertial>
    <collision><geometry><sphere radius="0.04"/></geometry></collision></link>
    <gazebo reference="caster"><mu1>0</mu1><mu2>0</mu2></gazebo>)";
  xml += wheelUrdf("left", -0.05, 0.2, 0.1, 0.1, 0.04, 0.5);
  xml += wheelUrdf("right", -0.05, -0.2, 0.1, 0.1, 0.04, 0.5);
  return xml + "</robot>";
}

struct DriveResult {
  double yaw_rate = 0, forward = 0, lateral = 0;  // means over the measured window
  double z_spread = 0;                            // max - min of the base height in it
  double sweeps_per_solve = 0;                    // the constraint solver's, while driving
};

// Spawns `urdf` on the ground plane heading `yaw`, commands the wheels the plugins' way,
// (v -+ w separation / 2) / r with the given torque, and averages from 1 s to `seconds`.
DriveResult drive(const std::string& urdf, double yaw, const std::vector<std::string>& left,
                  const std::vector<std::string>& right, double separation, double radius, double torque, double v,
                  double w, double seconds = 2.5, bool warm_start = true) {
  PhysicsWorld world;
  world.solver().setWarmStart(warm_start);
  world.addModel(groundPlane(), Eigen::Isometry3d::Identity());
  PhysicsModel& model = world.addModel(parse(urdf), xyzRpy(0, 0, 0, 0, 0, yaw));
  for (int i = 0; i < 300; ++i) world.step();  // land
  for (const auto& j : left) model.setJointMotor(model.jointIndex(j + "_joint"), 0, (v - w * separation / 2) / radius, 0, torque);
  for (const auto& j : right) model.setJointMotor(model.jointIndex(j + "_joint"), 0, (v + w * separation / 2) / radius, 0, torque);
  world.solver().resetCounters();
  DriveResult r;
  double z_min = 1e9, z_max = -1e9;
  int n = 0;
  for (int i = 1; i <= static_cast<int>(seconds * 1000); ++i) {
    world.step();
    if (i < 1000) continue;
    const Eigen::Isometry3d pose = model.pose();
    const Twist t = model.twist();
    const Eigen::Vector3d heading = pose.linear().col(0);
    r.yaw_rate += t.angular.z();
    r.forward += t.linear.dot(heading);
    r.lateral += t.linear.dot(Eigen::Vector3d::UnitZ().cross(heading));
    z_min = std::min(z_min, pose.translation().z());
    z_max = std::max(z_max, pose.translation().z());
    ++n;
  }
  r.yaw_rate /= n;
  r.forward /= n;
  r.lateral /= n;
  r.z_spread = z_max - z_min;
  r.sweeps_per_solve = static_cast<double>(world.solver().sweeps()) / std::max(1L, world.solver().solves());
  return r;
}

const std::vector<std::string> kSkidLeft{"front_left", "back_left"}, kSkidRight{"front_right", "back_right"};

}  // namespace

TEST(PhysicsWorld, SkidSteerTurnsOnTheSpotAtTheSameRateWhateverItsHeading) {
  // Commanded 0.5 rad/s, skid4 turns at 0.296 rad/s in PyBullet (URDF_USE_IMPLICIT_CYLINDER,
  // heading 45 degrees; scripts/bench_skid_steer.py) and 0.305 rad/s with Coulomb friction,
  // 0.5 / (1 + (0.2 / 0.25)^2). Before the friction rows followed the slip it turned at
  // about 0.04 rad/s when spawned heading 0 and at 0.29 rad/s near 45 degrees.
  for (const double yaw_deg : {0.0, 30.0, 90.0}) {
    const DriveResult r = drive(skid4Urdf(), yaw_deg * M_PI / 180, kSkidLeft, kSkidRight, 0.5, 0.1, 10, 0.0, 0.5);
    EXPECT_GT(r.yaw_rate, 0.9 * 0.296) << "heading " << yaw_deg;
    EXPECT_LT(r.yaw_rate, 1.1 * 0.296) << "heading " << yaw_deg;
    // It turns about its centre (before: drifting 0.04 m/s off it), and its body stays level.
    EXPECT_LT(std::abs(r.forward), 0.005) << "heading " << yaw_deg;
    EXPECT_LT(std::abs(r.lateral), 0.005) << "heading " << yaw_deg;
    EXPECT_LT(r.z_spread, 1e-4) << "heading " << yaw_deg;
  }
}

TEST(PhysicsWorld, SkidSteerDrivesStraightAndArcs) {
  // PyBullet: straight 0.300 m/s; the 0.3 m/s, 0.3 rad/s arc 0.180 rad/s at 0.298 m/s.
  const DriveResult straight = drive(skid4Urdf(), 0, kSkidLeft, kSkidRight, 0.5, 0.1, 10, 0.3, 0.0);
  EXPECT_NEAR(straight.forward, 0.3, 0.003);
  EXPECT_NEAR(straight.yaw_rate, 0.0, 0.003);
  const DriveResult arc = drive(skid4Urdf(), 0, kSkidLeft, kSkidRight, 0.5, 0.1, 10, 0.3, 0.3);
  EXPECT_NEAR(arc.yaw_rate, 0.180, 0.1 * 0.180);
  EXPECT_NEAR(arc.forward, 0.298, 0.1 * 0.298);
}

TEST(PhysicsWorld, DiffDriveRollsStraightAndTurnsAtTheCommandedRate) {
  // Rolling without slip: the kinematic rates, whatever the heading.
  const std::vector<std::string> left{"left"}, right{"right"};
  for (const double yaw : {0.0, 0.6}) {
    const DriveResult straight = drive(diffbotUrdf(), yaw, left, right, 0.4, 0.1, 10, 0.3, 0.0);
    EXPECT_NEAR(straight.forward, 0.3, 0.003);
    EXPECT_NEAR(straight.yaw_rate, 0.0, 0.003);
    EXPECT_NEAR(straight.lateral, 0.0, 0.003);
    const DriveResult turn = drive(diffbotUrdf(), yaw, left, right, 0.4, 0.1, 10, 0.0, 0.5);
    EXPECT_NEAR(turn.yaw_rate, 0.5, 0.005);
    EXPECT_NEAR(turn.forward, 0.0, 0.003);
    const DriveResult arc = drive(diffbotUrdf(), yaw, left, right, 0.4, 0.1, 10, 0.3, 0.5);
    EXPECT_NEAR(arc.yaw_rate, 0.5, 0.005);
    EXPECT_NEAR(arc.forward, 0.3, 0.003);
    EXPECT_LT(arc.z_spread, 1e-4);
  }
}

TEST(PhysicsWorld, WheelsHeldStillHoldTheVehicleStill) {
  // Nothing pushes a level vehicle sideways, so its wheel motors only have to hold. With
  // Bullet's default 10 solver sweeps a step from zero impulses they fell short: skid4 crept at
  // 0.16 mm/s, the diffbot turned at 5e-5 rad/s, a Pioneer crept at 0.2 mm/s; at SDF's 50 sweeps
  // both stayed within 5 um/s and 2e-7 rad/s. Warm started, they hold to 1e-15 m/s.
  const DriveResult diffbot = drive(diffbotUrdf(), 0.3, {"left"}, {"right"}, 0.4, 0.1, 10, 0, 0, 4);
  const DriveResult skid4 = drive(skid4Urdf(), 0.3, kSkidLeft, kSkidRight, 0.5, 0.1, 10, 0, 0, 4);
  for (const DriveResult& r : {diffbot, skid4}) {
    EXPECT_LT(std::abs(r.forward), 1e-9);
    EXPECT_LT(std::abs(r.lateral), 1e-9);
    EXPECT_LT(std::abs(r.yaw_rate), 1e-9);
  }
}

// The solver's warm start and early stop (contact_solver.h): a vehicle on its wheels drives as
// with every sweep from zero impulses, in a fraction of the sweeps.
TEST(ContactSolver, WarmStartedDrivingMatchesEverySweepFromZeroInAFewSweeps) {
  struct Case {
    double v, w;
    double max_sweeps;  // per solve, mean: measured 1.2 straight, 6.0 on the spot, 6.3 on the arc
  };
  for (const Case& c : {Case{0.3, 0.0, 3.0}, Case{0.0, 0.5, 10.0}, Case{0.3, 0.3, 10.0}}) {
    SCOPED_TRACE("v " + std::to_string(c.v) + ", w " + std::to_string(c.w));
    const DriveResult warm = drive(skid4Urdf(), 0.5, kSkidLeft, kSkidRight, 0.5, 0.1, 10, c.v, c.w, 2.5, true);
    const DriveResult cold = drive(skid4Urdf(), 0.5, kSkidLeft, kSkidRight, 0.5, 0.1, 10, c.v, c.w, 2.5, false);
    EXPECT_NEAR(warm.yaw_rate, cold.yaw_rate, 1e-3 * std::max(0.1, std::abs(cold.yaw_rate)));
    EXPECT_NEAR(warm.forward, cold.forward, 3e-3 * std::max(0.1, std::abs(cold.forward)));
    EXPECT_NEAR(warm.lateral, cold.lateral, 1e-3);
    EXPECT_LT(warm.z_spread, 1e-4);
    EXPECT_GE(warm.sweeps_per_solve, 1.0);
    EXPECT_LT(warm.sweeps_per_solve, c.max_sweeps);
    EXPECT_GT(cold.sweeps_per_solve, 12.0);  // from zero, many more
  }
}

TEST(ContactSolver, SeveralPointsInOneManifoldStartFromZeroAndTakeEverySweep) {
  // A box resting on its face: four corners in one manifold, whose split of the weight is not
  // unique, so they start cold (contact_solver.cpp) and the early stop is off for the solve.
  PhysicsWorld world;
  world.addModel(groundPlane(), Eigen::Isometry3d::Identity());
  const char* kBox = R"(<robot name="crate"><link name="body">
    <inertial><mass value="2"/><inertia ixx="0.02" ixy="0" ixz="0" iyy="0.02" iyz="0" izz="0.02"/></inertial>
    <collision><geometry><box size="0.2 0.2 0.2"/></geometry></collision></link></robot>)";
  PhysicsModel& box = world.addModel(parse(kBox), xyzRpy(0, 0, 0.1005, 0, 0, 0.3));
  for (int i = 0; i < 1000; ++i) world.step();
  world.solver().resetCounters();
  for (int i = 0; i < 500; ++i) world.step();
  EXPECT_EQ(world.solver().sweeps(), 50 * world.solver().solves());
  EXPECT_GT(world.solver().solves(), 400);
  EXPECT_NEAR(box.pose().translation().z(), 0.1, 2e-3);
  EXPECT_LT(box.twist().linear.norm(), 1e-3);
}

TEST(PhysicsWorld, LyingCylinderTouchesThePlaneAlongItsMidPlane) {
  // A full-width wheel r 0.3 x 0.25 lying on the plane: Bullet's convex-plane contact put its
  // one point on a rim edge, 0.125 m off the mid-plane.
  for (const double roll : {M_PI / 2, -M_PI / 2, M_PI / 2 + 1e-9}) {
    PhysicsWorld world;
    world.addModel(groundPlane(), Eigen::Isometry3d::Identity());
    const char* kWheel = R"(<robot name="wheel"><link name="wheel">
      <inertial><mass value="1"/><inertia ixx="0.03" ixy="0" ixz="0" iyy="0.03" iyz="0" izz="0.045"/></inertial>
      <collision><geometry><cylinder radius="0.3" length="0.25"/></geometry></collision></link></robot>)";
    PhysicsModel& wheel = world.addModel(parse(kWheel), xyzRpy(0, 0, 0.3, roll, 0, 0));
    for (int i = 0; i < 500; ++i) world.step();
    EXPECT_NEAR(wheel.pose().translation().z(), 0.3, 1e-3);
    const btCollisionObject* collider = wheel.linkCollider("wheel");
    btDispatcher* dispatcher = world.bulletWorld().getDispatcher();
    int touching = 0;
    for (int m = 0; m < dispatcher->getNumManifolds(); ++m) {
      const btPersistentManifold* manifold = dispatcher->getManifoldByIndexInternal(m);
      if (manifold->getBody0() != collider && manifold->getBody1() != collider) continue;
      for (int k = 0; k < manifold->getNumContacts(); ++k) {
        const btManifoldPoint& cp = manifold->getContactPoint(k);
        if (cp.getAppliedImpulse() <= 0) continue;
        const btVector3 p = manifold->getBody0() == collider ? cp.getPositionWorldOnA() : cp.getPositionWorldOnB();
        EXPECT_NEAR(p.y(), wheel.pose().translation().y(), 1e-3) << "roll " << roll;  // the axis is along y
        ++touching;
      }
    }
    EXPECT_GE(touching, 1);
  }
}

TEST(PhysicsWorld, StandingCylinderRestsOnItsEndCap) {
  PhysicsWorld world;
  world.addModel(groundPlane(), Eigen::Isometry3d::Identity());
  const char* kCan = R"(<robot name="can"><link name="can">
    <inertial><mass value="0.5"/><inertia ixx="0.001" ixy="0" ixz="0" iyy="0.001" iyz="0" izz="0.0005"/></inertial>
    <collision><geometry><cylinder radius="0.04" length="0.12"/></geometry></collision></link></robot>)";
  PhysicsModel& can = world.addModel(parse(kCan), xyzRpy(0.3, 0.2, 0.07, 0, 0, 0.4));
  for (int i = 0; i < 2000; ++i) world.step();
  EXPECT_NEAR(can.pose().translation().z(), 0.06, 1e-3);
  EXPECT_NEAR(can.pose().translation().x(), 0.3, 1e-3);
  EXPECT_NEAR(can.pose().translation().y(), 0.2, 1e-3);
  EXPECT_GT(can.pose().linear()(2, 2), std::cos(1e-3));  // upright
  EXPECT_LT(can.twist().linear.norm() + can.twist().angular.norm(), 1e-3);
}

// Cans stacked end cap on end cap (the Katana tutorial's tower): 15 g, r 0.033, 0.12 tall, mu 0.5.
std::string canUrdf(const std::string& name) {
  return R"(<robot name=")" + name + R"("><link name="can">
    <inertial><origin xyz="0 0 0.06"/><mass value="0.015"/><inertia ixx="2.2e-5" ixy="0" ixz="0" iyy="2.2e-5" iyz="0" izz="8.2e-6"/></inertial>
    <collision><origin xyz="0 0 0.06"/><geometry><cylinder radius="0.033" length="0.12"/></geometry></collision></link>
    <gazebo reference="can"><mu1>0.5</mu1><mu2>0.5</mu2></gazebo></robot>)";
}

// A stack of three cans, the upper two `offset` off the bottom one's axis, stands still: a
// real tower neither slides nor creeps (Bullet's convex-convex contact, one GJK point per step,
// let each can creep about 0.1 mm/s off the one below).
class CanTower : public ::testing::TestWithParam<double> {};

TEST_P(CanTower, StandsStillOnItsEndCaps) {
  const double offset = GetParam();
  PhysicsWorld world;
  world.addModel(groundPlane(), Eigen::Isometry3d::Identity());
  std::vector<PhysicsModel*> cans;
  for (int level = 0; level < 3; ++level)
    cans.push_back(&world.addModel(parse(canUrdf("can_" + std::to_string(level))),
                                   xyzRpy(0.3 + (level ? offset : 0.0), 0.1, 0.12 * level + 0.0005 * level, 0, 0,
                                          0.3 * level)));
  for (int i = 0; i < 2000; ++i) world.step();  // settle
  std::vector<Eigen::Vector3d> settled;
  for (PhysicsModel* can : cans) settled.push_back(can->pose().translation());
  for (int i = 0; i < 30000; ++i) world.step();  // 30 s
  for (int level = 0; level < 3; ++level) {
    const Eigen::Isometry3d pose = cans[level]->pose();
    SCOPED_TRACE("level " + std::to_string(level));
    EXPECT_NEAR(settled[level].z(), 0.12 * level, 1e-3);
    EXPECT_NEAR(settled[level].x(), 0.3 + (level ? offset : 0.0), 1e-3);
    EXPECT_LT((pose.translation() - settled[level]).norm(), 2e-4);  // over 30 s
    EXPECT_GT(pose.linear()(2, 2), std::cos(0.01));  // upright
  }
}

INSTANTIATE_TEST_SUITE_P(Offsets, CanTower, ::testing::Values(0.0, 0.01));

// A can set down tilted on another first touches it with its rim (Bullet's general convex
// contact), then rocks onto its end cap (the cap-on-cap contact): the pair's contact switches
// between the two ways, as when the Katana lets a can go onto the tower, and the can comes to
// rest standing on the other.
TEST(PhysicsWorld, ACanSetDownTiltedOnAnotherRocksOntoItsCapAndStands) {
  PhysicsWorld world;
  world.addModel(groundPlane(), Eigen::Isometry3d::Identity());
  PhysicsModel& below = world.addModel(parse(canUrdf("below")), xyzRpy(0.3, 0.1, 0.0005, 0, 0, 0));
  for (int i = 0; i < 500; ++i) world.step();
  PhysicsModel& above = world.addModel(parse(canUrdf("above")), xyzRpy(0.3, 0.1, 0.125, 0.1, 0, 0));
  for (int i = 0; i < 3000; ++i) world.step();
  const Eigen::Vector3d at = above.pose().translation();
  EXPECT_NEAR(at.z(), 0.12, 1e-3);
  EXPECT_LT((at - Eigen::Vector3d(0.3, 0.1, 0.12)).head<2>().norm(), 0.01);
  EXPECT_GT(above.pose().linear()(2, 2), std::cos(0.01));  // flat on the cap
  EXPECT_LT(above.twist().linear.norm() + above.twist().angular.norm(), 1e-3);
  EXPECT_NEAR(below.pose().translation().z(), 0.0, 1e-3);
  // Set down with its centre past the rim, a can lands on the cap, tips over the edge (from the
  // cap-on-cap contact to the general one) and falls to the floor.
  PhysicsModel& off = world.addModel(parse(canUrdf("off")), xyzRpy(0.3 + 0.045, 0.1 - 0.3, 0.1205, 0, 0, 0));
  PhysicsModel& under = world.addModel(parse(canUrdf("under")), xyzRpy(0.3, 0.1 - 0.3, 0.0005, 0, 0, 0));
  for (int i = 0; i < 3000; ++i) world.step();
  const Eigen::Vector3d fallen = off.pose().translation();
  EXPECT_LT(fallen.z(), 0.04);  // its frame, at its bottom cap's centre: on the floor, standing or lying
  EXPECT_GT(fallen.z(), -0.04);
  EXPECT_GT(fallen.x(), 0.3 + 0.033);  // off the side it overhung
  EXPECT_LT(fallen.x(), 0.3 + 0.3);
  EXPECT_NEAR(under.pose().translation().z(), 0.0, 2e-3);  // the one below stays standing
  EXPECT_GT(under.pose().linear()(2, 2), std::cos(0.05));
}

// Cans side by side still touch as cylinders (the contact the stacking case does not handle).
TEST(PhysicsWorld, CansSideBySidePushApartToTouching) {
  PhysicsWorld world;
  world.addModel(groundPlane(), Eigen::Isometry3d::Identity());
  PhysicsModel& a = world.addModel(parse(canUrdf("a")), xyzRpy(0.0, 0.0, 0.0005, 0, 0, 0));
  PhysicsModel& b = world.addModel(parse(canUrdf("b")), xyzRpy(0.064, 0.0, 0.0005, 0, 0, 0));
  for (int i = 0; i < 2000; ++i) world.step();
  const double gap = (b.pose().translation() - a.pose().translation()).head<2>().norm();
  EXPECT_GT(gap, 0.066 - 1e-3);  // 2 mm overlapping at the start
  EXPECT_LT(gap, 0.072);
  EXPECT_GT(a.pose().linear()(2, 2), std::cos(0.02));
  EXPECT_GT(b.pose().linear()(2, 2), std::cos(0.02));
}
