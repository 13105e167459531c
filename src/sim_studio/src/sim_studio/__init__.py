"""sim_studio: Gazebo's client and rqt's tools in a browser, served by a ROS node."""
