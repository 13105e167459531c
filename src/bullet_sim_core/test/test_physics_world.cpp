// The physics core against analytic mechanics: pendulum period, free fall, kinematic frames,
// limits, determinism. Runs without ROS.
#include <gtest/gtest.h>

#include <cmath>

#include "bullet_sim_core/description_error.h"
#include "bullet_sim_core/physics_world.h"
#include "bullet_sim_core/urdf_parser.h"

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

ModelDescription groundPlane() {
  ModelDescription ground;
  ground.name = "ground_plane";
  ground.is_static = true;
  ground.links.emplace_back();
  ground.links[0].name = "link";
  ground.links[0].collisions.emplace_back();
  ground.links[0].collisions[0].geometry.type = GeometryType::Plane;
  return ground;
}

std::string meshBoxUrdf(const std::string& name, double scale) {
  const std::string s = std::to_string(scale);
  return R"(<robot name=")" + name + R"("><link name="body">
    <inertial><mass value="1"/><inertia ixx="0.01" ixy="0" ixz="0" iyy="0.01" iyz="0" izz="0.01"/></inertial>
    <collision><geometry><mesh filename=")" BULLET_SIM_TEST_DATA_DIR R"(/meshes/cube.stl" scale=")" + s + " " + s +
         " " + s + R"("/></geometry></collision></link></robot>)";
}

}  // namespace

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
