"""Field paths as rqt_plot writes them, and reading their values out of ROS messages.

A field spec is a topic name followed by a path into its message, e.g.
  /simple_model/joint1_position_controller/state/process_value
  /arm/joint_states/position[0]          (an element of an array)
  /arm/joint_states/position[joint1_1]   (an element picked by the message's `name` list)
  /odom/pose/pose/position/x             (nested messages)
Which part is the topic is only known from the topics that exist: as rqt_plot does, the
topic is the longest published topic name that the spec starts with (whole name segments).

Nothing here talks to a ROS master; the script topic_plot does that.
"""
import math
import re

_SEGMENT = re.compile(r"^([A-Za-z_][A-Za-z0-9_]*)((?:\[[^\[\]]+\])*)$")
_INDEX = re.compile(r"\[([^\[\]]+)\]")


class FieldError(ValueError):
    """A field spec that is malformed or does not fit the message."""


class FieldPath(object):
    """One step of a path: a field name and the indices that follow it (`position[0]`)."""

    __slots__ = ("name", "indices")

    def __init__(self, name, indices=()):
        self.name = name
        self.indices = tuple(indices)

    def __eq__(self, other):
        return isinstance(other, FieldPath) and (self.name, self.indices) == (other.name, other.indices)

    def __repr__(self):
        return "FieldPath(%r, %r)" % (self.name, self.indices)

    def __str__(self):
        return self.name + "".join("[%s]" % i for i in self.indices)


def parse_field_path(path):
    """'pose/position/x' or 'position[0]' -> [FieldPath, ...]. Integer indices become ints
    (negative ones count from the end); other indices stay names (looked up in `name`)."""
    path = path.strip().strip("/")
    if not path:
        raise FieldError("empty field path: name a field of the message, e.g. /topic/data")
    steps = []
    for segment in path.split("/"):
        m = _SEGMENT.match(segment)
        if not m:
            raise FieldError("bad field path segment '%s' in '%s': expected a field name, optionally with "
                             "[index] or [name] after it" % (segment, path))
        indices = []
        for token in _INDEX.findall(m.group(2)):
            token = token.strip()
            indices.append(int(token) if re.match(r"^-?\d+$", token) else token)
        steps.append(FieldPath(m.group(1), indices))
    return steps


def split_topic_field(spec, topics):
    """(topic, field path string) for a spec such as '/ns/ctrl/state/process_value', given
    the topic names that exist. The topic is the longest one the spec starts with, ending
    at a '/' of the spec; the rest (possibly with [..] indices) is the field path."""
    if not spec.startswith("/"):
        spec = "/" + spec
    best = None
    for topic in topics:
        topic = "/" + topic.strip("/")
        if spec.startswith(topic) and len(spec) > len(topic) and spec[len(topic)] in "/[":
            if best is None or len(topic) > len(best):
                best = topic
    if best is None:
        return None
    field = spec[len(best):].lstrip("/")
    return best, field


def _numeric(value, where):
    if isinstance(value, bool):
        return float(value)
    if isinstance(value, (int, float)):
        return float(value)
    if hasattr(value, "to_sec") and callable(value.to_sec):  # rospy.Time / rospy.Duration
        return float(value.to_sec())
    kind = type(value).__name__
    if isinstance(value, (list, tuple)):
        raise FieldError("%s is an array of %d values: pick one with [index]" % (where, len(value)))
    if hasattr(value, "__slots__"):
        raise FieldError("%s is a message (%s), not a number: name one of its fields: %s"
                         % (where, getattr(value, "_type", kind), ", ".join(value.__slots__)))
    raise FieldError("%s is a %s, not a number" % (where, kind))


def extract(msg, steps):
    """The number at the path `steps` (from parse_field_path) in the message `msg`."""
    value = msg
    where = ""
    for step in steps:
        parent = value
        slots = getattr(parent, "__slots__", None)
        if slots is None or step.name not in slots:
            fields = ", ".join(slots) if slots else "none"
            raise FieldError("'%s' is not a field of %s (%s); its fields: %s"
                             % (step.name, where or "the message", getattr(parent, "_type", type(parent).__name__),
                                fields))
        value = getattr(parent, step.name)
        where = (where + "/" if where else "") + step.name
        for index in step.indices:
            if isinstance(value, (bytes, bytearray)):
                value = list(value)
            if not isinstance(value, (list, tuple)):
                raise FieldError("%s is not an array, so [%s] does not apply" % (where, index))
            if not isinstance(index, int):
                names = getattr(parent, "name", None)
                if not isinstance(names, (list, tuple)):
                    raise FieldError("[%s] picks by name, but %s has no `name` list beside %s"
                                     % (index, getattr(parent, "_type", "the message"), where))
                if index not in names:
                    raise FieldError("[%s]: not in %s's names %s" % (index, where, list(names)))
                index = list(names).index(index)
            if not -len(value) <= index < len(value):
                raise FieldError("%s[%d]: index out of range (%d elements)" % (where, index, len(value)))
            value = value[index]
            where += "[%d]" % index
    return _numeric(value, where)


def check_path(msg_class, steps):
    """Raises FieldError if `steps` cannot lead to a number in messages of `msg_class`
    (arrays are empty in a default message, so an index into one is not checked)."""
    try:
        extract(msg_class(), steps)
    except FieldError as e:
        if "index out of range" in str(e) or "not in" in str(e):
            return  # a real message may have the element
        raise


def message_time(msg, receipt_time):
    """The message's header stamp in seconds if it has a non-zero one, else receipt_time."""
    header = getattr(msg, "header", None)
    stamp = getattr(header, "stamp", None)
    if stamp is not None and hasattr(stamp, "to_sec"):
        t = stamp.to_sec()
        if t > 0 and not math.isnan(t):
            return t
    return receipt_time
