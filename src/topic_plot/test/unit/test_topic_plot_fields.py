"""topic_plot's pure logic: field specs, value extraction, recording and output files.
Real message classes, built in the tests; no ROS master."""
import csv
import os
import sys

import pytest

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "src"))

import rospy  # noqa: E402  (rospy.Time for header stamps)
from control_msgs.msg import JointControllerState  # noqa: E402
from geometry_msgs.msg import PoseStamped  # noqa: E402
from sensor_msgs.msg import JointState, LaserScan  # noqa: E402
from std_msgs.msg import Bool, Float64, Int32  # noqa: E402

from topic_plot.fields import (FieldError, FieldPath, check_path, extract, message_time,  # noqa: E402
                               parse_field_path, split_topic_field)
from topic_plot.series import Recorder, write_csv, write_png  # noqa: E402

STATE = "/simple_model/joint1_position_controller/state"
TOPICS = [STATE, "/simple_model/joint1_position_controller/command", "/simple_model/joint_states",
          "/simple_model", "/arm/joint_states", "/clock"]


# --- parsing ------------------------------------------------------------------------------

def test_parse_simple_and_nested_paths():
    assert parse_field_path("process_value") == [FieldPath("process_value")]
    assert parse_field_path("/pose/position/x") == [FieldPath("pose"), FieldPath("position"), FieldPath("x")]


def test_parse_indices_numeric_negative_and_by_name():
    assert parse_field_path("position[0]") == [FieldPath("position", [0])]
    assert parse_field_path("ranges[-1]") == [FieldPath("ranges", [-1])]
    assert parse_field_path("position[joint1_1]") == [FieldPath("position", ["joint1_1"])]


@pytest.mark.parametrize("bad", ["", "/", "pose//x", "1abc", "position[]", "position[0", "a b"])
def test_parse_rejects_malformed_paths(bad):
    with pytest.raises(FieldError):
        parse_field_path(bad)


# --- topic / field split, as rqt_plot ------------------------------------------------------

def test_split_takes_the_longest_published_topic():
    assert split_topic_field(STATE + "/process_value", TOPICS) == (STATE, "process_value")
    # "/simple_model" is also a prefix, but the longer state topic wins
    assert split_topic_field(STATE + "/set_point", TOPICS)[0] == STATE


def test_split_keeps_nested_fields_and_indices():
    assert split_topic_field("/arm/joint_states/position[2]", TOPICS) == ("/arm/joint_states", "position[2]")
    assert split_topic_field("/clock/clock", TOPICS) == ("/clock", "clock")


def test_split_matches_whole_name_segments_only():
    # "/arm/joint_states_extra/x" must not be read as topic "/arm/joint_states"
    assert split_topic_field("/arm/joint_states_extra/x", TOPICS) is None
    assert split_topic_field("/unknown/topic/data", TOPICS) is None


def test_split_accepts_a_spec_without_leading_slash():
    assert split_topic_field("arm/joint_states/velocity[0]", TOPICS) == ("/arm/joint_states", "velocity[0]")


# --- extraction from real messages ---------------------------------------------------------

def test_extract_float64_data():
    assert extract(Float64(data=1.5), parse_field_path("data")) == 1.5


def test_extract_ints_and_bools_become_floats():
    assert extract(Int32(data=-3), parse_field_path("data")) == -3.0
    assert extract(Bool(data=True), parse_field_path("data")) == 1.0


def test_extract_joint_controller_state_fields():
    msg = JointControllerState(set_point=1.5, process_value=1.2, process_value_dot=0.4, error=0.3, command=12.5)
    assert extract(msg, parse_field_path("process_value")) == 1.2
    assert extract(msg, parse_field_path("set_point")) == 1.5
    assert extract(msg, parse_field_path("error")) == pytest.approx(0.3)
    assert extract(msg, parse_field_path("command")) == 12.5


def test_extract_joint_state_by_index_and_by_name():
    msg = JointState(name=["joint1_1", "joint2_1"], position=[0.25, -0.5], velocity=[1.0, 2.0])
    assert extract(msg, parse_field_path("position[1]")) == -0.5
    assert extract(msg, parse_field_path("position[-1]")) == -0.5
    assert extract(msg, parse_field_path("velocity[joint2_1]")) == 2.0
    assert extract(msg, parse_field_path("position[joint1_1]")) == 0.25


def test_extract_nested_message_fields_and_stamp():
    msg = PoseStamped()
    msg.pose.position.x = 3.0
    msg.header.stamp = rospy.Time(12, 500000000)
    assert extract(msg, parse_field_path("pose/position/x")) == 3.0
    assert extract(msg, parse_field_path("header/stamp")) == 12.5


def test_extract_laser_ranges():
    msg = LaserScan(ranges=[2.0, float("inf"), 3.5])
    assert extract(msg, parse_field_path("ranges[2]")) == 3.5
    assert extract(msg, parse_field_path("ranges[1]")) == float("inf")


@pytest.mark.parametrize("path, words", [
    ("procces_value", ["not a field", "process_value"]),       # typo: the message's fields are listed
    ("header", ["is a message", "stamp"]),                     # a message, not a number
    ("header/frame_id", ["str", "not a number"]),
])
def test_extract_errors_name_the_problem(path, words):
    with pytest.raises(FieldError) as e:
        extract(JointControllerState(), parse_field_path(path))
    for word in words:
        assert word in str(e.value)


def test_extract_array_errors():
    msg = JointState(name=["a"], position=[1.0])
    with pytest.raises(FieldError, match="pick one with"):
        extract(msg, parse_field_path("position"))
    with pytest.raises(FieldError, match="out of range"):
        extract(msg, parse_field_path("position[3]"))
    with pytest.raises(FieldError, match="not in"):
        extract(msg, parse_field_path("position[b]"))
    with pytest.raises(FieldError, match="not an array"):
        extract(Float64(data=1.0), parse_field_path("data[0]"))


def test_check_path_against_message_classes():
    check_path(JointControllerState, parse_field_path("process_value"))
    check_path(JointState, parse_field_path("position[3]"))     # empty in a default message: fine
    with pytest.raises(FieldError):
        check_path(Float64, parse_field_path("value"))


# --- time stamps ---------------------------------------------------------------------------

def test_message_time_prefers_header_stamp():
    msg = JointControllerState()
    msg.header.stamp = rospy.Time(296, 891000000)
    assert message_time(msg, 5.0) == pytest.approx(296.891)


def test_message_time_falls_back_to_receipt_time():
    assert message_time(Float64(data=1.0), 7.25) == 7.25
    assert message_time(JointControllerState(), 7.25) == 7.25   # zero stamp: not set


# --- recording and output ------------------------------------------------------------------

def _recorder_with_samples():
    r = Recorder()
    r.add(STATE + "/process_value", STATE, "process_value")
    r.add(STATE + "/set_point", STATE, "set_point")
    r.add("/cmd/data", "/cmd", "data")
    for k in range(5):
        msg = JointControllerState(set_point=1.5, process_value=0.3 * k)
        msg.header.stamp = rospy.Time.from_sec(10.0 + 0.1 * k)
        r.on_message(STATE, msg, receipt_time=99.0)
        r.on_message("/cmd", Float64(data=float(k)), receipt_time=10.0 + 0.1 * k)
    return r


def test_recorder_records_every_field_of_a_topic():
    r = _recorder_with_samples()
    pv, sp, cmd = r.series
    assert pv.values == pytest.approx([0.0, 0.3, 0.6, 0.9, 1.2])
    assert pv.times == pytest.approx([10.0, 10.1, 10.2, 10.3, 10.4])   # header stamps, not receipt
    assert sp.values == [1.5] * 5
    assert cmd.times == pytest.approx([10.0, 10.1, 10.2, 10.3, 10.4])  # receipt time: no header
    assert r.start_time() == pytest.approx(10.0)
    assert sorted(r.topics()) == ["/cmd", STATE]


def test_recorder_keeps_first_error_and_ignores_other_topics():
    r = Recorder()
    s = r.add("/js/position[4]", "/js", "position[4]")
    r.on_message("/js", JointState(name=["a"], position=[1.0]), 1.0)
    r.on_message("/other", Float64(data=1.0), 1.0)
    assert s.values == [] and "out of range" in s.error


def test_write_csv(tmp_path):
    path = str(tmp_path / "out.csv")
    write_csv(path, _recorder_with_samples(), t0=10.0)
    with open(path) as f:
        rows = list(csv.reader(f))
    assert rows[0] == ["field", "time", "value"]
    assert len(rows) == 1 + 15
    assert rows[1] == [STATE + "/process_value", "0.000000", "0.0"]
    assert float(rows[5][1]) == pytest.approx(0.4)


def test_write_png(tmp_path):
    path = str(tmp_path / "out.png")
    write_png(path, _recorder_with_samples(), title="joint 1", t0=10.0)
    with open(path, "rb") as f:
        assert f.read(8) == b"\x89PNG\r\n\x1a\n"
    assert os.path.getsize(path) > 5000
