#!/usr/bin/env python3
"""teleop_twist_keyboard end to end: the node runs on a pseudo-terminal (as in a user's terminal
window), keys are typed into it, and the Twists arrive on the remapped cmd_vel topic."""
import os
import pty
import subprocess
import sys
import termios
import threading
import time
import unittest

import rospy
import rostest
from geometry_msgs.msg import Twist, TwistStamped

SCRIPT = os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', 'scripts', 'teleop_twist_keyboard')


class Teleop(object):
    """The node on a pseudo-terminal, its screen collected, messages on `topic` collected."""

    def __init__(self, name, topic, message_type, params):
        self.messages = []
        self.subscriber = rospy.Subscriber(topic, message_type, self.messages.append, queue_size=100)
        self.master, slave = pty.openpty()
        self.cooked = termios.tcgetattr(slave)
        self.slave = slave
        self.process = subprocess.Popen(
            [sys.executable, SCRIPT, '__name:=' + name, 'cmd_vel:=' + topic] + params,
            stdin=slave, stdout=slave, stderr=slave, close_fds=True)
        self.screen = b''
        threading.Thread(target=self._read_screen, daemon=True).start()

    def _read_screen(self):
        while True:
            try:
                data = os.read(self.master, 4096)
            except OSError:
                return
            if not data:
                return
            self.screen += data

    def wait_for(self, condition, timeout=10.0):
        deadline = time.monotonic() + timeout
        while time.monotonic() < deadline:
            if condition():
                return True
            time.sleep(0.02)
        return condition()

    def type(self, keys):
        os.write(self.master, keys.encode())

    def close(self):
        if self.process.poll() is None:
            self.process.kill()
            self.process.wait()
        self.subscriber.unregister()
        os.close(self.slave)
        os.close(self.master)


def twist_of(message):
    twist = getattr(message, 'twist', message)
    return (twist.linear.x, twist.linear.y, twist.linear.z, twist.angular.x, twist.angular.y, twist.angular.z)


class TeleopKeysTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        rospy.init_node('test_teleop_keys')

    def start(self, name, topic, message_type=Twist, params=()):
        # A node name per test: private parameters stay on the parameter server after a node.
        teleop = Teleop(name, topic, message_type, list(params))
        self.addCleanup(teleop.close)
        self.assertTrue(teleop.wait_for(lambda: b'currently:' in teleop.screen, 30), teleop.screen.decode())
        self.assertTrue(teleop.wait_for(lambda: len(teleop.messages) >= 1))  # the initial stop
        return teleop

    def press(self, teleop, key, expected):
        count = len(teleop.messages)
        teleop.type(key)
        self.assertTrue(teleop.wait_for(lambda: len(teleop.messages) > count), 'no message after %r' % key)
        for value, want in zip(twist_of(teleop.messages[-1]), expected):
            self.assertAlmostEqual(value, want, places=6, msg='after %r: %r' % (key, twist_of(teleop.messages[-1])))

    def test_keys_speeds_and_quit(self):
        teleop = self.start('teleop_plain', '/teleop_test/cmd_vel', params=['_speed:=1.0', '_turn:=2.0'])
        screen = teleop.screen.decode()
        self.assertIn('Reading from the keyboard  and Publishing to Twist!', screen)
        self.assertIn('For Holonomic mode (strafing), hold down the shift key:', screen)
        self.assertIn('currently:\tspeed 1.0\tturn 2.0', screen)
        self.assertEqual(twist_of(teleop.messages[0]), (0, 0, 0, 0, 0, 0))
        for key, expected in [('i', (1, 0, 0, 0, 0, 0)), ('u', (1, 0, 0, 0, 0, 2)), ('o', (1, 0, 0, 0, 0, -2)),
                              ('j', (0, 0, 0, 0, 0, 2)), ('l', (0, 0, 0, 0, 0, -2)), ('m', (-1, 0, 0, 0, 0, -2)),
                              (',', (-1, 0, 0, 0, 0, 0)), ('.', (-1, 0, 0, 0, 0, 2)),
                              ('U', (1, 1, 0, 0, 0, 0)), ('J', (0, 1, 0, 0, 0, 0)), ('L', (0, -1, 0, 0, 0, 0)),
                              ('>', (-1, -1, 0, 0, 0, 0)), ('t', (0, 0, 1, 0, 0, 0)), ('b', (0, 0, -1, 0, 0, 0)),
                              ('k', (0, 0, 0, 0, 0, 0)), ('i', (1, 0, 0, 0, 0, 0)), ('q', (1.1, 0, 0, 0, 0, 0)),
                              ('x', (0.99, 0, 0, 0, 0, 0)), ('j', (0, 0, 0, 0, 0, 2.2)), ('c', (0, 0, 0, 0, 0, 1.98)),
                              ('a', (0, 0, 0, 0, 0, 0))]:
            self.press(teleop, key, expected)
        self.assertIn('currently:\tspeed 1.1\tturn 2.2', teleop.screen.decode())

        # Keys typed faster than one publish each (a paste) all arrive, in order.
        count = len(teleop.messages)
        teleop.type('iwk')
        self.assertTrue(teleop.wait_for(lambda: len(teleop.messages) >= count + 3))
        self.assertEqual([round(twist_of(m)[0], 6) for m in teleop.messages[count:count + 3]], [0.99, 1.089, 0.0])

        # CTRL-C: a last stop, exit status 0, the terminal as it was.
        self.press(teleop, 'i', (1.089, 0, 0, 0, 0, 0))
        teleop.type('\x03')
        self.assertEqual(teleop.process.wait(timeout=10), 0)
        self.assertTrue(teleop.wait_for(lambda: twist_of(teleop.messages[-1]) == (0, 0, 0, 0, 0, 0)))
        self.assertEqual(termios.tcgetattr(teleop.slave), teleop.cooked)
        self.assertNotIn('Traceback', teleop.screen.decode())

    def test_stamped_key_timeout_and_repeat(self):
        teleop = self.start('teleop_stamped', '/teleop_test/stamped_cmd_vel', TwistStamped,
                            ['_stamped:=true', '_frame_id:=base_link', '_key_timeout:=0.6', '_repeat_rate:=10.0'])
        self.assertEqual(teleop.messages[0].header.frame_id, 'base_link')
        teleop.type('i')
        self.assertTrue(teleop.wait_for(lambda: twist_of(teleop.messages[-1])[0] == 0.5))
        moving_since = time.monotonic()
        # repeated at 10 Hz while moving, then stopped by the key timeout
        self.assertTrue(teleop.wait_for(lambda: twist_of(teleop.messages[-1])[0] == 0.0, 5))
        stopped_after = time.monotonic() - moving_since
        self.assertGreater(stopped_after, 0.4)
        self.assertLess(stopped_after, 1.5)
        moving = [m for m in teleop.messages if twist_of(m)[0] == 0.5]
        self.assertGreaterEqual(len(moving), 4)
        stamps = [m.header.stamp.to_sec() for m in teleop.messages]
        self.assertEqual(stamps, sorted(stamps))
        self.assertTrue(all(m.header.frame_id == 'base_link' for m in teleop.messages))
        teleop.process.terminate()  # as roslaunch stops it: no traceback, terminal restored
        self.assertEqual(teleop.process.wait(timeout=10), 0)
        self.assertEqual(termios.tcgetattr(teleop.slave), teleop.cooked)
        self.assertNotIn('Traceback', teleop.screen.decode())


if __name__ == '__main__':
    rostest.rosrun('teleop_twist_keyboard', 'teleop_keys', TeleopKeysTest)
