#pragma once
// One observation source of an obstacle layer (~<costmap>/<layer>/<source>): a LaserScan or
// PointCloud2 topic turned into points in the costmap's global frame when tf can place them,
// kept as costmap_2d's observation buffer keeps them.
#include <sensor_msgs/LaserScan.h>
#include <sensor_msgs/PointCloud2.h>

#include <deque>
#include <string>
#include <utility>
#include <vector>

#include "move_base/costmap_layer.h"
#include "navigation_core/obstacle_layer.h"

namespace move_base {

class ObservationSource {
 public:
  // Reads the source's parameters through `params` (a Reader on its namespace); obstacle_range
  // and raytrace_range are searched for up the namespaces, as costmap_2d does.
  ObservationSource(const std::string& name, const LayerContext& context, ros_params::Reader& params,
                    double layer_max_obstacle_height);

  // False (with an error said) when data_type is neither LaserScan nor PointCloud2.
  bool supported() const { return data_type_ == "LaserScan" || data_type_ == "PointCloud2"; }
  void subscribe();

  // Under the costmap's mutex: the observations that apply now, from what has arrived.
  void keep(const ros::Time& now);
  void addTo(navigation_core::LayeredCostmap& costmap, bool marking) const;
  bool isCurrent(const ros::Time& now) const;

 private:
  struct Raw {
    std::string frame;
    ros::Time stamp;
    std::vector<navigation_core::Point3> points;  // in `frame`
  };
  // A LaserScan's beam directions, kept while the scans' angles stay the same.
  struct BeamDirections {
    float angle_min = 0.0f, angle_increment = 0.0f;
    std::vector<double> cos, sin;
  };

  void onScan(const sensor_msgs::LaserScanConstPtr& scan);
  void onCloud(const sensor_msgs::PointCloud2ConstPtr& cloud);
  void queue(const std::string& frame, const ros::Time& stamp, std::vector<navigation_core::Point3> points);

  const LayerContext& context_;
  std::string name_, topic_, sensor_frame_, data_type_ = "PointCloud";
  double expected_update_rate_ = 0.0, observation_persistence_ = 0.0;
  bool inf_is_valid_ = false;
  navigation_core::ObstacleLayerOptions options_;
  ros::Subscriber subscriber_;
  ros::Time last_message_;
  std::deque<Raw> pending_;  // waiting for their transform
  BeamDirections beams_;
  // What each update applies, in the costmap's frame: the latest observation when
  // observation_persistence is 0, else those of the last that many seconds.
  std::deque<std::pair<ros::Time, navigation_core::Observation>> kept_;
};

}  // namespace move_base
