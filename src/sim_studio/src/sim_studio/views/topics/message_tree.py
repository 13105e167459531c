"""A ROS message as the echo's tree of fields (rostopic echo's content, rqt's expandable rows),
in plain JSON values. No ROS master.

Each node is {"name", "type", "value"} for a primitive (or a short primitive array) and
{"name", "type", "children"} for a message or an array of messages. Long arrays are cut
(an image's data would be megabytes of text): the first MAX_ITEMS values are kept and "more"
says how many were left out. NaN and infinities, which JSON lacks, become the strings "nan",
"inf" and "-inf", as rostopic echo prints them.
"""
import math

MAX_ITEMS = 32      # array elements shown
MAX_TEXT = 2000     # characters of a string field shown
MAX_DEPTH = 16      # nesting, far deeper than any message type


def message_tree(msg):
    """The fields of `msg` (a genpy message) as a list of nodes."""
    return _fields(msg, 0)


def _fields(msg, depth):
    types = getattr(msg, "_slot_types", [""] * len(msg.__slots__))
    return [_node(name, slot_type, getattr(msg, name), depth) for name, slot_type in zip(msg.__slots__, types)]


def _node(name, slot_type, value, depth):
    node = {"name": name, "type": slot_type}
    if depth > MAX_DEPTH:
        node["value"] = "..."
    elif hasattr(value, "__slots__") and hasattr(value, "_type"):
        node["children"] = _fields(value, depth + 1)
    elif hasattr(value, "secs") and hasattr(value, "nsecs"):  # time, duration
        node["value"] = "%d.%09d" % (value.secs, value.nsecs) if value.secs >= 0 else "%.9f" % value.to_sec()
    elif isinstance(value, (bytes, bytearray)):
        node["value"] = list(value[:MAX_ITEMS])
        node["length"] = len(value)
        if len(value) > MAX_ITEMS:
            node["more"] = len(value) - MAX_ITEMS
    elif isinstance(value, (list, tuple)):
        node["length"] = len(value)
        shown = value[:MAX_ITEMS]
        if shown and hasattr(shown[0], "__slots__"):
            element_type = slot_type.split("[")[0]
            node["children"] = [_node("[%d]" % k, element_type, v, depth + 1) for k, v in enumerate(shown)]
        else:
            node["value"] = [_plain(v) for v in shown]
        if len(value) > MAX_ITEMS:
            node["more"] = len(value) - MAX_ITEMS
    else:
        node["value"] = _plain(value)
    return node


def _plain(value):
    if isinstance(value, float):
        if math.isnan(value):
            return "nan"
        if math.isinf(value):
            return "inf" if value > 0 else "-inf"
        return value
    if isinstance(value, str):
        return value if len(value) <= MAX_TEXT else value[:MAX_TEXT] + "... (%d characters)" % len(value)
    if isinstance(value, (bool, int)):
        return value
    if hasattr(value, "tolist"):  # numpy scalars (numpy_msg)
        return _plain(value.tolist())
    return str(value)
