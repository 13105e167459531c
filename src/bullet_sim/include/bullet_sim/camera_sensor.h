#pragma once
// Camera sensor core, free of ROS: what a Gazebo <sensor type="camera"> with a gazebo_ros_camera
// plugin describes, and a CPU rasterizer that draws the visuals of a PhysicsWorld as that camera
// sees them (no display, no GPU). CameraPublisher turns the pictures into ROS messages.
#include <Eigen/Geometry>
#include <array>
#include <cstdint>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include "bullet_sim/model_description.h"

namespace bullet_sim {

class PhysicsWorld;

// Defaults are Gazebo's (sdformat's sensor.sdf / camera.sdf, gazebo_ros_camera_utils.cpp).
struct CameraConfig {
  std::string name;  // <sensor name>
  std::string link;  // the <gazebo reference> (URDF) or the SDF link the sensor sits on
  // Sensor frame in the link frame. As in Gazebo the camera looks along the sensor's +x with
  // +z up: image right is -y, image down is -z (the ROS optical frame is z forward, x right, y down).
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  double update_rate = 0.0;  // Hz; 0 means every physics step
  bool always_on = false;
  bool visualize = false;  // ignored

  // <camera>
  double horizontal_fov = 1.047;  // rad, in (0, pi); the vertical one follows from the aspect ratio
  int width = 320;
  int height = 240;
  std::string format = "R8G8B8";  // <image><format>
  std::string encoding = "rgb8";  // sensor_msgs encoding it maps to: rgb8, bgr8 or mono8
  double near_clip = 0.1;         // m
  double far_clip = 100.0;        // m
  // <camera><noise>: gaussian noise added to every channel, in [0, 1] colour units.
  std::string noise_type = "none";  // none, gaussian, gaussian_quantized (treated as gaussian)
  double noise_mean = 0.0;
  double noise_stddev = 0.0;

  // <plugin filename="libgazebo_ros_camera.so">; plugin_filename stays empty without one (then
  // Gazebo publishes nothing to ROS).
  std::string plugin_filename;
  std::string plugin_name;
  // <robotNamespace>: absent -> "" ; present but empty -> gazebo_ros uses the model name.
  std::string robot_namespace;
  bool robot_namespace_given = false;
  std::string camera_name;                         // topics live under <robotNamespace>/<cameraName>
  std::string image_topic_name = "image_raw";
  std::string camera_info_topic_name = "camera_info";
  std::string frame_name;      // gazebo_ros_camera_utils leaves it empty when missing
  double plugin_update_rate = 0.0;  // <updateRate>: throttles publishing further; 0 = the sensor's rate
  double hack_baseline = 0.0;       // m; P[3] = -fx * hackBaseline (the right camera of a stereo pair)
  // 0 means "compute it" for these, as in gazebo_ros_camera_utils.
  double focal_length = 0.0;
  double cx = 0.0;
  double cy = 0.0;
  double cx_prime = 0.0;  // read, unused: gazebo_ros_camera_utils does not put it in CameraInfo either
  // Copied into CameraInfo.D = {k1, k2, t1, t2, k3}; the image itself is not distorted (as in
  // Gazebo unless <camera><distortion> is given, which is not supported here).
  double distortion_k1 = 0.0, distortion_k2 = 0.0, distortion_k3 = 0.0;
  double distortion_t1 = 0.0, distortion_t2 = 0.0;
};

// Every camera <sensor> in the blocks: children of URDF <gazebo> blocks and SDF <sensor> blocks.
// Throws DescriptionError on malformed XML and bad values; the message names `source`, the
// element path and what was expected.
std::vector<CameraConfig> parseCameraSensors(const std::vector<GazeboExtension>& blocks, const std::string& source);

// sensor_msgs/CameraInfo's matrices as gazebo_ros_camera_utils fills them:
// fx = fy = width / (2 tan(hfov / 2)) (or <focalLength>), cx = (width + 1) / 2,
// cy = (height + 1) / 2 (or <Cx>, <Cy>), R = I, P = [fx 0 cx -fx*hackBaseline; 0 fy cy 0; 0 0 1 0],
// D = {k1, k2, t1, t2, k3} (plumb_bob). Note Gazebo's cx, cy sit one pixel right of and below the
// true image centre ((width - 1) / 2 in pixel indices), where both Gazebo and SceneRenderer put
// the optical axis; we publish Gazebo's numbers so that downstream code sees the same CameraInfo.
struct CameraIntrinsics {
  double fx = 0, fy = 0, cx = 0, cy = 0;
  std::array<double, 9> K{};
  std::array<double, 9> R{};
  std::array<double, 12> P{};
  std::array<double, 5> D{};
};
CameraIntrinsics cameraIntrinsics(const CameraConfig& config);

// 8-bit colour pixels as sensor_msgs/Image lays them out: rows top to bottom, pixels left to
// right, channels in the order `encoding` says ("rgb8" or "bgr8").
struct CameraImage {
  int width = 0;
  int height = 0;
  std::string encoding = "rgb8";
  std::vector<std::uint8_t> data;  // width * height * 3
  std::array<std::uint8_t, 3> rgb(int x, int y) const {  // whatever the order
    const std::uint8_t* p = &data[(static_cast<size_t>(y) * width + x) * 3];
    return encoding == "bgr8" ? std::array<std::uint8_t, 3>{{p[2], p[1], p[0]}}
                              : std::array<std::uint8_t, 3>{{p[0], p[1], p[2]}};
  }
};

// Light and background. Defaults are Gazebo's empty world: <scene> ambient 0.4 and background
// 0.7 grey (sdformat's defaults), and model://sun (diffuse 0.8, direction -0.5 0.1 -0.9).
struct RenderSettings {
  std::array<float, 3> background{{0.7f, 0.7f, 0.7f}};
  float ambient = 0.4f;
  float sun_diffuse = 0.8f;
  Eigen::Vector3d sun_direction{-0.5, 0.1, -0.9};  // where the light travels, world frame
  int segments = 24;  // around cylinders and spheres (spheres get segments / 2 stacks)
  int threads = 1;    // rows are split in bands between this many threads
};

// One visual placed in the world.
struct SceneItem {
  const VisualShape* visual = nullptr;
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();  // visual frame in the world
};

// Z-buffered, flat-shaded triangle rasterizer. Primitives are triangulated once per distinct
// geometry and cached; textures (box and plane visuals with texture_file) are loaded once.
// Surfaces: colour = rgba * (ambient + sun_diffuse * max(0, n . to_sun)), textured ones use the
// texture's colour instead of rgba. Boxes, cylinders, spheres and planes are single-sided (their
// back faces are culled, as in Gazebo); meshes are drawn two-sided. Alpha 0 visuals are skipped,
// other alphas are drawn opaque.
// Textures: every face of a box (and a plane's front) shows the whole image, unmirrored when seen
// from outside; on a vertical face the image's top is toward the box's +z, on the top and bottom
// faces it is toward the box's +x; on a plane the image's right is the plane frame's +x and its
// top +y (rotated onto the normal).
class SceneRenderer {
 public:
  explicit SceneRenderer(RenderSettings settings = RenderSettings());
  ~SceneRenderer();
  SceneRenderer(const SceneRenderer&) = delete;
  SceneRenderer& operator=(const SceneRenderer&) = delete;

  // What a camera whose sensor frame is at `camera_in_world` sees of every visual of every model.
  // Uses config's horizontal_fov, width, height, near_clip, far_clip, and encoding: the pixels come
  // out in bgr8 order for "bgr8" (saving a conversion), else in rgb8 order.
  void render(const PhysicsWorld& world, const Eigen::Isometry3d& camera_in_world, const CameraConfig& config,
              CameraImage& out);
  void render(const std::vector<SceneItem>& items, const Eigen::Isometry3d& camera_in_world,
              const CameraConfig& config, CameraImage& out);
  // The visuals of every model at their links' current poses (valid until a model changes).
  static std::vector<SceneItem> collect(const PhysicsWorld& world);

  // What could not be drawn (unreadable mesh or texture), each reported once, for the caller to log.
  std::vector<std::string> takeWarnings();
  const RenderSettings& settings() const { return settings_; }

 private:
  struct Impl;
  RenderSettings settings_;
  std::unique_ptr<Impl> impl_;
};

// Gazebo's gaussian image noise on 8-bit values: value + round(255 * (mean + stddev * N(0, 1))),
// clamped, independently per byte (so per channel). Drawing 2.4 million normal samples per
// 800x800 frame would cost more than rendering it, so one pattern of (bytes + 65536) samples is
// drawn once from `seed`, and each frame adds it from a fresh random offset: every frame's noise
// is i.i.d. with the right mean and spread, and the same seed gives the same frames.
class ImageNoise {
 public:
  ImageNoise(double mean, double stddev, std::uint64_t seed);
  void apply(std::vector<std::uint8_t>& bytes);

 private:
  double mean_, stddev_;
  std::mt19937_64 rng_;
  std::vector<std::int16_t> pattern_;
};

// The pixels in a sensor_msgs encoding: "rgb8", "bgr8", or "mono8" (luma, Rec. 601).
void encodeImage(const CameraImage& image, const std::string& encoding, std::vector<std::uint8_t>& out);

}  // namespace bullet_sim
