"""teleop_twist_keyboard's keys and speed logic (teleop_keyboard.keymap): no ROS master, no terminal."""
import os
import sys

import pytest

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "src"))

from teleop_keyboard import keymap  # noqa: E402
from teleop_keyboard.keymap import CTRL_C, NO_KEY, KeyboardTeleop, Velocity  # noqa: E402


# --- bindings --------------------------------------------------------------------------------

@pytest.mark.parametrize("key,expected", [
    # holonomic off: forward/backward with turning
    ("u", Velocity(0.5, 0, 0, 1.0)),
    ("i", Velocity(0.5, 0, 0, 0)),
    ("o", Velocity(0.5, 0, 0, -1.0)),
    ("j", Velocity(0, 0, 0, 1.0)),
    ("l", Velocity(0, 0, 0, -1.0)),
    ("m", Velocity(-0.5, 0, 0, -1.0)),
    (",", Velocity(-0.5, 0, 0, 0)),
    (".", Velocity(-0.5, 0, 0, 1.0)),
    # holonomic: strafing, never turning
    ("U", Velocity(0.5, 0.5, 0, 0)),
    ("I", Velocity(0.5, 0, 0, 0)),
    ("O", Velocity(0.5, -0.5, 0, 0)),
    ("J", Velocity(0, 0.5, 0, 0)),
    ("L", Velocity(0, -0.5, 0, 0)),
    ("M", Velocity(-0.5, 0.5, 0, 0)),
    ("<", Velocity(-0.5, 0, 0, 0)),
    (">", Velocity(-0.5, -0.5, 0, 0)),
    # up and down
    ("t", Velocity(0, 0, 0.5, 0)),
    ("b", Velocity(0, 0, -0.5, 0)),
])
def test_move_key_sets_velocity_and_publishes(key, expected):
    teleop = KeyboardTeleop()
    reaction = teleop.press(key)
    assert reaction.publish and not reaction.quit and reaction.lines == ()
    assert teleop.velocity() == expected


def test_bindings_cover_exactly_upstreams_keys():
    assert set(keymap.MOVE_BINDINGS) == set("uiojlm,.UIOJLM<>tb")
    assert set(keymap.SPEED_BINDINGS) == set("qzwxec")
    assert not set(keymap.MOVE_BINDINGS) & set(keymap.SPEED_BINDINGS)


def test_holonomic_keys_never_turn_and_plain_keys_never_strafe():
    for key, (x, y, z, th) in keymap.MOVE_BINDINGS.items():
        if key.isupper() or key in "<>":
            assert th == 0, key
        else:
            assert y == 0, key


def test_k_and_any_other_key_stop():
    for key in ["k", "K", " ", "a", "1", "\x1b", "\r", "\ufffd"]:
        teleop = KeyboardTeleop()
        teleop.press("u")
        reaction = teleop.press(key)
        assert reaction.publish and not reaction.quit, repr(key)
        assert teleop.velocity() == Velocity() and teleop.stopped


def test_stop_key_publishes_even_when_already_stopped():
    teleop = KeyboardTeleop()
    assert teleop.press("k").publish


def test_ctrl_c_stops_and_quits():
    teleop = KeyboardTeleop()
    teleop.press("i")
    reaction = teleop.press(CTRL_C)
    assert reaction.quit
    assert teleop.velocity() == Velocity()


# --- key timeout -----------------------------------------------------------------------------

def test_key_timeout_stops_a_moving_robot():
    teleop = KeyboardTeleop()
    teleop.press("i")
    reaction = teleop.press(NO_KEY)
    assert reaction.publish and not reaction.quit
    assert teleop.stopped


def test_key_timeout_sends_nothing_when_already_stopped():
    teleop = KeyboardTeleop()
    reaction = teleop.press(NO_KEY)
    assert not reaction.publish and not reaction.quit and reaction.lines == ()


# --- speeds ----------------------------------------------------------------------------------

@pytest.mark.parametrize("key,speed,turn", [
    ("q", 0.55, 1.1),
    ("z", 0.45, 0.9),
    ("w", 0.55, 1.0),
    ("x", 0.45, 1.0),
    ("e", 0.5, 1.1),
    ("c", 0.5, 0.9),
])
def test_speed_keys_scale_by_ten_percent(key, speed, turn):
    teleop = KeyboardTeleop(0.5, 1.0)
    reaction = teleop.press(key)
    assert teleop.speed == pytest.approx(speed) and teleop.turn == pytest.approx(turn)
    assert reaction.publish and not reaction.quit
    assert reaction.lines == (keymap.speed_line(teleop.speed, teleop.turn),)


def test_speed_key_keeps_direction_and_resends_it_at_the_new_speed():
    teleop = KeyboardTeleop(1.0, 2.0)
    teleop.press("u")
    assert teleop.press("q").publish
    assert teleop.velocity() == Velocity(pytest.approx(1.1), 0, 0, pytest.approx(2.2))


def test_speed_key_while_stopped_stays_stopped():
    teleop = KeyboardTeleop()
    teleop.press("q")
    assert teleop.velocity() == Velocity()


def test_speeds_compound():
    teleop = KeyboardTeleop(0.5, 1.0)
    for _ in range(3):
        teleop.press("q")
    assert teleop.speed == pytest.approx(0.5 * 1.1 ** 3)
    teleop.press("z")
    assert teleop.turn == pytest.approx(1.1 ** 3 * 0.9)


def test_banner_is_printed_again_every_fifteenth_speed_change():
    teleop = KeyboardTeleop()
    with_banner = [i for i in range(1, 46) if keymap.BANNER in teleop.press("w" if i % 2 else "x").lines]
    assert with_banner == [15, 30, 45]


def test_move_keys_do_not_count_towards_the_banner():
    teleop = KeyboardTeleop()
    for _ in range(14):
        teleop.press("e")
        teleop.press("i")
        teleop.press("k")
    assert keymap.BANNER in teleop.press("c").lines


def test_parameters_may_be_ints():
    teleop = KeyboardTeleop(speed=2, turn=3)
    teleop.press("u")
    assert teleop.velocity() == Velocity(2.0, 0, 0, 3.0)
    assert keymap.speed_line(teleop.speed, teleop.turn) == "currently:\tspeed 2.0\tturn 3.0 "


# --- texts -----------------------------------------------------------------------------------

def test_speed_line_format():
    assert keymap.speed_line(0.5, 1.0) == "currently:\tspeed 0.5\tturn 1.0 "


def test_banner_layout():
    lines = keymap.BANNER.split("\n")
    assert lines[0] == "" and lines[-1] == ""
    assert lines[1] == "Reading from the keyboard  and Publishing to Twist!"
    assert lines[3:7] == ["Moving around:", "   u    i    o", "   j    k    l", "   m    ,    ."]
    assert lines[8] == "For Holonomic mode (strafing), hold down the shift key:"
    assert lines[10:13] == ["   U    I    O", "   J    K    L", "   M    <    >"]
    for text in ["t : up (+z)", "b : down (-z)", "anything else : stop",
                 "q/z : increase/decrease max speeds by 10%",
                 "w/x : increase/decrease only linear speed by 10%",
                 "e/c : increase/decrease only angular speed by 10%", "CTRL-C to quit"]:
        assert text in lines
