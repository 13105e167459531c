// SdfElement: the one reader of SDF and URDF <gazebo> blocks. Strict numbers whatever the locale,
// and one wording for every error: "<source>: <path>: expected <form>, got '<text>'".
#include <gtest/gtest.h>

#include <clocale>
#include <cmath>
#include <string>

#include "bullet_sim_core/description_error.h"
#include "bullet_sim_core/sdf_element.h"
#include "bullet_sim_core/testing/error_of.h"

namespace bullet_sim {
namespace {

const char* kRobot = R"(<robot name="r">
  <gazebo reference="laser">
    <sensor name="lidar" type="ray">
      <pose>0 0 0.1 0 0 1.5707963</pose>
      <update_rate> 40 </update_rate>
      <always_on>TRUE</always_on>
      <ray><range><min>0.1</min><max>far</max></range></ray>
      <plugin name="p" filename="libgazebo_ros_laser.so"><topicName>scan</topicName></plugin>
    </sensor>
  </gazebo>
</robot>)";

TEST(SdfElement, PathsStartBelowTheRobotOrSdfRootAndNameTheAttributesThatIdentify) {
  const SdfElement robot = SdfElement::parse(kRobot, "m.urdf");
  const SdfElement sensor = robot.child("gazebo").child("sensor");
  EXPECT_EQ(sensor.path(), "<gazebo reference='laser'>/<sensor name='lidar'>");
  EXPECT_EQ(sensor.child("plugin").path(),
            "<gazebo reference='laser'>/<sensor name='lidar'>/<plugin name='p' filename='libgazebo_ros_laser.so'>");
  // An absent element still knows where it would be.
  const SdfElement noise = sensor.child("ray").child("noise").child("stddev");
  EXPECT_FALSE(noise);
  EXPECT_EQ(noise.path(), "<gazebo reference='laser'>/<sensor name='lidar'>/<ray>/<noise>/<stddev>");
}

TEST(SdfElement, ValuesAndFallbacks) {
  const SdfElement sensor = SdfElement::parse(kRobot, "m.urdf").child("gazebo").child("sensor");
  EXPECT_EQ(sensor.number("update_rate", 0.0, nonNegative()), 40.0);  // trimmed
  EXPECT_TRUE(sensor.boolean("always_on", false));                   // any case
  EXPECT_EQ(sensor.number("missing", 2.5), 2.5);
  EXPECT_EQ(sensor.string("missing", "x"), "x");
  const Eigen::Isometry3d pose = sensor.pose();
  EXPECT_NEAR(pose.translation().z(), 0.1, 1e-12);
  EXPECT_NEAR((pose.linear() * Eigen::Vector3d::UnitX()).y(), 1.0, 1e-7);  // yaw of 90 degrees
  EXPECT_TRUE(sensor.child("nothing").pose().isApprox(Eigen::Isometry3d::Identity()));
  EXPECT_EQ(sensor.child("plugin").string("topicName", ""), "scan");
  EXPECT_EQ(pluginLibraryName(" /opt/lib/libgazebo_ros_laser.so "), "libgazebo_ros_laser.so");
}

TEST(SdfElement, OneWordingForEveryMistake) {
  const SdfElement sensor = SdfElement::parse(kRobot, "m.urdf").child("gazebo").child("sensor");
  const std::string at = "m.urdf: <gazebo reference='laser'>/<sensor name='lidar'>";
  const SdfElement range = sensor.child("ray").child("range");
  EXPECT_EQ(errorOf([&] { range.number("max", 1.0, greaterThan(0.1, "<min>")); }),
            at + "/<ray>/<range>/<max>: expected a number > <min> (0.1), got 'far'");
  EXPECT_EQ(errorOf([&] { sensor.boolean("update_rate", false); }),
            at + "/<update_rate>: expected true, false, 1 or 0, got '40'");
  EXPECT_EQ(errorOf([&] { sensor.vector3("update_rate", Eigen::Vector3d::Zero()); }),
            at + "/<update_rate>: expected 3 numbers, got '40'");
  EXPECT_EQ(errorOf([&] { sensor.integer("update_rate", 1, 1, 10); }),
            at + "/<update_rate>: expected an integer in [1, 10], got '40'");
  EXPECT_EQ(errorOf([&] { sensor.child("always_on").asPose(); }),
            at + "/<always_on>: expected 6 numbers 'x y z roll pitch yaw', got 'TRUE'");
  EXPECT_EQ(errorOf([&] { sensor.requiredChild("camera"); }), at + ": missing required element <camera>");
  // A default that contradicts what was given is an error too, and says it was the default.
  EXPECT_EQ(errorOf([&] { range.number("resolution", 0.0, positive()); }),
            at + "/<ray>/<range>/<resolution>: expected a number > 0, got nothing (the default is 0)");
}

TEST(SdfElement, NumbersAreStrictAndIgnoreTheCLocale) {
  const SdfElement e = SdfElement::parse(
      "<x><a>1.5</a><b>1,5</b><c>nan</c><d>inf</d><e>+2e-3</e><f>3 4</f><g>0x10</g></x>", "s");
  // A locale with a decimal comma must not change what "1.5" means (strtod would read 1).
  const char* old = std::setlocale(LC_NUMERIC, "de_DE.UTF-8");
  EXPECT_EQ(e.number("a", 0), 1.5);
  EXPECT_EQ(e.number("e", 0), 0.002);
  for (const char* bad : {"b", "c", "d", "f", "g"}) EXPECT_NE(errorOf([&] { e.number(bad, 0); }), "") << bad;
  if (old) std::setlocale(LC_NUMERIC, "C");
}

TEST(SdfElement, MalformedXmlNamesTheSourceAndLine) {
  EXPECT_EQ(errorOf([] { SdfElement::parse("<a>\n<b></a>", "bad.sdf"); }).rfind("bad.sdf: malformed XML at line ", 0),
            0u);
  EXPECT_EQ(errorOf([] { SdfElement::parse("   ", "empty.sdf"); }).rfind("empty.sdf: ", 0), 0u);
}

TEST(SdfElement, PosesInDegreesAndUnsupportedFramesAreSaid) {
  const SdfElement e = SdfElement::parse(
      "<sdf><model name='m'><pose degrees='true'>0 0 0 0 0 90</pose><link name='l'>"
      "<pose relative_to='other'>0 0 0 0 0 0</pose></link></model></sdf>", "w.sdf");
  const Eigen::Isometry3d p = e.child("model").pose();
  EXPECT_NEAR((p.linear() * Eigen::Vector3d::UnitX()).y(), 1.0, 1e-12);
  EXPECT_EQ(errorOf([&] { e.child("model").child("link").pose(); }),
            "w.sdf: <model name='m'>/<link name='l'>/<pose>: relative_to='other' is not supported; poses are relative "
            "to the parent element");
}

}  // namespace
}  // namespace bullet_sim
