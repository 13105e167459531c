#!/usr/bin/env python3
"""An example check for a navigation stack: send move_base one goal in the map frame, wait for
its result, and print one JSON line: whether it succeeded, the sim seconds it took, and the value
of a parameter (to show which setting the run had).

  rosrun sim_batch goal_check.py --x -0.1 --y 3.0 [--yaw 1.5708] [--timeout 120] [--param NAME]
"""
import argparse
import json
import math

import actionlib
import rospy
from actionlib_msgs.msg import GoalStatus
from move_base_msgs.msg import MoveBaseAction, MoveBaseGoal


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--x", type=float, required=True, help="m, in the map frame")
    parser.add_argument("--y", type=float, required=True)
    parser.add_argument("--yaw", type=float, default=0.0, help="rad")
    parser.add_argument("--timeout", type=float, default=120.0, help="s of sim time")
    parser.add_argument("--param", help="a parameter whose value goes into the result")
    args = parser.parse_args(rospy.myargv()[1:])
    rospy.init_node("goal_check")
    client = actionlib.SimpleActionClient("move_base", MoveBaseAction)
    if not client.wait_for_server(rospy.Duration(120)):
        raise SystemExit("goal_check: no move_base action server in 120 s")
    goal = MoveBaseGoal()
    goal.target_pose.header.frame_id = "map"
    goal.target_pose.header.stamp = rospy.Time.now()
    goal.target_pose.pose.position.x, goal.target_pose.pose.position.y = args.x, args.y
    goal.target_pose.pose.orientation.z = math.sin(args.yaw / 2)
    goal.target_pose.pose.orientation.w = math.cos(args.yaw / 2)
    start = rospy.get_time()
    client.send_goal(goal)
    finished = client.wait_for_result(rospy.Duration(args.timeout))
    took = rospy.get_time() - start
    if not finished:
        client.cancel_goal()
    result = {"reached": finished and client.get_state() == GoalStatus.SUCCEEDED, "seconds": round(took, 2),
              "status_text": client.get_goal_status_text(), "sim_time": rospy.get_time()}
    if args.param:
        result[args.param] = rospy.get_param(args.param, None)
    print(json.dumps(result))


if __name__ == "__main__":
    main()
