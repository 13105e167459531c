// SDF world/model parsing against test/data (box_room.world, models/, packages/, bad/) and
// worlds/empty.world of the package.
#include <gtest/gtest.h>
#include <tinyxml2.h>

#include <cmath>
#include <cstdlib>
#include <functional>
#include <sstream>
#include <string>

#include "bullet_sim_core/description_error.h"
#include "bullet_sim_core/sdf_parser.h"
#include "bullet_sim_core/testing/error_of.h"

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

TEST(SdfWorldParser, SolverItersComeFromTheEngineInUse) {
  const ResourceResolver r;
  auto iters = [&](const std::string& physics) {
    return parseWorldString(worldWith(physics), "mem.world", "", r).physics.solver_iterations;
  };
  EXPECT_EQ(iters(""), 50);  // SDF's default, and PyBullet's
  EXPECT_EQ(iters("<physics type='ode'><ode><solver><iters>20</iters></solver></ode></physics>"), 20);
  EXPECT_EQ(iters("<physics><ode><solver><iters>30</iters></solver></ode></physics>"), 30);  // ode by default
  EXPECT_EQ(iters("<physics type='bullet'><bullet><solver><iters>70</iters></solver></bullet>"
                  "<ode><solver><iters>20</iters></solver></ode></physics>"),
            70);
  EXPECT_EQ(iters("<physics type='ode'><bullet><solver><iters>70</iters></solver></bullet></physics>"), 50);
}

// How contacts push out of an overlap: per collision from <surface><contact><ode>, for the world
// from the engine's <constraints>, with SDF's defaults.
TEST(SdfWorldParser, ContactCorrectionFromSurfacesAndPhysics) {
  const ResourceResolver r;
  const WorldDescription w = parseWorldString(
      worldWith("<physics><ode><constraints><contact_max_correcting_vel>5</contact_max_correcting_vel>"
                "<contact_surface_layer>0.002</contact_surface_layer></constraints></ode></physics>"
                "<model name='m'><link name='l'>"
                "<collision name='a'><geometry><sphere><radius>1</radius></sphere></geometry><surface><contact><ode>"
                "<max_vel>0.1</max_vel><min_depth>0.003</min_depth></ode></contact></surface></collision>"
                "<collision name='b'><geometry><sphere><radius>1</radius></sphere></geometry></collision>"
                "<collision name='c'><geometry><sphere><radius>1</radius></sphere></geometry><surface><contact><ode>"
                "<max_vel>-1</max_vel></ode></contact></surface></collision></link></model>"),
      "mem.world", "", r);
  EXPECT_DOUBLE_EQ(w.physics.contact_max_correcting_vel, 5);
  EXPECT_DOUBLE_EQ(w.physics.contact_surface_layer, 0.002);
  const std::vector<CollisionShape>& c = model(w, "m").model.links.at(0).collisions;
  ASSERT_EQ(c.size(), 3u);
  EXPECT_DOUBLE_EQ(c[0].surface.max_vel, 0.1);
  EXPECT_DOUBLE_EQ(c[0].surface.min_depth, 0.003);
  EXPECT_DOUBLE_EQ(c[1].surface.max_vel, 0.01);  // SDF's defaults
  EXPECT_DOUBLE_EQ(c[1].surface.min_depth, 0.0);
  EXPECT_DOUBLE_EQ(c[2].surface.max_vel, -1);  // Gazebo's "only the world's limit"

  const auto physics = [&](const std::string& p) { return parseWorldString(worldWith(p), "mem.world", "", r).physics; };
  EXPECT_DOUBLE_EQ(physics("").contact_max_correcting_vel, 100);  // SDF's defaults
  EXPECT_DOUBLE_EQ(physics("").contact_surface_layer, 0.001);
  // From the engine in use: Bullet's block has a surface layer and no correcting velocity.
  const PhysicsSettings bullet = physics(
      "<physics type='bullet'><bullet><constraints><contact_surface_layer>0.004</contact_surface_layer>"
      "</constraints></bullet><ode><constraints><contact_surface_layer>0.5</contact_surface_layer>"
      "<contact_max_correcting_vel>3</contact_max_correcting_vel></constraints></ode></physics>");
  EXPECT_DOUBLE_EQ(bullet.contact_surface_layer, 0.004);
  EXPECT_DOUBLE_EQ(bullet.contact_max_correcting_vel, 100);
}

TEST(SdfWorldParser, EmptyWorldUsesBuiltInModels) {
  const ResourceResolver nothing;  // ground_plane and sun need no file on disk
  const WorldDescription w = parseWorldFile(kData + "/../../../bullet_sim/worlds/empty.world", nothing);
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

TEST(SdfWorldParser, WorldPluginsAreSaidUnlessBuiltIn) {
  // box_room.world's libgazebo_ros_state.so is part of the node's /gazebo API.
  EXPECT_TRUE(boxRoom().warnings.empty());
  const WorldDescription w =
      parseWorldString(worldWith("<plugin name='wind' filename='libWindPlugin.so'/>"), "mem.world", "", ResourceResolver());
  ASSERT_EQ(w.warnings.size(), 1u);
  EXPECT_EQ(w.warnings[0], "mem.world: <world name='w'>/<plugin name='wind' filename='libWindPlugin.so'>: world plugin "
                           "'libWindPlugin.so' is not simulated by bullet_sim; the world is loaded without it");
}

TEST(SdfWorldParser, ALinkKeepsItsOwnFrame) {
  const WorldDescription w = boxRoom();  // kept alive: the reference points into it
  const ModelDescription& m = model(w, "box_a").model;
  EXPECT_EQ(m.root_link, "body");
  expectPose(m.root_pose, {0, 0, 0.5}, 0, 0, kHalfPi);  // the link's <pose> in the model frame
  ASSERT_EQ(m.links.size(), 1u);
  const LinkDescription& l = m.links[0];
  EXPECT_EQ(l.name, "body");

  // Shapes and the inertial are in the link frame, as in SDF.
  ASSERT_EQ(l.collisions.size(), 1u);
  EXPECT_EQ(l.collisions[0].name, "collision");
  expectPose(l.collisions[0].origin, {1, 0, 0}, 0, 0, 0);
  EXPECT_TRUE(l.collisions[0].geometry.box_size.isApprox(Eigen::Vector3d(0.5, 0.4, 0.3)));

  EXPECT_DOUBLE_EQ(l.inertial.mass, 2.0);
  expectPose(l.inertial.origin, {0.1, 0, 0}, 0, 0, 0);
  Eigen::Matrix3d inertia;
  inertia << 0.1, 0.01, 0.02, 0.01, 0.2, 0.03, 0.02, 0.03, 0.3;
  EXPECT_TRUE(l.inertial.inertia.isApprox(inertia));

  EXPECT_DOUBLE_EQ(l.mu1, 0.6);
  EXPECT_DOUBLE_EQ(l.mu2, 0.4);

  ASSERT_EQ(l.visuals.size(), 1u);
  const VisualShape& v = l.visuals[0];
  expectPose(v.origin, {0, 0, 0}, 0, 0, 0);
  EXPECT_EQ(v.geometry.type, GeometryType::Mesh);
  EXPECT_EQ(v.geometry.mesh_file, kData + "/models/test_box/meshes/box.stl");  // relative to the model dir
  EXPECT_TRUE(v.geometry.mesh_scale.isApprox(Eigen::Vector3d(2, 2, 2)));
  EXPECT_EQ(v.rgba, (std::array<float, 4>{{1, 0, 0, 1}}));  // Gazebo/Red
}

TEST(SdfWorldParser, SensorsSitOnTheirLinkAndPluginsOnTheModel) {
  const WorldDescription w = boxRoom();  // kept alive: the reference points into it
  const ModelDescription& m = model(w, "box_a").model;
  ASSERT_EQ(m.sensors.size(), 1u);
  const SensorDescription& sensor = m.sensors[0];
  EXPECT_EQ(sensor.name, "imu");
  EXPECT_EQ(sensor.type, "imu");
  EXPECT_EQ(sensor.link, "body");
  EXPECT_TRUE(sensor.plugins.empty());
  EXPECT_EQ(sensor.element.number("update_rate", 0), 100);
  expectPose(sensor.element.pose(), {0, 0, 0.1}, 0, 0, 0);  // in the link frame, as written
  EXPECT_EQ(sensor.element.path(), "<model name='test_box'>/<link name='body'>/<sensor name='imu'>");

  ASSERT_EQ(m.plugins.size(), 1u);
  EXPECT_EQ(m.plugins[0].filename, "libmover.so");
  EXPECT_EQ(m.plugins[0].name, "mover");
  EXPECT_EQ(m.plugins[0].element.number("speed", 0), 1);
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

TEST(SdfWorldParser, StaticMultiLinkModelHoldsEveryLinkWhereItsPosePutsIt) {
  const WorldDescription w = boxRoom();  // kept alive: the reference points into it
  const PlacedModel& walls = model(w, "walls");
  EXPECT_TRUE(walls.model.is_static);
  expectPose(walls.pose, {0, 0, 0}, 0, 0, 0.5);
  EXPECT_EQ(walls.model.root_link, "north");
  expectPose(walls.model.root_pose, {0, 5, 1}, 0, 0, 0);
  ASSERT_EQ(walls.model.links.size(), 2u);
  // The south link is held by a fixed joint at its pose relative to the north one.
  ASSERT_EQ(walls.model.joints.size(), 1u);
  const JointDescription& held = walls.model.joints[0];
  EXPECT_EQ(held.type, JointType::Fixed);
  EXPECT_EQ(held.parent, "north");
  EXPECT_EQ(held.child, "south");
  expectPose(held.origin, {0, -10, 0}, 0, 0, kHalfPi);
  const LinkDescription& south = walls.model.links[1];
  ASSERT_EQ(south.collisions.size(), 2u);
  expectPose(south.collisions[0].origin, {1, 0, 0}, 0, 0, 0);
  EXPECT_TRUE(south.collisions[1].geometry.plane_normal.isApprox(Eigen::Vector3d::UnitZ()));  // normalised
  EXPECT_TRUE(south.collisions[1].geometry.plane_size.isApprox(Eigen::Vector2d(3, 4)));
  ASSERT_EQ(walls.model.links[0].visuals.size(), 1u);
  EXPECT_EQ(walls.model.links[0].visuals[0].rgba, (std::array<float, 4>{{0.2f, 0.3f, 0.4f, 1}}));  // diffuse wins
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
  auto parsed = [&](const std::string& link_pose, const std::string& pose) {
    return parseSdfModel("<model name='m'><link name='l'><pose>" + link_pose + "</pose><collision name='c'><pose>" +
                             pose + "</pose><geometry><sphere><radius>1</radius></sphere></geometry></collision></link></model>",
                         "mem", "", r);
  };
  // roll 90 then yaw 90 about the fixed axes: x -> y, y -> z.
  const Eigen::Isometry3d t = parsed("0 0 0 0 0 0", "0 0 0 1.5707963267948966 0 1.5707963267948966")
                                  .links.at(0).collisions.at(0).origin;
  EXPECT_TRUE((t.linear() * Eigen::Vector3d::UnitX()).isApprox(Eigen::Vector3d::UnitY()));
  EXPECT_TRUE((t.linear() * Eigen::Vector3d::UnitY()).isApprox(Eigen::Vector3d::UnitZ()));
  // General angles: the link pose goes to the model, the shape's stays in the link frame.
  const ModelDescription m = parsed("1 2 3 0.3 -0.4 0.7", "0.5 -0.2 0.1 -1.1 0.2 2.5");
  EXPECT_TRUE(m.root_pose.linear().isApprox(rpyMatrix(0.3, -0.4, 0.7), 1e-12));
  EXPECT_TRUE(m.root_pose.translation().isApprox(Eigen::Vector3d(1, 2, 3), 1e-12));
  const Eigen::Isometry3d u = m.links.at(0).collisions.at(0).origin;
  EXPECT_TRUE(u.linear().isApprox(rpyMatrix(-1.1, 0.2, 2.5), 1e-12));
  EXPECT_TRUE(u.translation().isApprox(Eigen::Vector3d(0.5, -0.2, 0.1), 1e-12));
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
                 {"spawn request", "expected <sdf> or <model> as the root element, got <robot>"});
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
                 {"nan.world: ", "<model name='ball'>", "<sphere>/<radius>: expected a number >= 0, got 'nan'"});
}

TEST(SdfWorldParserErrors, NegativeRadius) {
  expectMentions(badWorldError("negative_radius.world"),
                 {"negative_radius.world: ", "<visual name='v'>/<geometry>/<cylinder>/<radius>",
                  "expected a number >= 0, got '-0.5'"});
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

TEST(SdfWorldParserErrors, MovingLinksNotJoinedIntoOneTree) {
  expectMentions(badWorldError("multi_link_moving.world"),
                 {"multi_link_moving.world: <world name='default'>/<model name='cart'>: ",
                  "link 'wheel' is not connected to link 'chassis' by joints; a moving model must be one tree"});
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
                 {"mem.world: ", "<box>/<size>: expected 3 numbers, got '1 inf 1'"});
  expectMentions(worldError("<model name='m'><static>1</static>" + link_start + "<box><size>1 2</size></box>" +
                            link_end + "</model>"),
                 {"<box>/<size>: expected 3 numbers, got '1 2'"});
  expectMentions(worldError("<model name='m'><static>1</static>" + link_start +
                            "<sphere><radius>1</radius><colour>red</colour></sphere>" + link_end + "</model>"),
                 {"<sphere>/<colour>: unexpected element in <sphere>; expected <radius>"});
  expectMentions(worldError("<model name='m'><static>yes</static>" + link_start +
                            "<sphere><radius>1</radius></sphere>" + link_end + "</model>"),
                 {"<model name='m'>/<static>: expected true, false, 1 or 0, got 'yes'"});
  expectMentions(worldError("<model name='m'>" + link_start + "<sphere><radius>1</radius></sphere>" + link_end +
                            "<joint name='j' type='fixed'/></model>"),
                 {"<model name='m'>/<joint name='j'>: missing required element <parent>"});
  expectMentions(worldError("<model name='m'><link name='l'><inertial><mass>-1</mass></inertial></link></model>"),
                 {"<inertial>/<mass>: expected a number >= 0, got '-1'"});
  expectMentions(worldError("<model name='m'><pose>1 2 3</pose>" + link_start +
                            "<sphere><radius>1</radius></sphere>" + link_end + "</model>"),
                 {"<model name='m'>/<pose>: expected 6 numbers 'x y z roll pitch yaw', got '1 2 3'"});
  expectMentions(worldError("<physics><max_step_size>0</max_step_size></physics>"),
                 {"<physics>/<max_step_size>: expected a number > 0, got '0'"});
  expectMentions(worldError("<physics><ode><solver><iters>0</iters></solver></ode></physics>"),
                 {"<physics>/<ode>/<solver>/<iters>: expected", "got '0'"});
  expectMentions(worldError("<include><uri>model://test_box</uri></include><include><uri>model://test_box</uri></include>"),
                 {"a model named 'test_box' is already in the world"});
  expectMentions(worldError("<include><name>x</name></include>"), {"<include>: missing required element <uri>"});
}

TEST(SdfWorldParserErrors, ContactCorrectionValues) {
  const ResourceResolver r;
  auto worldError = [&](const std::string& body) {
    return errorOf([&] { parseWorldString(worldWith(body), "mem.world", "", r); });
  };
  auto surface = [](const std::string& ode) {
    return "<model name='m'><link name='l'><collision name='c'><geometry><sphere><radius>1</radius></sphere>"
           "</geometry><surface><contact><ode>" + ode + "</ode></contact></surface></collision></link></model>";
  };
  expectMentions(worldError(surface("<min_depth>-0.001</min_depth>")),
                 {"mem.world: <world name='w'>/<model name='m'>/<link name='l'>/<collision name='c'>/<surface>/"
                  "<contact>/<ode>/<min_depth>: expected a number >= 0, got '-0.001'"});
  expectMentions(worldError(surface("<max_vel>fast</max_vel>")),
                 {"<collision name='c'>/<surface>/<contact>/<ode>/<max_vel>: expected a number, got 'fast'"});
  expectMentions(worldError(surface("<max_vel>nan</max_vel>")), {"<ode>/<max_vel>: expected a number, got 'nan'"});
  expectMentions(worldError("<physics><ode><constraints><contact_max_correcting_vel>-1</contact_max_correcting_vel>"
                            "</constraints></ode></physics>"),
                 {"<physics>/<ode>/<constraints>/<contact_max_correcting_vel>: expected a number >= 0, got '-1'"});
  expectMentions(worldError("<physics><ode><constraints><contact_surface_layer>1mm</contact_surface_layer>"
                            "</constraints></ode></physics>"),
                 {"<physics>/<ode>/<constraints>/<contact_surface_layer>: expected a number >= 0, got '1mm'"});
}

TEST(SdfWorldParserErrors, IncludedModelErrorsNameBothFiles) {
  const ResourceResolver r = testResolver();
  // Making the moving model static through the include is fine...
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

TEST(SdfWorldParser, LinkGravityFlag) {
  const ResourceResolver r;
  const WorldDescription w = parseWorldString(
      worldWith("<model name='m'><static>true</static><link name='on'/><link name='off'><gravity>false</gravity></link></model>"), "mem.world",
      "", r);
  const auto& links = model(w, "m").model.links;
  ASSERT_EQ(links.size(), 2u);
  EXPECT_TRUE(links[0].gravity);
  EXPECT_FALSE(links[1].gravity);
  expectMentions(errorOf([&] {
                   parseWorldString(worldWith("<model name='m'><link name='l'><gravity>maybe</gravity></link></model>"),
                                    "mem.world", "", r);
                 }),
                 {"gravity", "maybe"});
}
