"""Frontier exploration without ROS: the grid, frontier search (find_frontier and explore share it)."""
