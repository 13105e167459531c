"""What a mapping rostest checks, as a unittest mixin (needs a ROS master, the simulator and the mapper).

The robot drives a scripted path through its maze, steered by a waypoint follower on ground truth
(/gazebo/get_model_state, whose answers carry the sim time); the mapper sees only the laser (and,
for slam_gmapping, the odometry). Once, in setUpClass, the run is driven and recorded; the tests then
compare the mapper's poses (slam_out_pose, or tf map -> base frame for a mapper without that topic)
with the ground truth at their stamps, in the map frame (by default the robot's pose when the mapper
started: it is at rest until the run begins), and score the map that save_map writes against the
maze's walls.
"""
import math
import os
import subprocess
import tempfile
import threading

import numpy as np
import rospy
from gazebo_msgs.srv import GetModelState
from geometry_msgs.msg import PoseStamped, Twist

from bullet_sim_testing.gazebo import set_real_time_factor
from bullet_sim_testing.map_scoring import angle_diff, compose, interpolate, map_alignment, relative
from bullet_sim_testing.mobile import yaw_of
from bullet_sim_testing.walls import load_walls


def load_tour(path):
    """(waypoints [(x, y)], speed m/s, max turn command rad/s) of a mapping_tour.yaml."""
    import yaml
    with open(path) as f:
        tour = yaml.safe_load(f)
    return [tuple(w) for w in tour['waypoints']], float(tour['speed']), float(tour['max_turn'])


def follow_waypoints(truth_sample, cmd, waypoints, speed, max_turn, timeout):
    """Drives through the waypoints with ground truth, turning on the spot when the heading is off by
    more than 0.35 rad, else driving at `speed` steering towards the waypoint. truth_sample() returns
    (stamp, x, y, yaw); cmd is the Twist publisher. Returns how many waypoints were reached."""
    reached, end = 0, rospy.get_time() + timeout
    rate = rospy.Rate(50)
    for wx, wy in waypoints:
        while rospy.get_time() < end and not rospy.is_shutdown():
            _, x, y, yaw = truth_sample()
            if math.hypot(wx - x, wy - y) < 0.08:
                reached += 1
                break
            error = angle_diff(math.atan2(wy - y, wx - x), yaw)
            twist = Twist()
            twist.angular.z = max(-max_turn, min(max_turn, 3.0 * error))
            twist.linear.x = speed if abs(error) < 0.35 else 0.0
            cmd.publish(twist)
            rate.sleep()
    cmd.publish(Twist())
    return reached


class MappingRunChecks:
    MODEL = None             # model name in the simulator
    CMD_VEL = None           # where the drive plugin takes geometry_msgs/Twist
    WALLS = None             # the maze's walls yaml (ground truth)
    TOUR = None              # the path: a mapping_tour.yaml (waypoints in the world frame, speed)
    LASER_RANGE = None       # m, for which wall faces the robot could have seen
    POSITION_LIMIT = 0.05    # m: final and RMS position error must stay under this
    ANGLE_LIMIT = math.radians(2.0)
    MIN_PRECISION = 0.9      # share of the map's occupied cells within 0.1 m of a wall
    MIN_COVERAGE = 0.8       # share of the visible wall faces with an occupied cell within 0.1 m
    RUN_TIMEOUT = 400.0      # s of sim time for the whole path
    # The simulator's target real-time factor for the run: faster than real time keeps the suite
    # short (the Pioneer's runs: 80 s -> 35 s, errors unchanged).
    RTF = 3.0
    # Where the mapper's poses come from: its slam_out_pose topic, or (POSE_TOPIC None) tf from
    # TF_POSE[0] to TF_POSE[1], sampled at 20 Hz of sim time.
    POSE_TOPIC = '/slam_out_pose'
    TF_POSE = ('map', 'base_link')
    # The map frame in the world: None for the robot's pose at the start (hector_mapping), else
    # (x, y, yaw) (slam_gmapping's map is its odom frame, the world for odometrySource world).
    MAP_IN_WORLD = None

    @classmethod
    def setUpClass(cls):
        rospy.init_node('mapping_run_' + cls.MODEL, anonymous=True)
        rospy.wait_for_service('/gazebo/get_model_state', timeout=60)
        cls.get_state = rospy.ServiceProxy('/gazebo/get_model_state', GetModelState, persistent=True)
        set_real_time_factor(cls.RTF)
        cls.cmd = rospy.Publisher(cls.CMD_VEL, Twist, queue_size=1)
        cls.slam_poses, cls.lock = [], threading.Lock()
        if cls.POSE_TOPIC:
            rospy.Subscriber(cls.POSE_TOPIC, PoseStamped, cls._on_pose, queue_size=100)
        else:
            import tf2_ros
            cls.tf_buffer = tf2_ros.Buffer()
            cls.tf_listener = tf2_ros.TransformListener(cls.tf_buffer)
            cls.tf_timer = rospy.Timer(rospy.Duration(0.05), cls._sample_tf)
        cls.truth = []
        deadline = rospy.get_time() + 60
        while not cls._have_slam_pose() and rospy.get_time() < deadline:
            rospy.sleep(0.1)
        # At rest: where the map frame is, unless the mapper's map frame is a fixed one.
        cls.start = cls._truth_sample()[1:] if cls.MAP_IN_WORLD is None else tuple(cls.MAP_IN_WORLD)
        cls.waypoints, speed, max_turn = load_tour(cls.TOUR)
        cls.reached = follow_waypoints(cls._truth_sample, cls.cmd, cls.waypoints, speed, max_turn, cls.RUN_TIMEOUT)
        rospy.sleep(1.5)                      # stop, and let the mapper see the robot at rest
        cls.final_truth = cls._truth_sample()
        deadline = rospy.get_time() + 10
        while rospy.get_time() < deadline and cls._last_slam()[0] <= cls.final_truth[0]:
            rospy.sleep(0.1)

    # --- recording ---------------------------------------------------------------------------------

    @classmethod
    def _on_pose(cls, msg):
        with cls.lock:
            cls.slam_poses.append((msg.header.stamp.to_sec(), msg.pose.position.x, msg.pose.position.y,
                                   yaw_of(msg.pose.orientation)))

    @classmethod
    def _sample_tf(cls, _event):
        import tf2_ros
        try:
            t = cls.tf_buffer.lookup_transform(cls.TF_POSE[0], cls.TF_POSE[1], rospy.Time(0))
        except (tf2_ros.LookupException, tf2_ros.ConnectivityException, tf2_ros.ExtrapolationException):
            return
        with cls.lock:
            stamp = t.header.stamp.to_sec()
            if cls.slam_poses and stamp <= cls.slam_poses[-1][0]:
                return
            cls.slam_poses.append((stamp, t.transform.translation.x, t.transform.translation.y,
                                   yaw_of(t.transform.rotation)))

    @classmethod
    def _have_slam_pose(cls):
        with cls.lock:
            return bool(cls.slam_poses)

    @classmethod
    def _last_slam(cls):
        with cls.lock:
            return cls.slam_poses[-1]

    @classmethod
    def _truth_sample(cls):
        s = cls.get_state(model_name=cls.MODEL, relative_entity_name='world')
        if not s.success:
            raise RuntimeError(s.status_message)
        sample = (s.header.stamp.to_sec(), s.pose.position.x, s.pose.position.y, yaw_of(s.pose.orientation))
        cls.truth.append(sample)
        return sample

    # --- what the run shows ------------------------------------------------------------------------

    def pose_errors(self):
        """[(position error m, angle error rad)] of every mapper pose stamped while the truth was recorded."""
        truth = sorted(self.truth)
        with self.lock:
            poses = list(self.slam_poses)
        errors = []
        for t, x, y, yaw in poses:
            at = interpolate(truth, t)
            if at is None:
                continue
            expected = relative(self.start, at)
            errors.append((math.hypot(x - expected[0], y - expected[1]), abs(angle_diff(yaw, expected[2]))))
        return errors

    def test_the_path_was_driven(self):
        self.assertEqual(self.reached, len(self.waypoints), 'reached %d of %d waypoints' %
                         (self.reached, len(self.waypoints)))

    def test_final_pose_error(self):
        _, x, y, yaw = self._last_slam()
        expected = relative(self.start, self.final_truth[1:])
        position, angle = math.hypot(x - expected[0], y - expected[1]), abs(angle_diff(yaw, expected[2]))
        print('%s mapping: final pose error %.1f mm, %.2f deg (limits %.0f mm, %.1f deg)'
              % (self.MODEL, position * 1e3, math.degrees(angle), self.POSITION_LIMIT * 1e3,
                 math.degrees(self.ANGLE_LIMIT)))
        self.assertLess(position, self.POSITION_LIMIT)
        self.assertLess(angle, self.ANGLE_LIMIT)

    def test_rms_pose_error_over_the_run(self):
        errors = np.array(self.pose_errors())
        self.assertGreater(len(errors), 50, 'too few mapper poses to compare')
        rms = np.sqrt((errors ** 2).mean(axis=0))
        print('%s mapping: %d poses over %.0f m: RMS error %.1f mm, %.2f deg; max %.1f mm, %.2f deg'
              % (self.MODEL, len(errors), self.path_length(), rms[0] * 1e3, math.degrees(rms[1]),
                 errors[:, 0].max() * 1e3, math.degrees(errors[:, 1].max())))
        self.assertLess(rms[0], self.POSITION_LIMIT)
        self.assertLess(rms[1], self.ANGLE_LIMIT)

    def test_saved_map_lines_up_with_the_walls(self):
        from hector_style_mapping_tools import map_files
        folder = tempfile.mkdtemp(prefix='mapping_run_')
        base = os.path.join(folder, self.MODEL + '_map')
        subprocess.check_call(['rosrun', 'hector_style_mapping', 'save_map', '-f', base])
        for ext in ('.pgm', '.yaml', '.png'):
            self.assertTrue(os.path.getsize(base + ext) > 0, base + ext)
        image, resolution, origin = map_files.read_map(base + '.yaml')
        in_map = map_files.occupied_points(image, resolution, origin)
        in_world = [compose(self.start, (x, y, 0.0))[:2] for x, y in in_map]
        seen_from = [(x, y) for _, x, y, _ in self.truth[::25]]
        precision, mean, coverage = map_alignment(load_walls(self.WALLS), in_world, seen_from, self.LASER_RANGE)
        print('%s mapping: saved map %s: %d occupied cells, %.1f %% within 0.1 m of a wall (mean %.1f mm); '
              '%.1f %% of the visible wall faces mapped' % (self.MODEL, base + '.pgm', len(in_world),
                                                            100 * precision, 1e3 * mean, 100 * coverage))
        self.assertGreater(precision, self.MIN_PRECISION)
        self.assertGreater(coverage, self.MIN_COVERAGE)

    def path_length(self):
        xy = np.array([s[1:3] for s in sorted(self.truth)])
        return float(np.sum(np.hypot(*np.diff(xy, axis=0).T))) if len(xy) > 1 else 0.0
