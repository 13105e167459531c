"""What each key does: teleop_twist_keyboard's bindings and speed logic, without ROS or a terminal.

The bindings, the banner and the reactions follow ros-teleop/teleop_twist_keyboard:

- a move key sets a direction (x, y, z, th); the command is direction * speed for the linear
  parts and th * turn for the angular z;
- a speed key scales speed and/or turn by 10 % and re-sends the current direction at the new
  speeds; every 15th speed change prints the banner again;
- any other key stops (all zero); CTRL-C stops and quits;
- a key timeout (no key within key_timeout) stops too, but sends nothing if already stopped.
"""
from dataclasses import dataclass, field
from typing import Tuple

BANNER = """
Reading from the keyboard  and Publishing to Twist!
---------------------------
Moving around:
   u    i    o
   j    k    l
   m    ,    .

For Holonomic mode (strafing), hold down the shift key:
---------------------------
   U    I    O
   J    K    L
   M    <    >

t : up (+z)
b : down (-z)

anything else : stop

q/z : increase/decrease max speeds by 10%
w/x : increase/decrease only linear speed by 10%
e/c : increase/decrease only angular speed by 10%

CTRL-C to quit
"""

# key -> (x, y, z, th): signs of linear x, y, z and angular z.
MOVE_BINDINGS = {
    # holonomic off: forward/backward and turning
    "u": (1, 0, 0, 1),
    "i": (1, 0, 0, 0),
    "o": (1, 0, 0, -1),
    "j": (0, 0, 0, 1),
    "l": (0, 0, 0, -1),
    "m": (-1, 0, 0, -1),
    ",": (-1, 0, 0, 0),
    ".": (-1, 0, 0, 1),
    # holonomic (shift): forward/backward and strafing, no turning
    "U": (1, 1, 0, 0),
    "I": (1, 0, 0, 0),
    "O": (1, -1, 0, 0),
    "J": (0, 1, 0, 0),
    "L": (0, -1, 0, 0),
    "M": (-1, 1, 0, 0),
    "<": (-1, 0, 0, 0),
    ">": (-1, -1, 0, 0),
    # up and down
    "t": (0, 0, 1, 0),
    "b": (0, 0, -1, 0),
}

# key -> (factor on speed, factor on turn)
SPEED_BINDINGS = {
    "q": (1.1, 1.1),
    "z": (0.9, 0.9),
    "w": (1.1, 1.0),
    "x": (0.9, 1.0),
    "e": (1.0, 1.1),
    "c": (1.0, 0.9),
}

CTRL_C = "\x03"
NO_KEY = ""  # what the keyboard gives when key_timeout passed without a key
BANNER_EVERY = 15  # speed changes between two reprints of the banner

STOPPED = (0, 0, 0, 0)


def speed_line(speed, turn):
    """The line printed at start and after each speed change (upstream's format, %s floats)."""
    return "currently:\tspeed %s\tturn %s " % (speed, turn)


@dataclass(frozen=True)
class Velocity:
    """The Twist to publish: linear x, y, z (m/s) and angular z (rad/s); angular x, y are 0."""
    linear_x: float = 0.0
    linear_y: float = 0.0
    linear_z: float = 0.0
    angular_z: float = 0.0


@dataclass(frozen=True)
class Reaction:
    """What a key press asks of the node."""
    publish: bool = False  # send the (new) velocity
    quit: bool = False  # leave the key loop (the node then sends a final stop)
    lines: Tuple[str, ...] = field(default_factory=tuple)  # to print, in order


class KeyboardTeleop:
    """The key loop's state: a direction, the speed and the turn rate."""

    def __init__(self, speed=0.5, turn=1.0):
        self.speed = float(speed)
        self.turn = float(turn)
        self.direction = STOPPED
        self._speed_changes = 0

    @property
    def stopped(self):
        return self.direction == STOPPED

    def velocity(self):
        x, y, z, th = self.direction
        return Velocity(x * self.speed, y * self.speed, z * self.speed, th * self.turn)

    def press(self, key):
        """React to one key (a one-character string, or NO_KEY after a key timeout)."""
        if key in MOVE_BINDINGS:
            self.direction = MOVE_BINDINGS[key]
            return Reaction(publish=True)
        if key in SPEED_BINDINGS:
            speed_factor, turn_factor = SPEED_BINDINGS[key]
            self.speed *= speed_factor
            self.turn *= turn_factor
            lines = [speed_line(self.speed, self.turn)]
            if self._speed_changes == BANNER_EVERY - 1:
                lines.append(BANNER)
            self._speed_changes = (self._speed_changes + 1) % BANNER_EVERY
            return Reaction(publish=True, lines=tuple(lines))
        if key == NO_KEY and self.stopped:
            return Reaction()  # timed out while already stopped: nothing new to send
        self.direction = STOPPED
        if key == CTRL_C:
            return Reaction(quit=True)
        return Reaction(publish=True)
