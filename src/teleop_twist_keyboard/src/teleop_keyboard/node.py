"""The ROS side of teleop_twist_keyboard: parameters, the cmd_vel publisher and the key loop.

Imported by scripts/teleop_twist_keyboard once it knows stdin is a terminal.
"""
import collections
import sys
import threading

import rospy
from geometry_msgs.msg import Twist, TwistStamped

from teleop_keyboard import keymap, terminal


class TwistPublisher(threading.Thread):
    """Publishes on cmd_vel each velocity it is given, at once and in order, and the last one
    again every 1/repeat_rate s if repeat_rate > 0 (some bases stop without a steady stream)."""

    def __init__(self, repeat_rate, stamped, frame_id):
        super().__init__(name="cmd_vel publisher", daemon=True)
        self._message_type = TwistStamped if stamped else Twist
        self._frame_id = frame_id
        self.publisher = rospy.Publisher("cmd_vel", self._message_type, queue_size=10)
        self._period = 1.0 / repeat_rate if repeat_rate > 0 else None
        self._condition = threading.Condition()
        self._queue = collections.deque()  # velocities set and not yet published, oldest first
        self._last = keymap.Velocity()
        self._done = False
        self.start()

    def wait_for_subscribers(self):
        """Wait until something subscribes to cmd_vel (as upstream, so the first keys are not
        lost); False if ROS shut down first."""
        polls = 0
        while not rospy.is_shutdown() and self.publisher.get_num_connections() == 0:
            if polls % 5 == 4:
                print("Waiting for subscriber to connect to {}".format(self.publisher.resolved_name), flush=True)
            rospy.rostime.wallsleep(0.5)
            polls += 1
        return not rospy.is_shutdown()

    def set(self, velocity):
        with self._condition:
            self._queue.append(velocity)
            self._condition.notify()

    def stop(self):
        """Publish what is still queued, then a last zero velocity, and end the thread."""
        with self._condition:
            self._queue.append(keymap.Velocity())
            self._done = True
            self._condition.notify()
        self.join(timeout=2.0)

    def run(self):
        while True:
            with self._condition:
                if not self._condition.wait_for(lambda: self._queue or self._done, timeout=self._period):
                    self._queue.append(self._last)  # repeat_rate: the period passed without a key
                velocities = list(self._queue)
                self._queue.clear()
                done = self._done
            # Every key's command goes out, in order, even when keys come faster than one
            # publish (a paste, tmux send-keys).
            for velocity in velocities:
                self._publish(velocity)
            if velocities:
                self._last = velocities[-1]
            if done:
                return

    def _publish(self, velocity):
        twist = Twist()
        twist.linear.x = velocity.linear_x
        twist.linear.y = velocity.linear_y
        twist.linear.z = velocity.linear_z
        twist.angular.z = velocity.angular_z
        if self._message_type is TwistStamped:
            message = TwistStamped(twist=twist)
            message.header.stamp = rospy.Time.now()
            message.header.frame_id = self._frame_id
        else:
            message = twist
        try:
            self.publisher.publish(message)
        except rospy.ROSException:
            pass  # shutting down: the publisher is already closed


def main():
    """Run the node on the terminal on stdin; returns the exit status."""
    rospy.init_node("teleop_twist_keyboard")
    teleop = keymap.KeyboardTeleop(rospy.get_param("~speed", 0.5), rospy.get_param("~turn", 1.0))
    repeat_rate = float(rospy.get_param("~repeat_rate", 0.0))
    key_timeout = float(rospy.get_param("~key_timeout", 0.0))
    publisher = TwistPublisher(repeat_rate, bool(rospy.get_param("~stamped", False)),
                               str(rospy.get_param("~frame_id", "")))
    try:
        with terminal.RawKeyboard(sys.stdin) as keyboard:
            if not publisher.wait_for_subscribers():
                return 0
            publisher.set(teleop.velocity())
            print(keymap.BANNER)
            print(keymap.speed_line(teleop.speed, teleop.turn), flush=True)
            while True:
                key = keyboard.read_key(timeout=key_timeout if key_timeout > 0 else None,
                                        should_stop=rospy.is_shutdown)
                if key is None:  # ROS shut down, or the terminal hung up
                    break
                reaction = teleop.press(key)
                for line in reaction.lines:
                    print(line, flush=True)
                if reaction.publish:
                    publisher.set(teleop.velocity())
                if reaction.quit:
                    break
    except terminal.NotATerminal:
        sys.stderr.write(terminal.NO_TERMINAL_MESSAGE)
    finally:
        publisher.stop()
        if not rospy.is_shutdown():
            rospy.rostime.wallsleep(0.2)  # let rospy's sender thread deliver the final stop
    return 0
