"""Shared code of the controller_manager package's tools (spawner, unspawner, controller_manager).

`core` holds the pure logic (argument parsing, service and parameter names, controller names
from YAML, messages): it imports nothing from ROS, so unit tests need no master. `ros_io` is the
ROS side (waiting for services and /clock, bounded service calls, the controller manager's own
log lines as the reason of a failure) and imports rospy.
"""
