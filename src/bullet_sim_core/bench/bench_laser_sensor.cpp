// Micro-benchmark of LaserScanner::scan in a small maze (3 x 5 m, 0.04 m walls, interior walls,
// 20 obstacles, a ground plane), against the naive scan: one btCollisionWorld::rayTest per beam.
// Also counts the beams where the naive scan disagrees by more than 5 mm. Those are Bullet's
// convex casts being approximate: spot checks by marching along the beam in 0.1 mm steps agreed
// with LaserScanner every time (its box/cylinder/sphere/plane tests are closed-form).
//   usage: bench_laser_sensor [scans=2000]
#include <BulletCollision/NarrowPhaseCollision/btRaycastCallback.h>
#include <btBulletCollisionCommon.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <limits>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include "bullet_sim_core/laser_sensor.h"

namespace {

using bullet_sim::LaserConfig;
using bullet_sim::LaserScanner;

constexpr double kPi = 3.14159265358979323846;

// Owns a btCollisionWorld and what is in it; the world is declared last so it goes first.
class Maze {
 public:
  Maze()
      : config_(std::make_unique<btDefaultCollisionConfiguration>()),
        dispatcher_(std::make_unique<btCollisionDispatcher>(config_.get())),
        broadphase_(std::make_unique<btDbvtBroadphase>()),
        world_(std::make_unique<btCollisionWorld>(dispatcher_.get(), broadphase_.get(), config_.get())) {
    add(std::make_unique<btStaticPlaneShape>(btVector3(0, 0, 1), 0), btVector3(0, 0, 0));
    const double t = 0.04, h = 0.25;  // wall thickness, half height
    // Outer rectangle x in [0, 3], y in [0, 5].
    wall(1.5, -t / 2, 1.5 + t, t / 2, h);
    wall(1.5, 5 + t / 2, 1.5 + t, t / 2, h);
    wall(-t / 2, 2.5, t / 2, 2.5, h);
    wall(3 + t / 2, 2.5, t / 2, 2.5, h);
    // Interior walls.
    wall(1.0, 1.0, 1.0, t / 2, h);
    wall(2.0, 2.0, 1.0, t / 2, h);
    wall(1.0, 3.0, 1.0, t / 2, h);
    wall(2.0, 4.0, 1.0, t / 2, h);
    wall(1.5, 0.5, t / 2, 0.5, h);
    wall(1.5, 4.5, t / 2, 0.5, h);
    // Obstacles: boxes and cylinders scattered off the robot's path (see poseAt).
    std::mt19937 gen(1);
    std::uniform_real_distribution<double> x(0.2, 2.8), y(0.2, 4.8), s(0.03, 0.12), yaw(0, kPi);
    for (int i = 0; i < 20; ++i) {
      btVector3 p(x(gen), y(gen), h);
      while (p.y() > 1.1 && p.y() < 1.9) p.setY(y(gen));
      btQuaternion q;
      q.setEulerZYX(yaw(gen), 0, 0);
      if (i % 2) add(std::make_unique<btBoxShape>(btVector3(s(gen), s(gen), h)), p, q);
      else add(std::make_unique<btCylinderShapeZ>(btVector3(s(gen), s(gen), h)), p);
    }
  }
  const btCollisionWorld& world() const { return *world_; }
  int objects() const { return world_->getNumCollisionObjects(); }

 private:
  void wall(double cx, double cy, double hx, double hy, double hz) {
    add(std::make_unique<btBoxShape>(btVector3(hx, hy, hz)), btVector3(cx, cy, hz));
  }
  void add(std::unique_ptr<btCollisionShape> shape, const btVector3& p, const btQuaternion& q = btQuaternion::getIdentity()) {
    shape->setMargin(0.001);
    auto object = std::make_unique<btCollisionObject>();
    object->setCollisionShape(shape.get());
    object->setWorldTransform(btTransform(q, p));
    world_->addCollisionObject(object.get());
    shapes_.push_back(std::move(shape));
    objects_.push_back(std::move(object));
  }

  std::unique_ptr<btDefaultCollisionConfiguration> config_;
  std::unique_ptr<btCollisionDispatcher> dispatcher_;
  std::unique_ptr<btDbvtBroadphase> broadphase_;
  std::vector<std::unique_ptr<btCollisionShape>> shapes_;
  std::vector<std::unique_ptr<btCollisionObject>> objects_;
  std::unique_ptr<btCollisionWorld> world_;
};

// The sensor's pose for scan k: a robot going to and fro along the corridor between the walls
// at y = 1 and y = 2, turning as it goes, the scanner 0.2 m above the ground.
btTransform poseAt(int k, int scans) {
  const double s = 2 * kPi * k / scans;
  btQuaternion q;
  q.setEulerZYX(3 * s, 0, 0);
  return btTransform(q, btVector3(1.5 + 1.1 * std::sin(s), 1.5 + 0.2 * std::cos(s), 0.2));
}

// The straightforward scan: one world.rayTest per beam (Bullet's default convex cast, or GJK),
// same REP 117 post-processing.
void naiveScan(const LaserScanner& s, const btCollisionWorld& world, const btTransform& pose, bool gjk,
               std::vector<float>& out) {
  const LaserConfig& c = s.config();
  out.resize(s.beam_count());
  const btVector3 from = pose.getOrigin();
  for (int i = 0; i < s.beam_count(); ++i) {
    const double a = c.min_angle + i * s.angle_increment();
    const btVector3 to = from + pose.getBasis() * btVector3(std::cos(a), std::sin(a), 0) * c.range_max;
    btCollisionWorld::ClosestRayResultCallback cb(from, to);
    if (gjk) cb.m_flags = btTriangleRaycastCallback::kF_UseGjkConvexCastRaytest;
    world.rayTest(from, to, cb);
    const double r = cb.hasHit() ? cb.m_closestHitFraction * c.range_max : c.range_max;
    out[i] = r >= c.range_max ? std::numeric_limits<float>::infinity()
             : r <= c.range_min ? -std::numeric_limits<float>::infinity() : static_cast<float>(r);
  }
}

using ScanFn = std::function<void(const btTransform&, std::vector<float>&)>;

// Mean microseconds per scan over `scans` poses along the loop.
double time(int scans, const ScanFn& scan) {
  std::vector<float> ranges;
  for (int k = 0; k < 50; ++k) scan(poseAt(k, scans), ranges);  // warm-up
  const auto t0 = std::chrono::steady_clock::now();
  for (int k = 0; k < scans; ++k) scan(poseAt(k, scans), ranges);
  return std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - t0).count() / scans;
}

// How many beams of `other` differ from `reference` by more than 5 mm (or in kind: hit vs inf).
std::pair<int, int> compare(int scans, const ScanFn& reference, const ScanFn& other) {
  int differ = 0, total = 0;
  std::vector<float> a, b;
  for (int k = 0; k < scans; k += 37) {
    reference(poseAt(k, scans), a);
    other(poseAt(k, scans), b);
    for (size_t i = 0; i < a.size(); ++i, ++total)
      if (!(a[i] == b[i] || std::abs(a[i] - b[i]) <= 5e-3)) ++differ;
  }
  return {differ, total};
}

void report(const char* what, int beams, double us, std::pair<int, int> differ) {
  std::printf("  %-18s %8.1f us/scan  %6.2f Mrays/s  %6.2f %% of a core at 40 Hz", what, us, beams / us, us * 40 / 1e4);
  if (differ.second) std::printf("   %d of %d beams differ > 5 mm", differ.first, differ.second);
  std::printf("\n");
}

void bench(const Maze& maze, const char* name, int samples, double min_angle, double max_angle, double range_max,
           int scans) {
  LaserConfig c;
  c.samples = samples;
  c.min_angle = min_angle;
  c.max_angle = max_angle;
  c.range_min = 0.12;
  c.range_max = range_max;
  const LaserScanner s(c);
  std::mt19937 rng(0);
  const ScanFn batched = [&](const btTransform& p, std::vector<float>& r) { s.scan(maze.world(), p, {}, rng, r); };
  const ScanFn naive = [&](const btTransform& p, std::vector<float>& r) { naiveScan(s, maze.world(), p, false, r); };
  const ScanFn naive_gjk = [&](const btTransform& p, std::vector<float>& r) { naiveScan(s, maze.world(), p, true, r); };
  std::printf("%s: %d beams, range %.0f m, %d scans\n", name, s.beam_count(), range_max, scans);
  const double us = time(scans, batched);
  report("batched", s.beam_count(), us, {0, 0});
  const double us_naive = time(scans, naive);
  report("naive rayTest", s.beam_count(), us_naive, compare(scans, batched, naive));
  const double us_gjk = time(scans, naive_gjk);
  report("naive rayTest GJK", s.beam_count(), us_gjk, compare(scans, batched, naive_gjk));
  std::printf("  batched is %.1fx faster than naive, %.1fx than naive GJK\n", us_naive / us, us_gjk / us);
}

}  // namespace

int main(int argc, char** argv) {
  const int scans = argc > 1 ? std::max(1, std::atoi(argv[1])) : 2000;
  const Maze maze;
  std::printf("maze: %d collision objects (walls, obstacles, ground plane)\n", maze.objects());
  bench(maze, "720-beam scanner (+-pi)", 720, -kPi, kPi, 30.0, scans);
  bench(maze, "359-beam scanner (0..2pi)", 359, 0.0, 2 * kPi, 6.0, scans);
  std::printf("CPU share = us/scan * 40 Hz. Reproduce (optimised build, e.g. catkin build bullet_sim): %s %d\n",
              argv[0], scans);
  return 0;
}
