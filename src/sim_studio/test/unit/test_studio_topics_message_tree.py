"""The echo's tree of fields: nested messages, arrays cut short, NaN as text (real messages)."""
import json

import genpy
from geometry_msgs.msg import PoseArray, Pose
from sensor_msgs.msg import Image, JointState
from std_msgs.msg import Float64

from sim_studio.views.topics.message_tree import MAX_ITEMS, message_tree


def test_nested_fields_and_arrays():
    msg = JointState(name=["a", "b"], position=[1.0, float("nan")])
    msg.header.stamp = genpy.Time(12, 5000)
    tree = message_tree(msg)
    header = tree[0]
    assert header["name"] == "header" and header["type"] == "std_msgs/Header"
    assert header["children"][1] == {"name": "stamp", "type": "time", "value": "12.000005000"}
    assert tree[1]["value"] == ["a", "b"]
    assert tree[2]["value"] == [1.0, "nan"]
    json.dumps(tree, allow_nan=False)  # what the studio sends must be strict JSON


def test_long_arrays_and_bytes_are_cut():
    image = Image(height=100, width=100, encoding="mono8", step=100, data=bytes(10000))
    node = [n for n in message_tree(image) if n["name"] == "data"][0]
    assert len(node["value"]) == MAX_ITEMS and node["more"] == 10000 - MAX_ITEMS and node["length"] == 10000


def test_arrays_of_messages_are_children():
    poses = PoseArray(poses=[Pose(), Pose()])
    poses.poses[1].position.x = 2.0
    node = message_tree(poses)[1]
    assert [c["name"] for c in node["children"]] == ["[0]", "[1]"]
    assert node["children"][1]["children"][0]["children"][0] == {"name": "x", "type": "float64", "value": 2.0}


def test_a_float64():
    assert message_tree(Float64(2.5)) == [{"name": "data", "type": "float64", "value": 2.5}]
    assert message_tree(Float64(float("-inf")))[0]["value"] == "-inf"
