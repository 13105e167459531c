#pragma once
// A CPU rasterizer that draws the visuals of a PhysicsWorld as a camera sensor sees them (no
// display, no GPU), into 8-bit images laid out as sensor_msgs/Image wants them.
#include <Eigen/Geometry>
#include <array>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "bullet_sim_core/camera_sensor.h"
#include "bullet_sim_core/model_description.h"

namespace bullet_sim {

class PhysicsWorld;

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

// The pixels in a sensor_msgs encoding: "rgb8", "bgr8", or "mono8" (luma, Rec. 601).
void encodeImage(const CameraImage& image, const std::string& encoding, std::vector<std::uint8_t>& out);

}  // namespace bullet_sim
