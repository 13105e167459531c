// currentContacts (who touches whom, where, how hard) and PhysicsWorld::attach / detach (a fixed
// constraint between two models, as the grasp fix uses it).
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "bullet_sim_core/contacts.h"
#include "bullet_sim_core/description_error.h"
#include "bullet_sim_core/physics_world.h"
#include "bullet_sim_core/urdf_parser.h"
#include "ground_plane.h"

namespace bullet_sim {
namespace {

constexpr double kG = 9.8;

ModelDescription parse(const std::string& xml) { return parseUrdf(xml, "test.urdf", ResourceResolver()); }

std::string boxUrdf(const std::string& name, double mass, double side) {
  const std::string m = std::to_string(mass), s = std::to_string(side), i = std::to_string(mass * side * side / 6);
  return "<robot name='" + name + "'><link name='body'><inertial><mass value='" + m + "'/><inertia ixx='" + i +
         "' ixy='0' ixz='0' iyy='" + i + "' iyz='0' izz='" + i + "'/></inertial><collision><geometry><box size='" +
         s + " " + s + " " + s + "'/></geometry></collision></link></robot>";
}

// A post fixed to the world with a hinged arm (1 kg at 0.3 m) held by a motor: something to hold a box.
const char* kArm = R"(<robot name="arm"><link name="world"/>
  <joint name="anchor" type="fixed"><parent link="world"/><child link="post"/><origin xyz="0 0 1"/></joint>
  <link name="post"><inertial><mass value="5"/><inertia ixx="0.1" ixy="0" ixz="0" iyy="0.1" iyz="0" izz="0.1"/></inertial></link>
  <joint name="hinge" type="revolute"><parent link="post"/><child link="hand"/><axis xyz="0 0 1"/>
    <limit lower="-3" upper="3" effort="100" velocity="5"/></joint>
  <link name="hand"><inertial><origin xyz="0.3 0 0"/><mass value="1"/><inertia ixx="0.01" ixy="0" ixz="0" iyy="0.01" iyz="0" izz="0.01"/></inertial></link>
</robot>)";

PhysicsSettings earth() {
  PhysicsSettings s;
  s.gravity = Eigen::Vector3d(0, 0, -kG);
  return s;
}

Eigen::Isometry3d at(double x, double y, double z) {
  Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
  t.translation() = Eigen::Vector3d(x, y, z);
  return t;
}

TEST(Contacts, ABoxRestingOnTheGroundPressesWithItsWeight) {
  PhysicsWorld world(earth());
  world.addModel(groundPlane(), Eigen::Isometry3d::Identity());
  world.addModel(parse(boxUrdf("crate", 2.0, 0.2)), at(0.5, -1, 0.3));
  for (int i = 0; i < 1500; ++i) world.step();
  const auto contacts = currentContacts(world);
  ASSERT_GE(contacts.size(), 3u);  // a face on a plane: several points
  double force = 0;
  for (const Contact& c : contacts) {
    // Either order of the pair; the normal points from b to a.
    const bool crate_first = c.model_a == "crate";
    EXPECT_EQ(crate_first ? c.model_b : c.model_a, "ground_plane");
    EXPECT_EQ(crate_first ? c.link_a : c.link_b, "body");
    EXPECT_NEAR((crate_first ? c.normal : Eigen::Vector3d(-c.normal)).z(), 1.0, 1e-6);
    EXPECT_NEAR(c.position.z(), 0.0, 0.003);
    EXPECT_NEAR(c.position.x(), 0.5, 0.1 + 1e-3);  // on the 0.2 m face (and Bullet's margin)
    EXPECT_LT(c.depth, 0.003);
    force += c.force;
  }
  EXPECT_NEAR(force, 2.0 * kG, 0.05 * 2.0 * kG);
}

TEST(Contacts, NothingTouchingGivesNoContacts) {
  PhysicsWorld world(earth());
  world.addModel(groundPlane(), Eigen::Isometry3d::Identity());
  world.addModel(parse(boxUrdf("crate", 2.0, 0.2)), at(0, 0, 2.0));
  for (int i = 0; i < 100; ++i) world.step();
  EXPECT_TRUE(currentContacts(world).empty());
}

// Attached, the box rides with the arm's hand as the hinge turns; detached, it falls freely.
TEST(Attachments, AnAttachedBoxMovesWithTheHandAndFallsWhenDetached) {
  PhysicsWorld world(earth());
  PhysicsModel& arm = world.addModel(parse(kArm), Eigen::Isometry3d::Identity());
  PhysicsModel& box = world.addModel(parse(boxUrdf("can", 0.3, 0.06)), at(0.4, 0, 1.0));
  const int hinge = arm.jointIndex("hinge");
  arm.setJointMotor(hinge, 0.0, 0.0, 1.0, 50.0);
  const int id = world.attach("arm", "hand", "can", "body");
  EXPECT_GT(id, 0);
  for (int i = 0; i < 200; ++i) world.step();
  EXPECT_NEAR(box.pose().translation().z(), 1.0, 0.002);  // held, not dropped, not flung
  EXPECT_NEAR(box.pose().translation().x(), 0.4, 0.002);
  // Swing the hand at 1 rad/s for 1.5 s: the box follows on its 0.4 m radius, at the hand's angle.
  arm.setJointMotor(hinge, 0.0, 1.0, 0.0, 50.0);
  for (int i = 0; i < 1500; ++i) world.step();
  const double angle = arm.jointPosition(hinge);
  EXPECT_NEAR(angle, 1.5, 0.05);
  EXPECT_NEAR(box.pose().translation().x(), 0.4 * std::cos(angle), 0.005);
  EXPECT_NEAR(box.pose().translation().y(), 0.4 * std::sin(angle), 0.005);
  EXPECT_NEAR(box.pose().translation().z(), 1.0, 0.005);
  arm.setJointMotor(hinge, 0.0, 0.0, 0.0, 50.0);  // stop before letting go
  for (int i = 0; i < 200; ++i) world.step();

  EXPECT_TRUE(world.detach(id));
  EXPECT_FALSE(world.detach(id));
  const double z0 = box.pose().translation().z();
  for (int i = 0; i < 300; ++i) world.step();
  EXPECT_NEAR(z0 - box.pose().translation().z(), 0.5 * kG * 0.09, 0.05 * 0.5 * kG * 0.09);  // 0.3 s of free fall
}

TEST(Attachments, BadRequestsAreErrorsAndRemovingAModelDetachesIt) {
  PhysicsWorld world(earth());
  world.addModel(groundPlane(), Eigen::Isometry3d::Identity());
  world.addModel(parse(kArm), Eigen::Isometry3d::Identity());
  world.addModel(parse(boxUrdf("can", 0.3, 0.06)), at(0.4, 0, 1.0));
  EXPECT_THROW(world.attach("arm", "hand", "cup", "body"), DescriptionError);
  EXPECT_THROW(world.attach("arm", "finger", "can", "body"), DescriptionError);
  EXPECT_THROW(world.attach("arm", "hand", "ground_plane", "link"), DescriptionError);
  EXPECT_THROW(world.attach("can", "body", "can", "body"), DescriptionError);
  const int id = world.attach("arm", "hand", "can", "body");
  EXPECT_TRUE(world.removeModel("can"));
  for (int i = 0; i < 10; ++i) world.step();  // no dangling constraint
  EXPECT_FALSE(world.detach(id));
}

}  // namespace
}  // namespace bullet_sim
