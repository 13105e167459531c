#pragma once
// move_base's state machine (upstream's names, defaults and result texts): a goal from the
// move_base action or move_base_simple/goal is planned for on the global costmap (in a planner
// thread, at planner_frequency or when needed), followed by the local planner at
// controller_frequency; when planning or control fails for longer than its patience, or the robot
// oscillates, the recovery behaviours run in turn, and when none is left the goal is aborted.
#include <ros/ros.h>
#include <tf2_ros/buffer.h>

#include <actionlib/server/simple_action_server.h>
#include <condition_variable>
#include <memory>
#include <mutex>
#include <set>
#include <thread>
#include <vector>

#include <geometry_msgs/PoseStamped.h>
#include <move_base_msgs/MoveBaseAction.h>
#include <nav_msgs/GetPlan.h>
#include <std_srvs/Empty.h>

#include "move_base/costmap_ros.h"
#include "move_base/global_planner_ros.h"
#include "move_base/local_planner_ros.h"
#include "move_base/recoveries.h"

namespace move_base {

class MoveBase {
 public:
  explicit MoveBase(tf2_ros::Buffer& tf);
  ~MoveBase();

 private:
  enum State { PLANNING, CONTROLLING, CLEARING };
  enum RecoveryTrigger { PLANNING_R, CONTROLLING_R, OSCILLATION_R };

  void executeCb(const move_base_msgs::MoveBaseGoalConstPtr& goal);
  // One control cycle; true when the goal is done (reached or aborted).
  bool executeCycle();
  void planThread();
  // Checks and transforms a new goal; false (the goal aborted with the reason) if it is unusable.
  bool acceptGoal(const geometry_msgs::PoseStamped& goal, geometry_msgs::PoseStamped& in_global_frame);
  bool makePlan(const geometry_msgs::PoseStamped& goal, std::vector<geometry_msgs::PoseStamped>& plan);
  void onSimpleGoal(const geometry_msgs::PoseStampedConstPtr& goal);
  bool onMakePlan(nav_msgs::GetPlan::Request& request, nav_msgs::GetPlan::Response& response);
  bool onClearCostmaps(std_srvs::Empty::Request&, std_srvs::Empty::Response&);
  void publishZeroVelocity();
  void resetState();
  // What the private namespace may hold besides move_base's own parameters.
  std::set<std::string> namespacesAndOthers() const;

  tf2_ros::Buffer& tf_;
  ros::NodeHandle private_nh_;
  std::unique_ptr<CostmapROS> planner_costmap_, controller_costmap_;
  std::unique_ptr<GlobalPlannerROS> planner_;
  std::unique_ptr<LocalPlannerROS> controller_;
  std::vector<std::unique_ptr<RecoveryBehavior>> recoveries_;

  double planner_frequency_, controller_frequency_, planner_patience_, controller_patience_;
  int max_planning_retries_;
  double oscillation_timeout_, oscillation_distance_;
  bool recovery_behavior_enabled_;
  bool make_plan_add_unreachable_goal_;

  ros::Publisher cmd_vel_pub_, current_goal_pub_, action_goal_pub_, recovery_status_pub_;
  ros::Subscriber simple_goal_sub_;
  ros::ServiceServer make_plan_srv_, clear_costmaps_srv_;

  // Shared between the control loop and the planner thread, under planner_mutex_.
  std::mutex planner_mutex_;
  std::condition_variable planner_cond_;
  geometry_msgs::PoseStamped planner_goal_;
  bool run_planner_ = false, new_global_plan_ = false, shutting_down_ = false;
  std::vector<geometry_msgs::PoseStamped> latest_plan_;
  State state_ = PLANNING;
  RecoveryTrigger recovery_trigger_ = PLANNING_R;
  unsigned recovery_index_ = 0;
  int planning_retries_ = 0;
  ros::Time last_valid_plan_, last_valid_control_, last_oscillation_reset_;
  geometry_msgs::PoseStamped oscillation_pose_;
  geometry_msgs::PoseStamped recovery_pose_;  // where the last recovery ran

  std::thread planner_thread_;
  std::unique_ptr<actionlib::SimpleActionServer<move_base_msgs::MoveBaseAction>> as_;
};

}  // namespace move_base
