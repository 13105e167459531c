// URDF -> ModelDescription: structure, Gazebo blocks, and the errors a user sees.
#include <gtest/gtest.h>

#include "bullet_sim_core/description_error.h"
#include "bullet_sim_core/urdf_parser.h"
#include "bullet_sim_core/testing/error_of.h"

using bullet_sim::JointType;
using bullet_sim::parseUrdf;
using bullet_sim::ResourceResolver;

namespace {

const char* kArm = R"(<?xml version="1.0"?>
<robot name="arm">
  <link name="world"/>
  <joint name="fixed_base" type="fixed"><parent link="world"/><child link="base"/></joint>
  <link name="base">
    <inertial><mass value="2"/><inertia ixx="0.1" ixy="0" ixz="0" iyy="0.1" iyz="0" izz="0.1"/></inertial>
    <collision><geometry><box size="0.2 0.2 0.1"/></geometry></collision>
  </link>
  <joint name="shoulder" type="revolute">
    <parent link="base"/><child link="upper"/>
    <origin xyz="0 0 0.1" rpy="0 0 0"/><axis xyz="0 1 0"/>
    <limit lower="-1.5" upper="1.5" effort="10" velocity="2"/>
    <dynamics damping="0.7" friction="0.1"/>
  </joint>
  <link name="upper">
    <inertial><origin xyz="0 0 0.25"/><mass value="1"/><inertia ixx="0.02" ixy="0" ixz="0" iyy="0.02" iyz="0" izz="0.001"/></inertial>
    <collision><origin xyz="0 0 0.25"/><geometry><cylinder radius="0.03" length="0.5"/></geometry></collision>
    <visual><geometry><sphere radius="0.05"/></geometry><material name="red"><color rgba="1 0 0 1"/></material></visual>
  </link>
  <joint name="wrist" type="continuous"><parent link="upper"/><child link="hand"/><origin xyz="0 0 0.5"/><axis xyz="0 0 1"/></joint>
  <link name="hand"><inertial><mass value="0.2"/><inertia ixx="0.001" ixy="0" ixz="0" iyy="0.001" iyz="0" izz="0.001"/></inertial></link>
  <gazebo reference="upper"><mu1>0.5</mu1><mu2>0.3</mu2></gazebo>
  <gazebo><plugin name="x" filename="libgazebo_ros_control.so"/></gazebo>
</robot>)";

std::string replace(std::string s, const std::string& from, const std::string& to) {
  const auto pos = s.find(from);
  EXPECT_NE(pos, std::string::npos) << from;
  return s.replace(pos, from.size(), to);
}

std::string errorOf(const std::string& xml) { return bullet_sim::errorOf([&] { parseUrdf(xml, "arm.urdf", ResourceResolver()); }); }

}  // namespace

TEST(UrdfParser, ReadsLinksJointsLimitsAndGazeboBlocks) {
  const auto model = parseUrdf(kArm, "arm.urdf", ResourceResolver());
  EXPECT_EQ(model.name, "arm");
  EXPECT_TRUE(model.fixed_base);
  EXPECT_EQ(model.root_link, "world");
  ASSERT_EQ(model.links.size(), 4u);
  EXPECT_EQ(model.links[0].name, "world");  // parents before children
  ASSERT_EQ(model.joints.size(), 3u);
  const auto& shoulder = model.joints[1];
  EXPECT_EQ(shoulder.name, "shoulder");
  EXPECT_EQ(shoulder.type, JointType::Revolute);
  EXPECT_DOUBLE_EQ(shoulder.lower, -1.5);
  EXPECT_DOUBLE_EQ(shoulder.upper, 1.5);
  EXPECT_DOUBLE_EQ(shoulder.effort_limit, 10);
  EXPECT_DOUBLE_EQ(shoulder.damping, 0.7);
  EXPECT_DOUBLE_EQ(shoulder.friction, 0.1);
  EXPECT_TRUE(shoulder.axis.isApprox(Eigen::Vector3d::UnitY()));
  EXPECT_EQ(model.joints[2].type, JointType::Continuous);
  EXPECT_TRUE(std::isinf(model.joints[2].upper));
  const auto* upper = model.findLink("upper");
  ASSERT_NE(upper, nullptr);
  EXPECT_DOUBLE_EQ(upper->mu1, 0.5);
  EXPECT_DOUBLE_EQ(upper->mu2, 0.3);
  EXPECT_NEAR(upper->inertial.origin.translation().z(), 0.25, 1e-12);
  ASSERT_EQ(upper->visuals.size(), 1u);
  EXPECT_FLOAT_EQ(upper->visuals[0].rgba[0], 1.0f);
  ASSERT_EQ(model.plugins.size(), 1u);
  EXPECT_EQ(model.plugins[0].filename, "libgazebo_ros_control.so");
}

TEST(UrdfParser, MalformedXmlNamesTheLine) {
  const std::string e = errorOf("<robot name='a'>\n<link name='x'>\n</robot>");
  EXPECT_NE(e.find("arm.urdf: malformed XML at line"), std::string::npos) << e;
}

TEST(UrdfParser, NotUrdfSaysWhatWasExpected) {
  EXPECT_NE(errorOf("<sdf version='1.6'/>").find("expected a <robot> root element"), std::string::npos);
}

TEST(UrdfParser, UrdfdomErrorsAreReported) {
  const std::string e = errorOf(replace(kArm, "<parent link=\"upper\"/>", "<parent link=\"nowhere\"/>"));
  EXPECT_NE(e.find("arm.urdf: invalid URDF"), std::string::npos) << e;
  EXPECT_NE(e.find("nowhere"), std::string::npos) << e;
}

TEST(UrdfParser, NanInAJointOriginNamesTheJoint) {
  const std::string e = errorOf(replace(kArm, "<origin xyz=\"0 0 0.1\" rpy=\"0 0 0\"/>", "<origin xyz=\"nan 0 0.1\"/>"));
  // urdfdom itself rejects "nan" and names the joint.
  EXPECT_NE(e.find("arm.urdf: invalid URDF"), std::string::npos) << e;
  EXPECT_NE(e.find("joint [shoulder]"), std::string::npos) << e;
}

TEST(UrdfParser, UnsupportedJointTypeIsNamed) {
  const std::string e = errorOf(replace(kArm, "type=\"continuous\"", "type=\"floating\""));
  EXPECT_NE(e.find("<joint name='wrist'>"), std::string::npos) << e;
  EXPECT_NE(e.find("expected fixed, revolute, continuous or prismatic"), std::string::npos) << e;
}

TEST(UrdfParser, MissingMeshNamesLinkAndUri) {
  const std::string e = errorOf(replace(kArm, "<box size=\"0.2 0.2 0.1\"/>", "<mesh filename=\"/nonexistent/base.stl\"/>"));
  EXPECT_NE(e.find("<link name='base'>/<collision>/<geometry>/<mesh filename='/nonexistent/base.stl'>"),
            std::string::npos)
      << e;
}

TEST(UrdfParser, BadFrictionValueIsNamed) {
  const std::string e = errorOf(replace(kArm, "<mu1>0.5</mu1>", "<mu1>lots</mu1>"));
  EXPECT_NE(e.find("<gazebo reference='upper'>/<mu1>: expected a number >= 0, got 'lots'"), std::string::npos) << e;
}

// Gazebo's URDF importer writes <maxVel> and <minDepth> into every collision of the link as
// <surface><contact><ode> max_vel and min_depth; without them, SDF's defaults.
TEST(UrdfParser, MaxVelAndMinDepthSetEveryCollisionOfTheirLink) {
  const std::string two_collisions =
      replace(kArm, "<collision><origin xyz=\"0 0 0.25\"/>",
              "<collision><geometry><sphere radius=\"0.05\"/></geometry></collision><collision><origin xyz=\"0 0 0.25\"/>");
  const auto model = parseUrdf(replace(two_collisions, "<mu1>0.5</mu1>", "<maxVel>0.2</maxVel><minDepth>0.001</minDepth><mu1>0.5</mu1>"),
                               "arm.urdf", ResourceResolver());
  const auto* upper = model.findLink("upper");
  ASSERT_TRUE(upper);
  ASSERT_EQ(upper->collisions.size(), 2u);
  for (const auto& c : upper->collisions) {
    EXPECT_DOUBLE_EQ(c.surface.max_vel, 0.2);
    EXPECT_DOUBLE_EQ(c.surface.min_depth, 0.001);
  }
  const auto& base = model.findLink("base")->collisions.at(0).surface;
  EXPECT_DOUBLE_EQ(base.max_vel, 0.01);
  EXPECT_DOUBLE_EQ(base.min_depth, 0.0);
  // A negative maxVel leaves only the world's limit, as in Gazebo.
  const auto any = parseUrdf(replace(kArm, "<mu1>0.5</mu1>", "<maxVel>-1</maxVel>"), "arm.urdf", ResourceResolver());
  EXPECT_DOUBLE_EQ(any.findLink("upper")->collisions.at(0).surface.max_vel, -1);
}

TEST(UrdfParser, BadMaxVelOrMinDepthIsNamed) {
  std::string e = errorOf(replace(kArm, "<mu1>0.5</mu1>", "<maxVel>slow</maxVel>"));
  EXPECT_NE(e.find("arm.urdf: <gazebo reference='upper'>/<maxVel>: expected a number, got 'slow'"), std::string::npos) << e;
  e = errorOf(replace(kArm, "<mu1>0.5</mu1>", "<minDepth>-0.01</minDepth>"));
  EXPECT_NE(e.find("<gazebo reference='upper'>/<minDepth>: expected a number >= 0, got '-0.01'"), std::string::npos) << e;
  e = errorOf(replace(kArm, "<mu1>0.5</mu1>", "<maxVel>inf</maxVel>"));
  EXPECT_NE(e.find("<gazebo reference='upper'>/<maxVel>: expected a number, got 'inf'"), std::string::npos) << e;
}

TEST(UrdfParser, NegativeMassIsNamed) {
  const std::string e = errorOf(replace(kArm, "<mass value=\"0.2\"/>", "<mass value=\"-1\"/>"));
  EXPECT_NE(e.find("<link name='hand'>/<inertial>/<mass>: expected a mass >= 0"), std::string::npos) << e;
}

TEST(UrdfParser, GazeboMaterialPaintsEveryVisualOfItsLink) {
  // As in Gazebo, the <gazebo> material wins over the URDF's own colour.
  const auto model = parseUrdf(replace(kArm, "<mu1>0.5</mu1>", "<material>Gazebo/Blue</material><mu1>0.5</mu1>"),
                               "arm.urdf", ResourceResolver());
  const auto* upper = model.findLink("upper");
  ASSERT_EQ(upper->visuals.size(), 1u);
  EXPECT_EQ(upper->visuals[0].rgba, (std::array<float, 4>{{0, 0, 1, 1}}));
  EXPECT_TRUE(model.warnings.empty());
  // An unknown name keeps the URDF colour and says so, naming the element.
  const auto unknown = parseUrdf(replace(kArm, "<mu1>0.5</mu1>", "<material>Custom/Glow</material><mu1>0.5</mu1>"),
                                 "arm.urdf", ResourceResolver());
  EXPECT_EQ(unknown.findLink("upper")->visuals[0].rgba, (std::array<float, 4>{{1, 0, 0, 1}}));
  ASSERT_EQ(unknown.warnings.size(), 1u);
  EXPECT_EQ(unknown.warnings[0], "arm.urdf: <gazebo reference='upper'>/<material>: unknown material 'Custom/Glow' "
                                 "(the Gazebo/* colours are known); link 'upper' keeps its URDF colour");
}

TEST(UrdfParser, SensorsSitOnTheirLinkWithTheirPlugins) {
  const auto model = parseUrdf(replace(kArm, "<mu1>0.5</mu1>",
                                       "<sensor name='cam' type='camera'><plugin name='p' filename='libgazebo_ros_camera.so'/>"
                                       "</sensor><mu1>0.5</mu1>"),
                               "arm.urdf", ResourceResolver());
  ASSERT_EQ(model.sensors.size(), 1u);
  EXPECT_EQ(model.sensors[0].name, "cam");
  EXPECT_EQ(model.sensors[0].type, "camera");
  EXPECT_EQ(model.sensors[0].link, "upper");
  ASSERT_EQ(model.sensors[0].plugins.size(), 1u);
  EXPECT_EQ(model.sensors[0].plugins[0].filename, "libgazebo_ros_camera.so");
  EXPECT_EQ(model.plugins.size(), 1u);  // the sensor's plugin is not a model plugin
}

TEST(UrdfParser, BlockForANameThatIsNoLinkOrJointIsReported) {
  const auto model = parseUrdf(replace(kArm, "<gazebo reference=\"upper\">", "<gazebo reference=\"uper\">"),
                               "arm.urdf", ResourceResolver());
  ASSERT_EQ(model.warnings.size(), 1u);
  EXPECT_EQ(model.warnings[0], "arm.urdf: <gazebo reference='uper'>: no link or joint is named 'uper'; the block is ignored");
  EXPECT_DOUBLE_EQ(model.findLink("upper")->mu1, 1.0);
  // A joint's block (e.g. <implicitSpringDamper>) is fine.
  EXPECT_TRUE(parseUrdf(replace(kArm, "<gazebo reference=\"upper\">", "<gazebo reference=\"wrist\">"), "arm.urdf",
                        ResourceResolver())
                  .warnings.empty());
}
