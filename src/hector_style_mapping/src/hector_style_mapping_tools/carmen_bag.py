"""A CARMEN log's scans written to a rosbag, for the mapper (live with `rosbag play`, or offline with
bench_mapping_bag):

- `scan_topic`: sensor_msgs/LaserScan in `laser_frame`; readings at or beyond `max_range` (the
  scanner's "no return") become +inf, as REP 117 asks, and range_max is max_range;
- `/tf_static`: `base_frame` -> `laser_frame` (the laser's offset from the robot's centre);
- `truth_topic`: nav_msgs/Odometry of `base_frame` in `world_frame`, from the logged poses (ground
  truth in Radish's corrected logs), one at each scan's stamp.

There is no odom -> base tf: the logs' odometry fields are not raw odometry.
"""
import math

import rosbag
import rospy
from geometry_msgs.msg import TransformStamped
from nav_msgs.msg import Odometry
from sensor_msgs.msg import LaserScan
from tf2_msgs.msg import TFMessage

from hector_style_mapping_tools.carmen import saturation_range


def _quaternion(yaw):
    return 0.0, 0.0, math.sin(yaw / 2), math.cos(yaw / 2)


def scan_message(scan, stamp, frame, max_range, min_range):
    msg = LaserScan()
    msg.header.stamp = stamp
    msg.header.frame_id = frame
    msg.angle_min = scan.angle_min
    msg.angle_increment = scan.angle_increment
    msg.angle_max = scan.angle_min + scan.angle_increment * (len(scan.ranges) - 1)
    msg.range_min = min_range
    msg.range_max = max_range
    msg.ranges = [math.inf if r >= max_range else r for r in scan.ranges]
    return msg


def truth_message(scan, stamp, world_frame, base_frame):
    msg = Odometry()
    msg.header.stamp = stamp
    msg.header.frame_id = world_frame
    msg.child_frame_id = base_frame
    x, y, yaw = scan.robot_pose
    msg.pose.pose.position.x, msg.pose.pose.position.y = x, y
    o = msg.pose.pose.orientation
    o.x, o.y, o.z, o.w = _quaternion(yaw)
    return msg


def laser_mount(log, scan, stamp, base_frame, laser_frame):
    t = TransformStamped()
    t.header.stamp = stamp
    t.header.frame_id = base_frame
    t.child_frame_id = laser_frame
    rear = scan.kind == 'RLASER'
    t.transform.translation.x = -log.rear_laser_offset if rear else log.front_laser_offset
    r = t.transform.rotation
    r.x, r.y, r.z, r.w = _quaternion(math.pi if rear else 0.0)
    if scan.kind == 'ROBOTLASER1':  # the line gives both poses: the laser's in the robot's frame
        lx, ly, lt = scan.laser_pose
        rx, ry, rt = scan.robot_pose
        c, s = math.cos(rt), math.sin(rt)
        t.transform.translation.x = c * (lx - rx) + s * (ly - ry)
        t.transform.translation.y = -s * (lx - rx) + c * (ly - ry)
        r.x, r.y, r.z, r.w = _quaternion(lt - rt)
    return t


def write_bag(log, path, scan_topic='/scan', laser_frame='laser', base_frame='base_link',
              truth_topic='/ground_truth', world_frame='world', max_range=None, min_range=0.0):
    """Writes the bag; returns (scans written, the max range used for lines that do not give theirs
    (default: carmen.saturation_range), the seconds added to every stamp so that the first is positive)."""
    if not log.scans:
        raise ValueError('the log has no laser scans (FLASER or ROBOTLASER1 lines)')
    if max_range is None:
        max_range = saturation_range(log)
    shift = 1.0 - log.scans[0].stamp if log.scans[0].stamp < 1.0 else 0.0
    with rosbag.Bag(path, 'w') as bag:
        first = rospy.Time.from_sec(log.scans[0].stamp + shift)
        # Just before the first scan, so that a reader in bag order has it for that scan.
        before = first - rospy.Duration(0, 1000000)
        bag.write('/tf_static', TFMessage([laser_mount(log, log.scans[0], first, base_frame, laser_frame)]), before)
        for scan in log.scans:
            stamp = rospy.Time.from_sec(scan.stamp + shift)
            limit = scan.max_range if scan.max_range is not None else max_range
            bag.write(scan_topic, scan_message(scan, stamp, laser_frame, limit, min_range), stamp)
            bag.write(truth_topic, truth_message(scan, stamp, world_frame, base_frame), stamp)
    return len(log.scans), max_range, shift
