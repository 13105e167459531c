// SDF world/model parsing against test/data (box_room.world, models/, packages/, bad/) and
// worlds/empty.world of the package.
#include <gtest/gtest.h>
#include <tinyxml2.h>

#include <cmath>
#include <cstdlib>
#include <functional>
#include <sstream>
#include <string>

#include "bullet_sim/description_error.h"
#include "bullet_sim/sdf_world_parser.h"

using namespace bullet_sim;

namespace {

const std::string kData = BULLET_SIM_TEST_DATA_DIR;
constexpr double kHalfPi = 1.5707963267948966;

ResourceResolver testResolver() {
  setenv("ROS_PACKAGE_PATH", (kData + "/packages").c_str(), 1);
  setenv("GAZEBO_MODEL_PATH", (kData + "/models").c_str(), 1);
  return ResourceResolver::fromEnvironment();
}

const PlacedModel& model(const WorldDescription& w, const std::string& name) {
  for (const auto& m : w.models)
    if (m.model.name == name) return m;
  throw std::runtime_error("no model " + name);
}

std::string errorOf(const std::function<void()>& f) {
  try {
    f();
  } catch (const DescriptionError& e) {
    return e.what();
  }
  return "(no DescriptionError thrown)";
}

// Expects every part in the message.
void expectMentions(const std::string& msg, std::initializer_list<std::string> parts) {
  for (const auto& p : parts) EXPECT_NE(msg.find(p), std::string::npos) << "'" << p << "' not in: " << msg;
}

// R = Rz(yaw) * Ry(pitch) * Rx(roll), written out element by element (independent of Eigen's AngleAxis).
Eigen::Matrix3d rpyMatrix(double r, double p, double y) {
  const double cr = std::cos(r), sr = std::sin(r), cp = std::cos(p), sp = std::sin(p), cy = std::cos(y),
               sy = std::sin(y);
  Eigen::Matrix3d m;
  m << cy * cp, cy * sp * sr - sy * cr, cy * sp * cr + sy * sr,  //
      sy * cp, sy * sp * sr + cy * cr, sy * sp * cr - cy * sr,   //
      -sp, cp * sr, cp * cr;
  return m;
}

void expectPose(const Eigen::Isometry3d& t, Eigen::Vector3d xyz, double r, double p, double y) {
  EXPECT_TRUE(t.translation().isApprox(xyz, 1e-9) || (t.translation() - xyz).norm() < 1e-9)
      << t.translation().transpose() << " != " << xyz.transpose();
  EXPECT_TRUE(t.linear().isApprox(rpyMatrix(r, p, y), 1e-9)) << t.linear() << "\n!=\n" << rpyMatrix(r, p, y);
}

WorldDescription boxRoom() { return parseWorldFile(kData + "/box_room.world", testResolver()); }

std::string badWorldError(const std::string& file) {
  return errorOf([&] { parseWorldFile(kData + "/bad/" + file, testResolver()); });
}

std::string worldWith(const std::string& body) {
  return "<sdf version='1.6'><world name='w'>" + body + "</world></sdf>";
}

}  // namespace

TEST(SdfWorldParser, ReadsPhysicsAndGravity) {
  const WorldDescription w = boxRoom();
  EXPECT_EQ(w.name, "box_room");
  EXPECT_EQ(w.source, kData + "/box_room.world");
  // The <physics default="true"> profile, not the first one.
  EXPECT_DOUBLE_EQ(w.physics.max_step_size, 0.002);
  EXPECT_DOUBLE_EQ(w.physics.real_time_factor, 0.5);
  EXPECT_DOUBLE_EQ(w.physics.real_time_update_rate, 250);
  EXPECT_TRUE(w.physics.gravity.isApprox(Eigen::Vector3d(0.1, 0, -9.81)));  // world-level wins
}

TEST(SdfWorldParser, GravityInsidePhysicsAndDefaults) {
  const ResourceResolver r;
  WorldDescription w = parseWorldString(worldWith("<physics type='bullet'><gravity>0 0 -3</gravity></physics>"),
                                        "mem.world", "", r);
  EXPECT_TRUE(w.physics.gravity.isApprox(Eigen::Vector3d(0, 0, -3)));
  EXPECT_DOUBLE_EQ(w.physics.max_step_size, 0.001);  // defaults kept
  EXPECT_EQ(w.name, "w");
  w = parseWorldString("<sdf version='1.6'><world/></sdf>", "mem.world", "", r);
  EXPECT_EQ(w.name, "default");
  EXPECT_TRUE(w.physics.gravity.isApprox(Eigen::Vector3d(0, 0, -9.8)));
  EXPECT_TRUE(w.models.empty());
}

TEST(SdfWorldParser, EmptyWorldUsesBuiltInModels) {
  const ResourceResolver nothing;  // ground_plane and sun need no file on disk
  const WorldDescription w = parseWorldFile(kData + "/../../worlds/empty.world", nothing);
  EXPECT_EQ(w.name, "default");
  EXPECT_DOUBLE_EQ(w.physics.max_step_size, 0.001);
  EXPECT_DOUBLE_EQ(w.physics.real_time_factor, 1);
  EXPECT_DOUBLE_EQ(w.physics.real_time_update_rate, 1000);
  ASSERT_EQ(w.models.size(), 1u);  // the sun is a light, not a model

  const ModelDescription& g = w.models[0].model;
  EXPECT_EQ(g.name, "ground_plane");
  EXPECT_TRUE(g.is_static);
  EXPECT_EQ(g.root_link, "link");
  ASSERT_EQ(g.links.size(), 1u);
  const LinkDescription& l = g.links[0];
  EXPECT_EQ(l.name, "link");
  ASSERT_EQ(l.collisions.size(), 1u);
  EXPECT_EQ(l.collisions[0].geometry.type, GeometryType::Plane);
  EXPECT_TRUE(l.collisions[0].geometry.plane_normal.isApprox(Eigen::Vector3d::UnitZ()));
  EXPECT_TRUE(l.collisions[0].geometry.plane_size.isApprox(Eigen::Vector2d(100, 100)));
  ASSERT_EQ(l.visuals.size(), 1u);
  EXPECT_EQ(l.visuals[0].geometry.type, GeometryType::Plane);
  EXPECT_FLOAT_EQ(l.visuals[0].rgba[0], 0.7f);
  EXPECT_FLOAT_EQ(l.visuals[0].rgba[1], 0.7f);
  EXPECT_TRUE(w.models[0].pose.isApprox(Eigen::Isometry3d::Identity()));
}

TEST(SdfWorldParser, ModelsOfBoxRoom) {
  const WorldDescription w = boxRoom();
  std::vector<std::string> names;
  for (const auto& m : w.models) names.push_back(m.model.name);
  EXPECT_EQ(names, (std::vector<std::string>{"ground_plane", "box_a", "box_b", "pkg_cone", "walls", "ball"}));
}

TEST(SdfWorldParser, IncludeFromGazeboModelPath) {
  const WorldDescription w = boxRoom();
  const PlacedModel& a = model(w, "box_a");
  EXPECT_EQ(a.model.source, kData + "/models/test_box/model.sdf");  // chosen by model.config (version 1.6)
  EXPECT_FALSE(a.model.is_static);
  EXPECT_FALSE(a.model.fixed_base);
  EXPECT_TRUE(a.model.joints.empty());
  expectPose(a.pose, {1, 2, 0}, 0, 0, 0);                           // the include's pose replaces the model's
  expectPose(model(w, "box_b").pose, {0, 0, 0.25}, 0, 0, 0);         // no include pose: the model's own
}

TEST(SdfWorldParser, MovingSingleLinkModelIsExpressedInTheModelFrame) {
  const WorldDescription w = boxRoom();  // kept alive: the reference points into it
  const ModelDescription& m = model(w, "box_a").model;
  EXPECT_EQ(m.root_link, "body");
  ASSERT_EQ(m.links.size(), 1u);
  const LinkDescription& l = m.links[0];
  EXPECT_EQ(l.name, "body");

  // Link pose (0 0 0.5, yaw 90 deg) composed with the collision's (1 0 0).
  ASSERT_EQ(l.collisions.size(), 1u);
  EXPECT_EQ(l.collisions[0].name, "collision");
  expectPose(l.collisions[0].origin, {0, 1, 0.5}, 0, 0, kHalfPi);
  EXPECT_TRUE(l.collisions[0].geometry.box_size.isApprox(Eigen::Vector3d(0.5, 0.4, 0.3)));

  EXPECT_DOUBLE_EQ(l.inertial.mass, 2.0);
  expectPose(l.inertial.origin, {0, 0.1, 0.5}, 0, 0, kHalfPi);
  Eigen::Matrix3d inertia;
  inertia << 0.1, 0.01, 0.02, 0.01, 0.2, 0.03, 0.02, 0.03, 0.3;
  EXPECT_TRUE(l.inertial.inertia.isApprox(inertia));

  EXPECT_DOUBLE_EQ(l.mu1, 0.6);
  EXPECT_DOUBLE_EQ(l.mu2, 0.4);

  ASSERT_EQ(l.visuals.size(), 1u);
  const VisualShape& v = l.visuals[0];
  expectPose(v.origin, {0, 0, 0.5}, 0, 0, kHalfPi);
  EXPECT_EQ(v.geometry.type, GeometryType::Mesh);
  EXPECT_EQ(v.geometry.mesh_file, kData + "/models/test_box/meshes/box.stl");  // relative to the model dir
  EXPECT_TRUE(v.geometry.mesh_scale.isApprox(Eigen::Vector3d(2, 2, 2)));
  EXPECT_EQ(v.rgba, (std::array<float, 4>{{1, 0, 0, 1}}));  // Gazebo/Red
}

TEST(SdfWorldParser, SensorsAndPluginsAreKeptAsExtensions) {
  const WorldDescription w = boxRoom();  // kept alive: the reference points into it
  const ModelDescription& m = model(w, "box_a").model;
  ASSERT_EQ(m.extensions.size(), 2u);
  const GazeboExtension& sensor = m.extensions[0];
  EXPECT_EQ(sensor.reference, "body");
  tinyxml2::XMLDocument doc;
  ASSERT_EQ(doc.Parse(sensor.xml.c_str()), tinyxml2::XML_SUCCESS) << sensor.xml;
  const tinyxml2::XMLElement* s = doc.RootElement();
  EXPECT_STREQ(s->Name(), "sensor");
  EXPECT_STREQ(s->Attribute("type"), "imu");
  EXPECT_STREQ(s->FirstChildElement("update_rate")->GetText(), "100");
  // The sensor pose (0 0 0.1 in the link) re-expressed in the model frame.
  std::istringstream pose(s->FirstChildElement("pose")->GetText());
  double x, y, z, roll, pitch, yaw;
  pose >> x >> y >> z >> roll >> pitch >> yaw;
  expectPose(Eigen::Isometry3d(Eigen::Translation3d(x, y, z)) * Eigen::Isometry3d(rpyMatrix(roll, pitch, yaw)),
             {0, 0, 0.6}, 0, 0, kHalfPi);

  const GazeboExtension& plugin = m.extensions[1];
  EXPECT_EQ(plugin.reference, "");
  expectMentions(plugin.xml, {"<plugin name=\"mover\" filename=\"libmover.so\">", "<speed>1</speed>"});
}

TEST(SdfWorldParser, IncludeFromPackageModelsFolder) {
  const WorldDescription w = boxRoom();  // kept alive: the reference points into it
  const PlacedModel& cone = model(w, "pkg_cone");
  EXPECT_TRUE(cone.model.is_static);
  const LinkDescription& l = cone.model.links.at(0);
  ASSERT_EQ(l.collisions.size(), 1u);
  EXPECT_EQ(l.collisions[0].geometry.type, GeometryType::Cylinder);
  EXPECT_DOUBLE_EQ(l.collisions[0].geometry.radius, 0.2);
  EXPECT_DOUBLE_EQ(l.collisions[0].geometry.length, 0.6);
  ASSERT_EQ(l.visuals.size(), 1u);
  EXPECT_NE(l.visuals[0].geometry.mesh_file.find("/sim_assets/meshes/part.stl"), std::string::npos);
  EXPECT_EQ(l.visuals[0].rgba, (std::array<float, 4>{{0, 1, 0, 0.5f}}));  // diffuse wins over ambient
}

TEST(SdfWorldParser, StaticMultiLinkModelBecomesOneLink) {
  const WorldDescription w = boxRoom();  // kept alive: the reference points into it
  const PlacedModel& walls = model(w, "walls");
  EXPECT_TRUE(walls.model.is_static);
  expectPose(walls.pose, {0, 0, 0}, 0, 0, 0.5);
  EXPECT_EQ(walls.model.root_link, "north");
  ASSERT_EQ(walls.model.links.size(), 1u);
  const LinkDescription& l = walls.model.links[0];
  EXPECT_EQ(l.name, "north");
  ASSERT_EQ(l.collisions.size(), 3u);
  expectPose(l.collisions[0].origin, {0, 5, 1}, 0, 0, 0);
  expectPose(l.collisions[1].origin, {0, -4, 1}, 0, 0, kHalfPi);  // south pose * (1 0 0)
  expectPose(l.collisions[2].origin, {0, -5, 1}, 0, 0, kHalfPi);
  EXPECT_TRUE(l.collisions[2].geometry.plane_normal.isApprox(Eigen::Vector3d::UnitZ()));  // normalised
  EXPECT_TRUE(l.collisions[2].geometry.plane_size.isApprox(Eigen::Vector2d(3, 4)));
  ASSERT_EQ(l.visuals.size(), 1u);
  EXPECT_EQ(l.visuals[0].rgba, (std::array<float, 4>{{0.2f, 0.3f, 0.4f, 1}}));  // diffuse over the script
}

TEST(SdfWorldParser, WorldLevelMovingModelKeepsItsPose) {
  const WorldDescription w = boxRoom();  // kept alive: the reference points into it
  const PlacedModel& ball = model(w, "ball");
  EXPECT_FALSE(ball.model.is_static);
  EXPECT_EQ(ball.model.source, kData + "/box_room.world");
  expectPose(ball.pose, {3, 0, 1}, 0, 0, 0);
  const LinkDescription& l = ball.model.links.at(0);
  EXPECT_DOUBLE_EQ(l.inertial.mass, 0.5);
  EXPECT_TRUE(l.inertial.inertia.isApprox(Eigen::Matrix3d::Identity()));  // SDF default
  EXPECT_DOUBLE_EQ(l.mu1, 0.3);
  EXPECT_DOUBLE_EQ(l.mu2, 1.0);
  EXPECT_EQ(l.collisions.at(0).geometry.type, GeometryType::Sphere);
  EXPECT_DOUBLE_EQ(l.collisions.at(0).geometry.radius, 0.1);
}

TEST(SdfWorldParser, PoseUsesFixedAxisRollPitchYaw) {
  const ResourceResolver r;
  auto collisionOrigin = [&](const std::string& link_pose, const std::string& pose) {
    const ModelDescription m = parseSdfModel(
        "<model name='m'><link name='l'><pose>" + link_pose + "</pose><collision name='c'><pose>" + pose +
            "</pose><geometry><sphere><radius>1</radius></sphere></geometry></collision></link></model>",
        "mem", "", r);
    return m.links.at(0).collisions.at(0).origin;
  };
  // roll 90 then yaw 90 about the fixed axes: x -> y, y -> z.
  const Eigen::Isometry3d t = collisionOrigin("0 0 0 0 0 0", "0 0 0 1.5707963267948966 0 1.5707963267948966");
  EXPECT_TRUE((t.linear() * Eigen::Vector3d::UnitX()).isApprox(Eigen::Vector3d::UnitY()));
  EXPECT_TRUE((t.linear() * Eigen::Vector3d::UnitY()).isApprox(Eigen::Vector3d::UnitZ()));
  // General angles, and composition link * shape.
  const Eigen::Isometry3d u = collisionOrigin("1 2 3 0.3 -0.4 0.7", "0.5 -0.2 0.1 -1.1 0.2 2.5");
  const Eigen::Matrix3d rl = rpyMatrix(0.3, -0.4, 0.7), rs = rpyMatrix(-1.1, 0.2, 2.5);
  EXPECT_TRUE(u.linear().isApprox(rl * rs, 1e-12));
  EXPECT_TRUE(u.translation().isApprox(Eigen::Vector3d(1, 2, 3) + rl * Eigen::Vector3d(0.5, -0.2, 0.1), 1e-12));
}

TEST(SdfWorldParser, ParseSdfModelForms) {
  const ResourceResolver r;
  Eigen::Isometry3d pose;
  const std::string link = "<link name='l'><collision name='c'><geometry><box><size>1 1 1</size></box>"
                           "</geometry></collision></link>";
  ModelDescription m = parseSdfModel("<sdf version='1.6'><model name='a'><pose>1 0 0 0 0 0</pose>" + link +
                                         "</model></sdf>",
                                     "spawn request", "", r, &pose);
  EXPECT_EQ(m.name, "a");
  EXPECT_EQ(m.source, "spawn request");
  expectPose(pose, {1, 0, 0}, 0, 0, 0);
  m = parseSdfModel("<model name='b'>" + link + "</model>", "spawn request", "", r, &pose);
  EXPECT_EQ(m.name, "b");
  expectPose(pose, {0, 0, 0}, 0, 0, 0);

  expectMentions(errorOf([&] { parseSdfModel(worldWith(""), "spawn request", "", r); }),
                 {"spawn request", "<world name='w'>", "expected a <model>"});
  expectMentions(errorOf([&] { parseSdfModel("<robot name='r'/>", "spawn request", "", r); }),
                 {"spawn request", "<robot name='r'>", "expected <sdf> or <model>"});
}

// ---- errors: each names the file, the element and what was expected ----

TEST(SdfWorldParserErrors, MalformedXml) {
  // tinyxml2 reports the line of the element left open (<link>), not of the wrong end tag.
  expectMentions(badWorldError("malformed.world"), {kData + "/bad/malformed.world", "line 5", "malformed XML"});
  expectMentions(errorOf([&] { parseWorldFile(kData + "/bad/no_such.world", ResourceResolver()); }),
                 {"no_such.world"});
}

TEST(SdfWorldParserErrors, UnknownGeometry) {
  expectMentions(badWorldError("unknown_geometry.world"),
                 {"unknown_geometry.world: <world name='default'>/<model name='box'>/<link name='l'>/"
                  "<collision name='c'>/<geometry>: expected one of box, cylinder, sphere, plane, mesh",
                  "<cone>"});
}

TEST(SdfWorldParserErrors, MissingSize) {
  expectMentions(badWorldError("missing_size.world"),
                 {"missing_size.world: ", "<model name='box'>", "<geometry>/<box>: missing required element <size>"});
}

TEST(SdfWorldParserErrors, NaN) {
  expectMentions(badWorldError("nan.world"),
                 {"nan.world: ", "<model name='ball'>", "<sphere>/<radius>: expected a finite number, found 'nan'"});
}

TEST(SdfWorldParserErrors, NegativeRadius) {
  expectMentions(badWorldError("negative_radius.world"),
                 {"negative_radius.world: ", "<visual name='v'>/<geometry>/<cylinder>/<radius>",
                  "expected a non-negative value, found '-0.5'"});
}

TEST(SdfWorldParserErrors, UnknownModel) {
  expectMentions(badWorldError("unknown_model.world"),
                 {"unknown_model.world: <world name='default'>/<include>/<uri>: ",
                  "model://no_such_model: not found; searched: ", kData + "/models"});
}

TEST(SdfWorldParserErrors, MissingMesh) {
  expectMentions(badWorldError("missing_mesh.world"),
                 {"missing_mesh.world: ", "<model name='statue'>/<link name='body'>", "<mesh>/<uri>",
                  "mesh of link 'body' not found", "meshes/nope.stl"});
}

TEST(SdfWorldParserErrors, MultiLinkMovingModel) {
  expectMentions(badWorldError("multi_link_moving.world"),
                 {"multi_link_moving.world: <world name='default'>/<model name='cart'>: ",
                  "SDF models with more than one link or with <joint> are not supported for moving models; "
                  "describe it in URDF"});
}

TEST(SdfWorldParserErrors, MoreCases) {
  const ResourceResolver r = testResolver();
  auto worldError = [&](const std::string& body) {
    return errorOf([&] { parseWorldString(worldWith(body), "mem.world", kData, r); });
  };
  const std::string link_start = "<link name='l'><collision name='c'><geometry>";
  const std::string link_end = "</geometry></collision></link>";

  expectMentions(worldError("<model name='m'><static>1</static>" + link_start + "<box><size>1 inf 1</size></box>" +
                            link_end + "</model>"),
                 {"mem.world: ", "<box>/<size>: expected 3 finite numbers, found '1 inf 1'"});
  expectMentions(worldError("<model name='m'><static>1</static>" + link_start + "<box><size>1 2</size></box>" +
                            link_end + "</model>"),
                 {"<box>/<size>: expected 3 finite numbers, found '1 2'"});
  expectMentions(worldError("<model name='m'><static>1</static>" + link_start +
                            "<sphere><radius>1</radius><colour>red</colour></sphere>" + link_end + "</model>"),
                 {"<sphere>/<colour>: unexpected element in <sphere>; expected <radius>"});
  expectMentions(worldError("<model name='m'><static>yes</static>" + link_start +
                            "<sphere><radius>1</radius></sphere>" + link_end + "</model>"),
                 {"<model name='m'>/<static>: expected true, false, 1 or 0, found 'yes'"});
  expectMentions(worldError("<model name='m'>" + link_start + "<sphere><radius>1</radius></sphere>" + link_end +
                            "<joint name='j' type='fixed'/></model>"),
                 {"<model name='m'>: SDF models with more than one link or with <joint>"});
  expectMentions(worldError("<model name='m'><link name='l'><inertial><mass>-1</mass></inertial></link></model>"),
                 {"<inertial>/<mass>: expected a non-negative value, found '-1'"});
  expectMentions(worldError("<model name='m'><pose>1 2 3</pose>" + link_start +
                            "<sphere><radius>1</radius></sphere>" + link_end + "</model>"),
                 {"<model name='m'>/<pose>: expected 6 finite numbers, found '1 2 3'"});
  expectMentions(worldError("<physics><max_step_size>0</max_step_size></physics>"),
                 {"<physics>/<max_step_size>: expected a positive value"});
  expectMentions(worldError("<include><uri>model://test_box</uri></include><include><uri>model://test_box</uri></include>"),
                 {"a model named 'test_box' is already in the world"});
  expectMentions(worldError("<include><name>x</name></include>"), {"<include>: missing required element <uri>"});
}

TEST(SdfWorldParserErrors, IncludedModelErrorsNameBothFiles) {
  const ResourceResolver r = testResolver();
  // Making the two-link moving model static through the include is fine...
  EXPECT_NO_THROW(parseWorldString(worldWith("<include><uri>file://" + kData + "/models/test_box</uri>"
                                             "<static>true</static></include>"),
                                   "mem.world", "", r));
  // ...but an error inside an included file names the world, the include and the model file.
  const std::string msg = errorOf([&] {
    parseWorldString(worldWith("<include><uri>model://test_box</uri><static>false</static></include>"
                               "<include><uri>bad/nan.world</uri></include>"),
                     "mem.world", kData, r);
  });
  expectMentions(msg, {"mem.world: <world name='w'>/<include>: in bad/nan.world: ", kData + "/bad/nan.world: ",
                       "expected a <model>, found a <world>"});
}
