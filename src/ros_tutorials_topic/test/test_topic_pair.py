#!/usr/bin/env python3
"""The lecture's publisher / subscriber pair as a user runs them: on ros_tutorial_msg the counts
follow one another at 10 Hz with increasing stamps, and the subscriber node logs (on /rosout) the
same stamps and counts the publisher sent. The pair's node names come in ~publisher and
~subscriber."""
import re
import unittest

import rospy
import rostest
from rosgraph_msgs.msg import Log

from ros_tutorials_topic.msg import MsgTutorial

LOGGED = re.compile(r'^(send|receive) msg = (-?\d+)$')


def triples(values):
    """(sec, nsec, count) from a node's logged numbers, in order: a sec is the first of three, and
    wall-clock seconds are > 1e9 (the test may start listening in the middle of a triple)."""
    out = []
    k = 0
    while k + 2 < len(values):
        if values[k] > 1e9 and 0 <= values[k + 1] < 1e9:
            out.append((values[k] + 1e-9 * values[k + 1], values[k + 2]))
            k += 3
        else:
            k += 1
    return out


class TopicPairTest(unittest.TestCase):
    def setUp(self):
        rospy.init_node('topic_pair_checks')
        self.publisher = rospy.get_param('~publisher')
        self.subscriber = rospy.get_param('~subscriber')
        self.received = []  # (arrival, stamp, count) seen here
        self.logged = {self.publisher: [], self.subscriber: []}
        rospy.Subscriber('ros_tutorial_msg', MsgTutorial,
                         lambda m: self.received.append((rospy.get_time(), m.stamp.to_sec(), m.data)), queue_size=100)
        rospy.Subscriber('/rosout', Log, self.on_log, queue_size=1000)

    def on_log(self, log):
        match = LOGGED.match(log.msg)
        if match and log.name in self.logged:
            self.logged[log.name].append(int(match.group(2)))

    def test_counts_follow_one_another_at_10_hz_and_the_subscriber_logs_them(self):
        deadline = rospy.get_time() + 20.0
        while len(self.received) < 31 and rospy.get_time() < deadline:
            rospy.sleep(0.1)
        rospy.sleep(0.5)  # the last logs
        received = list(self.received)
        self.assertGreaterEqual(len(received), 31, 'ros_tutorial_msg: %d messages in 20 s' % len(received))
        counts = [c for _, _, c in received]
        stamps = [s for _, s, _ in received]
        self.assertEqual(counts, list(range(counts[0], counts[0] + len(counts))))
        self.assertTrue(all(b > a for a, b in zip(stamps, stamps[1:])))
        rate = (len(stamps) - 1) / (stamps[-1] - stamps[0])
        self.assertGreater(rate, 8.0)
        self.assertLess(rate, 12.0)

        sent = dict((c, s) for s, c in triples(self.logged[self.publisher]))
        heard = triples(self.logged[self.subscriber])
        self.assertGreaterEqual(len(heard), 25, '%s logged %d messages' % (self.subscriber, len(heard)))
        heard_counts = [c for _, c in heard]
        self.assertEqual(heard_counts, list(range(heard_counts[0], heard_counts[0] + len(heard))))
        # What the subscriber logs is what the publisher sent: the same count with the same stamp.
        seen_here = dict((c, s) for _, s, c in received)
        common = [c for c in heard_counts if c in seen_here and c in sent]
        self.assertGreaterEqual(len(common), 20)
        for s, c in heard:
            if c in seen_here:
                self.assertAlmostEqual(s, seen_here[c], places=6)
            if c in sent:
                self.assertAlmostEqual(s, sent[c], places=6)


if __name__ == '__main__':
    rostest.rosrun('ros_tutorials_topic', 'test_topic_pair', TopicPairTest)
