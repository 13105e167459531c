// topic_arrivals: the node benchmark's listener (scripts/bench_node_rtf.py).
//
//   topic_arrivals OUT_FILE SCAN_TOPIC JOINT_STATES_TOPIC
//
// Subscribes to /clock, a LaserScan and a JointState topic ("-": none) and keeps, for every message, the
// monotonic wall time of its arrival (to within a millisecond) and its sim-time stamp; writes them to OUT_FILE as
// "clock|scan|joint_states WALL STAMP" lines when it is stopped (SIGINT), and creates
// OUT_FILE.ready once one message of each kind subscribed has arrived. A C++ listener, so that the benchmark
// measures the simulator rather than a Python subscriber competing with it for the two cores.
#include <ros/callback_queue.h>
#include <ros/ros.h>
#include <rosgraph_msgs/Clock.h>
#include <sensor_msgs/JointState.h>
#include <sensor_msgs/LaserScan.h>

#include <chrono>
#include <cstdio>
#include <fstream>
#include <string>
#include <vector>

namespace {

struct Arrival {
  double wall;   // steady_clock (CLOCK_MONOTONIC, as Python's time.monotonic()), s
  double stamp;  // sim time, s
};

double now() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

class Recorder {
 public:
  Recorder(std::string out, bool scans, bool joint_states)
      : out_(std::move(out)), want_scans_(scans), want_joint_states_(joint_states) {}

  void clock(const rosgraph_msgs::Clock& m) { add(clock_, m.clock); }
  void scan(const sensor_msgs::LaserScan& m) { add(scans_, m.header.stamp); }
  void jointStates(const sensor_msgs::JointState& m) { add(joint_states_, m.header.stamp); }

  bool write() const {
    std::ofstream f(out_);
    char line[64];
    for (const auto& [name, arrivals] : {std::pair{"clock", &clock_}, std::pair{"scan", &scans_},
                                         std::pair{"joint_states", &joint_states_}}) {
      for (const Arrival& a : *arrivals) {
        std::snprintf(line, sizeof line, " %.6f %.6f\n", a.wall, a.stamp);
        f << name << line;
      }
    }
    return static_cast<bool>(f);
  }

 private:
  void add(std::vector<Arrival>& to, const ros::Time& stamp) {
    to.push_back({now(), stamp.toSec()});
    if (!ready_ && !clock_.empty() && (!want_scans_ || !scans_.empty()) &&
        (!want_joint_states_ || !joint_states_.empty())) {
      ready_ = true;
      std::ofstream(out_ + ".ready") << "ready\n";
    }
  }

  std::string out_;
  bool want_scans_, want_joint_states_;
  std::vector<Arrival> clock_, scans_, joint_states_;
  bool ready_ = false;
};

}  // namespace

int main(int argc, char** argv) {
  ros::init(argc, argv, "topic_arrivals", ros::init_options::AnonymousName);
  if (argc != 4) {
    std::fprintf(stderr, "usage: topic_arrivals OUT_FILE SCAN_TOPIC JOINT_STATES_TOPIC\n");
    return 2;
  }
  ros::NodeHandle nh;
  const std::string scan_topic = argv[2], joint_states_topic = argv[3];
  Recorder rec(argv[1], scan_topic != "-", joint_states_topic != "-");
  // roscpp's and rospy's default transport (TCP with Nagle's algorithm), as a user's node has it.
  ros::Subscriber clock = nh.subscribe("/clock", 1000, &Recorder::clock, &rec);
  ros::Subscriber scan, joints;
  if (scan_topic != "-") scan = nh.subscribe(scan_topic, 1000, &Recorder::scan, &rec);
  if (joint_states_topic != "-") joints = nh.subscribe(joint_states_topic, 1000, &Recorder::jointStates, &rec);
  // Takes what arrived every millisecond rather than being woken for each message (ros::spin()),
  // which on two cores would take a third of one from the simulator it measures. Arrival times
  // are those of the callbacks, so up to 1 ms late: nothing next to windows of seconds.
  while (ros::ok()) {
    ros::getGlobalCallbackQueue()->callAvailable();
    ros::WallDuration(0.001).sleep();
  }
  if (!rec.write()) {
    std::fprintf(stderr, "topic_arrivals: cannot write %s\n", argv[1]);
    return 1;
  }
  return 0;
}
