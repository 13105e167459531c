// physics_bench: step rate of bullet_sim's physics + a PD torque controller (issue 2).
//
//   physics_bench URDF [seconds_of_sim=20] [repeats=3] [--ground]
//
// --ground adds Gazebo's ground plane, as the simulator's empty world has it (PyBullet's run has none).
// Loads URDF (normally bench/arm5.urdf) fixed to the world, and at 1 kHz applies
//   tau_j = clamp(kp_j (q*_j - q_j) + kd_j (dq*_j - dq_j), +-effort_limit_j)
// to every moving joint, tracking a slow sinusoid q*_j = A_j sin(2 pi f_j t). The timed loop is
// exactly what a controller plugin does each step: read the joint states, compute and add the
// efforts, PhysicsWorld::step(). The run is repeated `repeats` times on a fresh world and the
// median rate is reported. scripts/bench_pybullet.py runs the same law in PyBullet.
//
// Output (parsed by scripts/bench):
//   bullet_sim steps/s: X
//   bullet_sim real-time factor: Y
//   bullet_sim tracking RMS error: Z rad
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
#include "bullet_sim_core/sdf_parser.h"
#include "bullet_sim_core/urdf_parser.h"

namespace {

// The same gains, amplitudes and frequencies are in scripts/bench_pybullet.py; keep them equal.
// Joint order: shoulder_pan, shoulder_lift, elbow, wrist_pitch, wrist_roll.
const double kKp[] = {200.0, 300.0, 150.0, 30.0, 5.0};
const double kKd[] = {10.0, 15.0, 8.0, 1.0, 0.1};
const double kAmplitude[] = {0.8, 0.5, 0.7, 0.6, 1.0};  // rad
const double kFrequency[] = {0.2, 0.25, 0.3, 0.4, 0.5};  // Hz
const int kGainCount = 5;
const double kSettleTime = 1.0;  // s: errors before this are start-up transient, not tracking

struct RunResult {
  double wall_seconds = 0.0;
  long steps = 0;
  double rms_error = 0.0;  // rad, over all joints, after kSettleTime
  double max_error = 0.0;  // rad
  double step_seconds = 0.0;  // with split_timing: wall time inside PhysicsWorld::step()
  std::vector<double> joint_rms;  // rad, per joint
};

// With `split_timing`, the time spent inside PhysicsWorld::step() is also summed into
// `step_seconds` (two clock reads per step: not used for the headline rate).
bool with_ground = false;

// model://ground_plane of the empty world.
bullet_sim::ModelDescription groundPlane() {
  return bullet_sim::parseSdfModel(
      "<model name='ground_plane'><static>true</static><link name='link'><collision name='c'><geometry><plane>"
      "<normal>0 0 1</normal><size>100 100</size></plane></geometry></collision></link></model>",
      "ground_plane", "", bullet_sim::ResourceResolver());
}

RunResult runOnce(const bullet_sim::ModelDescription& description, double sim_seconds, bool split_timing = false) {
  bullet_sim::PhysicsWorld world;  // 1 ms step, gravity -9.8 z
  if (with_ground) world.addModel(groundPlane(), Eigen::Isometry3d::Identity());
  bullet_sim::PhysicsModel& model = world.addModel(description, Eigen::Isometry3d::Identity());
  const int n = static_cast<int>(model.joints().size());
  const double dt = world.settings().max_step_size;
  const long steps = std::lround(sim_seconds / dt);
  std::vector<double> limit(n);
  for (int j = 0; j < n; ++j) {
    const double e = model.joints()[j].effort_limit;
    limit[j] = (std::isfinite(e) && e > 0) ? e : 1e9;
  }

  RunResult r;
  r.steps = steps;
  double sum_sq = 0.0;
  long samples = 0;
  std::vector<double> joint_sq(n, 0.0);
  const auto start = std::chrono::steady_clock::now();
  for (long i = 0; i < steps; ++i) {
    const double t = world.time();
    for (int j = 0; j < n; ++j) {
      const int g = j % kGainCount;
      const double w = 2.0 * M_PI * kFrequency[g];
      const double target = kAmplitude[g] * std::sin(w * t);
      const double target_vel = kAmplitude[g] * w * std::cos(w * t);
      const double q = model.jointPosition(j);
      const double err = target - q;
      double tau = kKp[g] * err + kKd[g] * (target_vel - model.jointVelocity(j));
      tau = std::max(-limit[j], std::min(limit[j], tau));
      model.addJointEffort(j, tau);
      if (t >= kSettleTime) {
        sum_sq += err * err;
        joint_sq[j] += err * err;
        ++samples;
        r.max_error = std::max(r.max_error, std::abs(err));
      }
    }
    if (split_timing) {
      const auto before = std::chrono::steady_clock::now();
      world.step();
      r.step_seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - before).count();
    } else {
      world.step();
    }
  }
  const auto end = std::chrono::steady_clock::now();
  r.wall_seconds = std::chrono::duration<double>(end - start).count();
  r.rms_error = samples > 0 ? std::sqrt(sum_sq / samples) : 0.0;
  for (int j = 0; j < n; ++j) r.joint_rms.push_back(samples > 0 ? std::sqrt(joint_sq[j] * n / samples) : 0.0);
  return r;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc > 1 && std::string(argv[argc - 1]) == "--ground") {
    with_ground = true;
    --argc;
  }
  if (argc < 2 || argc > 4) {
    std::cerr << "usage: physics_bench URDF [seconds_of_sim=20] [repeats=3] [--ground]\n";
    return 2;
  }
  const std::string path = argv[1];
  const double seconds = argc > 2 ? std::atof(argv[2]) : 20.0;
  const int repeats = argc > 3 ? std::atoi(argv[3]) : 3;
  if (!(seconds > kSettleTime) || repeats < 1) {
    std::cerr << "physics_bench: expected seconds_of_sim > " << kSettleTime << " and repeats >= 1\n";
    return 2;
  }
  std::ifstream in(path);
  if (!in) {
    std::cerr << "physics_bench: cannot read '" << path << "'\n";
    return 1;
  }
  std::stringstream text;
  text << in.rdbuf();
  try {
    const std::string base_dir = path.find('/') == std::string::npos ? "." : path.substr(0, path.rfind('/'));
    const bullet_sim::ModelDescription description =
        bullet_sim::parseUrdf(text.str(), path, bullet_sim::ResourceResolver::fromEnvironment(), base_dir);
    {
      bullet_sim::PhysicsWorld probe;
      const bullet_sim::PhysicsModel& m = probe.addModel(description, Eigen::Isometry3d::Identity());
      std::printf("bullet_sim model '%s': %zu moving joints, fixed base: %s\n", m.name().c_str(), m.joints().size(),
                  description.fixed_base ? "yes" : "no");
    }
    runOnce(description, 1.5);  // warm-up: page in code and data, let the CPU clock up

    std::vector<RunResult> runs;
    for (int i = 0; i < repeats; ++i) {
      runs.push_back(runOnce(description, seconds));
      const RunResult& r = runs.back();
      std::printf("  run %d: %ld steps in %.3f s wall = %.0f steps/s\n", i + 1, r.steps, r.wall_seconds,
                  r.steps / r.wall_seconds);
    }
    std::vector<double> rates;
    for (const RunResult& r : runs) rates.push_back(r.steps / r.wall_seconds);
    std::sort(rates.begin(), rates.end());
    const double median = rates[rates.size() / 2];
    const double dt = bullet_sim::PhysicsSettings().max_step_size;
    std::printf("bullet_sim steps/s: %.0f\n", median);
    std::printf("bullet_sim us/step: %.2f\n", 1e6 / median);
    std::printf("bullet_sim real-time factor: %.1f\n", median * dt);
    std::printf("bullet_sim tracking RMS error: %.4f rad (max %.4f rad, after %.0f s)\n", runs.front().rms_error,
                runs.front().max_error, kSettleTime);
    const RunResult split = runOnce(description, seconds, true);
    std::printf("bullet_sim physics share: %.2f us/step in PhysicsWorld::step() = %.0f steps/s without control\n",
                1e6 * split.step_seconds / split.steps, split.steps / split.step_seconds);
    std::printf("bullet_sim per-joint RMS error (rad):");
    for (double e : runs.front().joint_rms) std::printf(" %.4f", e);
    std::printf("\n");
  } catch (const std::exception& e) {
    std::cerr << "physics_bench: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
