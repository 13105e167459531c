"""The Pioneer's body-velocity controller (no ROS): turns velocity commands (cmd_vel, from
move_base or a teleop) into the commands the drive takes (/pioneer/cmd_vel), closing a PID
loop on each of the linear (m/s) and angular (rad/s) velocity errors with the measured
velocities from odometry:

    output = feedforward * command + PID(command - measured), clamped to the limits

- No command for cmd_timeout seconds: one zero command, then nothing (the controller goes
  idle and leaves the drive to whoever else commands it).
- A zero command is passed straight through and clears the integrators: stop means stop.
- No odometry for odom_timeout seconds: open loop (feedforward only, integrators cleared),
  so the robot still obeys, uncorrected, and the node warns.
- Time going backwards (a simulation reset): everything is cleared.

The report's controller (pioneer_pid_controller.cpp) multiplied the command by the P gain
and left I and D unused; its parameter layout (controller_gains/body/{linear,angular}/{p,i,d})
is kept.
"""
import math

from pioneer_ros.pid import Pid, PidGains, clamp

IDLE, STOPPED, CLOSED_LOOP, OPEN_LOOP = 'idle', 'stopped', 'closed loop', 'open loop'


class ControllerConfig:
    def __init__(self, linear, angular, feedforward_linear=1.0, feedforward_angular=1.0, rate=20.0,
                 cmd_timeout=0.5, odom_timeout=0.5):
        self.linear, self.angular = linear, angular  # PidGains, with the output limits
        self.feedforward_linear, self.feedforward_angular = float(feedforward_linear), float(feedforward_angular)
        self.rate, self.cmd_timeout, self.odom_timeout = float(rate), float(cmd_timeout), float(odom_timeout)
        if not self.rate > 0.0:
            raise ValueError('rate: expected a positive number of Hz, got %r' % rate)
        for name in ('cmd_timeout', 'odom_timeout'):
            if not getattr(self, name) > 0.0:
                raise ValueError('%s: expected a positive number of seconds, got %r' % (name, getattr(self, name)))


def _number(tree, path, default):
    """tree[path[0]][path[1]]... as a float, the default when absent; ValueError names the path."""
    node = tree
    for key in path:
        if not isinstance(node, dict) or key not in node:
            return float(default)
        node = node[key]
    try:
        value = float(node)
    except (TypeError, ValueError):
        raise ValueError('%s: expected a number, got %r' % ('/'.join(path), node))
    if math.isnan(value):
        raise ValueError('%s: expected a number, got NaN' % '/'.join(path))
    return value


def config_from_params(params):
    """A ControllerConfig from the parameter tree of pioneer_controller_params.yaml."""
    params = params or {}
    filter_time = _number(params, ('derivative_filter_time',), 0.0)

    def gains(axis, limit_default):
        base = ('controller_gains', 'body', axis)
        limit = _number(params, ('limits', axis), limit_default)
        if not limit > 0.0:
            raise ValueError('limits/%s: expected a positive number, got %r' % (axis, limit))
        return PidGains(p=_number(params, base + ('p',), 0.0), i=_number(params, base + ('i',), 0.0),
                        d=_number(params, base + ('d',), 0.0), i_clamp=_number(params, base + ('i_clamp',), limit),
                        output_min=-limit, output_max=limit, d_filter_time=filter_time)

    return ControllerConfig(
        linear=gains('linear', 1.0), angular=gains('angular', 2.0),
        feedforward_linear=_number(params, ('feedforward', 'linear'), 1.0),
        feedforward_angular=_number(params, ('feedforward', 'angular'), 1.0),
        rate=_number(params, ('rate',), 20.0),
        cmd_timeout=_number(params, ('cmd_timeout',), 0.5),
        odom_timeout=_number(params, ('odom_timeout',), 0.5))


class BodyVelocityController:
    """Times are seconds (floats) of one clock, the caller's (sim time in the node)."""

    def __init__(self, config):
        self.config = config
        self.linear_pid = Pid(config.linear)
        self.angular_pid = Pid(config.angular)
        self.command = None       # (linear, angular, stamp)
        self.measurement = None   # (linear, angular, stamp)
        self.mode = IDLE
        self._last_update = None

    def reset(self):
        self.linear_pid.reset()
        self.angular_pid.reset()
        self._last_update = None

    def set_command(self, linear, angular, stamp):
        if not (math.isfinite(linear) and math.isfinite(angular)):
            raise ValueError('expected finite velocities, got %r, %r' % (linear, angular))
        self.command = (float(linear), float(angular), float(stamp))

    def set_measurement(self, linear, angular, stamp):
        if math.isfinite(linear) and math.isfinite(angular):
            self.measurement = (float(linear), float(angular), float(stamp))

    def update(self, now):
        """(linear, angular) to send now, or None when there is nothing to send."""
        c = self.config
        if self._last_update is not None and now < self._last_update:
            self.command = self.measurement = None  # the clock jumped back: a reset
            self.reset()
            self.mode = IDLE
        if self.command is None or now - self.command[2] > c.cmd_timeout:
            was_active = self.mode != IDLE
            self.mode = IDLE
            self.reset()
            return (0.0, 0.0) if was_active else None
        linear_cmd, angular_cmd, _ = self.command
        if linear_cmd == 0.0 and angular_cmd == 0.0:
            self.mode = STOPPED
            self.reset()
            self._last_update = now
            return (0.0, 0.0)
        dt = 0.0 if self._last_update is None else now - self._last_update
        self._last_update = now
        fresh = self.measurement is not None and now - self.measurement[2] <= c.odom_timeout
        if not fresh:
            self.mode = OPEN_LOOP
            self.linear_pid.reset()
            self.angular_pid.reset()
            return (clamp(c.feedforward_linear * linear_cmd, c.linear.output_min, c.linear.output_max),
                    clamp(c.feedforward_angular * angular_cmd, c.angular.output_min, c.angular.output_max))
        if self.mode != CLOSED_LOOP:
            dt = 0.0  # the first closed-loop step has no history to integrate over
        self.mode = CLOSED_LOOP
        linear_meas, angular_meas, _ = self.measurement
        linear = self.linear_pid.update(linear_cmd - linear_meas, dt, measurement=linear_meas,
                                        feedforward=c.feedforward_linear * linear_cmd)
        angular = self.angular_pid.update(angular_cmd - angular_meas, dt, measurement=angular_meas,
                                          feedforward=c.feedforward_angular * angular_cmd)
        return linear, angular
