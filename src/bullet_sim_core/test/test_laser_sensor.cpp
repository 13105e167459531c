// Laser sensor: parsing of <sensor type="ray"> blocks, and scans checked against analytic
// distances in small Bullet worlds.
#include <gtest/gtest.h>

#include <BulletCollision/NarrowPhaseCollision/btRaycastCallback.h>
#include <btBulletCollisionCommon.h>

#include <cmath>
#include <limits>
#include <memory>
#include <numeric>
#include <random>
#include <string>
#include <vector>

#include "bullet_sim_core/description_error.h"
#include "bullet_sim_core/laser_sensor.h"
#include "bullet_sim_core/sdf_parser.h"
#include "bullet_sim_core/urdf_parser.h"
#include "bullet_sim_core/testing/error_of.h"

namespace bullet_sim {
namespace {

constexpr double kPi = 3.14159265358979323846;
const float kInf = std::numeric_limits<float>::infinity();

// ---------------------------------------------------------------------------------------------
// Parsing
// ---------------------------------------------------------------------------------------------

// The laser sensors of a URDF with the link `link` and the <gazebo> blocks `blocks`.
std::vector<LaserConfig> parse(const std::string& blocks, const std::string& link = "ray") {
  const ModelDescription m =
      parseUrdf("<robot name='m'><link name='" + link + "'/>" + blocks + "</robot>", "model.urdf", ResourceResolver(), "");
  std::vector<LaserConfig> out;
  for (const SensorDescription& s : m.sensors)
    if (isLaserSensor(s)) out.push_back(parseLaserSensor(s));
  return out;
}

// A URDF block with one ray sensor whose <ray> is `ray` and whose other children are `extra`.
std::string block(const std::string& ray, const std::string& extra = "") {
  return "<gazebo reference='ray'><sensor name='lidar' type='ray'>" + extra + "<ray>" + ray +
         "</ray></sensor></gazebo>";
}

const std::string kRange = "<range><min>0.05</min><max>10</max></range>";

// The DescriptionError message of parsing `xml`, or "" when it parses.
std::string errorOf(const std::string& xml) { return bullet_sim::errorOf([&] { parse(xml); }); }

TEST(LaserParse, DefaultsAreGazebos) {
  const auto sensors = parse(block(kRange));
  ASSERT_EQ(sensors.size(), 1u);
  const LaserConfig& c = sensors[0];
  EXPECT_EQ(c.name, "lidar");
  EXPECT_EQ(c.type, "ray");
  EXPECT_EQ(c.link, "ray");
  EXPECT_TRUE(c.pose.isApprox(Eigen::Isometry3d::Identity()));
  EXPECT_EQ(c.update_rate, 0.0);
  EXPECT_FALSE(c.always_on);
  EXPECT_FALSE(c.visualize);
  EXPECT_EQ(c.samples, 640);
  EXPECT_EQ(c.resolution, 1.0);
  EXPECT_EQ(c.min_angle, 0.0);
  EXPECT_EQ(c.max_angle, 0.0);
  EXPECT_EQ(c.vertical_samples, 1);
  EXPECT_EQ(c.range_min, 0.05);
  EXPECT_EQ(c.range_max, 10.0);
  EXPECT_EQ(c.range_resolution, 0.0);
  EXPECT_EQ(c.noise_type, "none");
  EXPECT_EQ(c.noise_stddev, 0.0);
}

TEST(LaserParse, EveryField) {
  const std::string xml = R"(
    <gazebo reference="base_scan">
      <sensor type="ray" name="head_hokuyo_sensor">
        <pose>0.1 -0.2 0.3 0 0 1.5</pose>
        <visualize>true</visualize>
        <update_rate>40</update_rate>
        <always_on>1</always_on>
        <ray>
          <scan>
            <horizontal>
              <samples>720</samples><resolution>1</resolution>
              <min_angle>-1.570796</min_angle><max_angle>1.570796</max_angle>
            </horizontal>
            <vertical><samples>1</samples><resolution>1</resolution>
              <min_angle>-0.1</min_angle><max_angle>0.2</max_angle></vertical>
          </scan>
          <range><min>0.10</min><max>30.0</max><resolution>0.01</resolution></range>
          <noise><type>gaussian</type><mean>0.001</mean><stddev>0.01</stddev></noise>
        </ray>
        <plugin name="gazebo_ros_head_hokuyo_controller" filename="libgazebo_ros_laser.so">
          <topicName>/rrbot/laser/scan</topicName>
          <frameName>hokuyo_link</frameName>
          <robotNamespace>rrbot</robotNamespace>
          <gaussianNoise>0.005</gaussianNoise>
          <hokuyoMinIntensity>101</hokuyoMinIntensity>
        </plugin>
      </sensor>
    </gazebo>)";
  const auto sensors = parse(xml, "base_scan");
  ASSERT_EQ(sensors.size(), 1u);
  const LaserConfig& c = sensors[0];
  EXPECT_EQ(c.name, "head_hokuyo_sensor");
  EXPECT_EQ(c.link, "base_scan");
  EXPECT_TRUE(c.pose.translation().isApprox(Eigen::Vector3d(0.1, -0.2, 0.3)));
  EXPECT_TRUE(c.pose.linear().isApprox(Eigen::AngleAxisd(1.5, Eigen::Vector3d::UnitZ()).toRotationMatrix()));
  EXPECT_TRUE(c.visualize);
  EXPECT_TRUE(c.always_on);
  EXPECT_EQ(c.update_rate, 40.0);
  EXPECT_EQ(c.samples, 720);
  EXPECT_EQ(c.resolution, 1.0);
  EXPECT_DOUBLE_EQ(c.min_angle, -1.570796);
  EXPECT_DOUBLE_EQ(c.max_angle, 1.570796);
  EXPECT_EQ(c.vertical_samples, 1);
  EXPECT_DOUBLE_EQ(c.vertical_min_angle, -0.1);
  EXPECT_DOUBLE_EQ(c.vertical_max_angle, 0.2);
  EXPECT_DOUBLE_EQ(c.range_min, 0.1);
  EXPECT_DOUBLE_EQ(c.range_max, 30.0);
  EXPECT_DOUBLE_EQ(c.range_resolution, 0.01);
  EXPECT_EQ(c.noise_type, "gaussian");
  EXPECT_DOUBLE_EQ(c.noise_mean, 0.001);
  EXPECT_DOUBLE_EQ(c.noise_stddev, 0.01);
}

TEST(LaserParse, GpuRaySdfSensorAndOtherSensors) {
  const std::string blocks =
      "<gazebo><plugin name='x' filename='libgazebo_ros_control.so'/></gazebo>"
      "<gazebo reference='laser'><material>Gazebo/Black</material>"
      "<sensor name='gpu' type='gpu_ray'><ray>" + kRange + "</ray>"
      "<plugin name='p' filename='libgazebo_ros_gpu_laser.so'><topicName>scan</topicName></plugin>"
      "</sensor><sensor name='imu' type='imu'/><sensor name='cam' type='camera'/></gazebo>";
  const auto sensors = parse(blocks, "laser");
  ASSERT_EQ(sensors.size(), 1u);
  EXPECT_EQ(sensors[0].name, "gpu");
  EXPECT_EQ(sensors[0].type, "gpu_ray");
  EXPECT_EQ(sensors[0].link, "laser");
  // An SDF link's sensor: its link is the SDF link.
  const ModelDescription m = parseSdfModel("<model name='m'><link name='base'><sensor name='sdf_lidar' type='ray'><ray>" +
                                               kRange + "</ray></sensor></link></model>",
                                           "m.sdf", "", ResourceResolver());
  ASSERT_EQ(m.sensors.size(), 1u);
  const LaserConfig sdf = parseLaserSensor(m.sensors[0]);
  EXPECT_EQ(sdf.name, "sdf_lidar");
  EXPECT_EQ(sdf.link, "base");
  EXPECT_DOUBLE_EQ(sdf.range_max, 10.0);
}

TEST(LaserParse, VerticalPoseTurnsTheScanPlane) {
  const auto sensors = parse(block(kRange, "<pose>0 0 0.2 1.5707963 0 0</pose>"));
  ASSERT_EQ(sensors.size(), 1u);
  // Fixed-axis RPY: roll about x takes the sensor's y axis (and the scan plane) to vertical.
  const Eigen::Vector3d y = sensors[0].pose.linear() * Eigen::Vector3d::UnitY();
  EXPECT_TRUE(y.isApprox(Eigen::Vector3d::UnitZ(), 1e-6)) << y.transpose();
  // And yaw after pitch after roll: R = Rz * Ry * Rx.
  const Eigen::Matrix3d rpy = parse(block(kRange, "<pose>0 0 0 0.3 0.2 0.1</pose>"))[0].pose.linear();
  const Eigen::Matrix3d expected = (Eigen::AngleAxisd(0.1, Eigen::Vector3d::UnitZ()) *
                                    Eigen::AngleAxisd(0.2, Eigen::Vector3d::UnitY()) *
                                    Eigen::AngleAxisd(0.3, Eigen::Vector3d::UnitX())).toRotationMatrix();
  EXPECT_TRUE(rpy.isApprox(expected, 1e-12));
}

TEST(LaserParse, RangeMaxNotANumberNamesTheElement) {
  EXPECT_EQ(errorOf(block("<range><min>0.05</min><max>abc</max></range>")),
            "model.urdf: <gazebo reference='ray'>/<sensor name='lidar'>/<ray>/<range>/<max>: "
            "expected a number > <min> (0.05), got 'abc'");
}

TEST(LaserParse, ErrorsNameTheElementAndTheExpectation) {
  const std::string sensor = "model.urdf: <gazebo reference='ray'>/<sensor name='lidar'>";
  const std::string ray = sensor + "/<ray>";
  const std::string horizontal = ray + "/<scan>/<horizontal>";
  struct Case {
    std::string xml, message;
  };
  const std::vector<Case> cases = {
      {block("<range><min>0.05</min><max>0.05</max></range>"),
       ray + "/<range>/<max>: expected a number > <min> (0.05), got '0.05'"},
      {block("<range><min>0.05</min></range>"),
       ray + "/<range>/<max>: expected a number > <min> (0.05), got nothing (the default is 0)"},
      {block("<range><min>nan</min><max>1</max></range>"),
       ray + "/<range>/<min>: expected a number >= 0, got 'nan'"},
      {block("<range><min>-1</min><max>1</max></range>"),
       ray + "/<range>/<min>: expected a number >= 0, got '-1'"},
      {block("<range><min>0</min><max>1</max><resolution>-0.1</resolution></range>"),
       ray + "/<range>/<resolution>: expected a number >= 0, got '-0.1'"},
      {block("<scan><horizontal><samples>0</samples></horizontal></scan>" + kRange),
       horizontal + "/<samples>: expected an integer in [1, 1000000], got '0'"},
      {block("<scan><horizontal><samples>12.5</samples></horizontal></scan>" + kRange),
       horizontal + "/<samples>: expected an integer in [1, 1000000], got '12.5'"},
      {block("<scan><horizontal><min_angle>1</min_angle><max_angle>-1</max_angle></horizontal></scan>" + kRange),
       horizontal + "/<max_angle>: expected a number >= <min_angle> (1), got '-1'"},
      {block("<scan><horizontal><min_angle>x1</min_angle></horizontal></scan>" + kRange),
       horizontal + "/<min_angle>: expected a number, got 'x1'"},
      {block("<scan><horizontal><resolution>0</resolution></horizontal></scan>" + kRange),
       horizontal + "/<resolution>: expected a number > 0, got '0'"},
      {block("<scan><vertical><samples>-3</samples></vertical></scan>" + kRange),
       ray + "/<scan>/<vertical>/<samples>: expected an integer in [1, 1000000], got '-3'"},
      {block(kRange, "<update_rate>-5</update_rate>"), sensor + "/<update_rate>: expected a number >= 0, got '-5'"},
      {block(kRange, "<update_rate>NaN</update_rate>"),
       sensor + "/<update_rate>: expected a number >= 0, got 'NaN'"},
      {block(kRange + "<noise><type>gaussian</type><stddev>-0.01</stddev></noise>"),
       ray + "/<noise>/<stddev>: expected a number >= 0, got '-0.01'"},
      {block(kRange + "<noise><type>uniform</type></noise>"),
       ray + "/<noise>/<type>: expected one of none, gaussian, gaussian_quantized, got 'uniform'"},
      {block(kRange, "<pose>0 0 0 0 0</pose>"),
       sensor + "/<pose>: expected 6 numbers 'x y z roll pitch yaw', got '0 0 0 0 0'"},
      {block(kRange, "<pose>0 0 0 0 0 inf</pose>"),
       sensor + "/<pose>: expected 6 numbers 'x y z roll pitch yaw', got '0 0 0 0 0 inf'"},
      {block(kRange, "<always_on>yes</always_on>"),
       sensor + "/<always_on>: expected true, false, 1 or 0, got 'yes'"},
      {"<gazebo reference='ray'><sensor name='lidar' type='ray'><ray>" + kRange + "</ray></sensor>",
       "model.urdf: malformed XML at line 1: "},
  };
  for (const Case& c : cases) {
    const std::string error = errorOf(c.xml);
    EXPECT_EQ(error.substr(0, c.message.size()), c.message) << "for " << c.xml;
  }
  // A sensor in a block without a link.
  EXPECT_EQ(errorOf("<gazebo><sensor name='s' type='ray'/></gazebo>"),
            "model.urdf: <gazebo>/<sensor name='s'>: expected the sensor's <gazebo> block to name its link with "
            "reference='LINK'");
}

// ---------------------------------------------------------------------------------------------
// Scanning
// ---------------------------------------------------------------------------------------------

// A btCollisionWorld that owns its objects. Members are declared so that the world goes first
// (it unregisters the objects from the broadphase), then objects, shapes, broadphase.
class TestWorld {
 public:
  TestWorld()
      : config_(std::make_unique<btDefaultCollisionConfiguration>()),
        dispatcher_(std::make_unique<btCollisionDispatcher>(config_.get())),
        broadphase_(std::make_unique<btDbvtBroadphase>()),
        world_(std::make_unique<btCollisionWorld>(dispatcher_.get(), broadphase_.get(), config_.get())) {}

  // Takes the shape; returns the new static object at `pose`.
  btCollisionObject* add(std::unique_ptr<btCollisionShape> shape, const btTransform& pose) {
    shape->setMargin(0.001);  // as the simulator's shapes
    auto object = std::make_unique<btCollisionObject>();
    object->setCollisionShape(shape.get());
    object->setWorldTransform(pose);
    world_->addCollisionObject(object.get());
    shapes_.push_back(std::move(shape));
    objects_.push_back(std::move(object));
    return objects_.back().get();
  }
  btCollisionObject* addBox(const btVector3& centre, const btVector3& half) {
    return add(std::make_unique<btBoxShape>(half), at(centre));
  }
  btCollisionShape* keep(std::unique_ptr<btCollisionShape> shape) {  // e.g. a compound's children
    shape->setMargin(0.001);
    shapes_.push_back(std::move(shape));
    return shapes_.back().get();
  }
  btTriangleMesh* keep(std::unique_ptr<btTriangleMesh> mesh) {
    meshes_.push_back(std::move(mesh));
    return meshes_.back().get();
  }
  static btTransform at(const btVector3& p, btScalar yaw = 0, btScalar roll = 0) {
    btQuaternion q;
    q.setEulerZYX(yaw, 0, roll);
    return btTransform(q, p);
  }
  const btCollisionWorld& world() const { return *world_; }

 private:
  std::unique_ptr<btDefaultCollisionConfiguration> config_;
  std::unique_ptr<btCollisionDispatcher> dispatcher_;
  std::unique_ptr<btDbvtBroadphase> broadphase_;
  std::vector<std::unique_ptr<btTriangleMesh>> meshes_;
  std::vector<std::unique_ptr<btCollisionShape>> shapes_;
  std::vector<std::unique_ptr<btCollisionObject>> objects_;
  std::unique_ptr<btCollisionWorld> world_;
};

// The room's inside: x in [-2, 3], y in [-1.5, 2], z in [0, 2.5]; walls 0.1 thick.
constexpr double kX0 = -2, kX1 = 3, kY0 = -1.5, kY1 = 2, kZ0 = 0, kZ1 = 2.5, kWall = 0.1;

void addRoomWalls(TestWorld& w) {
  const double cx = (kX0 + kX1) / 2, cy = (kY0 + kY1) / 2, hx = (kX1 - kX0) / 2 + kWall, hy = (kY1 - kY0) / 2;
  const double cz = (kZ0 + kZ1) / 2, hz = (kZ1 - kZ0) / 2;  // floor to ceiling
  w.addBox(btVector3(kX0 - kWall / 2, cy, cz), btVector3(kWall / 2, hy, hz));
  w.addBox(btVector3(kX1 + kWall / 2, cy, cz), btVector3(kWall / 2, hy, hz));
  w.addBox(btVector3(cx, kY0 - kWall / 2, cz), btVector3(hx, kWall / 2, hz));
  w.addBox(btVector3(cx, kY1 + kWall / 2, cz), btVector3(hx, kWall / 2, hz));
}

// Distance from p along unit d to the room's inside faces (walls, and floor/ceiling if `closed`).
double roomDistance(const Eigen::Vector3d& p, const Eigen::Vector3d& d, bool closed) {
  double best = std::numeric_limits<double>::infinity();
  const double lo[3] = {kX0, kY0, kZ0}, hi[3] = {kX1, kY1, kZ1};
  for (int k = 0; k < (closed ? 3 : 2); ++k) {
    if (d[k] > 1e-12) best = std::min(best, (hi[k] - p[k]) / d[k]);
    if (d[k] < -1e-12) best = std::min(best, (lo[k] - p[k]) / d[k]);
  }
  return best;
}

LaserConfig scanner(int samples, double min_angle, double max_angle, double range_min, double range_max) {
  LaserConfig c;
  c.samples = samples;
  c.min_angle = min_angle;
  c.max_angle = max_angle;
  c.range_min = range_min;
  c.range_max = range_max;
  return c;
}

// World direction of beam i of `s` for a sensor at `pose`.
Eigen::Vector3d beamDirection(const LaserScanner& s, int i, const btTransform& pose) {
  const double a = s.angle_min() + i * s.angle_increment();
  const btVector3 d = pose.getBasis() * btVector3(std::cos(a), std::sin(a), 0);
  return Eigen::Vector3d(d.x(), d.y(), d.z());
}

Eigen::Vector3d toEigen(const btVector3& v) { return Eigen::Vector3d(v.x(), v.y(), v.z()); }

btTransform toBullet(const Eigen::Isometry3d& t) {
  const Eigen::Quaterniond q(t.linear());
  const Eigen::Vector3d p = t.translation();
  return btTransform(btQuaternion(q.x(), q.y(), q.z(), q.w()), btVector3(p.x(), p.y(), p.z()));
}

std::vector<float> scanOnce(const LaserScanner& s, const btCollisionWorld& world, const btTransform& pose,
                            const std::vector<const btCollisionObject*>& ignore = {}) {
  std::mt19937 rng(42);
  std::vector<float> ranges;
  s.scan(world, pose, ignore, rng, ranges);
  return ranges;
}

const btTransform kPose = TestWorld::at(btVector3(0.7, -0.3, 0.5), 0.4);  // off-centre, yawed

TEST(LaserScanner, BeamGeometryIsGazebos) {
  const LaserScanner s(scanner(720, -kPi, kPi, 0.1, 30));
  EXPECT_EQ(s.beam_count(), 720);
  EXPECT_DOUBLE_EQ(s.angle_increment(), 2 * kPi / 719);
  EXPECT_EQ(LaserScanner(scanner(1, 0, 0, 0.1, 30)).angle_increment(), 0.0);
  LaserConfig twice = scanner(100, -1, 1, 0.1, 30);
  twice.resolution = 2;  // Gazebo publishes int(samples * resolution) readings
  EXPECT_EQ(LaserScanner(twice).beam_count(), 200);
  EXPECT_DOUBLE_EQ(LaserScanner(twice).angle_increment(), 2.0 / 199);
}

TEST(LaserScanner, BoxRoomMatchesAnalyticDistances) {
  TestWorld w;
  addRoomWalls(w);
  const LaserScanner s(scanner(360, -kPi, kPi, 0.1, 20));
  const auto ranges = scanOnce(s, w.world(), kPose);
  ASSERT_EQ(ranges.size(), 360u);
  for (int i = 0; i < 360; ++i) {
    const double expected = roomDistance(toEigen(kPose.getOrigin()), beamDirection(s, i, kPose), false);
    EXPECT_NEAR(ranges[i], expected, 1e-4) << "beam " << i;
  }
}

TEST(LaserScanner, NothingInRangeIsPlusInfinity) {
  TestWorld empty;
  for (float r : scanOnce(LaserScanner(scanner(90, -1, 1, 0.1, 5)), empty.world(), kPose)) EXPECT_EQ(r, kInf);

  TestWorld w;
  addRoomWalls(w);
  const LaserScanner s(scanner(360, -kPi, kPi, 0.1, 1.5));  // walls lie 0.8 .. 3.6 m away
  const auto ranges = scanOnce(s, w.world(), kPose);
  int far = 0;
  for (int i = 0; i < 360; ++i) {
    const double expected = roomDistance(toEigen(kPose.getOrigin()), beamDirection(s, i, kPose), false);
    if (expected >= 1.5 + 1e-4) {
      EXPECT_EQ(ranges[i], kInf) << "beam " << i;
      ++far;
    } else if (expected < 1.5 - 1e-4) {
      EXPECT_NEAR(ranges[i], expected, 1e-4) << "beam " << i;
    }
  }
  EXPECT_GT(far, 100);
  EXPECT_LT(far, 350);
}

TEST(LaserScanner, WallCloserThanRangeMinIsMinusInfinity) {
  TestWorld w;
  addRoomWalls(w);
  const btTransform near_wall = TestWorld::at(btVector3(kX1 - 0.2, 0, 0.5), 0.3);
  const LaserScanner s(scanner(360, -kPi, kPi, 0.5, 20));
  const auto ranges = scanOnce(s, w.world(), near_wall);
  int too_close = 0;
  for (int i = 0; i < 360; ++i) {
    const double expected = roomDistance(toEigen(near_wall.getOrigin()), beamDirection(s, i, near_wall), false);
    if (expected < 0.5 - 1e-4) {
      EXPECT_EQ(ranges[i], -kInf) << "beam " << i;  // REP 117: detected, but too close to measure
      ++too_close;
    } else if (expected > 0.5 + 1e-4) {
      EXPECT_NEAR(ranges[i], expected, 1e-4) << "beam " << i;
    }
  }
  EXPECT_GT(too_close, 50);
}

TEST(LaserScanner, GaussianNoiseHasTheConfiguredSpread) {
  TestWorld w;
  addRoomWalls(w);
  LaserConfig c = scanner(720, -kPi, kPi, 0.1, 20);
  c.noise_type = "gaussian";
  c.noise_stddev = 0.01;
  const LaserScanner s(c);
  std::mt19937 rng(7);
  std::vector<float> ranges;
  s.scan(w.world(), kPose, {}, rng, ranges);
  std::vector<double> errors;
  for (int i = 0; i < 720; ++i) {
    ASSERT_TRUE(std::isfinite(ranges[i]));
    errors.push_back(ranges[i] - roomDistance(toEigen(kPose.getOrigin()), beamDirection(s, i, kPose), false));
  }
  const double mean = std::accumulate(errors.begin(), errors.end(), 0.0) / errors.size();
  double var = 0;
  for (double e : errors) var += (e - mean) * (e - mean);
  const double stddev = std::sqrt(var / (errors.size() - 1));
  EXPECT_LT(std::abs(mean), 0.003);
  EXPECT_NEAR(stddev, 0.01, 0.002);
  // A second scan draws new noise.
  std::vector<float> again;
  s.scan(w.world(), kPose, {}, rng, again);
  EXPECT_NE(ranges, again);
}

TEST(LaserScanner, RangeResolutionQuantises) {
  TestWorld w;
  addRoomWalls(w);
  LaserConfig c = scanner(180, -kPi, kPi, 0.1, 20);
  c.range_resolution = 0.05;
  const LaserScanner s(c);
  const auto ranges = scanOnce(s, w.world(), kPose);
  for (int i = 0; i < 180; ++i) {
    const double expected = roomDistance(toEigen(kPose.getOrigin()), beamDirection(s, i, kPose), false);
    EXPECT_NEAR(ranges[i], expected, 0.025 + 1e-5) << "beam " << i;
    EXPECT_NEAR(ranges[i] / 0.05, std::round(ranges[i] / 0.05), 1e-4) << "beam " << i;
  }
}

TEST(LaserScanner, IgnoredObjectsAreNeverHit) {
  TestWorld w;
  addRoomWalls(w);
  // The sensor's own link: a box around the sensor, and a post right in front of it.
  const btCollisionObject* own = w.addBox(kPose.getOrigin(), btVector3(0.05, 0.05, 0.05));
  const btVector3 ahead = kPose.getOrigin() + kPose.getBasis() * btVector3(0.5, 0, 0);
  const btCollisionObject* post = w.add(std::make_unique<btBoxShape>(btVector3(0.05, 0.05, 1)), TestWorld::at(ahead, 0.4));
  const LaserScanner s(scanner(361, -kPi, kPi, 0.02, 20));
  const int front = 180;  // angle 0

  const auto seen = scanOnce(s, w.world(), kPose, {own});
  EXPECT_NEAR(seen[front], 0.45, 1e-4);  // the post's near face
  const auto ignored = scanOnce(s, w.world(), kPose, {own, post});
  for (int i = 0; i < 361; ++i) {
    const double expected = roomDistance(toEigen(kPose.getOrigin()), beamDirection(s, i, kPose), false);
    EXPECT_NEAR(ignored[i], expected, 1e-4) << "beam " << i;
  }
  // Not ignoring its own body: the sensor sits inside a solid, every beam is "too close".
  for (float r : scanOnce(s, w.world(), kPose, {post})) EXPECT_EQ(r, -kInf);
}

TEST(LaserScanner, VerticalScannerSeesFloorAndCeiling) {
  TestWorld w;
  addRoomWalls(w);
  w.addBox(btVector3(0.5, 0.25, kZ0 - 0.05), btVector3(3, 2, 0.05));  // floor
  w.addBox(btVector3(0.5, 0.25, kZ1 + 0.05), btVector3(3, 2, 0.05));  // ceiling
  LaserConfig c = parse(block(kRange, "<pose>0.05 0 0.1 1.5707963267948966 0 0</pose>"))[0];
  c.samples = 361;  // 1 degree apart
  c.min_angle = -kPi;
  c.max_angle = kPi;
  c.range_max = 20;
  const LaserScanner s(c);
  const btTransform link = TestWorld::at(btVector3(0.65, -0.3, 0.4), 0.4);
  const btTransform pose = link * toBullet(c.pose);
  const auto ranges = scanOnce(s, w.world(), pose);
  int floor_or_ceiling = 0;
  for (int i = 0; i < 361; ++i) {
    const Eigen::Vector3d d = beamDirection(s, i, pose);
    const double expected = roomDistance(toEigen(pose.getOrigin()), d, true);
    EXPECT_NEAR(ranges[i], expected, 1e-4) << "beam " << i;
    if (std::abs(d.z()) > 0.9) ++floor_or_ceiling;
  }
  EXPECT_GT(floor_or_ceiling, 100);
  EXPECT_NEAR(ranges[90], 0.5, 1e-4);   // angle -pi/2 looks straight down, from 0.5 m up
  EXPECT_NEAR(ranges[270], 2.0, 1e-4);  // and +pi/2 up, to the ceiling at 2.5 m
}

TEST(LaserScanner, CompoundWallsMatchTheBoxRoom) {
  TestWorld w;
  // The four walls as children of one compound, on an object that is itself moved and turned.
  const btTransform object_pose = TestWorld::at(btVector3(0.3, -0.2, 0.1), 0.7);
  auto compound = std::make_unique<btCompoundShape>();
  const double cx = (kX0 + kX1) / 2, cy = (kY0 + kY1) / 2, hx = (kX1 - kX0) / 2 + kWall, hy = (kY1 - kY0) / 2;
  const std::pair<btVector3, btVector3> walls[] = {
      {btVector3(kX0 - kWall / 2, cy, 1), btVector3(kWall / 2, hy, 1)},
      {btVector3(kX1 + kWall / 2, cy, 1), btVector3(kWall / 2, hy, 1)},
      {btVector3(cx, kY0 - kWall / 2, 1), btVector3(hx, kWall / 2, 1)},
      {btVector3(cx, kY1 + kWall / 2, 1), btVector3(hx, kWall / 2, 1)}};  // 2 m high is enough here
  for (const auto& [centre, half] : walls) {
    // child pose = object_pose^-1 * (wall in the world), so the walls land where the plain room's are
    compound->addChildShape(object_pose.inverse() * TestWorld::at(centre),
                            w.keep(std::make_unique<btBoxShape>(half)));
  }
  w.add(std::move(compound), object_pose);
  const LaserScanner s(scanner(360, -kPi, kPi, 0.1, 20));
  const auto ranges = scanOnce(s, w.world(), kPose);
  for (int i = 0; i < 360; ++i) {
    const double expected = roomDistance(toEigen(kPose.getOrigin()), beamDirection(s, i, kPose), false);
    EXPECT_NEAR(ranges[i], expected, 1e-4) << "beam " << i;
  }
}

// Distance along unit d from p to a vertical cylinder (axis z through c, radius r), or inf.
double cylinderDistance(const Eigen::Vector3d& p, const Eigen::Vector3d& d, const Eigen::Vector3d& c, double r) {
  const Eigen::Vector2d o = (p - c).head<2>(), v = d.head<2>();
  const double a = v.squaredNorm(), b = o.dot(v), q = o.squaredNorm() - r * r, disc = b * b - a * q;
  if (a == 0 || disc < 0 || b > 0) return std::numeric_limits<double>::infinity();
  return (-b - std::sqrt(disc)) / a;
}

TEST(LaserScanner, CylinderSphereMeshAndHull) {
  TestWorld w;
  addRoomWalls(w);
  const Eigen::Vector3d p = toEigen(kPose.getOrigin());
  // A cylinder 1.2 m ahead-left and a sphere behind (centred at the scan height).
  const Eigen::Vector3d cyl(1.5, 0.6, 0.5), ball(-0.8, -0.4, 0.5);
  w.add(std::make_unique<btCylinderShapeZ>(btVector3(0.3, 0.3, 0.5)), TestWorld::at(btVector3(1.5, 0.6, 0.5)));
  w.add(std::make_unique<btSphereShape>(0.25), TestWorld::at(btVector3(-0.8, -0.4, 0.5)));
  // A triangle-mesh panel (x = 2.5, y in [-1.4, -0.6]) and a convex hull pillar near (0.2, 1.2);
  // both go through Bullet's own rayTestSingle.
  auto tris = std::make_unique<btTriangleMesh>();
  tris->addTriangle(btVector3(2.5, -1.4, 0), btVector3(2.5, -0.6, 0), btVector3(2.5, -0.6, 1));
  tris->addTriangle(btVector3(2.5, -1.4, 0), btVector3(2.5, -0.6, 1), btVector3(2.5, -1.4, 1));
  btTriangleMesh* mesh = w.keep(std::move(tris));
  w.add(std::make_unique<btBvhTriangleMeshShape>(mesh, true), TestWorld::at(btVector3(0, 0, 0)));
  auto hull = std::make_unique<btConvexHullShape>();
  for (double x : {-0.1, 0.1})
    for (double y : {-0.1, 0.1})
      for (double z : {0.0, 1.0}) hull->addPoint(btVector3(x, y, z));
  w.add(std::move(hull), TestWorld::at(btVector3(0.2, 1.2, 0)));

  const LaserScanner s(scanner(720, -kPi, kPi, 0.1, 20));
  const auto ranges = scanOnce(s, w.world(), kPose);
  int on_cylinder = 0, on_ball = 0, on_mesh = 0, on_hull = 0;
  for (int i = 0; i < 720; ++i) {
    const Eigen::Vector3d d = beamDirection(s, i, kPose);
    double expected = roomDistance(p, d, false);
    const double tc = cylinderDistance(p, d, cyl, 0.3);
    const double tb = cylinderDistance(p, d, ball, 0.25);  // in the scan plane a sphere is a circle
    const double tm = d.x() > 0 ? (2.5 - p.x()) / d.x() : -1;
    const bool mesh_hit = tm > 0 && std::abs(p.y() + tm * d.y() + 1.0) <= 0.4;
    double th = std::numeric_limits<double>::infinity();  // the hull's 0.2 x 0.2 square
    for (int k = 0; k < 2; ++k)
      for (double side : {-0.1, 0.1}) {
        const Eigen::Vector2d c(0.2, 1.2);
        if (std::abs(d[k]) < 1e-12) continue;
        const double t = (c[k] + side - p[k]) / d[k];
        if (t > 0 && std::abs(p[1 - k] + t * d[1 - k] - c[1 - k]) <= 0.1) th = std::min(th, t);
      }
    if (tc < expected) expected = tc, ++on_cylinder;
    if (tb < expected) expected = tb, ++on_ball;
    if (mesh_hit && tm < expected) expected = tm, ++on_mesh;
    if (th < expected) {
      expected = th, ++on_hull;
      // Through Bullet's convex cast, which sees the hull grown by its 1 mm margin (and rounded).
      EXPECT_NEAR(ranges[i], expected, 5e-3) << "beam " << i;
      continue;
    }
    EXPECT_NEAR(ranges[i], expected, 1e-4) << "beam " << i;
  }
  EXPECT_GT(on_cylinder, 20);
  EXPECT_GT(on_ball, 20);
  EXPECT_GT(on_mesh, 20);
  EXPECT_GT(on_hull, 5);
}

TEST(LaserScanner, GroundPlaneAndTiltedScanner) {
  TestWorld w;
  w.add(std::make_unique<btStaticPlaneShape>(btVector3(0, 0, 1), 0), TestWorld::at(btVector3(0, 0, 0)));
  // Pitched down by 0.3 rad: the centre beam meets the ground at 1 / sin(0.3) from 1 m up.
  btQuaternion q;
  q.setEulerZYX(0.2, 0.3, 0);
  const btTransform pose(q, btVector3(0, 0, 1));
  const LaserScanner s(scanner(181, -kPi / 2, kPi / 2, 0.1, 20));
  const auto ranges = scanOnce(s, w.world(), pose);
  for (int i = 0; i < 181; ++i) {
    const Eigen::Vector3d d = beamDirection(s, i, pose);
    const double expected = d.z() < 0 ? -1 / d.z() : std::numeric_limits<double>::infinity();
    if (expected >= 20) EXPECT_EQ(ranges[i], kInf) << "beam " << i;
    else EXPECT_NEAR(ranges[i], expected, 1e-4) << "beam " << i;
  }
  EXPECT_NEAR(ranges[90], 1 / std::sin(0.3), 1e-4);

  // Several vertical layers: the first one (at the vertical min_angle, -0.2 rad: down) is scanned.
  LaserConfig layers = scanner(1, 0, 0, 0.1, 20);
  layers.vertical_samples = 4;
  layers.vertical_min_angle = -0.2;
  layers.vertical_max_angle = 0.2;
  const btTransform level(btQuaternion::getIdentity(), btVector3(0, 0, 1));
  const auto first_layer = scanOnce(LaserScanner(layers), w.world(), level);
  ASSERT_EQ(first_layer.size(), 1u);
  EXPECT_NEAR(first_layer[0], 1 / std::sin(0.2), 1e-4);
}

// The culling (broadphase query, AABB order, early exit) must not lose the nearest object: a
// scene of 30 turned boxes, against one btCollisionWorld::rayTest per beam. In single precision
// the reference uses the GJK convex cast (within ~2 mm): Bullet's default sub-simplex cast reports
// hits up to a metre short on these 1 mm-margin boxes. In double precision the default is exact.
TEST(LaserScanner, AgreesWithBulletsRayTestAmongManyBoxes) {
  TestWorld w;
  addRoomWalls(w);
  std::mt19937 gen(3);
  std::uniform_real_distribution<double> x(kX0 + 0.3, kX1 - 0.3), y(kY0 + 0.3, kY1 - 0.3), a(0, kPi), size(0.03, 0.3);
  for (int added = 0; added < 30;) {
    const btVector3 centre(x(gen), y(gen), 0.5);
    if (centre.distance(kPose.getOrigin()) < 0.5) continue;
    const double sx = size(gen), sy = size(gen), yaw = a(gen);
    w.add(std::make_unique<btBoxShape>(btVector3(sx, sy, 0.6)), TestWorld::at(centre, yaw));
    ++added;
  }
  const LaserScanner s(scanner(720, -kPi, kPi, 0.1, 20));
  const auto ranges = scanOnce(s, w.world(), kPose);
  for (int i = 0; i < 720; ++i) {
    const btVector3 from = kPose.getOrigin();
    const Eigen::Vector3d d = beamDirection(s, i, kPose);
    const btVector3 to = from + btVector3(d.x(), d.y(), d.z()) * 20;
    btCollisionWorld::ClosestRayResultCallback cb(from, to);
#ifndef BT_USE_DOUBLE_PRECISION
    cb.m_flags = btTriangleRaycastCallback::kF_UseGjkConvexCastRaytest;
#endif
    w.world().rayTest(from, to, cb);
    ASSERT_TRUE(cb.hasHit());
    EXPECT_NEAR(ranges[i], cb.m_closestHitFraction * 20, 2e-3) << "beam " << i;
  }
}

}  // namespace
}  // namespace bullet_sim
