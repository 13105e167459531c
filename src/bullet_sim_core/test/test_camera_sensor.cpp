// Camera sensor: parsing of <sensor type="camera"> blocks, and rendered pictures checked against
// the pinhole model (sizes, orientation, occlusion, clipping, textures), noise and encodings.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>
#include <string>
#include <vector>

#include "bullet_sim_core/camera_sensor.h"
#include "bullet_sim_core/description_error.h"
#include "bullet_sim_core/image_noise.h"
#include "bullet_sim_core/physics_world.h"
#include "bullet_sim_core/scene_renderer.h"
#include "bullet_sim_core/sdf_parser.h"
#include "bullet_sim_core/urdf_parser.h"
#include "bullet_sim_core/testing/error_of.h"

namespace bullet_sim {
namespace {

constexpr double kPi = 3.14159265358979323846;

// ---------------------------------------------------------------------------------------------
// Parsing
// ---------------------------------------------------------------------------------------------

// The camera sensors of a URDF whose only link is camera_link and whose <gazebo> blocks are `blocks`.
std::vector<CameraConfig> parse(const std::string& blocks) {
  const ModelDescription m =
      parseUrdf("<robot name='m'><link name='camera_link'/>" + blocks + "</robot>", "model.urdf", ResourceResolver(), "");
  std::vector<CameraConfig> out;
  for (const SensorDescription& s : m.sensors)
    if (isCameraSensor(s)) out.push_back(parseCameraSensor(s));
  return out;
}

std::string sensor(const std::string& body) {
  return "<gazebo reference='camera_link'><sensor name='cam' type='camera'>" + body + "</sensor></gazebo>";
}

std::string errorOf(const std::string& blocks) { return bullet_sim::errorOf([&] { parse(blocks); }); }

TEST(CameraParse, DefaultsAreGazebos) {
  const auto cams = parse(sensor(""));
  ASSERT_EQ(cams.size(), 1u);
  const CameraConfig& c = cams[0];
  EXPECT_EQ(c.name, "cam");
  EXPECT_EQ(c.link, "camera_link");
  EXPECT_TRUE(c.pose.isApprox(Eigen::Isometry3d::Identity()));
  EXPECT_EQ(c.update_rate, 0.0);
  EXPECT_DOUBLE_EQ(c.horizontal_fov, 1.047);
  EXPECT_EQ(c.width, 320);
  EXPECT_EQ(c.height, 240);
  EXPECT_EQ(c.format, "R8G8B8");
  EXPECT_EQ(c.encoding, "rgb8");
  EXPECT_DOUBLE_EQ(c.near_clip, 0.1);
  EXPECT_DOUBLE_EQ(c.far_clip, 100.0);
  EXPECT_EQ(c.noise_type, "none");
}

// The rrbot tutorial's camera sensor (its plugin is read by bullet_sim_plugins).
const char* kRrbotCamera = R"(
<gazebo reference="camera_link">
  <sensor type="camera" name="camera1">
    <pose>0.1 0 0.2 0 0.5 0</pose>
    <update_rate>30.0</update_rate>
    <camera name="head">
      <horizontal_fov>1.3962634</horizontal_fov>
      <image><width>800</width><height>600</height><format>B8G8R8</format></image>
      <clip><near>0.02</near><far>300</far></clip>
      <noise><type>gaussian</type><mean>0.0</mean><stddev>0.007</stddev></noise>
    </camera>
    <plugin name="camera_controller" filename="libgazebo_ros_camera.so"/>
  </sensor>
</gazebo>)";

TEST(CameraParse, EveryField) {
  const auto cams = parse(kRrbotCamera);
  ASSERT_EQ(cams.size(), 1u);
  const CameraConfig& c = cams[0];
  EXPECT_EQ(c.name, "camera1");
  EXPECT_TRUE(c.pose.translation().isApprox(Eigen::Vector3d(0.1, 0, 0.2)));
  EXPECT_TRUE(c.pose.linear().isApprox(Eigen::AngleAxisd(0.5, Eigen::Vector3d::UnitY()).toRotationMatrix()));
  EXPECT_EQ(c.update_rate, 30.0);
  EXPECT_DOUBLE_EQ(c.horizontal_fov, 1.3962634);
  EXPECT_EQ(c.width, 800);
  EXPECT_EQ(c.height, 600);
  EXPECT_EQ(c.encoding, "bgr8");
  EXPECT_DOUBLE_EQ(c.near_clip, 0.02);
  EXPECT_DOUBLE_EQ(c.far_clip, 300);
  EXPECT_EQ(c.noise_type, "gaussian");
  EXPECT_DOUBLE_EQ(c.noise_stddev, 0.007);
}

TEST(CameraParse, SdfLinkSensorsAndOtherSensorTypes) {
  // An SDF link's sensors: only the camera is a camera.
  const ModelDescription m = parseSdfModel(
      "<model name='m'><link name='base'>"
      "<sensor name='eye' type='camera'><camera><image><format>L8</format></image></camera>"
      "<plugin name='x' filename='libsomething_else.so'/></sensor>"
      "<sensor name='lidar' type='ray'/><sensor name='d' type='depth'/></link></model>",
      "m.sdf", "", ResourceResolver());
  ASSERT_EQ(m.sensors.size(), 3u);
  EXPECT_TRUE(isCameraSensor(m.sensors[0]));
  EXPECT_FALSE(isCameraSensor(m.sensors[1]));
  EXPECT_FALSE(isCameraSensor(m.sensors[2]));
  const CameraConfig c = parseCameraSensor(m.sensors[0]);
  EXPECT_EQ(c.name, "eye");
  EXPECT_EQ(c.link, "base");
  EXPECT_EQ(c.encoding, "mono8");
}

TEST(CameraParse, ErrorsNameSourceElementAndExpectation) {
  const std::string at = "model.urdf: <gazebo reference='camera_link'>/<sensor name='cam'>";
  EXPECT_EQ(errorOf(sensor("<camera name='head'><horizontal_fov>4</horizontal_fov></camera>")),
            at + "/<camera name='head'>/<horizontal_fov>: expected a number in (0, pi) radians, got '4'");
  EXPECT_EQ(errorOf(sensor("<camera><image><width>wide</width></image></camera>")),
            at + "/<camera>/<image>/<width>: expected an integer in [1, 16384], got 'wide'");
  EXPECT_EQ(errorOf(sensor("<camera><image><format>R16G16B16</format></image></camera>")),
            at + "/<camera>/<image>/<format>: expected one of R8G8B8, RGB_INT8, B8G8R8, BGR_INT8, L8, L_INT8, "
                 "got 'R16G16B16'");
  EXPECT_EQ(errorOf(sensor("<camera><clip><near>200</near></clip></camera>")),
            at + "/<camera>/<clip>/<far>: expected a number > <near> (200), got nothing (the default is 100)");
  EXPECT_EQ(errorOf(sensor("<camera><clip><near>0</near></clip></camera>")),
            at + "/<camera>/<clip>/<near>: expected a number > 0, got '0'");
  EXPECT_EQ(errorOf(sensor("<camera><noise><type>salt</type></noise></camera>")),
            at + "/<camera>/<noise>/<type>: expected one of none, gaussian, gaussian_quantized, got 'salt'");
  EXPECT_EQ(errorOf(sensor("<update_rate>-1</update_rate>")), at + "/<update_rate>: expected a number >= 0, got '-1'");
  EXPECT_EQ(errorOf("<gazebo><sensor name='cam' type='camera'/></gazebo>"),
            "model.urdf: <gazebo>/<sensor name='cam'>: expected the sensor's <gazebo> block to name its link with "
            "reference='LINK'");
  EXPECT_EQ(errorOf("<gazebo reference='camera_link'><sensor></gazebo>").rfind("model.urdf: malformed XML at line", 0),
            0u);
}

// ---------------------------------------------------------------------------------------------
// Rendering
// ---------------------------------------------------------------------------------------------

Eigen::Isometry3d at(double x, double y, double z, double yaw = 0, double pitch = 0) {
  Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
  t.translation() = Eigen::Vector3d(x, y, z);
  t.linear() = (Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()) * Eigen::AngleAxisd(pitch, Eigen::Vector3d::UnitY()))
                   .toRotationMatrix();
  return t;
}

VisualShape box(double sx, double sy, double sz, std::array<float, 4> rgba) {
  VisualShape v;
  v.geometry.type = GeometryType::Box;
  v.geometry.box_size = Eigen::Vector3d(sx, sy, sz);
  v.rgba = rgba;
  return v;
}

const std::array<float, 4> kRed{{1, 0, 0, 1}}, kGreen{{0, 1, 0, 1}}, kGrey{{0.7f, 0.7f, 0.7f, 1}};

VisualShape ground() {
  VisualShape v;
  v.geometry.type = GeometryType::Plane;  // normal z, 100 x 100, as model://ground_plane
  v.rgba = kGrey;
  return v;
}

// A 200 x 200 camera with a 90 degree field of view: f = 100 px, the axis through (100, 100).
CameraConfig camera() {
  CameraConfig c;
  c.width = 200;
  c.height = 200;
  c.horizontal_fov = kPi / 2;
  c.near_clip = 0.05;
  c.far_clip = 100;
  return c;
}

struct Rgb {
  int r, g, b;
};
Rgb px(const CameraImage& im, int x, int y) {
  const auto p = im.rgb(x, y);
  return {p[0], p[1], p[2]};
}
bool isRed(Rgb c) { return c.r > 60 && c.r > 3 * c.g && c.r > 3 * c.b; }
bool isGreen(Rgb c) { return c.g > 60 && c.g > 3 * c.r && c.g > 3 * c.b; }
bool isBlue(Rgb c) { return c.b > 60 && c.b > 3 * c.r && c.b > 3 * c.g; }
bool isYellow(Rgb c) { return c.r > 60 && c.g > 60 && c.r > 3 * c.b && c.g > 3 * c.b; }

// Columns of row y (or rows of column x) where `pred` holds: the first one and how many.
template <class Pred>
std::pair<int, int> runInRow(const CameraImage& im, int y, Pred pred) {
  int first = -1, count = 0;
  for (int x = 0; x < im.width; ++x)
    if (pred(px(im, x, y))) first = first < 0 ? x : first, ++count;
  return {first, count};
}
template <class Pred>
std::pair<int, int> runInColumn(const CameraImage& im, int x, Pred pred) {
  int first = -1, count = 0;
  for (int y = 0; y < im.height; ++y)
    if (pred(px(im, x, y))) first = first < 0 ? y : first, ++count;
  return {first, count};
}

class RenderTest : public ::testing::Test {
 protected:
  CameraImage render(const std::vector<SceneItem>& items, const Eigen::Isometry3d& cam, const CameraConfig& c = camera()) {
    CameraImage im;
    renderer_.render(items, cam, c, im);
    return im;
  }
  SceneRenderer renderer_;
  const VisualShape ground_ = ground();
  const VisualShape red_box_ = box(1, 1, 1, kRed);
};

TEST_F(RenderTest, RedBoxOnGroundMatchesThePinholeModel) {
  // Camera 0.5 m up looking along +x; the box's front face at x = 2.5 spans y, z in [-0.5, 0.5]
  // around the optical axis: 100 * 0.5 / 2.5 = 20 px each way.
  const auto im = render({{&ground_, Eigen::Isometry3d::Identity()}, {&red_box_, at(3, 0, 0.5)}}, at(0, 0, 0.5));
  EXPECT_TRUE(isRed(px(im, 100, 100)));
  const auto [x0, width] = runInRow(im, 100, isRed);
  EXPECT_NEAR(x0, 80, 1);
  EXPECT_NEAR(width, 40, 2);
  const auto [y0, height] = runInColumn(im, 100, isRed);
  EXPECT_NEAR(y0, 80, 1);
  EXPECT_NEAR(height, 40, 2);

  // Above the horizon: the background; below: the lit ground, 0.7 * (0.4 + 0.8 * cos(sun, z)).
  const Rgb sky = px(im, 10, 10);
  EXPECT_EQ(sky.r, 179);
  EXPECT_EQ(sky.g, 179);
  EXPECT_EQ(sky.b, 179);
  const double cos_sun = 0.9 / Eigen::Vector3d(-0.5, 0.1, -0.9).norm();
  const int ground_level = static_cast<int>(std::lround(std::min(1.0, 0.7 * (0.4 + 0.8 * cos_sun)) * 255));
  const Rgb floor = px(im, 10, 190);
  EXPECT_NEAR(floor.r, ground_level, 1);
  EXPECT_EQ(floor.r, floor.g);
  EXPECT_NE(floor.r, sky.r);
  // The horizon of a 100 m plane seen from 0.5 m: 50 m away, 100 * 0.5 / 50 = 1 px below centre.
  const auto [ground_top, ground_rows] = runInColumn(im, 10, [&](Rgb c) { return c.r == floor.r; });
  EXPECT_NEAR(ground_top, 101, 1);
  EXPECT_EQ(ground_rows, 200 - ground_top);
}

TEST_F(RenderTest, OrientationFollowsTheSensorFrame) {
  // A box to the left (+y) shows on the left; one above (+z) shows at the top.
  const VisualShape small = box(0.2, 0.2, 0.2, kRed);
  auto im = render({{&small, at(3, 1, 0.5)}}, at(0, 0, 0.5));
  auto [x0, w] = runInRow(im, 100, isRed);
  EXPECT_GT(w, 0);
  EXPECT_LT(x0 + w, 100);
  im = render({{&small, at(3, 0, 1.5)}}, at(0, 0, 0.5));
  auto [y0, h] = runInColumn(im, 100, isRed);
  EXPECT_GT(h, 0);
  EXPECT_LT(y0 + h, 100);

  // Turning the camera left (yaw > 0) moves what is ahead to the right of the image...
  im = render({{&red_box_, at(3, 0, 0.5)}}, at(0, 0, 0.5, 0.2));
  std::tie(x0, w) = runInRow(im, 100, isRed);
  EXPECT_NEAR(x0 + w / 2.0, 100 + 100 * std::tan(0.2), 3);
  // ...a quarter turn loses it, and pitching down (pitch > 0 about y) raises the horizon.
  im = render({{&red_box_, at(3, 0, 0.5)}}, at(0, 0, 0.5, kPi / 2));
  EXPECT_EQ(runInRow(im, 100, isRed).second, 0);
  im = render({{&ground_, Eigen::Isometry3d::Identity()}}, at(0, 0, 0.5, 0, 0.3));
  const Rgb sky = px(im, 100, 0);
  const auto [top, rows] = runInColumn(im, 100, [&](Rgb c) { return c.r != sky.r; });
  EXPECT_NEAR(top, 100 - 100 * std::tan(0.3), 2);
}

TEST_F(RenderTest, NearerHidesFartherWhateverTheOrder) {
  const VisualShape big_green = box(1, 3, 3, kGreen);
  const auto a = render({{&red_box_, at(3, 0, 0.5)}, {&big_green, at(6, 0, 0.5)}}, at(0, 0, 0.5));
  const auto b = render({{&big_green, at(6, 0, 0.5)}, {&red_box_, at(3, 0, 0.5)}}, at(0, 0, 0.5));
  EXPECT_TRUE(isRed(px(a, 100, 100)));
  // The green box's front face (at 5.5 m) spans 100 +- 27 px, the red one's 100 +- 20 px.
  EXPECT_TRUE(isGreen(px(a, 100, 76)));
  EXPECT_TRUE(isGreen(px(a, 100, 124)));
  EXPECT_EQ(a.data, b.data);
}

TEST_F(RenderTest, BehindTheCameraOrBeyondFarIsNotDrawn) {
  CameraConfig c = camera();
  c.far_clip = 10;
  const auto empty = render({{&ground_, Eigen::Isometry3d::Identity()}}, at(0, 0, 0.5), c);
  EXPECT_EQ(render({{&ground_, Eigen::Isometry3d::Identity()}, {&red_box_, at(-3, 0, 0.5)}}, at(0, 0, 0.5), c).data,
            empty.data);
  EXPECT_EQ(render({{&ground_, Eigen::Isometry3d::Identity()}, {&red_box_, at(20, 0, 0.5)}}, at(0, 0, 0.5), c).data,
            empty.data);
  // The ground ends at the far clip: 10 m away is 100 * 0.5 / 10 = 5 px below the axis.
  const Rgb sky = px(empty, 100, 0);
  EXPECT_NEAR(runInColumn(empty, 100, [&](Rgb p) { return p.r != sky.r; }).first, 105, 1);
  // A wall crossing the near plane beside the camera is cut there, not dropped.
  const VisualShape wall = box(4, 0.1, 2, kRed);
  const auto side = render({{&wall, at(1.5, 0.5, 0.5)}}, at(0, 0, 0.5));
  EXPECT_TRUE(isRed(px(side, 5, 100)));
  EXPECT_FALSE(isRed(px(side, 195, 100)));
}

// A 64 x 64 image with red, green, blue and yellow quadrants (top-left, top-right, bottom-left,
// bottom-right as stored in the file).
std::string quadrantTexture() {
  const std::string path = (std::filesystem::temp_directory_path() / "bullet_sim_quadrants.png").string();
  cv::Mat bgr(64, 64, CV_8UC3);
  for (int y = 0; y < 64; ++y)
    for (int x = 0; x < 64; ++x) {
      const bool right = x >= 32, bottom = y >= 32;
      cv::Vec3b c = !bottom ? (right ? cv::Vec3b(0, 255, 0) : cv::Vec3b(0, 0, 255))
                            : (right ? cv::Vec3b(0, 255, 255) : cv::Vec3b(255, 0, 0));
      bgr.at<cv::Vec3b>(y, x) = c;
    }
  cv::imwrite(path, bgr);
  return path;
}

TEST_F(RenderTest, TexturedBoxIsUprightAndUnmirroredOnEveryVerticalFace) {
  VisualShape panel = box(0.02, 1, 1, {{1, 1, 1, 1}});
  panel.texture_file = quadrantTexture();
  // Each case: where the panel is and how it is turned, and where the camera looks from.
  struct Case {
    Eigen::Isometry3d panel, camera;
  };
  const Case cases[] = {
      {at(2, 0, 0.5), at(0, 0, 0.5)},                    // its -x face
      {at(2, 0, 0.5), at(4, 0, 0.5, kPi)},               // its +x face, from behind
      {at(0, 2, 0.5, kPi / 2), at(0, 0, 0.5, kPi / 2)},  // turned with the camera
      {at(2, 0, 0.5, 0.4), at(0, 0, 0.5)},               // at an angle
  };
  for (const Case& c : cases) {
    const auto im = render({{&panel, c.panel}}, c.camera);
    // The panel spans +-0.5 m at 2 m: +-25 px around the centre; sample at +-12 px.
    EXPECT_TRUE(isRed(px(im, 88, 88)));
    EXPECT_TRUE(isGreen(px(im, 112, 88)));
    EXPECT_TRUE(isBlue(px(im, 88, 112)));
    EXPECT_TRUE(isYellow(px(im, 112, 112)));
  }
  // Seen from above (camera pitched straight down, image top toward +x): a top face's image
  // top is toward the box's +x.
  VisualShape tile = box(1, 1, 0.02, {{1, 1, 1, 1}});
  tile.texture_file = panel.texture_file;
  const auto top = render({{&tile, Eigen::Isometry3d::Identity()}}, at(0, 0, 2, 0, kPi / 2));
  EXPECT_TRUE(isRed(px(top, 88, 88)));
  EXPECT_TRUE(isGreen(px(top, 112, 88)));
  EXPECT_TRUE(isBlue(px(top, 88, 112)));
  EXPECT_TRUE(isYellow(px(top, 112, 112)));
}

TEST_F(RenderTest, MissingTextureKeepsTheColourAndWarnsOnce) {
  VisualShape v = box(1, 1, 1, kRed);
  v.texture_file = "/nonexistent/marker.png";
  render({{&v, at(3, 0, 0.5)}}, at(0, 0, 0.5));
  const auto im = render({{&v, at(3, 0, 0.5)}}, at(0, 0, 0.5));
  EXPECT_TRUE(isRed(px(im, 100, 100)));
  const auto warnings = renderer_.takeWarnings();
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_NE(warnings[0].find("/nonexistent/marker.png"), std::string::npos);
}

TEST_F(RenderTest, CylindersAndSpheresHaveTheirSize) {
  VisualShape cyl;
  cyl.geometry.type = GeometryType::Cylinder;
  cyl.geometry.radius = 0.5;
  cyl.geometry.length = 1;
  cyl.rgba = kRed;
  VisualShape ball = cyl;
  ball.geometry.type = GeometryType::Sphere;
  // Silhouette half-width of radius 0.5 at 3 m: 100 * tan(asin(0.5 / 3)) = 16.9 px; the cylinder's
  // height at its nearest (2.5 m) is +-20 px.
  auto im = render({{&cyl, at(3, 0, 0.5)}}, at(0, 0, 0.5));
  EXPECT_NEAR(runInRow(im, 100, isRed).second, 2 * 16.9, 2);
  EXPECT_NEAR(runInColumn(im, 100, isRed).second, 40, 2);
  im = render({{&ball, at(3, 0, 0.5)}}, at(0, 0, 0.5));
  EXPECT_NEAR(runInRow(im, 100, isRed).second, 2 * 16.9, 2);
  EXPECT_NEAR(runInColumn(im, 100, isRed).second, 2 * 16.9, 2);
}

TEST(CameraWorld, RendersTheVisualsOfAPhysicsWorld) {
  PhysicsWorld world;
  ModelDescription m;
  m.name = "marker";
  m.source = "test";
  m.is_static = true;
  m.root_link = "link";
  LinkDescription link;
  link.name = "link";
  VisualShape v = box(1, 1, 1, kRed);
  v.origin.translation() = Eigen::Vector3d(0, 0, 0.5);  // the visual's origin in its link counts
  link.visuals.push_back(v);
  m.links.push_back(link);
  world.addModel(m, at(3, 0, 0));
  SceneRenderer renderer;
  CameraImage im;
  renderer.render(world, at(0, 0, 0.5), camera(), im);
  EXPECT_TRUE(isRed(px(im, 100, 100)));
  EXPECT_NEAR(runInColumn(im, 100, isRed).second, 40, 2);
}

TEST(CameraImage, NoiseIsRepeatableAndHasItsSpread) {
  std::vector<std::uint8_t> a(100 * 100 * 3, 128), b = a, first;
  ImageNoise noise_a(0, 0.02, 7), noise_b(0, 0.02, 7);
  noise_a.apply(a);
  noise_b.apply(b);
  EXPECT_EQ(a, b);
  double sum = 0, sum2 = 0;
  for (std::uint8_t v : a) sum += v - 128, sum2 += (v - 128.0) * (v - 128.0);
  const double n = a.size(), mean = sum / n;
  EXPECT_NEAR(mean, 0, 0.1);
  EXPECT_NEAR(std::sqrt(sum2 / n - mean * mean), 0.02 * 255, 0.2);
  // The next frame's noise is different, and clamped at the ends of the range.
  first = a;
  a.assign(a.size(), 128);
  noise_a.apply(a);
  EXPECT_NE(a, first);
  std::vector<std::uint8_t> white(1000, 255);
  ImageNoise(0.5, 0, 1).apply(white);
  EXPECT_EQ(white, std::vector<std::uint8_t>(1000, 255));
}

TEST(CameraImage, Encodings) {
  CameraImage im;
  im.width = 1, im.height = 1;
  im.data = {200, 100, 10};
  std::vector<std::uint8_t> out;
  encodeImage(im, "rgb8", out);
  EXPECT_EQ(out, (std::vector<std::uint8_t>{200, 100, 10}));
  encodeImage(im, "bgr8", out);
  EXPECT_EQ(out, (std::vector<std::uint8_t>{10, 100, 200}));
  encodeImage(im, "mono8", out);
  ASSERT_EQ(out.size(), 1u);
  EXPECT_NEAR(out[0], 0.299 * 200 + 0.587 * 100 + 0.114 * 10, 1);
  im.encoding = "bgr8";  // the same bytes read as blue 200, red 10
  encodeImage(im, "rgb8", out);
  EXPECT_EQ(out, (std::vector<std::uint8_t>{10, 100, 200}));
  encodeImage(im, "mono8", out);
  EXPECT_NEAR(out[0], 0.299 * 10 + 0.587 * 100 + 0.114 * 200, 1);
}

TEST_F(RenderTest, RendersStraightIntoBgrOrder) {
  VisualShape panel = box(0.02, 1, 1, {{1, 1, 1, 1}});
  panel.texture_file = quadrantTexture();
  const std::vector<SceneItem> scene = {{&ground_, Eigen::Isometry3d::Identity()}, {&panel, at(2, 0, 0.5)},
                                        {&red_box_, at(4, 1.5, 0.5)}};
  CameraConfig c = camera();
  const CameraImage rgb = render(scene, at(0, 0, 0.5), c);
  c.encoding = "bgr8";
  const CameraImage bgr = render(scene, at(0, 0, 0.5), c);
  EXPECT_EQ(bgr.encoding, "bgr8");
  std::vector<std::uint8_t> converted;
  encodeImage(rgb, "bgr8", converted);
  EXPECT_EQ(bgr.data, converted);
}

}  // namespace
}  // namespace bullet_sim
