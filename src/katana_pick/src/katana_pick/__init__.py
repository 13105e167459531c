"""Pick-and-stack for the Katana tutorial: can detection in a laser scan and the arm's analytic
inverse kinematics, as pure functions without ROS (the nodes only convert messages)."""
