"""pioneer_ros.pid: P, I and D terms, anti-windup and output limits (no ROS master needed)."""
import math
import os
import sys

import pytest

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', '..', 'src'))

from pioneer_ros.pid import Pid, PidGains  # noqa: E402


def test_proportional_only():
    pid = Pid(PidGains(p=2.0))
    assert pid.update(0.5, 0.1) == pytest.approx(1.0)
    assert pid.update(-0.25, 0.1) == pytest.approx(-0.5)


def test_feedforward_is_added():
    pid = Pid(PidGains(p=1.0))
    assert pid.update(0.1, 0.05, feedforward=0.4) == pytest.approx(0.5)


def test_integral_accumulates_error_times_dt():
    pid = Pid(PidGains(i=2.0))
    for _ in range(10):
        out = pid.update(0.5, 0.1)
    assert out == pytest.approx(2.0 * 0.5 * 1.0)
    assert pid.integral == pytest.approx(1.0)


def test_integral_is_clamped():
    pid = Pid(PidGains(i=10.0, i_clamp=0.3))
    for _ in range(100):
        out = pid.update(1.0, 0.1)
    assert out == pytest.approx(0.3)
    for _ in range(100):
        out = pid.update(-1.0, 0.1)
    assert out == pytest.approx(-0.3)


def test_derivative_of_the_error():
    pid = Pid(PidGains(d=0.5))
    assert pid.update(0.0, 0.1) == pytest.approx(0.0)  # no history yet
    assert pid.update(1.0, 0.1) == pytest.approx(0.5 * 10.0)


def test_derivative_on_measurement_ignores_setpoint_steps():
    pid = Pid(PidGains(p=0.0, d=1.0))
    pid.update(0.0, 0.1, measurement=0.0)
    # The setpoint jumps (error 0 -> 1) while the measurement stays: no derivative kick.
    assert pid.update(1.0, 0.1, measurement=0.0) == pytest.approx(0.0)
    # The measurement rises at 2 per second: D opposes it.
    assert pid.update(0.8, 0.1, measurement=0.2) == pytest.approx(-2.0)


def test_derivative_filter_smooths_a_step():
    pid = Pid(PidGains(d=1.0, d_filter_time=0.1))
    pid.update(0.0, 0.1)
    first = pid.update(1.0, 0.1)
    assert first == pytest.approx(0.5 * 10.0)  # alpha = dt / (tf + dt) = 0.5
    assert abs(pid.update(1.0, 0.1)) < first   # and decays once the error is steady


def test_output_is_limited():
    pid = Pid(PidGains(p=10.0, output_min=-1.0, output_max=0.5))
    assert pid.update(1.0, 0.1) == pytest.approx(0.5)
    assert pid.saturated
    assert pid.update(-1.0, 0.1) == pytest.approx(-1.0)


def test_no_windup_while_saturated():
    gains = PidGains(p=1.0, i=1.0, output_min=-1.0, output_max=1.0)
    pid = Pid(gains)
    for _ in range(200):  # a long block: output pinned at the limit
        assert pid.update(2.0, 0.1) == pytest.approx(1.0)
    assert pid.integral < 0.5  # it stopped integrating once the output hit the limit
    # When the error reverses, the output leaves the limit at once instead of after
    # unwinding 20 s worth of integral.
    assert pid.update(-0.5, 0.1) < 0.5


def test_integrating_out_of_saturation_is_allowed():
    pid = Pid(PidGains(p=1.0, i=1.0, output_min=-1.0, output_max=1.0))
    pid.integral = 0.8
    pid.update(-0.1, 0.1, feedforward=2.0)  # saturated high, but the error pulls down
    assert pid.integral == pytest.approx(0.79)


def test_zero_dt_neither_integrates_nor_differentiates():
    pid = Pid(PidGains(p=1.0, i=5.0, d=5.0))
    pid.update(1.0, 0.1)
    integral, derivative = pid.integral, pid.derivative
    pid.update(3.0, 0.0)
    assert (pid.integral, pid.derivative) == (integral, derivative)


def test_reset_clears_the_history():
    pid = Pid(PidGains(i=1.0, d=1.0))
    pid.update(1.0, 0.1)
    pid.update(2.0, 0.1)
    pid.reset()
    assert pid.integral == 0.0 and pid.derivative == 0.0
    assert pid.update(0.0, 0.1) == 0.0


@pytest.mark.parametrize('kwargs', [dict(p=math.nan), dict(i_clamp=-1.0), dict(output_min=1.0, output_max=0.0),
                                    dict(d_filter_time=-0.1)])
def test_bad_gains_are_refused(kwargs):
    with pytest.raises(ValueError):
        PidGains(**kwargs)


def test_non_finite_error_is_refused():
    with pytest.raises(ValueError):
        Pid(PidGains(p=1.0)).update(math.inf, 0.1)
