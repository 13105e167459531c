#!/usr/bin/env bash
# `$(find xacro)/xacro.py` and `rosrun xacro xacro.py`: xacro's old name (deprecated in ROS Jade,
# removed in Noetic), still in older lectures' launch files. Runs ./xacro with every argument;
# stdout is xacro's alone (the URDF a launch file's command= reads), the note goes to stderr.
here="$(cd "$(dirname "$(readlink -f "${BASH_SOURCE[0]}")")" && pwd)"
echo "xacro.py: deprecated name (since ROS Jade), running xacro; new files use \$(find xacro)/xacro" >&2
exec "$here/xacro" "$@"
