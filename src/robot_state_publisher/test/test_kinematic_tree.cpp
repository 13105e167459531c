// The joints and frames robot_state_publisher publishes, from a small URDF with every joint kind.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include <urdf_parser/urdf_parser.h>

#include "robot_state_publisher/kinematic_tree.h"

namespace robot_state_publisher {
namespace {

const char* const kRobot = R"(<robot name="sample">
  <link name="base_link"/>
  <link name="laser"/> <link name="arm"/> <link name="slider"/> <link name="wheel"/>
  <link name="finger1"/> <link name="finger2"/> <link name="loose"/>
  <joint name="laser_joint" type="fixed">
    <parent link="base_link"/> <child link="laser"/> <origin xyz="0.1 0 0.2" rpy="0 0 1.5707963267948966"/>
  </joint>
  <joint name="arm_joint" type="revolute">
    <parent link="base_link"/> <child link="arm"/> <origin xyz="0.5 0 0"/> <axis xyz="0 0 1"/>
    <limit lower="-3" upper="3" effort="1" velocity="1"/>
  </joint>
  <joint name="slide_joint" type="prismatic">
    <parent link="arm"/> <child link="slider"/> <origin xyz="0 0.2 0"/> <axis xyz="1 0 0"/>
    <limit lower="0" upper="1" effort="1" velocity="1"/>
  </joint>
  <joint name="wheel_joint" type="continuous">
    <parent link="base_link"/> <child link="wheel"/> <origin xyz="0 0.3 0" rpy="-1.5707963267948966 0 0"/>
    <axis xyz="0 0 1"/>
  </joint>
  <joint name="finger1_joint" type="prismatic">
    <parent link="slider"/> <child link="finger1"/> <axis xyz="0 1 0"/> <limit lower="0" upper="1" effort="1" velocity="1"/>
  </joint>
  <joint name="finger2_joint" type="prismatic">
    <parent link="slider"/> <child link="finger2"/> <axis xyz="0 1 0"/> <limit lower="-1" upper="1" effort="1" velocity="1"/>
    <mimic joint="finger1_joint" multiplier="-1" offset="0.1"/>
  </joint>
  <joint name="loose_joint" type="floating"> <parent link="base_link"/> <child link="loose"/> </joint>
</robot>)";

class KinematicTreeTest : public ::testing::Test {
 protected:
  KinematicTreeTest() : model_(urdf::parseURDF(kRobot)), tree_(*model_) {}
  urdf::ModelInterfaceSharedPtr model_;
  KinematicTree tree_;
};

TEST_F(KinematicTreeTest, FixedJointsAreApartWithTheirOrigin) {
  ASSERT_EQ(tree_.fixedJoints().size(), 1u);
  const JointFrame& laser = tree_.fixedJoints()[0];
  EXPECT_EQ(laser.parent, "base_link");
  EXPECT_EQ(laser.child, "laser");
  const KDL::Frame f = laser.segment.pose(0.0);
  EXPECT_NEAR(f.p.x(), 0.1, 1e-12);
  EXPECT_NEAR(f.p.z(), 0.2, 1e-12);
  double roll, pitch, yaw;
  f.M.GetRPY(roll, pitch, yaw);
  EXPECT_NEAR(yaw, M_PI / 2, 1e-12);
  EXPECT_EQ(tree_.movingJoint("laser_joint"), nullptr);
}

TEST_F(KinematicTreeTest, ARevoluteJointTurnsItsChildAboutItsAxisAfterTheOrigin) {
  const JointFrame* arm = tree_.movingJoint("arm_joint");
  ASSERT_NE(arm, nullptr);
  EXPECT_EQ(arm->parent, "base_link");
  EXPECT_EQ(arm->child, "arm");
  const KDL::Frame f = arm->segment.pose(0.7);
  EXPECT_NEAR(f.p.x(), 0.5, 1e-12);  // the origin is not moved by the joint
  EXPECT_NEAR(f.p.y(), 0.0, 1e-12);
  double roll, pitch, yaw;
  f.M.GetRPY(roll, pitch, yaw);
  EXPECT_NEAR(yaw, 0.7, 1e-12);
}

TEST_F(KinematicTreeTest, APrismaticJointSlidesAlongItsAxis) {
  const JointFrame* slide = tree_.movingJoint("slide_joint");
  ASSERT_NE(slide, nullptr);
  EXPECT_EQ(slide->parent, "arm");
  const KDL::Frame f = slide->segment.pose(0.25);
  EXPECT_NEAR(f.p.x(), 0.25, 1e-12);
  EXPECT_NEAR(f.p.y(), 0.2, 1e-12);
}

TEST_F(KinematicTreeTest, AContinuousJointsAxisIsInTheRotatedJointFrame) {
  // The wheel's origin turns -90 degrees about x: its z axis is the base's +y.
  const JointFrame* wheel = tree_.movingJoint("wheel_joint");
  ASSERT_NE(wheel, nullptr);
  const KDL::Frame f = wheel->segment.pose(M_PI / 2);
  const KDL::Vector x_of_child = f.M.UnitX();
  EXPECT_NEAR(x_of_child.z(), -1.0, 1e-12);  // its x turned from the base's x towards -z
  EXPECT_NEAR(f.p.y(), 0.3, 1e-12);
}

TEST_F(KinematicTreeTest, MimicRulesAndFloatingJointsAreListed) {
  ASSERT_EQ(tree_.mimicRules().size(), 1u);
  const MimicRule& m = tree_.mimicRules()[0];
  EXPECT_EQ(m.joint, "finger2_joint");
  EXPECT_EQ(m.follows, "finger1_joint");
  EXPECT_DOUBLE_EQ(m.multiplier, -1.0);
  EXPECT_DOUBLE_EQ(m.offset, 0.1);
  EXPECT_EQ(tree_.floatingJoints(), std::vector<std::string>{"loose_joint"});
  EXPECT_EQ(tree_.movingJoint("loose_joint"), nullptr);
  EXPECT_EQ(tree_.movingJoint("no_such_joint"), nullptr);
}

TEST(PrefixedFrame, AsTfResolves) {
  EXPECT_EQ(prefixedFrame("", "base_link"), "base_link");
  EXPECT_EQ(prefixedFrame("robot1", "base_link"), "robot1/base_link");
  EXPECT_EQ(prefixedFrame("/robot1", "base_link"), "robot1/base_link");
  EXPECT_EQ(prefixedFrame("robot1", "/base_link"), "base_link");
}

}  // namespace
}  // namespace robot_state_publisher
