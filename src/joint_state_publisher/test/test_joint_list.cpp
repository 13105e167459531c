// JointList: which joints joint_state_publisher publishes, their default positions, mimic chains,
// sources, the delta sweep, and the errors for descriptions it cannot use.
#include <gtest/gtest.h>

#include <cmath>

#include "joint_state_publisher/joint_list.h"

namespace joint_state_publisher {
namespace {

std::string robot(const std::string& joints) { return "<robot name=\"r\">" + joints + "</robot>"; }

std::string joint(const std::string& name, const std::string& type, const std::string& inside = "") {
  return "<joint name=\"" + name + "\" type=\"" + type + "\"><parent link=\"a\"/><child link=\"" + name + "_link\"/>" +
         inside + "</joint>";
}

std::string limit(double lower, double upper) {
  return "<limit lower=\"" + std::to_string(lower) + "\" upper=\"" + std::to_string(upper) +
         "\" effort=\"1\" velocity=\"1\"/>";
}

const std::string kArm = robot(joint("base", "fixed") + joint("wheel", "continuous") +
                               joint("elbow", "revolute", limit(-1, 2)) +
                               joint("lift", "prismatic", limit(0.1, 0.5)) + joint("float", "floating") +
                               joint("broken", "revolute") + joint("finger", "prismatic", limit(0, 0.04)) +
                               joint("finger_mirror", "prismatic", limit(-0.04, 0) +
                                     "<mimic joint=\"finger\" multiplier=\"-1\" offset=\"0.01\"/>"));

TEST(JointList, MovingJointsInTheUrdfsOrderAtTheirDefaultPositions) {
  const JointList list(kArm, Options());
  EXPECT_EQ(list.names(), (std::vector<std::string>{"wheel", "elbow", "lift", "finger", "finger_mirror"}));
  // A range without 0 defaults to its middle; the mirror follows the finger at 0: -1 * 0 + 0.01.
  const JointStateArrays a = list.arrays();
  EXPECT_EQ(a.position, (std::vector<double>{0.0, 0.0, 0.3, 0.0, 0.01}));
  EXPECT_TRUE(a.velocity.empty());
  EXPECT_TRUE(a.effort.empty());
  ASSERT_EQ(list.warnings().size(), 1u);  // a revolute joint without <limit>
  EXPECT_NE(list.warnings()[0].find("broken is not fixed, nor continuous, but limits are not specified"),
            std::string::npos);
}

TEST(JointList, ZerosSoftLimitsAndDefaultsFollowTheParameters) {
  Options o;
  o.zeros = {{"elbow", 0.5}, {"lift", 0.0}};  // 0 counts as none, as upstream: lift stays at its middle
  o.publish_default_velocities = true;
  o.publish_default_efforts = true;
  const std::string soft = robot(joint("elbow", "revolute", limit(-1, 2)) +
                                 joint("lift", "prismatic", limit(0.1, 0.5) +
                                       "<safety_controller soft_lower_limit=\"0.2\" soft_upper_limit=\"0.3\"/>"));
  JointStateArrays a = JointList(soft, o).arrays();
  EXPECT_EQ(a.position, (std::vector<double>{0.5, 0.25}));  // the soft limits' middle
  EXPECT_EQ(a.velocity, (std::vector<double>{0.0, 0.0}));
  EXPECT_EQ(a.effort, (std::vector<double>{0.0, 0.0}));
  o.use_smallest_joint_limits = false;
  o.publish_default_positions = false;
  a = JointList(soft, o).arrays();
  EXPECT_TRUE(a.position.empty());  // until a source gives them
  EXPECT_EQ(a.name.size(), 2u);
}

TEST(JointList, SourcesSetFreeJointsAndDependentsFollowThem) {
  JointList list(kArm, Options());
  list.set("finger", 0.03, 0.2, 1.5);
  list.set("finger_mirror", 9.0, 9.0, 9.0);  // not free: ignored, as upstream
  list.set("nonexistent", 1.0, std::nullopt, std::nullopt);
  list.set("elbow", std::nullopt, -0.5, std::nullopt);
  const JointStateArrays a = list.arrays();
  EXPECT_DOUBLE_EQ(a.position[3], 0.03);
  EXPECT_DOUBLE_EQ(a.position[4], -0.03 + 0.01);
  ASSERT_EQ(a.velocity.size(), 5u);
  EXPECT_DOUBLE_EQ(a.velocity[1], -0.5);
  EXPECT_DOUBLE_EQ(a.velocity[4], -0.2);  // scaled by the factor
  EXPECT_DOUBLE_EQ(a.effort[4], 1.5);     // not scaled, as upstream
  EXPECT_DOUBLE_EQ(a.velocity[0], 0.0);   // no value yet: 0
}

TEST(JointList, MimicChainsComposeAndLoopsAreErrors) {
  const std::string chain = robot(joint("a", "revolute", limit(-3, 3)) +
                                  joint("b", "revolute", limit(-3, 3) + "<mimic joint=\"a\" multiplier=\"2\" offset=\"0.1\"/>") +
                                  joint("c", "revolute", limit(-3, 3) + "<mimic joint=\"b\" multiplier=\"3\" offset=\"0.2\"/>"));
  JointList list(chain, Options());
  list.set("a", 0.5, std::nullopt, std::nullopt);
  // c = 3 * b + 0.2 = 3 * (2 * a + 0.1) + 0.2
  EXPECT_NEAR(list.arrays().position[2], 3 * (2 * 0.5 + 0.1) + 0.2, 1e-12);
  Options no_mimic;
  no_mimic.use_mimic_tags = false;
  EXPECT_TRUE(JointList(chain, no_mimic).isFree("c"));

  Options looped;
  looped.dependent_joints["a"] = {"c", 1.0, 0.0};
  try {
    JointList bad(chain, looped);
    FAIL() << "a loop a -> c -> b -> a was accepted";
  } catch (const JointListError& e) {
    EXPECT_NE(std::string(e.what()).find("infinite recursive mimic chain"), std::string::npos) << e.what();
  }
  const JointList orphan(robot(joint("m", "revolute", limit(-1, 1) + "<mimic joint=\"ghost\"/>")), Options());
  EXPECT_TRUE(orphan.names().empty());
  ASSERT_EQ(orphan.warnings().size(), 1u);
  EXPECT_NE(orphan.warnings()[0].find("follows 'ghost'"), std::string::npos);
}

TEST(JointList, DependentJointsFromTheParameter) {
  Options o;
  o.dependent_joints["lift"] = {"elbow", 0.1, 0.2};
  JointList list(kArm, o);
  EXPECT_FALSE(list.isFree("lift"));
  list.set("elbow", 1.0, std::nullopt, std::nullopt);
  EXPECT_NEAR(list.arrays().position[2], 0.1 * 1.0 + 0.2, 1e-12);
}

TEST(JointList, TheDeltaSweepTurnsAtLimitsAndWrapsContinuousJoints) {
  JointList list(robot(joint("wheel", "continuous") + joint("elbow", "revolute", limit(-0.25, 0.25))), Options());
  list.set("wheel", M_PI - 0.05, std::nullopt, std::nullopt);
  list.sweep(0.1);
  EXPECT_NEAR(list.arrays().position[0], -M_PI, 1e-12);  // past pi: round to -pi
  EXPECT_NEAR(list.arrays().position[1], 0.1, 1e-12);
  for (int i = 0; i < 3; ++i) list.sweep(0.1);  // 0.2, past 0.25 -> held at 0.25 and turned, 0.15
  EXPECT_NEAR(list.arrays().position[1], 0.15, 1e-12);
}

TEST(JointList, DescriptionsItCannotUseAreNamed) {
  const auto error = [](const std::string& xml) {
    try {
      JointList list(xml, Options());
    } catch (const JointListError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(error("<robot").find("not XML"), std::string::npos);
  EXPECT_NE(error("<model/>").find("no <robot> element"), std::string::npos);
  EXPECT_NE(error("<COLLADA/>").find("COLLADA"), std::string::npos);
  EXPECT_NE(error(robot(joint("elbow", "revolute", "<limit lower=\"x\" upper=\"1\"/>"))).find("joint 'elbow': <limit lower=\"x\">"),
            std::string::npos);
}

}  // namespace
}  // namespace joint_state_publisher
