#pragma once
// Plain description of a model and a world, independent of where it came from (URDF, SDF,
// a .world file) and of Bullet. Parsers produce it; PhysicsWorld builds bodies from it.
#include <Eigen/Geometry>
#include <array>
#include <limits>
#include <string>
#include <vector>

#include "bullet_sim_core/sdf_element.h"

namespace bullet_sim {

enum class GeometryType { Box, Cylinder, Sphere, Plane, Mesh };

struct Geometry {
  GeometryType type = GeometryType::Box;
  Eigen::Vector3d box_size = Eigen::Vector3d::Zero();  // Box: full extents (m)
  double radius = 0.0;                                 // Cylinder, Sphere
  double length = 0.0;                                 // Cylinder, along its local z
  Eigen::Vector3d plane_normal = Eigen::Vector3d::UnitZ();  // Plane (infinite for physics)
  Eigen::Vector2d plane_size = Eigen::Vector2d(100, 100);   // Plane: extent to draw/ray-cast
  std::string mesh_file;                               // Mesh: absolute path, already resolved
  Eigen::Vector3d mesh_scale = Eigen::Vector3d::Ones();
};

// How a collision's contacts push overlapping bodies apart: SDF's <surface><contact><ode> <max_vel>
// and <min_depth> (URDF: <gazebo reference="link"> <maxVel>, <minDepth>), with SDF's defaults and
// Gazebo's meaning (docs/SIMULATOR.md, "Interpenetration"; contact_solver.cpp).
struct ContactSurface {
  double max_vel = 0.01;   // m/s, the fastest its contacts correct an overlap; < 0: only the world's limit
  double min_depth = 0.0;  // m, >= 0: the overlap its contacts leave uncorrected
};

struct CollisionShape {
  std::string name;
  Eigen::Isometry3d origin = Eigen::Isometry3d::Identity();  // in the link frame
  Geometry geometry;
  ContactSurface surface;
};

struct VisualShape {
  std::string name;
  Eigen::Isometry3d origin = Eigen::Isometry3d::Identity();  // in the link frame
  Geometry geometry;
  std::array<float, 4> rgba{{0.7f, 0.7f, 0.7f, 1.0f}};
  std::string texture_file;  // optional image, absolute path
};

struct Inertial {
  double mass = 0.0;  // 0 on a moving link means "no inertial given"; the builder substitutes a small one
  Eigen::Isometry3d origin = Eigen::Isometry3d::Identity();  // centre of mass frame in the link frame
  Eigen::Matrix3d inertia = Eigen::Matrix3d::Zero();         // about the COM, in the origin's axes
};

struct LinkDescription {
  std::string name;
  Inertial inertial;
  std::vector<CollisionShape> collisions;
  std::vector<VisualShape> visuals;
  // Contact friction (Gazebo's <mu1>/<mu2> from <gazebo reference="link">); Bullet has one
  // isotropic coefficient, we use their mean.
  double mu1 = 1.0;
  double mu2 = 1.0;
  // False: the world's gravity does not act on this link (Gazebo's <turnGravityOff> in a
  // <gazebo reference> block, or SDF's <gravity>false</gravity>).
  bool gravity = true;
};

enum class JointType { Fixed, Revolute, Continuous, Prismatic };

struct JointDescription {
  std::string name;
  JointType type = JointType::Fixed;
  std::string parent;
  std::string child;
  Eigen::Isometry3d origin = Eigen::Isometry3d::Identity();  // child link frame in the parent link frame, at 0
  Eigen::Vector3d axis = Eigen::Vector3d::UnitX();           // unit, in the child link frame
  // The point the joint turns about, in the child link frame: URDF puts it at the child link's
  // origin, SDF at the joint's <pose>.
  Eigen::Vector3d pivot = Eigen::Vector3d::Zero();
  double lower = -std::numeric_limits<double>::infinity();   // position limits (rad or m)
  double upper = std::numeric_limits<double>::infinity();
  double effort_limit = std::numeric_limits<double>::infinity();    // N or N m; <=0 in URDF means unlimited
  double velocity_limit = std::numeric_limits<double>::infinity();  // rad/s or m/s
  double damping = 0.0;   // viscous, N m s/rad
  double friction = 0.0;  // Coulomb, N m
};

// A <plugin>: a Gazebo plugin library the model or a sensor asks for. Its parameters are read by
// the plugin that the simulator registers under that library name.
struct PluginDescription {
  std::string filename;  // as written, e.g. "libgazebo_ros_laser.so"
  std::string name;      // name='...'
  SdfElement element;    // the <plugin> element
};

// A <sensor> on a link: SDF's <link><sensor>, URDF's <gazebo reference="link"><sensor>.
struct SensorDescription {
  std::string name;
  std::string type;  // "ray", "gpu_ray", "camera", ...
  std::string link;
  SdfElement element;  // the <sensor> element; its <pose> is in the link frame
  std::vector<PluginDescription> plugins;
};

// A URDF <transmission>, as ros_control reads it.
struct TransmissionDescription {
  std::string name;
  std::string type;  // "transmission_interface/SimpleTransmission"
  struct Joint {
    std::string name;
    std::vector<std::string> hardware_interfaces;  // as written
  };
  struct Actuator {
    std::string name;
    double mechanical_reduction = 1.0;
    std::vector<std::string> hardware_interfaces;  // older tutorials put them here
  };
  std::vector<Joint> joints;
  std::vector<Actuator> actuators;
  SdfElement element;  // for messages
};

struct ModelDescription {
  std::string name;
  std::string source;  // file name or "spawn request" — used in error messages
  bool is_static = false;
  // Root of the link tree. A URDF robot fixed to the world has the massless root "world"
  // (fixed_base true): the model frame is then the world link's frame.
  std::string root_link;
  // The root link's frame in the model frame: identity for URDF, the root link's <pose> for SDF.
  Eigen::Isometry3d root_pose = Eigen::Isometry3d::Identity();
  bool fixed_base = false;
  std::vector<LinkDescription> links;
  std::vector<JointDescription> joints;
  std::vector<SensorDescription> sensors;
  std::vector<PluginDescription> plugins;  // model plugins: <gazebo><plugin>, SDF <model><plugin>
  std::vector<TransmissionDescription> transmissions;
  // What the parser ignored or substituted (an unknown material, say), for the node to log.
  std::vector<std::string> warnings;

  const LinkDescription* findLink(const std::string& link_name) const {
    for (const auto& l : links)
      if (l.name == link_name) return &l;
    return nullptr;
  }
};

struct PhysicsSettings {
  double max_step_size = 0.001;        // s
  double real_time_factor = 1.0;       // 0: as fast as possible
  double real_time_update_rate = 1000; // Hz; with max_step_size gives the target factor, as in Gazebo
  Eigen::Vector3d gravity = Eigen::Vector3d(0, 0, -9.8);
  // Sweeps of the constraint solver per step, at most: SDF's <ode|bullet><solver><iters>, whose
  // default (and PyBullet's) is 50. From zero impulses fewer leave joint motors short of their
  // target in contact (at Bullet's own 10 a Pioneer held by its wheel motors crept 0.2 mm/s).
  int solver_iterations = 50;
  // Where the rows start from the last step's impulses (contact_solver.h), the sweeps stop once
  // one changes no constraint's velocity by more than this, m/s or rad/s. 0: every sweep runs.
  double solver_tolerance = 1e-5;
  // <physics><ode><constraints>: no contact corrects an overlap faster than this (m/s), whatever its
  // surfaces' max_vel; and the depth a contact may sink before it is corrected (m), which, as in
  // Gazebo, only a contact between bodies without surfaces of their own would use: every link's
  // collisions carry a min_depth (0 by default) that takes its place, so it has no effect on models.
  double contact_max_correcting_vel = 100.0;
  double contact_surface_layer = 0.001;
};

struct PlacedModel {
  ModelDescription model;
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();  // model frame in the world
};

struct WorldDescription {
  std::string name = "default";
  std::string source;
  PhysicsSettings physics;
  std::vector<PlacedModel> models;
  std::vector<std::string> warnings;  // what the parser ignored (world plugins), for the node to log
};

}  // namespace bullet_sim
