"""topic_plot: plot numeric fields of ROS topics to a PNG (an rqt_plot stand-in)."""
