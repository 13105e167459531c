"""map_server's map files, as pure functions (no ROS): loading a map's YAML and image into
OccupancyGrid data (load.py), and map_saver's PGM and YAML (save.py)."""
