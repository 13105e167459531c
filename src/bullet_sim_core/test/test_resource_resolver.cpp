// ResourceResolver against the folders of test/data: models/ (a GAZEBO_MODEL_PATH entry)
// and packages/ (a ROS_PACKAGE_PATH entry holding sim_assets_pkg, inner_pkg, ignored_pkg).
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <string>

#include "bullet_sim_core/description_error.h"
#include "bullet_sim_core/resource_resolver.h"
#include "bullet_sim_core/testing/error_of.h"

using bullet_sim::errorOf;
using bullet_sim::ResourceResolver;

namespace {

const std::string kData = BULLET_SIM_TEST_DATA_DIR;

ResourceResolver testResolver() {
  // Empty entries ("::") must be skipped. A home without ~/.gazebo/models (the simulator makes one in
  // the real home, which would join the model path).
  setenv("HOME", (kData + "/packages").c_str(), 1);
  setenv("ROS_PACKAGE_PATH", (kData + "/packages::" + kData + "/no_such_folder").c_str(), 1);
  setenv("GAZEBO_MODEL_PATH", (kData + "/models:").c_str(), 1);
  return ResourceResolver::fromEnvironment();
}

std::string canonical(const std::string& p) { return std::filesystem::canonical(p).string(); }

}  // namespace

TEST(ResourceResolver, ReadsPathsFromEnvironment) {
  const ResourceResolver r = testResolver();
  ASSERT_EQ(r.package_path.size(), 2u);
  EXPECT_EQ(r.package_path[0], kData + "/packages");
  // GAZEBO_MODEL_PATH first, then the models/ folder of each package.
  ASSERT_EQ(r.model_path.size(), 2u);
  EXPECT_EQ(r.model_path[0], kData + "/models");
  EXPECT_EQ(canonical(r.model_path[1]), canonical(kData + "/packages/sim_assets/models"));
}

TEST(ResourceResolver, FindsPackagesByManifestName) {
  const ResourceResolver r = testResolver();
  EXPECT_EQ(canonical(r.findPackage("sim_assets_pkg")), canonical(kData + "/packages/sim_assets"));
  EXPECT_EQ(canonical(r.findPackage("inner_pkg")), canonical(kData + "/packages/nested/inner_pkg"));
  EXPECT_EQ(r.findPackage("sim_assets"), "");   // the folder name is not the package name
  EXPECT_EQ(r.findPackage("ignored_pkg"), "");  // CATKIN_IGNORE
  EXPECT_EQ(r.findPackage("no_such_pkg"), "");
}

TEST(ResourceResolver, ResolvesPackageUris) {
  const ResourceResolver r = testResolver();
  EXPECT_EQ(r.resolve("package://sim_assets_pkg/meshes/part.stl"),
            canonical(kData + "/packages/sim_assets/meshes/part.stl"));

  std::string msg = errorOf([&] { r.resolve("package://no_such_pkg/a.stl"); });
  EXPECT_NE(msg.find("package://no_such_pkg/a.stl"), std::string::npos) << msg;
  EXPECT_NE(msg.find(kData + "/packages"), std::string::npos) << msg;

  msg = errorOf([&] { r.resolve("package://sim_assets_pkg/meshes/nope.stl"); });
  EXPECT_NE(msg.find("package://sim_assets_pkg/meshes/nope.stl"), std::string::npos) << msg;
  EXPECT_NE(msg.find("nope.stl"), std::string::npos) << msg;
}

TEST(ResourceResolver, FindsModels) {
  const ResourceResolver r = testResolver();
  EXPECT_EQ(r.findModelDir("test_box"), kData + "/models/test_box");
  EXPECT_EQ(canonical(r.findModelDir("pkg_cone")), canonical(kData + "/packages/sim_assets/models/pkg_cone"));
  EXPECT_EQ(r.resolve("model://test_box/meshes/box.stl"), kData + "/models/test_box/meshes/box.stl");

  std::string msg = errorOf([&] { r.findModelDir("no_such_model"); });
  EXPECT_NE(msg.find("model://no_such_model: not found; searched: "), std::string::npos) << msg;
  EXPECT_NE(msg.find(kData + "/models"), std::string::npos) << msg;
  EXPECT_NE(msg.find("sim_assets/models"), std::string::npos) << msg;

  msg = errorOf([&] { r.resolve("model://test_box/meshes/nope.stl"); });
  EXPECT_NE(msg.find("model://test_box/meshes/nope.stl"), std::string::npos) << msg;
  EXPECT_NE(msg.find(kData + "/models"), std::string::npos) << msg;
}

TEST(ResourceResolver, ResolvesFilesAndPaths) {
  const ResourceResolver r = testResolver();
  const std::string stl = kData + "/models/test_box/meshes/box.stl";
  EXPECT_EQ(r.resolve("file://" + stl), stl);
  EXPECT_EQ(r.resolve(stl), stl);
  EXPECT_EQ(r.resolve("meshes/box.stl", kData + "/models/test_box"), stl);
  EXPECT_EQ(r.resolve("../test_box/./meshes/box.stl", kData + "/models/test_box"), stl);

  std::string msg = errorOf([&] { r.resolve("meshes/nope.stl", kData); });
  EXPECT_NE(msg.find("meshes/nope.stl"), std::string::npos) << msg;
  EXPECT_NE(msg.find("relative to " + kData), std::string::npos) << msg;

  msg = errorOf([&] { r.resolve("http://example.com/a.stl"); });
  EXPECT_NE(msg.find("unsupported URI scheme"), std::string::npos) << msg;
}

TEST(ResourceResolver, HandBuiltResolverSearchesOnlyItsFolders) {
  ResourceResolver r;  // no environment at all
  r.model_path = {kData + "/models"};
  EXPECT_EQ(r.findModelDir("test_box"), kData + "/models/test_box");
  EXPECT_EQ(r.findPackage("sim_assets_pkg"), "");
  EXPECT_NE(errorOf([&] { r.findModelDir("pkg_cone"); }), "");
}
