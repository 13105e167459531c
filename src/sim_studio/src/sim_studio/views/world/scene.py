"""/gazebo/scene_info (a MarkerArray) -> what the page draws: every visual in its link's frame
and every laser and camera, as plain JSON; and the mesh files it names, the only files the
World view serves. Pure: reads the message's fields, no ROS calls.

The simulator's layout (bullet_sim's scene_info.h): a DELETEALL marker first, then per model
(`ns`) each visual with header.frame_id "model::link", its pose in that link, type, scale,
colour and, for meshes, mesh_resource "file:///abs/path"; per sensor a LINE_LIST with text
"laser:<topic>" or "camera:<topic>", its pose in the link and scale.x its range.
"""
import hashlib
import os
import posixpath
from urllib.parse import quote, unquote, urlparse

# visualization_msgs/Marker's type and action numbers
CUBE, SPHERE, CYLINDER, LINE_LIST, MESH_RESOURCE = 1, 2, 3, 5, 10
DELETEALL = 3
TYPES = {CUBE: "box", SPHERE: "sphere", CYLINDER: "cylinder", MESH_RESOURCE: "mesh"}
MESH_TYPES = (".stl", ".dae", ".obj")  # what the page's loaders read (three.js's STL, Collada, OBJ)
MESH_URL = "/api/world/mesh/%s/%s"


def pose_list(pose):
    p, q = pose.position, pose.orientation
    return [p.x, p.y, p.z, q.x, q.y, q.z, q.w]


def mesh_id(path):
    """A stable name for a mesh file in URLs: the page never sends a path, only this."""
    return hashlib.sha1(path.encode("utf-8", "surrogateescape")).hexdigest()[:20]


def mesh_path(resource):
    """The absolute path of a "file:///..." mesh resource the page can load, or None (another
    scheme, a relative path, a type no loader reads)."""
    url = urlparse(resource)
    if url.scheme != "file" or url.netloc not in ("", "localhost"):
        return None
    path = unquote(url.path)
    if not posixpath.isabs(path) or os.path.splitext(path)[1].lower() not in MESH_TYPES:
        return None
    return posixpath.normpath(path)


def read_scene(markers):
    """(scene, meshes): scene = {"visuals": [...], "sensors": [...], "skipped": [...]}, and
    meshes = {mesh id: absolute path} for the visuals' mesh files. Markers before the last
    DELETEALL are dropped, as rviz would."""
    start = 0
    for i, marker in enumerate(markers):
        if marker.action == DELETEALL:
            start = i + 1
    visuals, sensors, skipped, meshes = [], [], [], {}
    for marker in markers[start:]:
        common = {"model": marker.ns, "frame": marker.header.frame_id, "pose": pose_list(marker.pose),
                  "color": [marker.color.r, marker.color.g, marker.color.b, marker.color.a]}
        if marker.type == LINE_LIST and ":" in marker.text:
            kind, topic = marker.text.split(":", 1)
            if kind in ("laser", "camera"):
                sensors.append(dict(common, kind=kind, topic=topic, range=marker.scale.x))
            continue
        kind = TYPES.get(marker.type)
        if kind is None:
            skipped.append("%s/%s: marker type %d is not drawn" % (marker.ns, marker.text, marker.type))
            continue
        visual = dict(common, type=kind, name=marker.text, scale=[marker.scale.x, marker.scale.y, marker.scale.z])
        if kind == "mesh":
            path = mesh_path(marker.mesh_resource)
            if path is None:
                skipped.append("%s/%s: mesh %s is not a .stl, .dae or .obj file" % (marker.ns, marker.text,
                                                                                     marker.mesh_resource))
                continue
            meshes[mesh_id(path)] = path
            visual["mesh"] = MESH_URL % (mesh_id(path), quote(posixpath.basename(path)))
            visual["format"] = os.path.splitext(path)[1].lower()[1:]
        visuals.append(visual)
    return {"visuals": visuals, "sensors": sensors, "skipped": skipped}, meshes
