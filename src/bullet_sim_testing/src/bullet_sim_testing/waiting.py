"""Waiting in wall time for something a test observes through callbacks or services."""
import time


def wait_until(condition, timeout, step=0.05):
    """True as soon as condition() is, else condition()'s value after `timeout` seconds."""
    deadline = time.monotonic() + timeout
    while time.monotonic() < deadline:
        if condition():
            return True
        time.sleep(step)
    return condition()
