"""Single key presses from a terminal: raw mode while waiting for a key, a timeout, a clean exit.

The terminal is put in raw mode only while waiting for a key and restored right after it (so
what the node prints between keys is laid out normally), and restored again when the
`RawKeyboard` context is left, however it is left. Bytes are read straight from the file
descriptor (os.read): a buffered sys.stdin.read(1) can swallow keys typed quickly or pasted
(several arrive at once) into a buffer that select() does not see.
"""
import os
import select
import sys
import termios
import time
import tty

NO_TERMINAL_MESSAGE = """\
teleop_twist_keyboard: standard input is not a terminal, so there are no key presses to read.
The keyboard teleop needs a terminal of its own. Run it in a separate terminal:

    rosrun teleop_twist_keyboard teleop_twist_keyboard

or, from a launch file, give it a terminal window:

    <node pkg="teleop_twist_keyboard" type="teleop_twist_keyboard" name="teleop_twist_keyboard"
          output="screen" launch-prefix="xterm -e"/>
"""


class NotATerminal(Exception):
    """Standard input is not a terminal (a pipe, /dev/null, closed: roslaunch without one, CI)."""


def terminal_fd(stream):
    """The file descriptor of `stream` if it is a terminal whose settings can be read, else raise."""
    try:
        fd = stream.fileno()
    except (AttributeError, ValueError, OSError) as error:  # None, closed, or no descriptor
        raise NotATerminal(str(error)) from None
    if not os.isatty(fd):
        raise NotATerminal("file descriptor %d is not a terminal" % fd)
    try:
        termios.tcgetattr(fd)
    except termios.error as error:
        raise NotATerminal(str(error)) from None
    return fd


def has_terminal(stream=None):
    try:
        terminal_fd(sys.stdin if stream is None else stream)
    except NotATerminal:
        return False
    return True


class RawKeyboard:
    """Reads single keys from a terminal. Use as a context manager:

        with RawKeyboard(sys.stdin) as keyboard:
            key = keyboard.read_key(timeout=0.6, should_stop=rospy.is_shutdown)
    """

    def __init__(self, stream=None, poll_interval=0.1):
        self._stream = sys.stdin if stream is None else stream
        self._poll_interval = poll_interval
        self._fd = None
        self._saved = None

    def __enter__(self):
        self._fd = terminal_fd(self._stream)
        self._saved = termios.tcgetattr(self._fd)
        return self

    def __exit__(self, *exc_info):
        self.restore()
        return False

    def restore(self):
        """Put the terminal back as it was when the context was entered (safe to call twice)."""
        if self._saved is not None:
            try:
                termios.tcsetattr(self._fd, termios.TCSADRAIN, self._saved)
            except termios.error:
                pass  # the terminal went away (hang-up): nothing left to restore

    def read_key(self, timeout=None, should_stop=None):
        """Wait for one key and return it as a one-character string.

        timeout: seconds to wait (None or <= 0: forever); returns "" when it passes without a key.
        should_stop: polled every poll_interval; when it returns True, returns None. Also None at
        end of file (the terminal hung up). Raw mode means CTRL-C arrives as the key "\\x03".
        """
        if self._fd is None:
            raise RuntimeError("RawKeyboard.read_key outside its 'with' block")
        deadline = time.monotonic() + timeout if timeout is not None and timeout > 0 else None
        try:
            # TCSANOW, not setraw's default TCSAFLUSH: that would throw away keys typed
            # (or pasted) while the previous one was being handled.
            tty.setraw(self._fd, termios.TCSANOW)
        except termios.error:
            return None  # the terminal hung up
        try:
            while True:
                if should_stop is not None and should_stop():
                    return None
                wait = self._poll_interval
                if deadline is not None:
                    wait = min(wait, max(0.0, deadline - time.monotonic()))
                ready, _, _ = select.select([self._fd], [], [], wait)
                if ready:
                    try:
                        data = os.read(self._fd, 1)
                    except OSError:  # EIO: the terminal hung up while we waited
                        return None
                    if not data:
                        return None
                    # A byte of a multi-byte character (or of an arrow key's escape sequence)
                    # is just "another key": it stops the robot, as upstream.
                    return data.decode("utf-8", errors="replace")
                if deadline is not None and time.monotonic() >= deadline:
                    return ""
        finally:
            self.restore()
