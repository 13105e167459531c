// ros_params::Reader on a tree already fetched from the parameter server: no master needed.
#include <gtest/gtest.h>

#include "ros_params/reader.h"

namespace {

using XmlRpc::XmlRpcValue;

// yaml {gains: {p: 2, d: 0.5}, rate: "fast", limits: [1, 2], empty: {}}, as the master returns it.
XmlRpcValue tree() {
  XmlRpcValue t;
  t["gains"]["p"] = 2;
  t["gains"]["d"] = 0.5;
  t["rate"] = "fast";
  t["limits"].setSize(2);
  t["limits"][0] = 1.0;
  t["limits"][1] = 2.0;
  int offset = 0;
  t["empty"] = XmlRpcValue("<value><struct></struct></value>", &offset);
  return t;
}

TEST(TreeReader, ReadsNestedNamesAsTheServerWould) {
  ros_params::Reader params(tree(), "/controller");
  double p = 0, d = 0, i = 7;
  EXPECT_TRUE(params.read("gains/p", &p));
  EXPECT_TRUE(params.read("gains/d", &d));
  EXPECT_FALSE(params.read("gains/i", &i));
  EXPECT_EQ(std::make_tuple(p, d, i), std::make_tuple(2.0, 0.5, 7.0));
  EXPECT_TRUE(params.has("gains"));
  EXPECT_FALSE(params.has("absent/deeper"));
  EXPECT_TRUE(params.ok()) << params.problems();
}

TEST(TreeReader, WrongTypesAndLevelsThatAreNotDictionariesAreProblems) {
  ros_params::Reader params(tree(), "/controller");
  double rate = 20, linear = 1;
  EXPECT_FALSE(params.read("rate", &rate, "a rate in Hz"));
  EXPECT_FALSE(params.read("limits/linear", &linear));
  EXPECT_FALSE(params.read("limits/angular", &linear));  // the same problem, once
  EXPECT_EQ(std::make_pair(rate, linear), std::make_pair(20.0, 1.0));
  EXPECT_EQ(params.problems(), "/controller/rate: expected a rate in Hz, got the string 'fast'\n"
                               "/controller/limits: expected a dictionary, got a list of 2 items");
}

TEST(TreeReader, UnknownNamesAreTheTreesLeavesNeverAskedFor) {
  ros_params::Reader params(tree(), "/controller/");  // a trailing slash is one slash
  double value = 0;
  params.read("gains/p", &value);
  params.read("rate", &value);
  params.read("limit", &value);
  EXPECT_EQ(params.unknown(), (std::vector<std::string>{"/controller/empty", "/controller/gains/d (did you mean gains/p?)",
                                                        "/controller/limits (did you mean limit?)"}));
}

TEST(TreeReader, NothingSetIsAnEmptyTree) {
  ros_params::Reader params(XmlRpcValue(), "/controller");
  double value = 3;
  EXPECT_FALSE(params.read("gains/p", &value));
  EXPECT_EQ(value, 3.0);
  EXPECT_TRUE(params.ok());
  EXPECT_TRUE(params.unknown().empty());
}

}  // namespace
