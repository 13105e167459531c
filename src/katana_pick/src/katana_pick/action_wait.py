"""Waiting for an action goal's result without SimpleActionClient's lost-result race.

SimpleActionClient.send_goal assigns its goal handle only after the goal is published, and its
transition callback drops every transition of a handle it does not hold ("Got a transition
callback on a goal handle that we're not tracking"). A server that answers at once (the gripper
told to open when it is open already), with the client's thread descheduled on a loaded machine,
gets its ACTIVE and DONE in before the assignment: wait_for_result then waits out its whole
timeout for a goal that finished long ago. The goal handle's own state machine sees every
transition, so it is asked as well.
"""
import rospy
from actionlib import CommState

# How often the goal handle's state is looked at while the client's wait has not returned (sim time).
POLL = rospy.Duration(0.05)


def wait_for_result(client, timeout):
    """client.wait_for_result(timeout) for the goal just sent, true also when the client missed the
    goal's end. Afterwards client.get_state() and get_result() read the goal handle: they are right
    either way."""
    deadline = rospy.Time.now() + timeout
    while not rospy.is_shutdown():
        remaining = deadline - rospy.Time.now()
        if client.wait_for_result(min(POLL, remaining) if remaining > rospy.Duration(0) else POLL):
            return True
        if client.gh is not None and client.gh.get_comm_state() == CommState.DONE:
            return True
        if rospy.Time.now() >= deadline:
            return False
    return False
