// bench_skid_steer: a wheeled vehicle on bullet_sim's physics core, one set of wheel speeds.
//
//   bench_skid_steer URDF --torque T --joint NAME=RAD_PER_S [--joint ...] [--z 0] [--yaw 0]
//       [--settle 0.5] [--seconds 4] [--window 1] [--gate CENTER,HALF [--gate-seconds 1]]
//       [--trace BIN_SECONDS] [--contacts] [--iters 50] [--tolerance 1e-5] [--cold]
//
// The counterpart of scripts/bench_skid_steer_pybullet.py, with the same protocol: a ground
// plane of friction 1 (the SDF worlds' built-in ground_plane), the URDF (xacro-expanded) with
// its root link frame spawned at (0, 0, Z) heading YAW degrees, gravity -9.8, 1 ms steps. The
// wheels are held at 0 rad/s for SETTLE seconds while the vehicle lands, then each --joint gets
// its velocity command through PhysicsModel::setJointMotor(joint, 0, speed, 0, T), exactly as
// the diff drive and skid steer plugins drive their wheels, for up to SECONDS.
//
// Printed is one JSON line: the mean yaw rate and forward speed (the root link frame's velocity
// along its own x) over the samples from WINDOW seconds after the command on. With --gate only
// the samples whose heading (mod 90 degrees) lies within CENTER +- HALF degrees count, and the
// run stops once GATE_SECONDS of them are in (the yaw rate of Bullet's Featherstone contacts
// depends on the heading relative to the world axes; scripts/bench_skid_steer.py explains).
// Also: the base height's spread and the largest tilt over the counted samples, the wall time
// per physics step, with --trace the means in bins of BIN_SECONDS ([t, yaw rate, forward speed,
// heading]), with --contacts every link's contact points with the ground at the end, and the
// solver's sweeps per solve (--iters and --tolerance set its sweeps and early stop, as a world's
// <iters> and PhysicsSettings::solver_tolerance do; --cold starts every step's solve from zero
// impulses, as Bullet's own solver does).
#include <BulletCollision/NarrowPhaseCollision/btPersistentManifold.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include "bullet_sim_core/physics_world.h"
#include "bullet_sim_core/resource_resolver.h"
#include "bullet_sim_core/urdf_parser.h"

namespace {

struct Options {
  std::string urdf;
  double z = 0.0;
  double yaw_deg = 0.0;
  double torque = 0.0;
  std::vector<std::pair<std::string, double>> joints;
  double settle = 0.5;
  double seconds = 4.0;
  double window = 1.0;
  bool gated = false;
  double gate_center = 45.0, gate_half = 7.5;  // degrees, heading mod 90
  double gate_seconds = 1.0;
  double trace = 0.0;  // s per bin; 0: no trace
  bool contacts = false;
  bullet_sim::PhysicsSettings physics;  // 1 ms steps, gravity -9.8 z
  bool cold = false;
};

[[noreturn]] void usage(const std::string& why) {
  std::cerr << "bench_skid_steer: " << why << "\n"
            << "usage: bench_skid_steer URDF --torque T --joint NAME=RAD_PER_S [--joint ...] [--z 0] [--yaw 0]\n"
            << "       [--settle 0.5] [--seconds 4] [--window 1] [--gate CENTER,HALF [--gate-seconds 1]]\n"
            << "       [--trace BIN_SECONDS] [--contacts] [--iters 50] [--tolerance 1e-5] [--cold]\n";
  std::exit(2);
}

Options parseArgs(int argc, char** argv) {
  Options o;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    auto value = [&]() -> std::string {
      if (i + 1 >= argc) usage(a + " needs a value");
      return argv[++i];
    };
    if (a == "--z") o.z = std::atof(value().c_str());
    else if (a == "--yaw") o.yaw_deg = std::atof(value().c_str());
    else if (a == "--torque") o.torque = std::atof(value().c_str());
    else if (a == "--settle") o.settle = std::atof(value().c_str());
    else if (a == "--seconds") o.seconds = std::atof(value().c_str());
    else if (a == "--window") o.window = std::atof(value().c_str());
    else if (a == "--gate-seconds") o.gate_seconds = std::atof(value().c_str());
    else if (a == "--trace") o.trace = std::atof(value().c_str());
    else if (a == "--contacts") o.contacts = true;
    else if (a == "--iters") o.physics.solver_iterations = std::atoi(value().c_str());
    else if (a == "--tolerance") o.physics.solver_tolerance = std::atof(value().c_str());
    else if (a == "--cold") o.cold = true;
    else if (a == "--gate") {
      const std::string v = value();
      if (std::sscanf(v.c_str(), "%lf,%lf", &o.gate_center, &o.gate_half) != 2 || !(o.gate_half > 0))
        usage("--gate expects CENTER,HALF in degrees, got '" + v + "'");
      o.gated = true;
    } else if (a == "--joint") {
      const std::string v = value();
      const auto eq = v.find('=');
      if (eq == std::string::npos) usage("--joint expects NAME=RAD_PER_S, got '" + v + "'");
      o.joints.emplace_back(v.substr(0, eq), std::atof(v.c_str() + eq + 1));
    } else if (!a.empty() && a[0] == '-') usage("unknown option " + a);
    else if (o.urdf.empty()) o.urdf = a;
    else usage("more than one URDF given");
  }
  if (o.urdf.empty()) usage("no URDF given");
  if (!(o.torque > 0)) usage("--torque must be > 0");
  if (!(o.seconds > o.window) || o.window < 0 || o.settle < 0) usage("expected 0 <= window < seconds, settle >= 0");
  return o;
}

bullet_sim::ModelDescription groundPlane() {
  bullet_sim::ModelDescription ground;
  ground.name = "ground_plane";
  ground.is_static = true;
  ground.links.emplace_back();
  ground.links[0].name = "link";
  ground.links[0].collisions.emplace_back();
  ground.links[0].collisions[0].geometry.type = bullet_sim::GeometryType::Plane;
  return ground;  // mu1 = mu2 = 1
}

// The contact points between each of the model's bodies and the ground, as JSON: world
// position, position in the frame of the body's first link, depth and normal force.
std::string contactReport(bullet_sim::PhysicsWorld& world, const bullet_sim::PhysicsModel& model,
                          const bullet_sim::PhysicsModel& ground, double dt) {
  const btCollisionObject* plane = ground.linkCollider("link");
  std::ostringstream out;
  out << "{";
  bool first_body = true;
  btDispatcher* dispatcher = world.bulletWorld().getDispatcher();
  for (const std::string& link : model.linkNames()) {
    const btCollisionObject* collider = model.linkCollider(link);
    if (!collider) continue;
    bool first_link_of_body = false;  // a merged body is reported once, under its first link
    for (const auto& l : model.description().links)
      if (model.linkCollider(l.name) == collider) {
        first_link_of_body = (l.name == link);
        break;
      }
    if (!first_link_of_body) continue;
    const Eigen::Isometry3d link_pose = model.linkPose(link);
    std::ostringstream points;
    int count = 0;
    double force = 0.0;
    for (int m = 0; m < dispatcher->getNumManifolds(); ++m) {
      const btPersistentManifold* manifold = dispatcher->getManifoldByIndexInternal(m);
      const bool a_is_link = manifold->getBody0() == collider && manifold->getBody1() == plane;
      const bool b_is_link = manifold->getBody1() == collider && manifold->getBody0() == plane;
      if (!a_is_link && !b_is_link) continue;
      for (int k = 0; k < manifold->getNumContacts(); ++k) {
        const btManifoldPoint& cp = manifold->getContactPoint(k);
        const btVector3 p = a_is_link ? cp.getPositionWorldOnA() : cp.getPositionWorldOnB();
        const Eigen::Vector3d world_p(p.x(), p.y(), p.z());
        const Eigen::Vector3d local = link_pose.inverse() * world_p;
        char buffer[256];
        std::snprintf(buffer, sizeof(buffer),
                      "%s{\"world\":[%.5f,%.5f,%.6f],\"in_link\":[%.5f,%.5f,%.5f],\"depth\":%.3g,\"normal_force\":%.4g}",
                      count ? "," : "", world_p.x(), world_p.y(), world_p.z(), local.x(), local.y(), local.z(),
                      cp.getDistance(), cp.getAppliedImpulse() / dt);
        points << buffer;
        force += cp.getAppliedImpulse() / dt;
        ++count;
      }
    }
    if (count == 0) continue;
    out << (first_body ? "" : ",") << "\"" << link << "\":{\"points\":" << count << ",\"normal_force\":" << force
        << ",\"list\":[" << points.str() << "]}";
    first_body = false;
  }
  out << "}";
  return out.str();
}

double yawOf(const Eigen::Isometry3d& pose) {
  const Eigen::Matrix3d r = pose.linear();
  return std::atan2(r(1, 0), r(0, 0));
}

// Heading in [0, 90) degrees: the friction directions of Bullet's contacts repeat every 90.
double headingMod90(double heading_rad) {
  const double deg = std::fmod(heading_rad * 180.0 / M_PI, 90.0);
  return deg < 0 ? deg + 90.0 : deg;
}

}  // namespace

int main(int argc, char** argv) {
  const Options o = parseArgs(argc, argv);
  std::ifstream in(o.urdf);
  if (!in) {
    std::cerr << "bench_skid_steer: cannot read '" << o.urdf << "'\n";
    return 1;
  }
  std::stringstream text;
  text << in.rdbuf();
  try {
    const std::string base_dir = o.urdf.find('/') == std::string::npos ? "." : o.urdf.substr(0, o.urdf.rfind('/'));
    const bullet_sim::ModelDescription description =
        bullet_sim::parseUrdf(text.str(), o.urdf, bullet_sim::ResourceResolver::fromEnvironment(), base_dir);
    bullet_sim::PhysicsWorld world(o.physics);
    world.solver().setWarmStart(!o.cold);
    const bullet_sim::PhysicsModel& ground = world.addModel(groundPlane(), Eigen::Isometry3d::Identity());
    Eigen::Isometry3d spawn = Eigen::Isometry3d::Identity();
    spawn.translation().z() = o.z;
    spawn.linear() = Eigen::AngleAxisd(o.yaw_deg * M_PI / 180.0, Eigen::Vector3d::UnitZ()).toRotationMatrix();
    bullet_sim::PhysicsModel& model = world.addModel(description, spawn);
    const double dt = world.settings().max_step_size;

    std::vector<std::pair<int, double>> commands;
    for (const auto& [name, speed] : o.joints) {
      const int j = model.jointIndex(name);
      if (j < 0) usage("no moving joint named '" + name + "' in " + o.urdf);
      commands.emplace_back(j, speed);
      model.setJointMotor(j, 0.0, 0.0, 0.0, o.torque);  // hold the wheels while the vehicle lands
    }
    const long settle_steps = std::lround(o.settle / dt);
    const long steps = std::lround(o.seconds / dt);
    const long window_start = std::lround(o.window / dt);
    const long gate_steps = std::lround(o.gate_seconds / dt);
    for (long i = 0; i < settle_steps; ++i) world.step();
    for (const auto& [j, speed] : commands) model.setJointMotor(j, 0.0, speed, 0.0, o.torque);
    world.solver().resetCounters();

    double yaw_sum = 0, fwd_sum = 0, lat_sum = 0, z_sum = 0, z_sq = 0, tilt_max = 0;
    double z_min = 1e9, z_max = -1e9, step_seconds = 0;
    long n = 0, done = 0;
    double heading = yawOf(model.pose()), last_yaw = heading;
    const long trace_steps = o.trace > 0 ? std::max(1L, std::lround(o.trace / dt)) : 0;
    std::ostringstream trace;
    double bin_yaw = 0, bin_fwd = 0;
    for (long i = 0; i < steps; ++i) {
      const auto before = std::chrono::steady_clock::now();
      world.step();
      step_seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - before).count();
      done = i + 1;
      const Eigen::Isometry3d pose = model.pose();
      const bullet_sim::Twist twist = model.twist();
      const double yaw = yawOf(pose);
      heading += std::remainder(yaw - last_yaw, 2 * M_PI);
      last_yaw = yaw;
      const double hx = std::cos(yaw), hy = std::sin(yaw);
      const double forward = twist.linear.x() * hx + twist.linear.y() * hy;
      if (trace_steps) {
        bin_yaw += twist.angular.z();
        bin_fwd += forward;
        if ((i + 1) % trace_steps == 0) {
          char buffer[128];
          std::snprintf(buffer, sizeof(buffer), "%s[%.4g,%.6g,%.6g,%.6g]", trace.tellp() > 0 ? "," : "",
                        (i + 1) * dt, bin_yaw / trace_steps, bin_fwd / trace_steps, heading);
          trace << buffer;
          bin_yaw = bin_fwd = 0;
        }
      }
      if (i + 1 < window_start) continue;
      if (o.gated && std::abs(headingMod90(heading) - o.gate_center) > o.gate_half) continue;
      yaw_sum += twist.angular.z();
      fwd_sum += forward;
      lat_sum += -twist.linear.x() * hy + twist.linear.y() * hx;
      const double z = pose.translation().z();
      z_sum += z;
      z_sq += z * z;
      z_min = std::min(z_min, z);
      z_max = std::max(z_max, z);
      tilt_max = std::max(tilt_max, std::acos(std::max(-1.0, std::min(1.0, pose.linear()(2, 2)))));
      ++n;
      if (o.gated && n >= gate_steps && !trace_steps) break;
    }
    std::printf("{\"engine\": \"bullet_sim\", \"samples\": %ld, \"end_time\": %.4g, \"us_per_step\": %.4g, "
                "\"sweeps_per_solve\": %.4g", n, done * dt, 1e6 * step_seconds / std::max(1L, done),
                static_cast<double>(world.solver().sweeps()) / std::max(1L, world.solver().solves()));
    if (n > 0) {
      const double z_mean = z_sum / n;
      std::printf(", \"yaw_rate\": %.9g, \"forward_speed\": %.9g, \"lateral_speed\": %.9g, \"z_mean\": %.9g, "
                  "\"z_std\": %.9g, \"z_ptp\": %.9g, \"tilt_max\": %.9g",
                  yaw_sum / n, fwd_sum / n, lat_sum / n, z_mean,
                  std::sqrt(std::max(0.0, z_sq / n - z_mean * z_mean)), z_max - z_min, tilt_max);
    } else {
      std::printf(", \"yaw_rate\": null, \"forward_speed\": null");
    }
    if (trace_steps) std::printf(", \"trace\": [%s]", trace.str().c_str());
    if (o.contacts) std::printf(", \"contacts\": %s", contactReport(world, model, ground, dt).c_str());
    std::printf("}\n");
  } catch (const std::exception& e) {
    std::cerr << "bench_skid_steer: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
