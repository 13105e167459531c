#include "bullet_sim/physics_reconfigure.h"

#include <dynamic_reconfigure/ConfigDescription.h>

#include <algorithm>
#include <functional>
#include <string>
#include <vector>

#include "bullet_sim/simulator.h"
#include "bullet_sim_core/description_error.h"

namespace bullet_sim {
namespace {

// One parameter of gazebo_ros's Physics.cfg: its name, type and range as upstream declares them,
// the value in effect here, and how a new value applies (none: an ODE setting with no
// counterpart in our solver, reported as it stands and left so).
struct Parameter {
  std::string name, type, description;
  double default_value, min, max;
  std::function<double(PhysicsWorld&)> get;
  std::function<void(PhysicsSettings&, double)> set;
};

const std::vector<Parameter>& parameters() {
  static const std::vector<Parameter> table = {
      {"time_step", "double", "Length of one physics step (s)", 0.001, 0, 10,
       [](PhysicsWorld& w) { return w.settings().max_step_size; },
       [](PhysicsSettings& s, double v) { s.max_step_size = v; }},
      // Upstream's range ends at 1000; worlds here run at up to tens of thousands of steps a second.
      {"max_update_rate", "double", "Steps per second of wall time to keep to; 0: as fast as possible", 1000, 0, 1e7,
       [](PhysicsWorld& w) { return w.settings().real_time_update_rate; },
       [](PhysicsSettings& s, double v) { s.real_time_update_rate = v; }},
      {"gravity_x", "double", "Gravity along the world's x axis (m/s^2)", 0, -100, 100,
       [](PhysicsWorld& w) { return w.settings().gravity.x(); }, [](PhysicsSettings& s, double v) { s.gravity.x() = v; }},
      {"gravity_y", "double", "Gravity along the world's y axis (m/s^2)", 0, -100, 100,
       [](PhysicsWorld& w) { return w.settings().gravity.y(); }, [](PhysicsSettings& s, double v) { s.gravity.y() = v; }},
      {"gravity_z", "double", "Gravity along the world's z axis (m/s^2)", -9.8, -100, 100,
       [](PhysicsWorld& w) { return w.settings().gravity.z(); }, [](PhysicsSettings& s, double v) { s.gravity.z() = v; }},
      {"auto_disable_bodies", "bool", "ODE's; bodies are never disabled here", 0, 0, 1,
       [](PhysicsWorld&) { return 0.0; }, nullptr},
      {"sor_pgs_precon_iters", "int", "ODE's; the solver here has no preconditioning sweeps", 0, 0, 10000,
       [](PhysicsWorld&) { return 0.0; }, nullptr},
      {"sor_pgs_iters", "int", "Constraint solver sweeps per step, at most", 50, 1, 10000,
       [](PhysicsWorld& w) { return w.settings().solver_iterations; },
       [](PhysicsSettings& s, double v) { s.solver_iterations = static_cast<int>(v); }},
      {"sor_pgs_w", "double", "Successive over-relaxation of the solver (Bullet's)", 1.0, 0, 5,
       [](PhysicsWorld& w) { return w.bulletWorld().getSolverInfo().m_sor; }, nullptr},
      {"sor_pgs_rms_error_tol", "double", "Sweeps stop once one changes no row's velocity by more (m/s)", 1e-5, -1,
       10000, [](PhysicsWorld& w) { return w.settings().solver_tolerance; },
       [](PhysicsSettings& s, double v) { s.solver_tolerance = std::max(v, 0.0); }},
      {"cfm", "double", "Constraint force mixing (Bullet's global CFM)", 0, 0, 10,
       [](PhysicsWorld& w) { return w.bulletWorld().getSolverInfo().m_globalCfm; }, nullptr},
      {"erp", "double", "Error reduction of the joints (Bullet's ERP)", 0.2, 0, 10,
       [](PhysicsWorld& w) { return w.bulletWorld().getSolverInfo().m_erp; }, nullptr},
      {"contact_surface_layer", "double", "Overlap a contact leaves uncorrected (m)", 0.001, 0, 10,
       [](PhysicsWorld& w) { return w.settings().contact_surface_layer; },
       [](PhysicsSettings& s, double v) { s.contact_surface_layer = v; }},
      {"contact_max_correcting_vel", "double", "Fastest a contact pushes an overlap apart (m/s)", 100, 0, 1e7,
       [](PhysicsWorld& w) { return w.settings().contact_max_correcting_vel; },
       [](PhysicsSettings& s, double v) { s.contact_max_correcting_vel = v; }},
      {"max_contacts", "int", "ODE's; Bullet keeps up to 4 points per pair of shapes", 20, 0, 1e7,
       [](PhysicsWorld&) { return 20.0; }, nullptr},
  };
  return table;
}

// One Config holding `value(p)` for every parameter, each under its type.
dynamic_reconfigure::Config configOf(const std::function<double(const Parameter&)>& value) {
  dynamic_reconfigure::Config config;
  for (const Parameter& p : parameters()) {
    const double v = value(p);
    if (p.type == "double") {
      dynamic_reconfigure::DoubleParameter d;
      d.name = p.name;
      d.value = v;
      config.doubles.push_back(d);
    } else if (p.type == "int") {
      dynamic_reconfigure::IntParameter i;
      i.name = p.name;
      i.value = static_cast<int>(v);
      config.ints.push_back(i);
    } else {
      dynamic_reconfigure::BoolParameter b;
      b.name = p.name;
      b.value = v != 0.0;
      config.bools.push_back(b);
    }
  }
  dynamic_reconfigure::GroupState group;
  group.name = "Default";
  group.state = true;
  config.groups.push_back(group);
  return config;
}

}  // namespace

PhysicsReconfigure::PhysicsReconfigure(Simulator& sim) : sim_(sim), node_("/gazebo") {
  descriptions_ = node_.advertise<dynamic_reconfigure::ConfigDescription>("parameter_descriptions", 1, true);
  updates_ = node_.advertise<dynamic_reconfigure::Config>("parameter_updates", 1, true);
  dynamic_reconfigure::ConfigDescription description;
  dynamic_reconfigure::Group group;
  group.name = "Default";
  for (const Parameter& p : parameters()) {
    dynamic_reconfigure::ParamDescription d;
    d.name = p.name;
    d.type = p.type;
    d.level = 1;
    d.description = p.description;
    group.parameters.push_back(d);
  }
  description.groups.push_back(group);
  description.dflt = configOf([](const Parameter& p) { return p.default_value; });
  description.min = configOf([](const Parameter& p) { return p.min; });
  description.max = configOf([](const Parameter& p) { return p.max; });
  descriptions_.publish(description);
  publishUpdate();
  service_ = node_.advertiseService("set_parameters", &PhysicsReconfigure::setParameters, this);
}

dynamic_reconfigure::Config PhysicsReconfigure::current() const {
  PhysicsWorld& world = sim_.physics();
  return configOf([&](const Parameter& p) { return p.get(world); });
}

void PhysicsReconfigure::publishUpdate() { updates_.publish(current()); }

// As dynamic_reconfigure's server: values are clamped to their range, names it does not know are
// skipped, and the answer is the whole configuration in effect afterwards.
bool PhysicsReconfigure::setParameters(dynamic_reconfigure::Reconfigure::Request& req,
                                       dynamic_reconfigure::Reconfigure::Response& res) {
  PhysicsSettings settings = sim_.physics().settings();
  auto apply = [&](const std::string& name, double value) {
    for (const Parameter& p : parameters()) {
      if (p.name != name) continue;
      if (p.set) p.set(settings, std::clamp(value, p.min, p.max));
      else ROS_WARN_STREAM("/gazebo/set_parameters: " << name << " is " << p.description << "; left as it is");
      return;
    }
    ROS_WARN_STREAM("/gazebo/set_parameters: no physics parameter named '" << name << "'; skipped");
  };
  for (const auto& d : req.config.doubles) apply(d.name, d.value);
  for (const auto& i : req.config.ints) apply(i.name, i.value);
  for (const auto& b : req.config.bools) apply(b.name, b.value ? 1.0 : 0.0);
  try {
    sim_.physics().setSettings(settings);
    sim_.setPaused(sim_.paused());  // restart real-time tracking at the new rate
  } catch (const DescriptionError& e) {
    ROS_ERROR_STREAM("/gazebo/set_parameters: " << e.what() << "; the physics are unchanged");
  }
  res.config = current();
  publishUpdate();
  return true;
}

}  // namespace bullet_sim
