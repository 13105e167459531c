"""The ROS side of frontier exploration (find_frontier and explore share it)."""
