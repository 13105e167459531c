#!/usr/bin/env python3
"""An example check, as a user writes one for their own robot: drive the robot straight for some
seconds of sim time and print one JSON line with how far it went. sim_batch runs it beside the
scenario's launch file and takes that line as the run's result.

  rosrun sim_batch drive_check.py --model m_robot --speed 0.2 --seconds 2
"""
import argparse
import json
import math

import rospy
from gazebo_msgs.srv import GetModelState
from geometry_msgs.msg import Twist


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--model", required=True)
    parser.add_argument("--cmd-vel", default="/cmd_vel")
    parser.add_argument("--speed", type=float, default=0.2, help="m/s")
    parser.add_argument("--seconds", type=float, default=2.0, help="of sim time")
    args = parser.parse_args(rospy.myargv()[1:])
    rospy.init_node("drive_check")
    rospy.wait_for_service("/gazebo/get_model_state", timeout=60)
    state = rospy.ServiceProxy("/gazebo/get_model_state", GetModelState)
    while not state(model_name=args.model).success:  # spawned a little after the world
        rospy.sleep(0.1)
    command = rospy.Publisher(args.cmd_vel, Twist, queue_size=1)
    while command.get_num_connections() == 0 and not rospy.is_shutdown():  # its drive plugin listens
        rospy.sleep(0.1)
    rospy.sleep(0.5)  # of sim time: the robot settles on its wheels after its spawn
    start = state(model_name=args.model).pose.position
    started = rospy.get_time()
    forward = Twist()
    forward.linear.x = args.speed
    end_time = started + args.seconds
    rate = rospy.Rate(20)
    while rospy.get_time() < end_time and not rospy.is_shutdown():
        command.publish(forward)
        rate.sleep()
    command.publish(Twist())
    end = state(model_name=args.model).pose.position
    # The robot drives on while the stop and the last state call travel: on a busy machine sim
    # time runs some tenths of a second past end_time, so the run reports the time it measured over.
    print(json.dumps({"distance": math.hypot(end.x - start.x, end.y - start.y), "commanded": args.speed * args.seconds,
                      "measured_over_s": rospy.get_time() - started, "sim_time": rospy.get_time()}))


if __name__ == "__main__":
    main()
