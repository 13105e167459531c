"""The numeric fields of a message type as rqt_plot field paths, for the page's completion list
(rqt_plot completes them as you type). An array offers its first element ([0]). No ROS master."""
import roslib.message

NUMERIC = {"bool", "int8", "uint8", "int16", "uint16", "int32", "uint32", "int64", "uint64", "float32", "float64",
           "byte", "char", "time", "duration"}
MAX_DEPTH = 6


def numeric_paths(cls, prefix="", depth=0):
    """['data'] for std_msgs/Float64, ['position[0]', ...] for sensor_msgs/JointState, ..."""
    if depth > MAX_DEPTH:
        return []
    paths = []
    for name, slot_type in zip(cls.__slots__, cls._slot_types):
        base = slot_type.split("[")[0]
        path = prefix + name + ("[0]" if "[" in slot_type else "")
        if base in NUMERIC:
            paths.append(path)
        elif base != "string":
            nested = roslib.message.get_message_class("std_msgs/Header" if base == "Header" else base)
            if nested is not None:
                paths.extend(numeric_paths(nested, path + "/", depth + 1))
    return paths
