// SDF models with joints (the RE510 lecture's model-editor vehicle is one): links keep their
// frames, joints connect them in a tree with SDF's axis conventions, and every mistake in a
// <joint> is named. The physics then turns a joint about its SDF pivot.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <limits>
#include <string>

#include "bullet_sim_core/description_error.h"
#include "bullet_sim_core/physics_world.h"
#include "bullet_sim_core/sdf_parser.h"
#include "bullet_sim_core/testing/error_of.h"

using namespace bullet_sim;

namespace {

ModelDescription parse(const std::string& xml) { return parseSdfModel(xml, "vehicle.sdf", "", ResourceResolver()); }

std::string link(const std::string& name, const std::string& pose, const std::string& geometry = "<sphere><radius>0.1</radius></sphere>") {
  return "<link name='" + name + "'><pose>" + pose + "</pose><inertial><mass>1</mass><inertia><ixx>0.01</ixx>"
         "<iyy>0.01</iyy><izz>0.01</izz></inertia></inertial><collision name='c'><geometry>" + geometry +
         "</geometry></collision></link>";
}

// The lecture's vehicle, as Gazebo's model editor saves it (SDF 1.6, one wheel shown): a body, a
// wheel rolled 90 degrees on a revolute joint about its -Z with the editor's +-DBL_MAX limits, and a
// lidar on a fixed joint.
std::string vehicle(const std::string& version = "1.6", const std::string& axis = "0 0 -1",
                    const std::string& axis_extra = "") {
  return "<sdf version='" + version + "'><model name='my_vehicle'>" + link("link", "0 0 0.5 0 0 0") +
         link("link_0", "0.6 0.775 0.3 1.5707963267948966 0 0") + link("lidar", "0.8 0 0.7 0 0 0") +
         "<joint name='front_left_wheel_joint' type='revolute'><parent>link</parent><child>link_0</child>"
         "<axis><xyz>" + axis + "</xyz>" + axis_extra +
         "<limit><lower>-1.79769e+308</lower><upper>1.79769e+308</upper><effort>-1</effort><velocity>-1</velocity></limit>"
         "<dynamics><damping>0.1</damping></dynamics></axis></joint>"
         "<joint name='lidar_joint' type='fixed'><parent>link</parent><child>lidar</child></joint>"
         "</model></sdf>";
}

const JointDescription& joint(const ModelDescription& m, const std::string& name) {
  for (const auto& j : m.joints)
    if (j.name == name) return j;
  throw std::runtime_error("no joint " + name);
}

TEST(SdfJoints, TheModelEditorsVehicleBecomesATreeOfLinks) {
  const ModelDescription m = parse(vehicle());
  EXPECT_EQ(m.root_link, "link");
  EXPECT_TRUE(m.root_pose.translation().isApprox(Eigen::Vector3d(0, 0, 0.5)));
  EXPECT_FALSE(m.fixed_base);
  ASSERT_EQ(m.links.size(), 3u);
  EXPECT_EQ(m.links[0].name, "link");  // parents before children
  ASSERT_EQ(m.joints.size(), 2u);

  const JointDescription& wheel = joint(m, "front_left_wheel_joint");
  EXPECT_EQ(wheel.type, JointType::Revolute);
  EXPECT_EQ(wheel.parent, "link");
  EXPECT_EQ(wheel.child, "link_0");
  // The child's frame in the parent's: the two link poses' difference.
  EXPECT_TRUE(wheel.origin.translation().isApprox(Eigen::Vector3d(0.6, 0.775, -0.2), 1e-12));
  EXPECT_TRUE((wheel.origin.linear() * Eigen::Vector3d::UnitZ()).isApprox(-Eigen::Vector3d::UnitY(), 1e-9));
  // -Z of the rolled wheel is +y of the body: positive speeds roll the vehicle forward.
  EXPECT_TRUE(wheel.axis.isApprox(-Eigen::Vector3d::UnitZ(), 1e-12));
  EXPECT_TRUE((wheel.origin.linear() * wheel.axis).isApprox(Eigen::Vector3d::UnitY(), 1e-9));
  EXPECT_TRUE(wheel.pivot.isZero());
  // The editor's +-DBL_MAX limits and -1 effort/velocity mean none.
  EXPECT_TRUE(std::isinf(wheel.lower) && wheel.lower < 0);
  EXPECT_TRUE(std::isinf(wheel.upper) && wheel.upper > 0);
  EXPECT_TRUE(std::isinf(wheel.effort_limit));
  EXPECT_TRUE(std::isinf(wheel.velocity_limit));
  EXPECT_DOUBLE_EQ(wheel.damping, 0.1);

  const JointDescription& lidar = joint(m, "lidar_joint");
  EXPECT_EQ(lidar.type, JointType::Fixed);
  EXPECT_TRUE(lidar.origin.translation().isApprox(Eigen::Vector3d(0.8, 0, 0.2), 1e-12));
}

TEST(SdfJoints, AxisFramesFollowTheSdfVersion) {
  // SDF 1.4 gives the axis in the model frame: +y of the model is -z of the rolled wheel.
  const ModelDescription old = parse(vehicle("1.4", "0 1 0"));
  EXPECT_TRUE(joint(old, "front_left_wheel_joint").axis.isApprox(-Eigen::Vector3d::UnitZ(), 1e-9));
  // 1.5 and later: the joint frame, unless <use_parent_model_frame> says the model frame.
  const ModelDescription flagged =
      parse(vehicle("1.6", "0 1 0", "<use_parent_model_frame>true</use_parent_model_frame>"));
  EXPECT_TRUE(joint(flagged, "front_left_wheel_joint").axis.isApprox(-Eigen::Vector3d::UnitZ(), 1e-9));
  // And a limited revolute joint keeps its limits; a prismatic one slides along its axis.
  const ModelDescription limited = parse(
      "<model name='m'>" + link("a", "0 0 0 0 0 0") + link("b", "0 0 1 0 0 0") + link("c", "0 0 2 0 0 0") +
      "<joint name='hinge' type='revolute'><parent>a</parent><child>b</child><axis><xyz>1 0 0</xyz>"
      "<limit><lower>-0.5</lower><upper>0.7</upper><effort>3</effort><velocity>2</velocity></limit></axis></joint>"
      "<joint name='slider' type='prismatic'><parent>b</parent><child>c</child><axis><xyz>0 0 2</xyz></axis></joint>"
      "</model>");
  const JointDescription& hinge = joint(limited, "hinge");
  EXPECT_DOUBLE_EQ(hinge.lower, -0.5);
  EXPECT_DOUBLE_EQ(hinge.upper, 0.7);
  EXPECT_DOUBLE_EQ(hinge.effort_limit, 3);
  EXPECT_DOUBLE_EQ(hinge.velocity_limit, 2);
  const JointDescription& slider = joint(limited, "slider");
  EXPECT_EQ(slider.type, JointType::Prismatic);
  EXPECT_TRUE(slider.axis.isApprox(Eigen::Vector3d::UnitZ()));  // normalised
}

TEST(SdfJoints, AJointPoseMovesThePivotAndAWorldParentFixesTheModel) {
  const ModelDescription m = parse(
      "<model name='pendulum'>" + link("bob", "0.5 0 1 0 0 0") +
      "<joint name='swing' type='continuous'><parent>world</parent><child>bob</child><pose>-0.5 0 0 0 0 0</pose>"
      "<axis><xyz>0 1 0</xyz></axis></joint></model>");
  EXPECT_TRUE(m.fixed_base);
  EXPECT_EQ(m.root_link, "world");
  ASSERT_EQ(m.links.size(), 2u);
  EXPECT_EQ(m.links[0].name, "world");
  const JointDescription& swing = joint(m, "swing");
  EXPECT_EQ(swing.type, JointType::Continuous);
  EXPECT_TRUE(swing.pivot.isApprox(Eigen::Vector3d(-0.5, 0, 0)));
  EXPECT_TRUE(swing.origin.translation().isApprox(Eigen::Vector3d(0.5, 0, 1)));
}

TEST(SdfJoints, MistakesInJointsAreNamed) {
  const std::string two = link("a", "0 0 0 0 0 0") + link("b", "1 0 0 0 0 0");
  const auto modelError = [&](const std::string& body) {
    return errorOf([&] { parse("<sdf version='1.6'><model name='m'>" + body + "</model></sdf>"); });
  };
  EXPECT_EQ(modelError(two + "<joint name='j' type='revolute'><child>b</child></joint>"),
            "vehicle.sdf: <model name='m'>/<joint name='j'>: missing required element <parent>");
  EXPECT_EQ(modelError(two + "<joint name='j' type='revolute'><parent>a</parent><child>c</child></joint>"),
            "vehicle.sdf: <model name='m'>/<joint name='j'>/<child>: expected the name of a link of this model "
            "(a, b), got 'c'");
  EXPECT_EQ(modelError(two + "<joint name='j' type='revolute'><parent>wheel</parent><child>b</child></joint>"),
            "vehicle.sdf: <model name='m'>/<joint name='j'>/<parent>: expected the name of a link of this model "
            "(a, b, or world), got 'wheel'");
  EXPECT_EQ(modelError(two + "<joint name='j' type='revolute'><parent>a</parent><child>b</child>"
                             "<axis><xyz>0 1</xyz></axis></joint>"),
            "vehicle.sdf: <model name='m'>/<joint name='j'>/<axis>/<xyz>: expected 3 numbers, got '0 1'");
  EXPECT_EQ(modelError(two + "<joint name='j' type='revolute'><parent>a</parent><child>b</child>"
                             "<axis><xyz>0 0 0</xyz></axis></joint>"),
            "vehicle.sdf: <model name='m'>/<joint name='j'>/<axis>/<xyz>: expected a non-zero axis, got '0 0 0'");
  EXPECT_EQ(modelError(two + "<joint name='j' type='ball'><parent>a</parent><child>b</child></joint>"),
            "vehicle.sdf: <model name='m'>/<joint name='j'>: type='ball': expected revolute, continuous, prismatic "
            "or fixed (bullet_sim has no ball joints)");
  EXPECT_EQ(modelError(two + "<joint name='j' type='revolute'><parent>a</parent><child>b</child><axis>"
                             "<limit><lower>1</lower><upper>-1</upper></limit></axis></joint>"),
            "vehicle.sdf: <model name='m'>/<joint name='j'>/<axis>/<limit>/<upper>: expected a number >= <lower> "
            "(1), got '-1'");
  EXPECT_EQ(modelError(two + "<joint name='j' type='fixed'><parent>a</parent><child>a</child></joint>"),
            "vehicle.sdf: <model name='m'>/<joint name='j'>/<child>: expected a link other than the parent 'a'");
  const std::string three = two + link("c", "2 0 0 0 0 0");
  EXPECT_EQ(modelError(three + "<joint name='j' type='fixed'><parent>a</parent><child>c</child></joint>"
                               "<joint name='k' type='fixed'><parent>b</parent><child>c</child></joint>"),
            "vehicle.sdf: <model name='m'>/<joint name='k'>/<child>: link 'c' already has a parent joint; a link "
            "has one parent");
  EXPECT_EQ(modelError(three + "<joint name='j' type='fixed'><parent>a</parent><child>b</child></joint>"),
            "vehicle.sdf: <model name='m'>: link 'c' is not connected to link 'a' by joints; a moving model must be "
            "one tree of links (is there a <joint> missing, or a loop?)");
  // A loop leaves no link without a parent but the first; the others are not reached from it.
  EXPECT_NE(modelError(three + "<joint name='j' type='fixed'><parent>c</parent><child>b</child></joint>"
                               "<joint name='k' type='fixed'><parent>b</parent><child>c</child></joint>")
                .find("is not connected to link 'a' by joints"),
            std::string::npos);
}

// A pendulum whose SDF link frame is at the bob and whose joint <pose> puts the pivot 0.5 m away:
// released level, it must swing down on a circle about the pivot (a joint about the link origin
// would spin the bob in place).
TEST(SdfJoints, ThePhysicsTurnsAJointAboutItsSdfPivot) {
  const ModelDescription m = parse(
      "<model name='pendulum'><link name='bob'><pose>0.5 0 1 0 0 0</pose><inertial><mass>1</mass><inertia>"
      "<ixx>1e-6</ixx><iyy>1e-6</iyy><izz>1e-6</izz></inertia></inertial></link>"
      "<joint name='swing' type='continuous'><parent>world</parent><child>bob</child><pose>-0.5 0 0 0 0 0</pose>"
      "<axis><xyz>0 1 0</xyz></axis></joint></model>");
  PhysicsWorld world;
  PhysicsModel& pendulum = world.addModel(m, Eigen::Isometry3d::Identity());
  const Eigen::Vector3d pivot(0, 0, 1);
  double lowest = 1.0, fastest = 0.0;
  for (int i = 0; i < 1000; ++i) {
    world.step();
    const Eigen::Vector3d bob = pendulum.linkPose("bob").translation();
    ASSERT_NEAR((bob - pivot).norm(), 0.5, 1e-3) << "at step " << i;
    ASSERT_NEAR(bob.y(), 0.0, 1e-9);
    lowest = std::min(lowest, bob.z());
    fastest = std::max(fastest, pendulum.linkTwist("bob").linear.norm());
  }
  EXPECT_NEAR(lowest, 0.5, 0.01);                     // down through the bottom of the circle
  EXPECT_NEAR(fastest, std::sqrt(2 * 9.8 * 0.5), 0.03);  // a point mass falling 0.5 m
}

}  // namespace
