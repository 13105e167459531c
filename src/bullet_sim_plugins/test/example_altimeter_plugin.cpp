// A newcomer's sensor plugin, the way docs/ARCHITECTURE.md says to write one: this file and its
// registration line at the bottom are all it takes (plus adding the file to a library's sources).
// It is an altimeter: the height of its link above z = 0, every 1/<update_rate> s of sim time, plus
// the plugin's <offset>. A real plugin would publish the reading; this one records it for the test
// (test_plugin_registry.cpp) to read through altimeterReadings().
#include <vector>

#include "bullet_sim_plugins/plugin_registry.h"

namespace bullet_sim {

std::vector<double>& altimeterReadings() {
  static std::vector<double> readings;
  return readings;
}

namespace {

const SensorDescription& sensorOf(const PluginContext& context) {
  if (!context.sensor) context.plugin.element.fail("expected this plugin inside a <sensor>");
  return *context.sensor;
}

class ExampleAltimeterPlugin : public ModelPlugin {
 public:
  explicit ExampleAltimeterPlugin(const PluginContext& context)
      : model_(context.model),
        link_(sensorOf(context).link),
        // Parameters are read through SdfElement, so bad values get the same errors as everywhere.
        period_(1.0 / sensorOf(context).element.number("update_rate", 10.0, positive())),
        offset_(context.plugin.element.number("offset", 0.0)) {}

  void afterStep(const ros::Time& now) override {
    if (now.toSec() + 1e-9 < next_) return;
    next_ = now.toSec() + period_;
    altimeterReadings().push_back(model_.linkPose(link_).translation().z() + offset_);
  }
  void reset() override { next_ = 0.0; }

 private:
  const PhysicsModel& model_;
  const std::string link_;
  const double period_;
  const double offset_;
  double next_ = 0.0;
};

}  // namespace
}  // namespace bullet_sim

BULLET_SIM_REGISTER_PLUGIN("libexample_altimeter.so", bullet_sim::ExampleAltimeterPlugin)
