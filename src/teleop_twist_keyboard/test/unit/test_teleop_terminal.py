"""teleop_twist_keyboard's terminal handling (teleop_keyboard.terminal) on a pseudo-terminal and on
pipes, and the script's behaviour without a terminal: no ROS master, no real terminal."""
import os
import subprocess
import sys
import termios
import threading
import time

import pytest

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "..", "src"))

from teleop_keyboard import terminal  # noqa: E402
from teleop_keyboard.terminal import NotATerminal, RawKeyboard  # noqa: E402

SCRIPT = os.path.join(HERE, "..", "..", "scripts", "teleop_twist_keyboard")


@pytest.fixture
def pty_pair():
    """(writer fd, file object of the terminal side): a pseudo-terminal standing in for the user's."""
    master, slave = os.openpty()
    stream = os.fdopen(slave, "r")
    yield master, stream
    stream.close()
    try:
        os.close(master)
    except OSError:
        pass  # the test hung up


def lflag(stream):
    return termios.tcgetattr(stream.fileno())[3]


# --- not a terminal --------------------------------------------------------------------------

def test_pipe_is_not_a_terminal():
    read_end, write_end = os.pipe()
    with os.fdopen(read_end) as stream:
        assert not terminal.has_terminal(stream)
        with pytest.raises(NotATerminal):
            with RawKeyboard(stream):
                pass
    os.close(write_end)


def test_missing_or_closed_stdin_is_not_a_terminal():
    assert not terminal.has_terminal(type("NoFileno", (), {})())
    with open(os.devnull) as stream:
        pass
    assert not terminal.has_terminal(stream)  # closed: fileno() raises ValueError
    with open(os.devnull) as devnull:
        assert not terminal.has_terminal(devnull)


def test_pty_is_a_terminal(pty_pair):
    assert terminal.has_terminal(pty_pair[1])


def test_message_names_the_ways_to_give_it_a_terminal():
    text = terminal.NO_TERMINAL_MESSAGE
    assert "not a terminal" in text
    assert "rosrun teleop_twist_keyboard teleop_twist_keyboard" in text
    assert 'launch-prefix="xterm -e"' in text


@pytest.mark.parametrize("stdin", [subprocess.DEVNULL, subprocess.PIPE])
def test_script_without_terminal_says_so_and_exits_0(stdin):
    """What roslaunch without a terminal, or CI, sees: the message, no traceback, status 0.
    No master is running: the script must not get as far as ROS."""
    env = dict(os.environ, ROS_MASTER_URI="http://127.0.0.1:1")  # nothing listens there
    result = subprocess.run([sys.executable, SCRIPT], stdin=stdin, capture_output=True, text=True,
                            timeout=30, env=env, input=None)
    assert result.returncode == 0
    assert "Traceback" not in result.stderr + result.stdout
    assert "not a terminal" in result.stderr
    assert "rosrun teleop_twist_keyboard teleop_twist_keyboard" in result.stderr
    assert 'launch-prefix="xterm -e"' in result.stderr


# --- raw mode and reading keys ---------------------------------------------------------------

def test_read_key_returns_one_key_per_call_even_when_typed_together(pty_pair):
    master, stream = pty_pair
    with RawKeyboard(stream) as keyboard:
        os.write(master, b"uiq")
        assert [keyboard.read_key(timeout=2.0) for _ in range(3)] == ["u", "i", "q"]


def test_read_key_is_raw_ctrl_c_is_a_key_and_no_enter_needed(pty_pair):
    master, stream = pty_pair
    # Typed while read_key waits (in raw mode): in cooked mode the line discipline would turn
    # CTRL-C into SIGINT for the terminal's foreground process group instead.
    typist = threading.Timer(0.3, os.write, args=(master, b"\x03"))
    with RawKeyboard(stream) as keyboard:
        typist.start()
        assert keyboard.read_key(timeout=5.0) == "\x03"
    typist.join()


def test_raw_mode_only_while_waiting_and_restored_after(pty_pair):
    master, stream = pty_pair
    cooked = termios.tcgetattr(stream.fileno())
    assert lflag(stream) & termios.ICANON and lflag(stream) & termios.ECHO
    seen = {}

    def press_while_raw():
        time.sleep(0.3)
        seen["lflag"] = lflag(stream)
        os.write(master, b"k")

    with RawKeyboard(stream) as keyboard:
        thread = threading.Thread(target=press_while_raw)
        thread.start()
        assert keyboard.read_key(timeout=5.0) == "k"
        thread.join()
        assert termios.tcgetattr(stream.fileno()) == cooked  # between keys: as before
    assert not seen["lflag"] & (termios.ICANON | termios.ECHO | termios.ISIG)
    assert termios.tcgetattr(stream.fileno()) == cooked


def test_terminal_restored_when_the_loop_raises(pty_pair):
    _, stream = pty_pair
    cooked = termios.tcgetattr(stream.fileno())
    with pytest.raises(KeyError):
        with RawKeyboard(stream) as keyboard:
            keyboard.read_key(should_stop=lambda: (_ for _ in ()).throw(KeyError("boom")))
    assert termios.tcgetattr(stream.fileno()) == cooked


def test_timeout_returns_empty_string(pty_pair):
    _, stream = pty_pair
    with RawKeyboard(stream, poll_interval=0.05) as keyboard:
        start = time.monotonic()
        assert keyboard.read_key(timeout=0.3) == ""
        assert 0.25 <= time.monotonic() - start < 2.0


def test_should_stop_ends_an_endless_wait(pty_pair):
    _, stream = pty_pair
    deadline = time.monotonic() + 0.3
    with RawKeyboard(stream, poll_interval=0.05) as keyboard:
        assert keyboard.read_key(timeout=None, should_stop=lambda: time.monotonic() > deadline) is None
    assert time.monotonic() - deadline < 1.0


def test_hang_up_is_end_of_input(pty_pair):
    master, stream = pty_pair
    with RawKeyboard(stream, poll_interval=0.05) as keyboard:
        os.close(master)
        assert keyboard.read_key(timeout=2.0) is None


def test_hang_up_while_waiting_is_end_of_input(pty_pair):
    master, stream = pty_pair
    closer = threading.Timer(0.3, os.close, args=(master,))
    with RawKeyboard(stream, poll_interval=0.05) as keyboard:
        closer.start()
        assert keyboard.read_key(timeout=5.0) is None
    closer.join()


def test_non_ascii_bytes_are_other_keys(pty_pair):
    master, stream = pty_pair
    with RawKeyboard(stream) as keyboard:
        os.write(master, "é".encode("utf-8"))
        first = keyboard.read_key(timeout=2.0)
        second = keyboard.read_key(timeout=2.0)
    assert len(first) == 1 and len(second) == 1
    assert first not in "uiojklm,.UIOJKLM<>tbqzwxec"


def test_read_key_outside_with_block_is_an_error(pty_pair):
    with pytest.raises(RuntimeError):
        RawKeyboard(pty_pair[1]).read_key(timeout=0.1)
