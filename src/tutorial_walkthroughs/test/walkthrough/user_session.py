"""A new user's machine, for replaying a tutorial's commands as it writes them.

A UserSession is an empty home folder whose ~/.bashrc sources this workspace (where the tutorials
source /opt/ros/<distro>/setup.bash), a plain Debian PATH, and nothing else of ours. The test types
the tutorial's lines into it:

    user = UserSession(tmp_path)
    user.run('''mkdir -p ~/catkin_ws/src
                cd ~/catkin_ws/src
                catkin_create_pkg tutorial roscpp''')   # lines run in order, stop at the first failure;
                                                          # the last `cd` carries over, as in a terminal
    user.write('~/catkin_ws/src/tutorial/launch/spawn.launch', text)   # the user's editor
    sim = user.start('roslaunch tutorial spawn.launch')  # "on another terminal": left running
    sim.wait_for(r'Spawn status: (.*)')                   # what the terminal shows
    sim.interrupt()                                      # Ctrl+C

Every process the session starts carries a marker in its environment; close() stops them all
(Ctrl+C, then SIGTERM, then SIGKILL), whatever became of their parents, so no roscore, simulator
or rviz outlives the test.
"""
import fcntl
import os
import pty
import re
import shlex
import signal
import subprocess
import tempfile
import termios
import threading
import time
import uuid

WORKSPACE = os.path.abspath(os.path.join(os.path.dirname(__file__), '..', '..', '..', '..'))
MARKER = 'TUTORIAL_WALKTHROUGH_SESSION'
ANSI = re.compile(r'\x1b\[[0-9;]*[A-Za-z]')  # colours and cursor moves in a terminal's output


class CommandFailed(AssertionError):
    pass


class Terminal:
    """A command left running in a terminal of its own (a pseudo-terminal, so that programs
    behave as they do for the user: line-buffered output, keys read from the keyboard, Ctrl+C to
    the foreground processes); what it shows is kept."""

    def __init__(self, command, script, env, cwd, log_path):
        self.command = command
        self.log_path = log_path
        master, slave = pty.openpty()

        def own_terminal():  # a session whose controlling terminal is this one
            os.setsid()
            fcntl.ioctl(0, termios.TIOCSCTTY, 0)
            # Ctrl+C and Ctrl+\ as a terminal's shell has them, whatever this process inherited: a
            # test run started in the background (`cmd &` in a script) ignores SIGINT, and a shell
            # started with it ignored cannot trap it (run_pioneer_gazebo's trap never ran).
            for sig in (signal.SIGINT, signal.SIGQUIT):
                signal.signal(sig, signal.SIG_DFL)
            signal.pthread_sigmask(signal.SIG_UNBLOCK, {signal.SIGINT, signal.SIGQUIT})

        self.process = subprocess.Popen(['bash', '-c', script], env=env, cwd=cwd, stdin=slave, stdout=slave,
                                        stderr=slave, preexec_fn=own_terminal, close_fds=True)
        os.close(slave)
        self._master = master
        self._output = []
        self._lock = threading.Lock()
        self._reader = threading.Thread(target=self._read, daemon=True)
        self._reader.start()

    def _read(self):
        with open(self.log_path, 'w') as log:
            while True:
                try:
                    data = os.read(self._master, 65536)
                except OSError:  # EIO: every process holding the terminal has ended
                    break
                if not data:
                    break
                text = ANSI.sub('', data.decode('utf-8', 'replace').replace('\r', ''))
                log.write(text)
                log.flush()
                with self._lock:
                    self._output.append(text)

    @property
    def output(self):
        with self._lock:
            return ''.join(self._output)

    def wait_for(self, pattern, timeout=60.0):
        """The first match of the regular expression in the output; fails after timeout seconds,
        or when the command ends without printing it."""
        deadline = time.monotonic() + timeout
        regex = re.compile(pattern, re.M)
        while True:
            match = regex.search(self.output)
            if match:
                return match
            if self.process.poll() is not None:
                self._reader.join(timeout=2)
                match = regex.search(self.output)
                if match:
                    return match
                raise CommandFailed('`%s` ended (status %s) without printing /%s/; its output:\n%s'
                                    % (self.command, self.process.returncode, pattern, tail(self.output)))
            if time.monotonic() > deadline:
                raise CommandFailed('`%s` did not print /%s/ within %.0f s; its output:\n%s'
                                    % (self.command, pattern, timeout, tail(self.output)))
            time.sleep(0.1)

    def send(self, keys):
        """Keys typed into the terminal."""
        os.write(self._master, keys.encode())

    def interrupt(self):
        """Ctrl+C: the terminal sends SIGINT to its foreground processes."""
        if self.process.poll() is None:
            try:
                self.send('\x03')
            except OSError:
                pass

    def wait(self, timeout=30.0):
        self.process.wait(timeout=timeout)
        self._reader.join(timeout=5)
        return self.process.returncode

    @property
    def running(self):
        return self.process.poll() is None


class UserSession:
    def __init__(self, folder, name='walkthrough'):
        self.home = os.path.join(str(folder), 'home')
        os.makedirs(self.home)
        self.logs = os.path.join(str(folder), 'terminals')
        os.makedirs(self.logs)
        self.cwd = self.home
        self.id = '%s-%s' % (name, uuid.uuid4().hex[:8])
        self.terminals = []
        self.last_stderr = ''
        with open(os.path.join(self.home, '.bashrc'), 'w') as f:
            # The tutorials' ROS installation step ("source /opt/ros/<distro>/setup.bash"): here, this workspace.
            f.write('source %s/devel/setup.bash\n' % WORKSPACE)
            # Debian's interactive shells load bash-completion, where Debian's rosbash defines roscd and rosls.
            f.write('source /usr/share/bash-completion/completions/rosbash\n')
        self.env = {
            'HOME': self.home, 'USER': os.environ.get('USER', 'root'), 'LANG': 'C.UTF-8', 'TERM': 'dumb',
            'PATH': '/usr/local/sbin:/usr/local/bin:/usr/sbin:/usr/bin:/sbin:/bin',
            'TMPDIR': tempfile.gettempdir(), MARKER: self.id,
        }
        # The machine's own settings, as a new user's shell has them (run_tests.py names the nodes
        # localhost when a walkthrough has a network namespace of its own).
        for name in ('DISPLAY', 'ROS_HOSTNAME', 'ROS_IP'):
            if name in os.environ:
                self.env[name] = os.environ[name]

    def speed_up(self, factor):
        """Not a tutorial's step: the test's own, to wait less. The simulator runs `factor` times
        faster than real time from now on (its 1 ms steps, `factor` thousand a second), set as a
        user would, through dynamic_reconfigure."""
        self.run('rosrun dynamic_reconfigure dynparam set /gazebo max_update_rate %d' % (1000 * factor))

    def screen(self):
        """A display for the tutorial's GUI programs (rviz): a virtual one (Xvfb), as the user's desktop."""
        for number in range(90, 140):
            if not os.path.exists('/tmp/.X11-unix/X%d' % number) and not os.path.exists('/tmp/.X%d-lock' % number):
                break
        xvfb = subprocess.Popen(['Xvfb', ':%d' % number, '-screen', '0', '1280x1024x24', '-nolisten', 'tcp'],
                                env=self.env, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL,
                                start_new_session=True)
        deadline = time.monotonic() + 15
        while not os.path.exists('/tmp/.X11-unix/X%d' % number):
            if xvfb.poll() is not None or time.monotonic() > deadline:
                raise CommandFailed('Xvfb :%d did not start' % number)
            time.sleep(0.1)
        self.env['DISPLAY'] = ':%d' % number

    def path(self, path):
        return os.path.join(self.home, path[2:]) if path.startswith('~/') else path

    def write(self, path, text):
        """What the user types into their editor (gedit in the tutorials)."""
        path = self.path(path)
        os.makedirs(os.path.dirname(path), exist_ok=True)
        with open(path, 'w') as f:
            f.write(text)

    def read(self, path):
        with open(self.path(path)) as f:
            return f.read()

    def _script(self, lines, state_file=None):
        body = '\n'.join(line.strip() for line in lines.strip().splitlines() if line.strip())
        script = 'source ~/.bashrc\ncd %s\nset -e\n%s\n' % (shlex.quote(self.cwd), body)
        if state_file:
            script += 'pwd > %s\n' % shlex.quote(state_file)
        return script

    def run(self, lines, timeout=300.0, check=True):
        """Types the lines into a terminal, one after another, and waits for the last; fails at the
        first line that fails (unless check=False). Returns (status, what they printed on stdout);
        their stderr (ROS's tools warn there, e.g. of rosdep's missing cache) is in last_stderr."""
        state = os.path.join(self.logs, 'cwd-%d' % len(os.listdir(self.logs)))
        process = subprocess.run(['bash', '-c', self._script(lines, state)], env=self.env, cwd=self.home,
                                 stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, timeout=timeout,
                                 start_new_session=True)
        self.last_stderr = process.stderr
        if process.returncode == 0 and os.path.exists(state):
            with open(state) as f:
                self.cwd = f.read().strip()
        if check and process.returncode != 0:
            raise CommandFailed('these lines failed (status %d):\n%s\noutput:\n%s\n%s'
                                % (process.returncode, lines.strip(), tail(process.stdout), tail(process.stderr)))
        return process.returncode, process.stdout

    def start(self, lines, cwd=None):
        """Types the lines into a new terminal and leaves them running (the tutorials' "on another
        terminal"). A new terminal starts in the home folder, or in cwd."""
        saved, self.cwd = self.cwd, self.path(cwd) if cwd else self.home
        script = self._script(lines)
        self.cwd = saved
        log = os.path.join(self.logs, 'terminal-%d.log' % len(self.terminals))
        terminal = Terminal(lines.strip(), script, dict(self.env, TERM='xterm'), self.home, log)
        self.terminals.append(terminal)
        return terminal

    def processes(self):
        """Pids of every process this session started that is still alive, wherever it now hangs."""
        found = []
        needle = ('%s=%s' % (MARKER, self.id)).encode()
        for pid in os.listdir('/proc'):
            if not pid.isdigit() or int(pid) == os.getpid():
                continue
            try:
                with open('/proc/%s/environ' % pid, 'rb') as f:
                    if needle in f.read().split(b'\0'):
                        found.append(int(pid))
            except OSError:
                pass
        return found

    def close(self):
        """Ctrl+C in every terminal, then SIGTERM and SIGKILL to whatever of the session remains."""
        for terminal in self.terminals:
            terminal.interrupt()
        # (seconds to wait for what was sent last, what to send to the rest then)
        for grace, next_signal in ((15.0, signal.SIGTERM), (10.0, signal.SIGKILL), (5.0, None)):
            deadline = time.monotonic() + grace
            while self.processes() and time.monotonic() < deadline:
                time.sleep(0.2)
            remaining = self.processes()
            if not remaining:
                return
            for pid in remaining if next_signal else []:
                try:
                    os.kill(pid, next_signal)
                except OSError:
                    pass
        raise AssertionError('processes that would not stop: %s' % self.processes())


def tail(text, lines=60):
    return '\n'.join(text.splitlines()[-lines:])
