#!/usr/bin/env python3
"""move_base reads its parameters through ros_params: a value of the wrong type is an error naming
its full path, what was expected and what was found (the default is used, move_base keeps going); a
misspelt parameter, in move_base's namespace, a planner's or a costmap layer's, is a warning with the
nearest name it reads; upstream's parameters it accepts without effect, and the namespaces of its
components, are not warned about; a layer type it does not have is an error naming those it has."""
import os
import signal
import subprocess
import unittest

import rospy
import rostest

PARAMS = {
    'controler_frequency': 5.0,                      # a typo of controller_frequency
    'planner_patience': 'five',                      # a string where a number belongs
    'controller_frequency': 10,                      # an int for a double: fine
    'TrajectoryPlannerROS': {'max_vel_x': 0.4, 'max_vel_xx': 0.5, 'heading_scoring': False, 'vx_samples': 6.0},
    'NavfnROS': {'allow_unknown': 1, 'visualize_potential': False},
    'conservative_reset_dist': 2.0,
    'global_costmap': {'global_frame': 'odom', 'robot_base_frame': 'base_link', 'rolling_window': True,
                       'width': 4, 'height': 4},
    'local_costmap': {'global_frame': 'odom', 'robot_base_frame': 'base_link', 'rolling_window': True,
                      'width': 3, 'height': 3,
                      'plugins': [{'name': 'obstacles', 'type': 'costmap_2d::ObstacleLayer'},
                                  {'name': 'people', 'type': 'social_navigation_layers::ProxemicLayer'},
                                  {'name': 'inflation', 'type': 'costmap_2d::InflationLayer'}],
                      'obstacles': {'observation_sources': 'scan', 'max_obstacle_height': 0.6, 'raytrace_range': 3.0,
                                    'scan': {'data_type': 'LaserScan', 'obstacle_range': 'far', 'marknig': True}},
                      'inflation': {'inflation_radius': 0.3, 'inflation_radiuss': 0.5}},
}


class MoveBaseParamsTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        rospy.init_node('move_base_params_test')
        rospy.set_param('/mb', PARAMS)
        process = subprocess.Popen(['rosrun', 'move_base', 'move_base', '__name:=mb'], stdout=subprocess.PIPE,
                                   stderr=subprocess.STDOUT, text=True,
                                   env=dict(os.environ, ROSCONSOLE_STDOUT_LINE_BUFFERED='1'))
        try:
            rospy.wait_for_service('/mb/make_plan', timeout=60)  # advertised once it has read everything
        finally:
            process.send_signal(signal.SIGINT)
            output = process.communicate(timeout=30)[0]
        cls.output = output

    def test_it_starts_despite_the_bad_parameters(self):
        self.assertIn('ready for goals', self.output)

    def test_a_wrong_type_is_an_error_naming_path_expected_and_found(self):
        self.assertIn("/mb/planner_patience: expected a number, got the string 'five'; using the default.",
                      self.output)
        self.assertIn('/mb/NavfnROS/allow_unknown: expected true or false, got 1; using the default.', self.output)
        self.assertIn("/mb/local_costmap/obstacles/scan/obstacle_range: expected a number, got the string 'far'; "
                      "using the default.", self.output)

    def test_a_layer_type_it_does_not_have_is_an_error_naming_the_types_it_has(self):
        self.assertIn('/mb/local_costmap/plugins: layer people has type social_navigation_layers::ProxemicLayer, '
                      'which this move_base does not have (it has costmap_2d::InflationLayer, '
                      'costmap_2d::ObstacleLayer, costmap_2d::StaticLayer, costmap_2d::VoxelLayer); the layer is '
                      'left out.', self.output)

    def test_misspelt_parameters_are_warned_with_the_nearest_name(self):
        self.assertIn('/mb/controler_frequency (did you mean controller_frequency?) is no parameter that move_base '
                      'reads: it has no effect.', self.output)
        self.assertIn('/mb/TrajectoryPlannerROS/max_vel_xx (did you mean max_vel_x?) is no parameter that '
                      'move_base reads', self.output)
        # in a layer's namespace and in an observation source's
        self.assertIn('/mb/local_costmap/inflation/inflation_radiuss (did you mean inflation_radius?) is no '
                      'parameter that move_base reads', self.output)
        self.assertIn('/mb/local_costmap/obstacles/scan/marknig (did you mean marking?) is no parameter that '
                      'move_base reads', self.output)

    def test_what_it_reads_or_accepts_is_not_warned_about(self):
        warned = [line for line in self.output.splitlines() if 'is no parameter that move_base reads' in line]
        self.assertEqual(len(warned), 4, '\n'.join(warned))
        for name in ('heading_scoring', 'vx_samples', 'visualize_potential', 'conservative_reset_dist',
                     'global_costmap', 'controller_frequency:', 'local_costmap/obstacles/max_obstacle_height',
                     'local_costmap/obstacles/observation_sources', 'local_costmap/plugins',
                     'local_costmap/obstacles/raytrace_range'):  # searched for by the sources
            self.assertNotIn('/mb/' + name, '\n'.join(warned))
        self.assertNotIn('vx_samples: expected', self.output)  # 6.0 is a whole number: an integer


if __name__ == '__main__':
    rostest.rosrun('move_base', 'test_params', MoveBaseParamsTest)
