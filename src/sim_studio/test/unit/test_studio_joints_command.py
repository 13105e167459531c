"""The Joints view's page command -> bullet_sim_msgs/JointCmd, and the fields read on the way."""
import pytest

from sim_studio import request_fields
from sim_studio.views.joints.joint_command import joint_cmd


def test_force_position_velocity_and_reset():
    cmd = joint_cmd("katana", "katana_motor1_pan_joint", {"force": "1.5"})
    assert cmd.name == "katana::katana_motor1_pan_joint"
    assert (cmd.set_force, cmd.force, cmd.set_position, cmd.set_velocity, cmd.reset) == (True, 1.5, False, False, False)
    cmd = joint_cmd("m", "j", {"position": {"target": 0.5, "p": 10, "i": "0.1", "d": 0.5}})
    assert cmd.set_position and not cmd.set_force
    assert (cmd.position.target, cmd.position.p, cmd.position.i, cmd.position.d) == (0.5, 10, 0.1, 0.5)
    assert (cmd.position.i_max, cmd.position.i_min, cmd.position.cmd_max, cmd.position.cmd_min) == (0, 0, 0, 0)
    cmd = joint_cmd("m", "j", {"velocity": {"target": -1}})  # gains default to 0
    assert cmd.set_velocity and cmd.velocity.target == -1 and cmd.velocity.p == 0
    assert joint_cmd("m", "j", {"reset": True}).reset


@pytest.mark.parametrize("message,error", [
    ({"force": "abc"}, "force: expected a number, got 'abc'"),
    ({"force": float("nan")}, "force: expected a finite number"),
    ({"force": True}, "force: expected a number, got True"),
    ({"position": {"p": 1}}, "position.target: expected a number, got nothing"),
    ({"velocity": {"target": 1, "d": "x"}}, "velocity.d: expected a number, got 'x'"),
    ({"position": 3}, "position: expected an object with target, p, i, d"),
    ({"reset": "yes"}, "needs one of force, position, velocity or reset"),
    ({}, "needs one of force"),
])
def test_bad_fields_are_named(message, error):
    with pytest.raises(ValueError, match=error.replace(".", r"\.").replace("(", r"\(")):
        joint_cmd("m", "j", message)


def test_request_fields():
    assert request_fields.number({"x": " 2 "}, "x") == 2.0
    assert request_fields.number({}, "x", 3) == 3.0
    assert request_fields.number({"x": ""}, "x", 3) == 3.0
    with pytest.raises(ValueError, match="rtf: expected a number >= 0, got -1"):
        request_fields.number({"rtf": -1}, "rtf", low=0)
    with pytest.raises(ValueError, match="x: expected a number <= 1, got 2"):
        request_fields.number({"x": 2}, "x", high=1)
    assert request_fields.name({"model": "arm"}, "model") == "arm"
    with pytest.raises(ValueError, match="model: expected a name"):
        request_fields.name({"model": ""}, "model")
