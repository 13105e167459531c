"""A discrete PID controller with anti-windup and output limits (no ROS).

u = feedforward + p * e + I + D, clamped to [output_min, output_max], where
- I is the integral term, i * integral(e dt), itself clamped to [-i_clamp, i_clamp] (in output
  units, like control_toolbox's i_clamp), and not integrated further while the output is
  saturated in the direction the error pushes (conditional integration), so it does not wind
  up while the output is limited;
- D is d times the rate of change of the error, or, when the caller passes the measurement,
  of minus the measurement (the same thing for a constant setpoint, without the kick a step
  in the setpoint gives), low-pass filtered with time constant d_filter_time.
"""
import math


def clamp(value, low, high):
    return max(low, min(high, value))


class PidGains:
    """The gains and limits of one Pid. Checked on construction: ValueError names the field."""

    def __init__(self, p=0.0, i=0.0, d=0.0, i_clamp=math.inf, output_min=-math.inf, output_max=math.inf,
                 d_filter_time=0.0):
        self.p, self.i, self.d = float(p), float(i), float(d)
        self.i_clamp = float(i_clamp)
        self.output_min, self.output_max = float(output_min), float(output_max)
        self.d_filter_time = float(d_filter_time)
        for name in ('p', 'i', 'd'):
            if not math.isfinite(getattr(self, name)):
                raise ValueError('%s: expected a finite gain, got %r' % (name, getattr(self, name)))
        if not self.i_clamp >= 0.0:
            raise ValueError('i_clamp: expected a number >= 0, got %r' % self.i_clamp)
        if not self.output_min <= self.output_max:
            raise ValueError('output_min %r is above output_max %r' % (self.output_min, self.output_max))
        if not self.d_filter_time >= 0.0:
            raise ValueError('d_filter_time: expected seconds >= 0, got %r' % self.d_filter_time)

    def __repr__(self):
        return ('PidGains(p=%g, i=%g, d=%g, i_clamp=%g, output=[%g, %g], d_filter_time=%g)'
                % (self.p, self.i, self.d, self.i_clamp, self.output_min, self.output_max, self.d_filter_time))


class Pid:
    def __init__(self, gains):
        self.gains = gains
        self.reset()

    def reset(self):
        """Forget the integral and the derivative's history (e.g. after a pause)."""
        self.integral = 0.0      # the I term, in output units
        self.derivative = 0.0    # the filtered rate of the differentiated signal
        self._previous = None    # the last differentiated signal
        self.output = 0.0
        self.saturated = False

    def update(self, error, dt, measurement=None, feedforward=0.0):
        """The output for this error after dt seconds. dt <= 0 (a repeated time stamp) gives
        the proportional and feedforward response without integrating or differentiating."""
        g = self.gains
        if not (math.isfinite(error) and math.isfinite(feedforward)):
            raise ValueError('expected a finite error and feedforward, got %r and %r' % (error, feedforward))
        if dt > 0.0:
            signal = error if measurement is None else -measurement
            if self._previous is not None:
                rate = (signal - self._previous) / dt
                alpha = dt / (g.d_filter_time + dt)
                self.derivative += alpha * (rate - self.derivative)
            self._previous = signal
            candidate = clamp(self.integral + g.i * error * dt, -g.i_clamp, g.i_clamp)
        else:
            candidate = self.integral
        fixed = feedforward + g.p * error + g.d * self.derivative
        unsaturated = fixed + candidate
        output = clamp(unsaturated, g.output_min, g.output_max)
        # Conditional integration: keep the old integral when the output is limited and the
        # new integral would push it further into the limit.
        if output != unsaturated and (candidate - self.integral) * (unsaturated - output) > 0.0:
            unsaturated = fixed + self.integral
            output = clamp(unsaturated, g.output_min, g.output_max)
        else:
            self.integral = candidate
        self.saturated = output != unsaturated
        self.output = output
        return output
