"""The robot's position in the map frame: from a geometry_msgs/PoseStamped topic (hector_mapping's
slam_out_pose, the lecture's input) while it is published in that frame, else from tf."""
import threading

import rospy
import tf2_ros
from geometry_msgs.msg import PoseStamped


class RobotPose:
    def __init__(self, base_frame, transform_tolerance, pose_topic=None):
        self.base_frame = base_frame.lstrip('/')
        self.tolerance = transform_tolerance
        self.buffer = tf2_ros.Buffer(cache_time=rospy.Duration(10.0))
        self.listener = tf2_ros.TransformListener(self.buffer)
        self.lock = threading.Lock()
        self.last_pose = None  # (frame, x, y, receive time)
        if pose_topic:
            rospy.Subscriber(pose_topic, PoseStamped, self._on_pose, queue_size=1)

    def _on_pose(self, msg):
        with self.lock:
            self.last_pose = (msg.header.frame_id.lstrip('/'), msg.pose.position.x, msg.pose.position.y, rospy.get_time())

    def xy(self, frame):
        """(x, y) of the robot in `frame`, or (None, why not)."""
        with self.lock:
            last = self.last_pose
        if last is not None and last[0] == frame and rospy.get_time() - last[3] <= max(self.tolerance, 1.0):
            return (last[1], last[2]), None
        try:
            t = self.buffer.lookup_transform(frame, self.base_frame, rospy.Time(0))
        except (tf2_ros.LookupException, tf2_ros.ConnectivityException, tf2_ros.ExtrapolationException) as e:
            return None, 'no transform from %s to %s: %s' % (frame, self.base_frame, e)
        age = (rospy.Time.now() - t.header.stamp).to_sec()
        if age > self.tolerance and t.header.stamp != rospy.Time(0):
            return None, ('the transform from %s to %s is %.2f s old (transform_tolerance %.2f s)'
                          % (frame, self.base_frame, age, self.tolerance))
        return (t.transform.translation.x, t.transform.translation.y), None
