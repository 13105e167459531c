"""The latest map (nav_msgs/OccupancyGrid), with map_msgs/OccupancyGridUpdate patches applied, as a
frontier_exploration Grid, and when it was made: the map's stamp (its arrival when the stamp is 0),
a patch's arrival."""
import threading

import numpy as np
import rospy
from map_msgs.msg import OccupancyGridUpdate
from nav_msgs.msg import OccupancyGrid

from frontier_exploration.grid import Grid, yaw_of_quaternion


class MapInput:
    def __init__(self, topic, updates_topic=None):
        self.lock = threading.Lock()
        self.values = None       # [row, col], int16
        self.info = None
        self.frame_id = None
        self.made_at = None      # s
        self.topic = rospy.resolve_name(topic)
        rospy.Subscriber(topic, OccupancyGrid, self._on_map, queue_size=1)
        if updates_topic:
            rospy.Subscriber(updates_topic, OccupancyGridUpdate, self._on_update, queue_size=10)

    def grid(self):
        """(Grid, frame id, time made in s) of the latest map, or (None, None, None) before the first one."""
        with self.lock:
            if self.values is None:
                return None, None, None
            i = self.info
            return Grid(self.values.copy(), i.resolution, i.origin.position.x, i.origin.position.y,
                        yaw_of_quaternion(i.origin.orientation)), self.frame_id, self.made_at

    def _on_map(self, msg):
        i = msg.info
        try:
            values = Grid.from_flat(msg.data, i.width, i.height, i.resolution).values
        except ValueError as e:
            rospy.logwarn_throttle(10.0, '%s: ignoring a map that does not add up: %s' % (self.topic, e))
            return
        made_at = msg.header.stamp.to_sec() or rospy.get_time()
        with self.lock:
            old = self.info
            self.values, self.info, self.frame_id = values, i, msg.header.frame_id.lstrip('/')
            self.made_at = made_at
        if old is not None and (old.width, old.height, old.resolution, old.origin.position.x, old.origin.position.y) != (
                i.width, i.height, i.resolution, i.origin.position.x, i.origin.position.y):
            rospy.loginfo('%s: the map is now %d x %d cells of %.3f m from (%.2f, %.2f) (was %d x %d from (%.2f, %.2f)); '
                          'frontiers are searched on the new one' % (
                              self.topic, i.width, i.height, i.resolution, i.origin.position.x, i.origin.position.y,
                              old.width, old.height, old.origin.position.x, old.origin.position.y))

    def _on_update(self, msg):
        with self.lock:
            if self.values is None:
                return
            height, width = self.values.shape
            if msg.x < 0 or msg.y < 0 or msg.x + msg.width > width or msg.y + msg.height > height \
                    or len(msg.data) != msg.width * msg.height:
                rospy.logwarn_throttle(10.0, 'ignoring a map update of %d x %d cells at (%d, %d) with %d values: the map '
                                       'is %d x %d' % (msg.width, msg.height, msg.x, msg.y, len(msg.data), width, height))
                return
            patch = np.asarray(msg.data, dtype=np.int16).reshape(msg.height, msg.width)
            self.values[msg.y:msg.y + msg.height, msg.x:msg.x + msg.width] = patch
            self.made_at = rospy.get_time()
