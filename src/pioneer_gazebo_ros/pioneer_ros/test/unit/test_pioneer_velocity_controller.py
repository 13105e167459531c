"""pioneer_ros.velocity_controller: the controller's modes and timeouts, its parameters, and
the shipped gains on a simulated drive (no ROS master needed)."""
import math
import os
import sys

import pytest
import yaml

PACKAGE = os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', '..')
sys.path.insert(0, os.path.join(PACKAGE, 'src'))

from pioneer_ros.velocity_controller import (CLOSED_LOOP, IDLE, OPEN_LOOP, STOPPED,  # noqa: E402
                                             BodyVelocityController, config_from_params)

PARAMS_FILE = os.path.join(PACKAGE, 'pioneer_controller_params.yaml')


def shipped_params():
    with open(PARAMS_FILE) as f:
        return yaml.safe_load(f)


def controller(**overrides):
    params = shipped_params()
    params.update(overrides)
    return BodyVelocityController(config_from_params(params))


def test_shipped_params_load_with_the_report_layout():
    config = config_from_params(shipped_params())
    assert config.linear.p > 0 and config.linear.i > 0 and config.linear.d > 0
    assert config.angular.p > 0 and config.angular.i > 0 and config.angular.d > 0
    assert (config.linear.output_min, config.linear.output_max) == (-1.0, 1.0)
    assert (config.angular.output_min, config.angular.output_max) == (-2.0, 2.0)
    assert config.linear.i_clamp == 0.3 and config.angular.i_clamp == 0.6
    assert config.rate == 20.0 and config.cmd_timeout == 0.5 and config.odom_timeout == 0.5


def test_missing_params_take_defaults_and_bad_ones_are_named():
    config = config_from_params({})
    assert config.linear.p == 0.0 and config.feedforward_linear == 1.0 and config.linear.output_max == 1.0
    with pytest.raises(ValueError, match='controller_gains/body/linear/p'):
        config_from_params({'controller_gains': {'body': {'linear': {'p': 'fast'}}}})
    with pytest.raises(ValueError, match='limits/angular'):
        config_from_params({'limits': {'angular': -1.0}})
    with pytest.raises(ValueError, match='rate'):
        config_from_params({'rate': 0})


def test_idle_until_a_command_arrives():
    c = controller()
    assert c.update(1.0) is None and c.mode == IDLE


def test_open_loop_without_odometry_passes_the_command_through():
    c = controller()
    c.set_command(0.4, -0.3, 1.0)
    assert c.update(1.0) == pytest.approx((0.4, -0.3))
    assert c.mode == OPEN_LOOP


def test_output_is_limited_even_open_loop():
    c = controller()
    c.set_command(3.0, -9.0, 1.0)
    assert c.update(1.0) == pytest.approx((1.0, -2.0))


def test_closed_loop_corrects_a_shortfall():
    c = controller()
    c.set_command(0.5, 0.0 + 1e-9, 1.0)
    c.set_measurement(0.3, 0.0, 1.0)
    linear, _ = c.update(1.0)
    assert c.mode == CLOSED_LOOP
    assert linear == pytest.approx(0.5 + 0.5 * 0.2)  # feedforward + p * error on the first step
    c.set_measurement(0.3, 0.0, 1.05)
    later, _ = c.update(1.05)
    assert later > linear  # the integral adds to it while the shortfall lasts


def test_stale_odometry_falls_back_to_open_loop():
    c = controller()
    c.set_command(0.5, 0.2, 1.0)
    c.set_measurement(0.3, 0.1, 1.0)
    c.update(1.0)
    c.set_command(0.5, 0.2, 1.6)
    assert c.update(1.6) == pytest.approx((0.5, 0.2))
    assert c.mode == OPEN_LOOP


def test_zero_command_stops_at_once_and_clears_the_integral():
    c = controller()
    c.set_command(0.5, 0.0, 1.0)
    for k in range(10):
        c.set_measurement(0.2, 0.0, 1.0 + 0.05 * k)
        c.update(1.0 + 0.05 * k)
    assert c.linear_pid.integral > 0
    c.set_command(0.0, 0.0, 1.5)
    assert c.update(1.5) == (0.0, 0.0)
    assert c.mode == STOPPED and c.linear_pid.integral == 0.0


def test_command_timeout_sends_one_stop_then_goes_quiet():
    c = controller()
    c.set_command(0.5, 0.1, 1.0)
    assert c.update(1.2) is not None
    assert c.update(1.6) == (0.0, 0.0)
    assert c.mode == IDLE
    assert c.update(1.7) is None


def test_clock_jumping_back_resets_everything():
    c = controller()
    c.set_command(0.5, 0.1, 10.0)
    c.set_measurement(0.4, 0.1, 10.0)
    c.update(10.0)
    assert c.update(0.5) is None  # reset_simulation: the old command is gone
    assert c.mode == IDLE


def test_non_finite_commands_are_refused():
    with pytest.raises(ValueError):
        controller().set_command(math.nan, 0.0, 1.0)


def simulate(gains_params, command, efficiency, duration=3.0, tau=0.05, rate=20.0, physics_dt=0.001):
    """A drive that reaches efficiency * its command with time constant tau (slip, a weak
    motor), odometry read at the controller's instants. Returns [(t, measured)]."""
    c = BodyVelocityController(config_from_params(gains_params))
    velocity, drive_command, t, trace = 0.0, 0.0, 0.0, []
    next_control = 0.0
    while t < duration:
        if t >= next_control - 1e-9:
            c.set_command(command, 0.0, t)
            c.set_measurement(velocity, 0.0, t)
            out = c.update(t)
            drive_command = out[0] if out else 0.0
            trace.append((t, velocity))
            next_control += 1.0 / rate
        velocity += (efficiency * drive_command - velocity) * physics_dt / tau
        t += physics_dt
    return trace


def test_shipped_gains_remove_a_20_percent_shortfall_without_overshoot():
    trace = simulate(shipped_params(), command=0.5, efficiency=0.8)
    final = trace[-1][1]
    assert final == pytest.approx(0.5, rel=0.02)
    assert max(v for _, v in trace) < 0.5 * 1.05
    settled = next(t for t, v in trace if abs(v - 0.5) < 0.02 * 0.5)
    assert settled < 2.0
    # Feedforward alone would stay 20 % short:
    open_loop = simulate({'controller_gains': {}}, command=0.5, efficiency=0.8)
    assert open_loop[-1][1] == pytest.approx(0.4, rel=0.01)


def test_shipped_gains_do_not_oscillate_with_a_perfect_drive():
    trace = simulate(shipped_params(), command=0.8, efficiency=1.0)
    values = [v for _, v in trace]
    assert values[-1] == pytest.approx(0.8, rel=0.01)
    assert max(values) < 0.8 * 1.05
