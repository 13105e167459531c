// Frame time of SceneRenderer in a maze-like world: a ground plane, a 3 x 5 m maze of 30 wall
// boxes with 10 cylinder obstacles, a textured marker on a wall, and a robot of 20 primitives
// driving ahead of the camera. The camera (0.3 m up) follows a path through the maze, turning.
// Reports the mean and worst time per frame (render from the PhysicsWorld, plus noise and the
// bgr8 conversion the publisher does) for 800x800 and 640x480, on 1 and 2 threads.
//   usage: bench_camera [frames=300]
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <filesystem>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>
#include <string>
#include <vector>

#include "bullet_sim_core/camera_sensor.h"
#include "bullet_sim_core/image_noise.h"
#include "bullet_sim_core/physics_world.h"
#include "bullet_sim_core/scene_renderer.h"

namespace {

using namespace bullet_sim;

constexpr double kPi = 3.14159265358979323846;

Eigen::Isometry3d pose(double x, double y, double z, double yaw = 0, double pitch = 0) {
  Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
  t.translation() = Eigen::Vector3d(x, y, z);
  t.linear() = (Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()) * Eigen::AngleAxisd(pitch, Eigen::Vector3d::UnitY()))
                   .toRotationMatrix();
  return t;
}

VisualShape shape(GeometryType type, const Eigen::Vector3d& size, const Eigen::Isometry3d& origin,
                  std::array<float, 4> rgba) {
  VisualShape v;
  v.geometry.type = type;
  v.geometry.box_size = size;
  v.geometry.radius = size.x();
  v.geometry.length = size.z();
  v.origin = origin;
  v.rgba = rgba;
  return v;
}

ModelDescription staticModel(const std::string& name, std::vector<VisualShape> visuals) {
  ModelDescription m;
  m.name = name;
  m.source = "bench";
  m.is_static = true;
  m.root_link = "link";
  LinkDescription link;
  link.name = "link";
  link.visuals = std::move(visuals);
  m.links.push_back(link);
  return m;
}

void buildWorld(PhysicsWorld& world, const std::string& marker_png) {
  VisualShape ground;
  ground.geometry.type = GeometryType::Plane;
  ground.rgba = {0.7f, 0.7f, 0.7f, 1};
  world.addModel(staticModel("ground_plane", {ground}), Eigen::Isometry3d::Identity());

  const std::array<float, 4> wall_colour{0.9f, 0.9f, 0.85f, 1};
  const double t = 0.04, h = 0.5;
  std::vector<VisualShape> walls;
  auto wall = [&](double x0, double y0, double x1, double y1) {  // a wall from (x0,y0) to (x1,y1)
    const Eigen::Vector3d size(std::max(std::abs(x1 - x0), t), std::max(std::abs(y1 - y0), t), h);
    walls.push_back(shape(GeometryType::Box, size, pose((x0 + x1) / 2, (y0 + y1) / 2, h / 2), wall_colour));
  };
  wall(0, 0, 3, 0), wall(0, 5, 3, 5), wall(0, 0, 0, 5), wall(3, 0, 3, 5);  // outer rectangle
  for (int i = 0; i < 26; ++i) {  // interior walls on a 0.5 m grid, alternating directions
    const double x = 0.5 * (1 + i % 5), y = 0.5 * (1 + (i * 7) % 9);
    if (i % 2) wall(x, y, x + 0.5, y);
    else wall(x, y, x, y + 0.5);
  }
  VisualShape marker = shape(GeometryType::Box, Eigen::Vector3d(0.01, 0.3, 0.3), pose(2.98, 2.5, 0.25),
                             {1, 1, 1, 1});
  marker.texture_file = marker_png;
  walls.push_back(marker);
  for (int i = 0; i < 10; ++i)
    walls.push_back(shape(GeometryType::Cylinder, Eigen::Vector3d(0.05, 0, 0.4),
                          pose(0.25 + 0.27 * i, 0.3 + 0.45 * i, 0.2), {0.2f, 0.3f, 0.9f, 1}));
  world.addModel(staticModel("maze", walls), Eigen::Isometry3d::Identity());

  // A robot: chassis, 4 wheels, casters, a 5-link arm with joints, a gripper, sensors: 20 parts.
  std::vector<VisualShape> robot;
  const std::array<float, 4> orange{1, 0.5f, 0.05f, 1}, black{0.1f, 0.1f, 0.1f, 1}, grey{0.5f, 0.5f, 0.5f, 1};
  robot.push_back(shape(GeometryType::Box, {0.4, 0.3, 0.1}, pose(0, 0, 0.1), orange));
  for (int i = 0; i < 4; ++i)
    robot.push_back(shape(GeometryType::Cylinder, {0.05, 0, 0.03},
                          pose(i < 2 ? 0.12 : -0.12, i % 2 ? 0.17 : -0.17, 0.05) *
                              Eigen::Isometry3d(Eigen::AngleAxisd(kPi / 2, Eigen::Vector3d::UnitX())),
                          black));
  for (int i = 0; i < 5; ++i) {
    robot.push_back(shape(GeometryType::Cylinder, {0.025, 0, 0.12}, pose(0.05, 0, 0.2 + 0.12 * i), grey));
    robot.push_back(shape(GeometryType::Sphere, {0.035, 0, 0}, pose(0.05, 0, 0.26 + 0.12 * i), orange));
  }
  robot.push_back(shape(GeometryType::Box, {0.02, 0.08, 0.05}, pose(0.05, 0, 0.85), grey));
  robot.push_back(shape(GeometryType::Box, {0.05, 0.05, 0.05}, pose(0.18, 0, 0.18), black));
  robot.push_back(shape(GeometryType::Sphere, {0.03, 0, 0}, pose(-0.15, 0, 0.03), black));
  robot.push_back(shape(GeometryType::Sphere, {0.03, 0, 0}, pose(0.15, 0, 0.03), black));
  robot.push_back(shape(GeometryType::Box, {0.06, 0.06, 0.04}, pose(0.1, 0, 0.17), grey));
  world.addModel(staticModel("robot", robot), pose(1.0, 1.3, 0));
}

struct Result {
  double mean_ms, worst_ms, cpu_ms, render_ms;  // wall per frame, worst wall, CPU (this thread), render part
};

// CPU time of the calling thread: what a frame costs even when other processes share the cores.
double threadCpuMs() {
  timespec t;
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return t.tv_sec * 1e3 + t.tv_nsec * 1e-6;
}

Result run(PhysicsWorld& world, int width, int height, double hfov, int threads, int frames) {
  CameraConfig config;
  config.width = width;
  config.height = height;
  config.horizontal_fov = hfov;
  config.near_clip = 0.02;
  config.far_clip = 300;
  config.encoding = "bgr8";  // as a B8G8R8 camera; rendered in that order directly
  RenderSettings settings;
  settings.threads = threads;
  SceneRenderer renderer(settings);
  ImageNoise noise(0.0, 0.007, 1);
  CameraImage image;
  std::vector<std::uint8_t> message;
  PhysicsModel* robot = world.findModel("robot");
  double total = 0, worst = 0, cpu = 0, render = 0;
  for (int i = -5; i < frames; ++i) {  // 5 warm-up frames (triangulation, texture loading)
    const double s = std::max(i, 0) / double(frames);
    // Down the maze's middle and back, looking around; the robot keeps 0.8 m ahead.
    const double y = 0.3 + 4.4 * (s < 0.5 ? 2 * s : 2 - 2 * s), yaw = (s < 0.5 ? kPi / 2 : -kPi / 2) + 0.6 * std::sin(12 * s);
    const Eigen::Isometry3d camera = pose(1.5, y, 0.3, yaw);
    robot->setPose(pose(1.5 + 0.8 * std::cos(yaw), y + 0.8 * std::sin(yaw), 0, yaw));
    const auto start = std::chrono::steady_clock::now();
    const double cpu_start = threadCpuMs();
    renderer.render(world, camera, config, image);
    const auto rendered = std::chrono::steady_clock::now();
    encodeImage(image, config.encoding, message);
    noise.apply(message);
    const auto end = std::chrono::steady_clock::now();
    const double ms = std::chrono::duration<double, std::milli>(end - start).count();
    if (i < 0) continue;
    total += ms;
    worst = std::max(worst, ms);
    cpu += threadCpuMs() - cpu_start;
    render += std::chrono::duration<double, std::milli>(rendered - start).count();
  }
  if (frames > 0) cv::imwrite("/tmp/bench_camera_" + std::to_string(width) + "x" + std::to_string(height) + ".png",
                              cv::Mat(height, width, CV_8UC3, message.data()));
  const double n = std::max(frames, 1);
  return {total / n, worst, cpu / n, render / n};
}

}  // namespace

int main(int argc, char** argv) {
  const int frames = argc > 1 ? std::atoi(argv[1]) : 300;
  const std::string marker = (std::filesystem::temp_directory_path() / "bench_camera_marker.png").string();
  cv::Mat checker(200, 200, CV_8UC3);
  for (int y = 0; y < 200; ++y)
    for (int x = 0; x < 200; ++x)
      checker.at<cv::Vec3b>(y, x) = ((x / 40 + y / 40) % 2) ? cv::Vec3b(255, 255, 255) : cv::Vec3b(0, 0, 0);
  cv::imwrite(marker, checker);

  PhysicsWorld world;
  buildWorld(world, marker);
  std::printf("bench_camera: %d frames per case, maze world (ground, 31 walls + marker, 10 cylinders, robot of 20)\n",
              frames);
  std::printf("per frame (render + copy into the message + noise), wall-clock mean and worst, CPU time of\n"
              "the main thread (with 2 threads the helper's share is not in it), and the render part alone:\n");
  std::printf("%-10s %-8s %-10s %-10s %-10s %-10s\n", "size", "threads", "mean ms", "worst ms", "cpu ms", "render ms");
  const struct {
    int w, h;
    double hfov;
  } sizes[] = {{800, 800, 1.3962634}, {640, 480, 1.047}};
  for (const auto& size : sizes)
    for (int threads : {1, 2}) {
      const Result r = run(world, size.w, size.h, size.hfov, threads, frames);
      std::printf("%4dx%-5d %-8d %-10.2f %-10.2f %-10.2f %-10.2f\n", size.w, size.h, threads, r.mean_ms, r.worst_ms,
                  r.cpu_ms, r.render_ms);
    }
  std::printf("last frames written to /tmp/bench_camera_WxH.png\n");
  return 0;
}
