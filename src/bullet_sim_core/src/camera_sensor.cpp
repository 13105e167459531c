#include "bullet_sim_core/camera_sensor.h"

namespace bullet_sim {
namespace {

constexpr double kPi = 3.14159265358979323846;

// gazebo_ros_camera_utils' formats (the 16-bit and Bayer ones are not supported).
bool encodingOf(const std::string& format, std::string& encoding) {
  if (format == "R8G8B8" || format == "RGB_INT8") encoding = "rgb8";
  else if (format == "B8G8R8" || format == "BGR_INT8") encoding = "bgr8";
  else if (format == "L8" || format == "L_INT8") encoding = "mono8";
  else return false;
  return true;
}

}  // namespace

bool isCameraSensor(const SensorDescription& sensor) { return sensor.type == "camera"; }

CameraConfig parseCameraSensor(const SensorDescription& sensor) {
  const SdfElement& e = sensor.element;
  CameraConfig c;
  c.name = sensor.name;
  c.link = sensor.link;
  c.pose = e.pose();
  c.update_rate = e.number("update_rate", c.update_rate, nonNegative());
  c.always_on = e.boolean("always_on", c.always_on);
  c.visualize = e.boolean("visualize", c.visualize);

  const SdfElement camera = e.child("camera");
  c.horizontal_fov =
      camera.number("horizontal_fov", c.horizontal_fov, {[](double v) { return v > 0 && v < kPi; }, "in (0, pi) radians"});
  const SdfElement image = camera.child("image");
  c.width = static_cast<int>(image.integer("width", c.width, 1, 16384));
  c.height = static_cast<int>(image.integer("height", c.height, 1, 16384));
  c.format = image.string("format", c.format);
  if (!encodingOf(c.format, c.encoding))
    image.child("format").fail("expected one of R8G8B8, RGB_INT8, B8G8R8, BGR_INT8, L8, L_INT8, got '" + c.format + "'");

  const SdfElement clip = camera.child("clip");
  c.near_clip = clip.number("near", c.near_clip, positive());
  c.far_clip = clip.number("far", c.far_clip, greaterThan(c.near_clip, "<near>"));

  if (const SdfElement noise = camera.child("noise")) {
    c.noise_type = noise.string("type", "gaussian");  // noise.sdf's type is required; cameras support gaussian
    if (c.noise_type != "none" && c.noise_type != "gaussian" && c.noise_type != "gaussian_quantized")
      noise.child("type").fail("expected one of none, gaussian, gaussian_quantized, got '" + c.noise_type + "'");
    c.noise_mean = noise.number("mean", 0.0);
    c.noise_stddev = noise.number("stddev", 0.0, nonNegative());
  }
  return c;
}

}  // namespace bullet_sim
