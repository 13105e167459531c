"""The publisher's messages: a field tree per type, and messages built from expressions with every
value checked against its field's type (real genpy messages, no master)."""
import math

import genpy
import pytest
from geometry_msgs.msg import Twist
from sensor_msgs.msg import JointState
from std_msgs.msg import Float64, Header, Int8, String, UInt8MultiArray

from sim_studio.views.publisher.message_fields import (FieldError, build, compile_expressions, convert, describe,
                                                        message_class)


def make(cls, i=1, t=0.0, **expressions):
    return build(cls, compile_expressions(cls, expressions), {"i": i, "t": t})


def test_message_class_of_installed_and_unknown_types():
    assert message_class("std_msgs/Float64") is Float64
    with pytest.raises(FieldError, match="unknown message type std_msgs/Flaot64: not installed"):
        message_class("std_msgs/Flaot64")
    with pytest.raises(FieldError, match="not a message type name"):
        message_class("Float64")


def test_the_tree_of_a_nested_type():
    tree = describe(JointState)
    assert [f["path"] for f in tree] == ["header", "name", "position", "velocity", "effort"]
    assert [c["path"] for c in tree[0]["children"]] == ["header/seq", "header/stamp", "header/frame_id"]
    assert tree[2]["type"] == "float64[]" and "children" not in tree[2]


def test_sin_i_over_100_in_a_float64():
    assert make(Float64, i=42, data="sin(i/100)").data == math.sin(0.42)


def test_nested_fields_arrays_and_time():
    msg = make(JointState, i=2, t=12.5, **{"header/stamp": "t", "header/frame_id": "base", "name": "['a', 'b']",
                                          "position": "[i, i/4]"})
    assert msg.header.stamp == genpy.Time.from_sec(12.5)
    assert msg.header.frame_id == "base"  # rqt: a string field's text that does not evaluate is the string
    assert msg.name == ["a", "b"] and msg.position == [2.0, 0.5]
    twist = make(Twist, **{"linear": "{'x': 0.5}", "angular/z": "-i"})
    assert (twist.linear.x, twist.angular.z) == (0.5, -1.0)


def test_numbers_convert_as_rqt_converts_them():
    assert make(Int8, data="2.9").data == 2          # int(), as rqt does for an integer field
    assert make(Float64, data="3").data == 3.0
    assert make(String, data="i * 2").data == "2"    # str() of the value
    assert make(UInt8MultiArray, data="[1, 2, 255]").data == b"\x01\x02\xff"


def test_empty_expressions_leave_defaults():
    assert make(Float64, data="  ").data == 0.0


@pytest.mark.parametrize("cls, expressions, words", [
    (Float64, {"data": "'ten'"}, "field 'data' (float64): expected a number, got the text 'ten'"),
    (Float64, {"data": "hello"}, "field 'data' (float64): name 'hello' is not defined"),
    (Float64, {"velocity": "1"}, "field 'velocity': std_msgs/Float64 has no such field (its fields: data)"),
    (Float64, {"data": "sin("}, "field 'data' (float64): not a Python expression"),
    (Float64, {"data": "[1, 2]"}, "expected a number, got a list of 2"),
    (Int8, {"data": "200"}, "field 'data' (int8): 200 is out of int8's range (-128 to 127)"),
    (Int8, {"data": "nan"}, "expected a finite number, got nan"),
    (UInt8MultiArray, {"data": "[1, 256]"}, "field 'data' (uint8[]): [1] (uint8): 256 is out of uint8's range"),
    (UInt8MultiArray, {"data": "3"}, "expected a list such as [1, 2, 3]"),
    (Twist, {"linear": "{'w': 1}"}, "field 'linear' (geometry_msgs/Vector3): geometry_msgs/Vector3 has no field 'w'"),
    (Twist, {"linear": "1.0"}, "expected a dict of geometry_msgs/Vector3's fields"),
    (Header, {"stamp": "-1"}, "a time cannot be negative"),
    (Header, {"stamp": "'now'"}, "expected a number of seconds"),
    (Float64, {"data": "1/0"}, "field 'data' (float64): ZeroDivisionError"),
])
def test_what_does_not_fit_names_the_field_and_why(cls, expressions, words):
    with pytest.raises(FieldError) as refused:
        make(cls, **expressions)
    assert words in str(refused.value)


def test_every_bad_field_is_named_at_once():
    with pytest.raises(FieldError) as refused:  # unknown and unparsable: found before anything runs
        make(Twist, **{"linear/x": "sin(", "angular/q": "1"})
    assert "'linear/x'" in str(refused.value) and "'angular/q'" in str(refused.value)
    with pytest.raises(FieldError) as refused:  # values that do not fit
        make(Twist, **{"linear/x": "'a'", "angular/z": "1/0"})
    assert "'linear/x'" in str(refused.value) and "'angular/z'" in str(refused.value)


def test_fixed_length_arrays_and_float32():
    from geometry_msgs.msg import PoseWithCovariance
    from std_msgs.msg import Float32
    with pytest.raises(FieldError, match="expected exactly 36 elements"):
        make(PoseWithCovariance, covariance="[0.0] * 35")
    assert len(make(PoseWithCovariance, covariance="[0.0] * 36").covariance) == 36
    with pytest.raises(FieldError, match="beyond float32's range"):
        make(Float32, data="1e39")


def test_convert_bool():
    assert convert(True, "bool") is True and convert(0, "bool") is False
    with pytest.raises(FieldError, match="expected True or False"):
        convert(2, "bool")
