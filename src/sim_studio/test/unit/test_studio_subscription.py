"""Messages as they arrive in the studio's process: decoded, or rospy.AnyMsg when another
subscriber of the same topic asked for that first (real messages, no master)."""
import io

import rospy
from std_msgs.msg import Float64, String

from sim_studio import subscription


def raw(msg):
    buffer = io.BytesIO()
    msg.serialize(buffer)
    any_msg = rospy.AnyMsg()
    any_msg._buff = buffer.getvalue()
    any_msg._connection_header = {"type": msg._type}
    return any_msg


def test_either_form_decodes_to_the_message():
    assert subscription.typed(Float64(2.5)).data == 2.5
    assert subscription.typed(raw(Float64(2.5))).data == 2.5
    assert subscription.typed(raw(Float64(2.5)), Float64).data == 2.5


def test_type_and_size_of_either_form():
    assert subscription.type_of(raw(String("abc"))) == "std_msgs/String"
    assert subscription.type_of(String("abc")) == "std_msgs/String"
    assert subscription.serialized_size(String("abc")) == subscription.serialized_size(raw(String("abc"))) == 7


def test_a_type_that_is_not_installed():
    unknown = raw(Float64(1.0))
    unknown._connection_header = {"type": "nowhere_msgs/Thing"}
    assert subscription.message_class("nowhere_msgs/Thing") is None
    assert subscription.typed(unknown) is None
