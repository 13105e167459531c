#include "move_base/move_base.h"

#include <cmath>

#include <geometry_msgs/Twist.h>
#include <move_base_msgs/RecoveryStatus.h>
#include <tf2/utils.h>
#include <tf2_geometry_msgs/tf2_geometry_msgs.h>

#include "move_base/ros_params.h"
#include "ros_params/reader.h"

namespace move_base {

namespace {

double distance(const geometry_msgs::PoseStamped& a, const geometry_msgs::PoseStamped& b) {
  return std::hypot(a.pose.position.x - b.pose.position.x, a.pose.position.y - b.pose.position.y);
}

// move_base's isQuaternionValid, with its messages: finite, not near zero length, and (once
// normalised) with its z axis close to vertical. A non-unit quaternion is accepted and normalised.
bool validQuaternion(const geometry_msgs::Quaternion& q, std::string* why) {
  if (!std::isfinite(q.x) || !std::isfinite(q.y) || !std::isfinite(q.z) || !std::isfinite(q.w)) {
    *why = "Quaternion has nans or infs... discarding as a navigation goal";
    return false;
  }
  tf2::Quaternion t(q.x, q.y, q.z, q.w);
  if (t.length2() < 1e-6) {
    *why = "Quaternion has length close to zero... discarding as navigation goal";
    return false;
  }
  t.normalize();
  const tf2::Vector3 up = tf2::quatRotate(t, tf2::Vector3(0, 0, 1));
  if (std::abs(up.dot(tf2::Vector3(0, 0, 1)) - 1) > 1e-6) {
    *why = "Quaternion is invalid... for navigation the z-axis of the quaternion must be close to vertical.";
    return false;
  }
  return true;
}

}  // namespace

MoveBase::MoveBase(tf2_ros::Buffer& tf) : tf_(tf), private_nh_("~") {
  ros::NodeHandle nh;
  ros_params::Reader params(private_nh_);
  const std::string global_planner = params.get<std::string>("base_global_planner", "navfn/NavfnROS");
  const std::string local_planner =
      params.get<std::string>("base_local_planner", "base_local_planner/TrajectoryPlannerROS");
  planner_frequency_ = params.get("planner_frequency", 0.0);
  controller_frequency_ = params.get("controller_frequency", 20.0);
  planner_patience_ = params.get("planner_patience", 5.0);
  controller_patience_ = params.get("controller_patience", 15.0);
  max_planning_retries_ = params.get("max_planning_retries", -1);
  oscillation_timeout_ = params.get("oscillation_timeout", 0.0);
  oscillation_distance_ = params.get("oscillation_distance", 0.5);
  recovery_behavior_enabled_ = params.get("recovery_behavior_enabled", true);
  make_plan_add_unreachable_goal_ = params.get("make_plan_add_unreachable_goal", true);
  if (params.get("shutdown_costmaps", false))
    ROS_WARN("~shutdown_costmaps is not supported: the costmaps keep running between goals.");
  if (!(controller_frequency_ > 0)) {
    ROS_ERROR("~controller_frequency must be above 0 (got %g); using 20.", controller_frequency_);
    controller_frequency_ = 20.0;
  }

  cmd_vel_pub_ = nh.advertise<geometry_msgs::Twist>("cmd_vel", 1);
  current_goal_pub_ = private_nh_.advertise<geometry_msgs::PoseStamped>("current_goal", 0);
  action_goal_pub_ = ros::NodeHandle("move_base").advertise<move_base_msgs::MoveBaseActionGoal>("goal", 1);
  recovery_status_pub_ = private_nh_.advertise<move_base_msgs::RecoveryStatus>("recovery_status", 1);

  planner_costmap_ = std::make_unique<CostmapROS>("global_costmap", tf_);
  try {
    planner_ = std::make_unique<GlobalPlannerROS>(global_planner, *planner_costmap_);
  } catch (const std::exception& e) {
    throw std::runtime_error(std::string("Failed to create the global planner: ") + e.what());
  }
  controller_costmap_ = std::make_unique<CostmapROS>("local_costmap", tf_);
  try {
    controller_ = std::make_unique<LocalPlannerROS>(local_planner, *controller_costmap_, tf_, controller_frequency_);
  } catch (const std::exception& e) {
    throw std::runtime_error(std::string("Failed to create the local planner: ") + e.what());
  }
  recoveries_ = loadRecoveries(params, *planner_costmap_, *controller_costmap_, cmd_vel_pub_);
  reportParams(params, namespacesAndOthers());

  simple_goal_sub_ = ros::NodeHandle("move_base_simple").subscribe("goal", 1, &MoveBase::onSimpleGoal, this);
  make_plan_srv_ = private_nh_.advertiseService("make_plan", &MoveBase::onMakePlan, this);
  clear_costmaps_srv_ = private_nh_.advertiseService("clear_costmaps", &MoveBase::onClearCostmaps, this);

  planner_thread_ = std::thread([this] { planThread(); });
  as_ = std::make_unique<actionlib::SimpleActionServer<move_base_msgs::MoveBaseAction>>(
      nh, "move_base", [this](const move_base_msgs::MoveBaseGoalConstPtr& goal) { executeCb(goal); }, false);
  as_->start();
  ROS_INFO("move_base: %s and %s on %s / %s, ready for goals.", global_planner.c_str(), local_planner.c_str(),
           planner_costmap_->globalFrame().c_str(), controller_costmap_->globalFrame().c_str());
}

MoveBase::~MoveBase() {
  {
    std::lock_guard<std::mutex> lock(planner_mutex_);
    shutting_down_ = true;
  }
  planner_cond_.notify_all();
  if (as_) as_->shutdown();
  if (planner_thread_.joinable()) planner_thread_.join();
}

std::set<std::string> MoveBase::namespacesAndOthers() const {
  // The components' namespaces (each reports its own parameters), the planners not in use (their
  // parameters are no mistake), what the costmaps search for upwards from their namespaces, and
  // upstream's parameters this move_base accepts without effect.
  std::set<std::string> names = {"global_costmap", "local_costmap", planner_->name(), controller_->name(),
                                 "conservative_reset", "aggressive_reset", "rotate_recovery",
                                 "NavfnROS", "GlobalPlanner", "TrajectoryPlannerROS", "DWAPlannerROS",
                                 "footprint", "robot_radius", "footprint_padding",
                                 "make_plan_clear_costmap", "restore_defaults"};
  for (const auto& r : recoveries_) names.insert(r->name);
  return names;
}

void MoveBase::onSimpleGoal(const geometry_msgs::PoseStampedConstPtr& goal) {
  ROS_DEBUG("In ROS goal callback, wrapping the PoseStamped in the action message and re-sending to the server.");
  move_base_msgs::MoveBaseActionGoal action_goal;
  action_goal.header.stamp = ros::Time::now();
  action_goal.goal.target_pose = *goal;
  action_goal_pub_.publish(action_goal);
}

void MoveBase::publishZeroVelocity() { cmd_vel_pub_.publish(geometry_msgs::Twist()); }

void MoveBase::resetState() {
  {
    std::lock_guard<std::mutex> lock(planner_mutex_);
    run_planner_ = false;
  }
  state_ = PLANNING;
  recovery_index_ = 0;
  recovery_trigger_ = PLANNING_R;
  publishZeroVelocity();
}

bool MoveBase::acceptGoal(const geometry_msgs::PoseStamped& goal, geometry_msgs::PoseStamped& in_global_frame) {
  std::string why;
  if (!validQuaternion(goal.pose.orientation, &why)) {
    ROS_ERROR("%s", why.c_str());
    as_->setAborted(move_base_msgs::MoveBaseResult(),
                    "Aborting on goal because it was sent with an invalid quaternion");
    return false;
  }
  // The goal in the global costmap's frame, at the latest transform. Upstream plans to an
  // untransformed goal when this fails; an unknown frame is aborted here instead, naming it.
  geometry_msgs::PoseStamped g = goal;
  g.header.frame_id = frameId(goal.header.frame_id);
  g.header.stamp = ros::Time(0);
  tf2::Quaternion q;
  tf2::fromMsg(g.pose.orientation, q);
  g.pose.orientation = tf2::toMsg(q.normalized());
  const std::string& frame = planner_costmap_->globalFrame();
  try {
    in_global_frame = g.header.frame_id.empty() || g.header.frame_id == frame ? g : tf_.transform(g, frame);
  } catch (const tf2::TransformException& e) {
    const std::string text = "Failed to transform the goal pose from " + goal.header.frame_id + " into the " + frame +
                             " frame: " + e.what();
    ROS_ERROR("%s", text.c_str());
    as_->setAborted(move_base_msgs::MoveBaseResult(), "Aborting on goal because " + text);
    return false;
  }
  in_global_frame.header.frame_id = frame;
  in_global_frame.header.stamp = ros::Time::now();
  return true;
}

bool MoveBase::makePlan(const geometry_msgs::PoseStamped& goal, std::vector<geometry_msgs::PoseStamped>& plan) {
  plan.clear();
  if (planner_costmap_->waitingForMap()) {
    ROS_WARN_THROTTLE(2, "The global costmap is waiting for its map: no plan yet.");
    return false;
  }
  navigation_core::Pose2 pose;
  if (!planner_costmap_->robotPose(pose)) {
    ROS_WARN("Unable to get starting pose of robot, unable to create global plan");
    return false;
  }
  geometry_msgs::PoseStamped start;
  start.header.frame_id = planner_costmap_->globalFrame();
  start.pose.position.x = pose.x;
  start.pose.position.y = pose.y;
  start.pose.orientation = tf2::toMsg(tf2::Quaternion(tf2::Vector3(0, 0, 1), pose.theta));
  std::string why;
  if (!planner_->makePlan(start, goal, -1.0, plan, &why) || plan.empty()) {
    ROS_DEBUG("Failed to find a plan to point (%.2f, %.2f): %s", goal.pose.position.x, goal.pose.position.y,
              why.c_str());
    ROS_WARN_THROTTLE(2, "%s: no plan to (%.2f, %.2f): %s", planner_->name().c_str(), goal.pose.position.x,
                      goal.pose.position.y, why.c_str());
    return false;
  }
  return true;
}

void MoveBase::planThread() {
  std::unique_lock<std::mutex> lock(planner_mutex_);
  while (!shutting_down_ && ros::ok()) {
    planner_cond_.wait_for(lock, std::chrono::milliseconds(100), [this] { return run_planner_ || shutting_down_; });
    if (!run_planner_ || shutting_down_) continue;
    const geometry_msgs::PoseStamped goal = planner_goal_;
    const ros::Time started = ros::Time::now();
    lock.unlock();
    std::vector<geometry_msgs::PoseStamped> plan;
    const bool ok = makePlan(goal, plan);
    lock.lock();
    if (ok) {
      latest_plan_.swap(plan);
      new_global_plan_ = true;
      last_valid_plan_ = ros::Time::now();
      planning_retries_ = 0;
      if (run_planner_) state_ = CONTROLLING;
      if (planner_frequency_ <= 0) run_planner_ = false;
    } else if (state_ == PLANNING) {
      ++planning_retries_;
      const ros::Time attempt_end = last_valid_plan_ + ros::Duration(planner_patience_);
      if (run_planner_ && (ros::Time::now() > attempt_end ||
                           (max_planning_retries_ >= 0 && planning_retries_ > max_planning_retries_))) {
        state_ = CLEARING;
        run_planner_ = false;
        publishZeroVelocity();
        recovery_trigger_ = PLANNING_R;
      }
    }
    // The next plan: after 1 / planner_frequency, or (failed, planner_frequency 0) after one
    // control period rather than at once as upstream, which spins a core until the patience ends.
    double wait = planner_frequency_ > 0 ? 1.0 / planner_frequency_ - (ros::Time::now() - started).toSec()
                                         : (ok ? 0.0 : 1.0 / controller_frequency_);
    if (wait > 0 && run_planner_) {
      lock.unlock();
      ros::Duration(wait).sleep();
      lock.lock();
    }
  }
}

void MoveBase::executeCb(const move_base_msgs::MoveBaseGoalConstPtr& move_base_goal) {
  geometry_msgs::PoseStamped goal;
  if (!acceptGoal(move_base_goal->target_pose, goal)) return;
  publishZeroVelocity();
  const auto start_planning = [&](const geometry_msgs::PoseStamped& g) {
    std::lock_guard<std::mutex> lock(planner_mutex_);
    planner_goal_ = g;
    run_planner_ = true;
    new_global_plan_ = false;
    state_ = PLANNING;
    recovery_index_ = 0;
    recovery_trigger_ = PLANNING_R;
    last_valid_control_ = last_valid_plan_ = last_oscillation_reset_ = ros::Time::now();
    planning_retries_ = 0;
    planner_cond_.notify_one();
  };
  start_planning(goal);
  current_goal_pub_.publish(goal);
  ros::Rate rate(controller_frequency_);
  ros::NodeHandle n;
  while (n.ok()) {
    if (as_->isPreemptRequested()) {
      if (as_->isNewGoalAvailable()) {
        const move_base_msgs::MoveBaseGoal next = *as_->acceptNewGoal();
        if (!acceptGoal(next.target_pose, goal)) {
          resetState();
          return;
        }
        publishZeroVelocity();  // the old plan is not followed while the new one is made
        start_planning(goal);
        current_goal_pub_.publish(goal);
      } else {
        resetState();
        ROS_DEBUG("move_base preempting the current goal");
        as_->setPreempted();
        return;
      }
    }
    if (executeCycle()) return;
    if (!rate.sleep() && state_ == CONTROLLING && rate.cycleTime().toSec() > 1.5 / controller_frequency_)
      ROS_WARN_THROTTLE(10, "Control loop missed its desired rate of %.4fHz... the loop actually took %.4f seconds",
                        controller_frequency_, rate.cycleTime().toSec());
  }
  {
    std::lock_guard<std::mutex> lock(planner_mutex_);
    run_planner_ = false;
  }
  as_->setAborted(move_base_msgs::MoveBaseResult(), "Aborting on the goal because the node has been killed");
}

bool MoveBase::executeCycle() {
  navigation_core::Pose2 pose;
  geometry_msgs::PoseStamped current;
  current.header.frame_id = planner_costmap_->globalFrame();
  current.header.stamp = ros::Time::now();
  if (planner_costmap_->robotPose(pose)) {
    current.pose.position.x = pose.x;
    current.pose.position.y = pose.y;
    current.pose.orientation = tf2::toMsg(tf2::Quaternion(tf2::Vector3(0, 0, 1), pose.theta));
    move_base_msgs::MoveBaseFeedback feedback;
    feedback.base_position = current;
    as_->publishFeedback(feedback);
    // Moved far enough: not oscillating.
    if (distance(current, oscillation_pose_) >= oscillation_distance_) {
      last_oscillation_reset_ = ros::Time::now();
      oscillation_pose_ = current;
      if (recovery_trigger_ == OSCILLATION_R) recovery_index_ = 0;
    }
    // The recoveries start over once the robot has got somewhere: oscillation_distance from where
    // the last one ran. Upstream starts them over on any new plan or valid command, so a plan made
    // through cells a clearing recovery has just emptied, blocked again a moment later, sends it
    // round the first recovery for ever.
    const double progress = oscillation_distance_ > 0 ? oscillation_distance_ : 0.5;
    if (recovery_index_ > 0 && distance(current, recovery_pose_) >= progress) recovery_index_ = 0;
  }

  if (!controller_costmap_->isCurrent()) {
    ROS_WARN_THROTTLE(2, "[%s]:Sensor data is out of date, we're not going to allow commanding of the base for safety",
                      ros::this_node::getName().c_str());
    publishZeroVelocity();
    return false;
  }

  std::unique_lock<std::mutex> lock(planner_mutex_);
  if (new_global_plan_) {
    new_global_plan_ = false;
    const std::vector<geometry_msgs::PoseStamped> plan = latest_plan_;
    lock.unlock();
    if (!controller_->setPlan(plan)) {
      ROS_ERROR("Failed to pass global plan to the controller, aborting.");
      resetState();
      as_->setAborted(move_base_msgs::MoveBaseResult(), "Failed to pass global plan to the controller.");
      return true;
    }
    lock.lock();
  }

  switch (state_) {
    case PLANNING:
      run_planner_ = true;
      planner_cond_.notify_one();
      break;

    case CONTROLLING: {
      lock.unlock();
      if (controller_->isGoalReached()) {
        ROS_DEBUG("Goal reached!");
        resetState();
        as_->setSucceeded(move_base_msgs::MoveBaseResult(), "Goal reached.");
        return true;
      }
      if (oscillation_timeout_ > 0 && last_oscillation_reset_ + ros::Duration(oscillation_timeout_) < ros::Time::now()) {
        publishZeroVelocity();
        lock.lock();
        state_ = CLEARING;
        recovery_trigger_ = OSCILLATION_R;
        break;
      }
      geometry_msgs::Twist cmd;
      std::string why;
      if (controller_->computeVelocityCommands(cmd, &why)) {
        last_valid_control_ = ros::Time::now();
        cmd_vel_pub_.publish(cmd);
        lock.lock();
        if (controller_->isGoalReached()) {
          lock.unlock();
          resetState();
          as_->setSucceeded(move_base_msgs::MoveBaseResult(), "Goal reached.");
          return true;
        }
      } else {
        ROS_WARN_THROTTLE(1, "%s: %s", controller_->name().c_str(), why.c_str());
        const ros::Time attempt_end = last_valid_control_ + ros::Duration(controller_patience_);
        publishZeroVelocity();
        lock.lock();
        if (ros::Time::now() > attempt_end) {
          state_ = CLEARING;
          recovery_trigger_ = CONTROLLING_R;
        } else {
          // Plan again, from where the robot is now.
          last_valid_plan_ = ros::Time::now();
          planning_retries_ = 0;
          state_ = PLANNING;
          run_planner_ = true;
          planner_cond_.notify_one();
        }
      }
      break;
    }

    case CLEARING:
      if (recovery_behavior_enabled_ && recovery_index_ < recoveries_.size()) {
        RecoveryBehavior& behaviour = *recoveries_[recovery_index_];
        ROS_DEBUG("Executing behavior %u of %zu", recovery_index_ + 1, recoveries_.size());
        move_base_msgs::RecoveryStatus status;
        status.pose_stamped = current;
        status.current_recovery_number = recovery_index_;
        status.total_number_of_recoveries = static_cast<std::uint32_t>(recoveries_.size());
        status.recovery_behavior_name = behaviour.name;
        recovery_status_pub_.publish(status);
        recovery_pose_ = current;
        lock.unlock();
        behaviour.run();
        lock.lock();
        last_oscillation_reset_ = ros::Time::now();
        ROS_DEBUG("Going back to planning state");
        last_valid_plan_ = ros::Time::now();
        planning_retries_ = 0;
        state_ = PLANNING;
        run_planner_ = true;
        planner_cond_.notify_one();
        ++recovery_index_;
      } else {
        const RecoveryTrigger trigger = recovery_trigger_;
        lock.unlock();
        ROS_DEBUG("All recovery behaviors have failed, locking the planner and disabling it.");
        resetState();
        if (trigger == CONTROLLING_R) {
          ROS_ERROR("Aborting because a valid control could not be found. Even after executing all recovery behaviors");
          as_->setAborted(move_base_msgs::MoveBaseResult(),
                          "Failed to find a valid control. Even after executing recovery behaviors.");
        } else if (trigger == PLANNING_R) {
          ROS_ERROR("Aborting because a valid plan could not be found. Even after executing all recovery behaviors");
          as_->setAborted(move_base_msgs::MoveBaseResult(),
                          "Failed to find a valid plan. Even after executing recovery behaviors.");
        } else {
          ROS_ERROR("Aborting because the robot appears to be oscillating over and over. Even after executing all "
                    "recovery behaviors");
          as_->setAborted(move_base_msgs::MoveBaseResult(), "Robot is oscillating. Even after executing recovery behaviors.");
        }
        return true;
      }
      break;
  }
  return false;
}

bool MoveBase::onMakePlan(nav_msgs::GetPlan::Request& request, nav_msgs::GetPlan::Response& response) {
  if (as_->isActive()) {
    ROS_ERROR("move_base must be in an inactive state to make a plan for an external user");
    return false;
  }
  geometry_msgs::PoseStamped start = request.start;
  const std::string& frame = planner_costmap_->globalFrame();
  if (start.header.frame_id.empty()) {
    navigation_core::Pose2 pose;
    if (!planner_costmap_->robotPose(pose)) {
      ROS_ERROR("move_base cannot make a plan for you because it could not get the start pose of the robot");
      return false;
    }
    start.pose.position.x = pose.x;
    start.pose.position.y = pose.y;
    start.pose.orientation.w = 1.0;
  }
  geometry_msgs::PoseStamped goal = request.goal;
  try {
    for (geometry_msgs::PoseStamped* p : {&start, &goal}) {
      p->header.frame_id = frameId(p->header.frame_id);
      p->header.stamp = ros::Time(0);
      if (!p->header.frame_id.empty() && p->header.frame_id != frame) *p = tf_.transform(*p, frame);
    }
  } catch (const tf2::TransformException& e) {
    ROS_ERROR("make_plan: cannot transform the start or goal into %s: %s", frame.c_str(), e.what());
    return false;
  }
  std::string why;
  const double tolerance = make_plan_add_unreachable_goal_ ? request.tolerance : 0.0;
  if (!planner_->makePlan(start, goal, tolerance, response.plan.poses, &why))
    ROS_WARN("make_plan: no plan to (%.2f, %.2f): %s", goal.pose.position.x, goal.pose.position.y, why.c_str());
  response.plan.header.frame_id = frame;
  response.plan.header.stamp = ros::Time::now();
  return true;
}

bool MoveBase::onClearCostmaps(std_srvs::Empty::Request&, std_srvs::Empty::Response&) {
  planner_costmap_->resetObstacles();
  controller_costmap_->resetObstacles();
  return true;
}

}  // namespace move_base
