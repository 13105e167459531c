"""Subscribing from a process every view shares.

rospy keeps one subscription per topic per process, and its message class is the one the first
Subscriber of that topic asked for: a later Subscriber gets messages of that class whatever it
asked for. So a view that subscribed with rospy.AnyMsg (to count bytes without decoding) would
hand AnyMsg to another view's typed callback on the same topic. Views therefore subscribe with
the topic's real class whenever it is installed (`subscribe`), and take what arrives in either
form (`typed`, `serialized_size`, `type_of`).
"""
import io

import roslib.message
import rospy


def message_class(type_name):
    """The installed class of a message type name, or None."""
    try:
        return roslib.message.get_message_class(type_name) if type_name else None
    except Exception:  # roslib raises several kinds for a package that is not there
        return None


def subscribe(topic, type_name, callback, **options):
    """A Subscriber with the type's class when it is installed, else rospy.AnyMsg."""
    return rospy.Subscriber(topic, message_class(type_name) or rospy.AnyMsg, callback, **options)


def typed(msg, cls=None):
    """`msg` decoded: as it is when it already is, else (an AnyMsg) with `cls` or the class its
    publisher named; None when that class is not installed."""
    if not isinstance(msg, rospy.AnyMsg):
        return msg
    cls = cls or message_class(type_of(msg))
    return cls().deserialize(msg._buff) if cls is not None else None


def type_of(msg):
    if isinstance(msg, rospy.AnyMsg):
        return (getattr(msg, "_connection_header", None) or {}).get("type", "")
    return msg._type


def serialized_size(msg):
    """The bytes the message took on the wire (rostopic bw's size), serializing it again when it
    arrived decoded."""
    if isinstance(msg, rospy.AnyMsg):
        return len(msg._buff)
    buffer = io.BytesIO()
    msg.serialize(buffer)
    return buffer.tell()
