// ros_params::Reader on a real parameter server (reader.test sets the parameters).
#include <gtest/gtest.h>
#include <ros/ros.h>

#include <algorithm>

#include "ros_params/reader.h"

namespace {

ros::NodeHandle privateNh() { return ros::NodeHandle("~"); }

TEST(Reader, ReadsEachTypeAndKeepsTheDefaultOfWhatIsNotSet) {
  ros_params::Reader params(privateNh());
  double rate = 0, period = 0, absent = 1.5;
  int size = 0;
  bool enabled = false;
  std::string frame;
  std::vector<double> gains;
  std::vector<std::string> joints;
  EXPECT_TRUE(params.read("rate", &rate));
  EXPECT_DOUBLE_EQ(rate, 40.0);
  EXPECT_TRUE(params.read("period", &period));
  EXPECT_DOUBLE_EQ(period, 0.25);
  EXPECT_TRUE(params.read("size", &size));
  EXPECT_EQ(size, 200);
  EXPECT_TRUE(params.read("enabled", &enabled));
  EXPECT_TRUE(enabled);
  EXPECT_TRUE(params.read("frame", &frame));
  EXPECT_EQ(frame, "/map");
  EXPECT_TRUE(params.read("gains", &gains));
  EXPECT_EQ(gains, (std::vector<double>{1.0, 2.5, 3.0}));
  EXPECT_TRUE(params.read("joints", &joints));
  EXPECT_EQ(joints, (std::vector<std::string>{"joint1", "joint2"}));
  EXPECT_FALSE(params.read("absent", &absent));
  EXPECT_DOUBLE_EQ(absent, 1.5);
  EXPECT_DOUBLE_EQ(params.get("period", 9.0), 0.25);
  EXPECT_DOUBLE_EQ(params.get("absent", 9.0), 9.0);
  EXPECT_EQ(params.get<std::string>("frame", "odom"), "/map");
  EXPECT_DOUBLE_EQ(params.getRenamed("absent", "period", 9.0), 0.25);
  EXPECT_TRUE(params.ok()) << params.problems();
}

TEST(Reader, AWrongTypeIsAProblemNamingThePathAndKeepsTheDefault) {
  ros_params::Reader params(privateNh());
  const std::string ns = privateNh().getNamespace();
  double nan_value = 1.0;
  int half = 3;
  bool wrong_bool = false;
  double frame_as_number = 2.0;
  std::vector<double> bad_gains{9.0};
  EXPECT_FALSE(params.read("not_a_number", &nan_value));
  EXPECT_FALSE(params.read("half", &half));
  EXPECT_FALSE(params.read("wrong_bool", &wrong_bool));
  EXPECT_FALSE(params.read("frame", &frame_as_number));
  EXPECT_FALSE(params.read("bad_gains", &bad_gains));
  EXPECT_EQ(params.get("wrong_bool", true), true);  // the fallback; the same problem is said once
  EXPECT_DOUBLE_EQ(nan_value, 1.0);
  EXPECT_EQ(half, 3);
  EXPECT_FALSE(wrong_bool);
  EXPECT_DOUBLE_EQ(frame_as_number, 2.0);
  EXPECT_EQ(bad_gains, std::vector<double>{9.0});
  EXPECT_FALSE(params.ok());
  EXPECT_EQ(params.problemList(), (std::vector<std::string>{
                                      ns + "/not_a_number: expected a number, got NaN",
                                      ns + "/half: expected an integer, got 2.5",
                                      ns + "/wrong_bool: expected true or false, got the string 'yes'",
                                      ns + "/frame: expected a number, got the string '/map'",
                                      ns + "/bad_gains: expected a list of numbers, got the string 'two' at [1]",
                                  }));
}

TEST(Reader, ARequiredParameterMissingIsAProblem) {
  ros_params::Reader params(privateNh());
  std::string joint = "kept";
  EXPECT_FALSE(params.require("joint", &joint, "the name of a joint"));
  EXPECT_EQ(joint, "kept");
  EXPECT_EQ(params.problems(),
            privateNh().getNamespace() + "/joint: required parameter missing; expected the name of a joint");
}

TEST(Reader, ProblemsSayWhatTheCallerExpectedAndCheckedValues) {
  ros_params::Reader params(privateNh());
  const std::string ns = privateNh().getNamespace();
  double gain = 4.0;
  std::string joint = "kept";
  EXPECT_FALSE(params.read("frame", &gain, "a number (the proportional gain)"));
  EXPECT_FALSE(params.require("rate", &joint, "the name of a joint"));  // set, of the wrong type
  EXPECT_TRUE(params.has("period"));
  EXPECT_FALSE(params.has("absent"));
  EXPECT_FALSE(params.fail("period", "is 0.25; expected at least 1"));
  EXPECT_EQ(params.problems(), ns + "/frame: expected a number (the proportional gain), got the string '/map'\n" +
                                   ns + "/rate: expected the name of a joint, got 40\n" +
                                   ns + "/period: is 0.25; expected at least 1");
  EXPECT_DOUBLE_EQ(gain, 4.0);
  EXPECT_EQ(joint, "kept");
}

TEST(Reader, ARenamedParameterIsReadUnderItsOldNameWithAWarning) {
  ros_params::Reader params(privateNh());
  double value = 0;
  EXPECT_TRUE(params.readRenamed("new_name", "old_name", &value));
  EXPECT_DOUBLE_EQ(value, 7.5);
  ASSERT_EQ(params.warnings().size(), 1u);
  EXPECT_EQ(params.warnings()[0],
            privateNh().getNamespace() + "/old_name has been renamed to new_name: its value is used (rename it)");
  double rate = 0;
  EXPECT_TRUE(params.readRenamed("rate", "old_name", &rate));  // the new name wins, no warning
  EXPECT_DOUBLE_EQ(rate, 40.0);
  EXPECT_EQ(params.warnings().size(), 1u);
}

TEST(Reader, UnknownParametersAreTheOnesNeverAskedForWithTheNearestName) {
  ros_params::Reader params(privateNh());
  const std::string ns = privateNh().getNamespace();
  double number = 0;
  XmlRpc::XmlRpcValue inflation;
  for (const char* name : {"rate", "period", "not_a_number", "size", "half", "enabled", "frame", "wrong_bool", "gains",
                           "bad_gains", "joints", "old_name", "controller_frequency"})
    params.read(name, &inflation);
  params.read("inflation", &inflation);  // a namespace read whole covers what is under it
  params.read("never_set", &number);
  EXPECT_EQ(params.unknown(), (std::vector<std::string>{ns + "/controler_frequncy (did you mean controller_frequency?)"}));
  EXPECT_EQ(params.unknown({"controler_frequncy"}), std::vector<std::string>{});  // read elsewhere
}

TEST(Reader, SearchFindsTheNearestUpTheNamespacesAsSearchParamDoes) {
  const std::string ns = privateNh().getNamespace();
  ros_params::Reader params(ros::NodeHandle("~inflation"));
  double radius = 0, scaling = 0, rate = 0, absent = 1.5;
  EXPECT_TRUE(params.search("cost_scaling_factor", &scaling));  // in its own namespace
  EXPECT_DOUBLE_EQ(scaling, 10.0);
  EXPECT_TRUE(params.search("rate", &rate));  // one level up
  EXPECT_DOUBLE_EQ(rate, 40.0);
  EXPECT_TRUE(params.search("robot_radius", &radius));  // at the root
  EXPECT_DOUBLE_EQ(radius, 0.3);
  EXPECT_EQ(params.searchPath("robot_radius"), "/robot_radius");
  EXPECT_FALSE(params.search("set_nowhere", &absent));
  EXPECT_DOUBLE_EQ(absent, 1.5);
  EXPECT_TRUE(params.ok());
  bool wrong = false;
  EXPECT_FALSE(params.search("frame", &wrong));  // found one level up, of the wrong type
  EXPECT_EQ(params.problems(), ns + "/frame: expected true or false, got the string '/map'");
  EXPECT_EQ(params.unknown(), std::vector<std::string>{ns + "/inflation/radius"});  // searched names count as read
}

}  // namespace

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "reader_check");
  ros::NodeHandle nh;
  return RUN_ALL_TESTS();
}
