"""The frontiers for rviz (visualization_msgs/MarkerArray on ~frontiers), as explore_lite draws them:
each frontier's cells as points (blue; red when given up on for good, grey when out of reach) and a green
sphere at its goal, smaller for lower-ranked frontiers; the chosen goal's sphere is larger."""
import rospy
from geometry_msgs.msg import Point
from std_msgs.msg import ColorRGBA
from visualization_msgs.msg import Marker, MarkerArray

BLUE = ColorRGBA(0.0, 0.0, 1.0, 1.0)
RED = ColorRGBA(1.0, 0.0, 0.0, 1.0)
GREY = ColorRGBA(0.5, 0.5, 0.5, 1.0)
GREEN = ColorRGBA(0.0, 1.0, 0.0, 1.0)


def frontier_markers(candidates, grid, frame, chosen_goal, previous_count):
    """(MarkerArray, how many markers it holds); markers left over from the last array are deleted."""
    stamp = rospy.Time.now()
    markers = []
    for c in candidates:
        xs, ys = grid.cell_to_world(c.frontier.rows, c.frontier.cols)
        cells = Marker(type=Marker.POINTS, action=Marker.ADD, ns='frontiers', id=len(markers), frame_locked=True)
        cells.header.frame_id, cells.header.stamp = frame, stamp
        cells.pose.orientation.w = 1.0
        cells.scale.x = cells.scale.y = grid.resolution
        cells.color = RED if c.blacklisted else (GREY if c.checked and c.goal is None else BLUE)
        cells.points = [Point(float(x), float(y), 0.0) for x, y in zip(xs, ys)]
        markers.append(cells)
        if c.goal is None:
            continue
        sphere = Marker(type=Marker.SPHERE, action=Marker.ADD, ns='frontiers', id=len(markers), frame_locked=True)
        sphere.header.frame_id, sphere.header.stamp = frame, stamp
        sphere.pose.position.x, sphere.pose.position.y = c.goal
        sphere.pose.orientation.w = 1.0
        size = 0.25 if chosen_goal is not None and tuple(chosen_goal[:2]) == c.goal else 0.12
        sphere.scale.x = sphere.scale.y = sphere.scale.z = size
        sphere.color = GREEN
        markers.append(sphere)
    count = len(markers)
    for i in range(count, previous_count):
        gone = Marker(action=Marker.DELETE, ns='frontiers', id=i)
        gone.header.frame_id = frame
        markers.append(gone)
    return MarkerArray(markers=markers), count
