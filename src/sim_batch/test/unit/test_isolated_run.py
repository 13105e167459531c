"""isolated_run.py with real roscores (no Ray): a run's own master and folders, its result line,
the time limit killing the whole process group, a failure's logs, two runs at once apart."""
import io
import os
import subprocess
import tarfile
import sys
import threading
import time

from sim_batch.isolated_run import last_json_line, run_isolated
from sim_batch.scenario import Run

from process_probe import alive


def test_a_command_runs_on_its_own_master_and_its_json_line_is_the_result(tmp_path):
    command = ('rosparam set /answer 42 && echo "noise" && '
               'echo "{\\"answer\\": $(rosparam get /answer), \\"home\\": \\"$ROS_HOME\\", \\"seed\\": $SIM_BATCH_SEED}"')
    record, archive = run_isolated(Run(scenario="a", command=command, seed=7, time_limit=60), str(tmp_path))
    assert record["state"] == "ok", record
    assert record["result"]["answer"] == 42 and record["result"]["seed"] == 7
    assert record["result"]["home"].startswith(str(tmp_path))  # its own ROS_HOME, gone afterwards
    assert not os.path.exists(record["result"]["home"])
    assert record["master"].startswith("http://127.0.0.1:") and record["master"] != os.environ.get("ROS_MASTER_URI")
    assert 0.5 < record["wall_s"] < 30 and record["sim_s"] is None
    assert archive is None


def test_the_record_counts_the_cpu_time_of_the_runs_processes(tmp_path):
    # 3 CPU-seconds burned: well above how much the master's start-up and stop vary between runs
    # on a busy machine (about 0.5 s of the 1-3 s they cost)
    burn = ("python3 -c 'import time; t = time.process_time()\nwhile time.process_time() - t < 3.0: pass' "
            "&& echo '{}'")
    idle = run_isolated(Run(scenario="idle", command="echo '{}'", time_limit=60), str(tmp_path))[0]
    busy = run_isolated(Run(scenario="busy", command=burn, time_limit=60), str(tmp_path))[0]
    assert idle["state"] == busy["state"] == "ok", (idle, busy)
    # the master's start-up and stop in both; the three burned seconds, all of them, in the busy one
    assert 0.0 < idle["cpu_s"] < 5.0, idle
    assert 3.0 <= busy["cpu_s"] < 3.0 + 5.0, busy
    assert 2.0 < busy["cpu_s"] - idle["cpu_s"] < 4.5, (idle, busy)


def test_the_time_limit_stops_every_process_of_the_run_and_the_logs_come_back(tmp_path):
    # background jobs (which ignore SIGINT), a grandchild and the foreground: all stopped;
    # their durations mark them for pgrep
    # and one in a session of its own ignoring SIGINT and SIGTERM, as roslaunch's nodes are in theirs
    command = ("(sleep 300.11; true) & bash -c 'sleep 300.12; true' & "
               "setsid bash -c \"trap '' INT TERM; sleep 300.14; true\" & echo started; sleep 300.13")
    record, archive = run_isolated(Run(scenario="slow", command=command, time_limit=5), str(tmp_path))
    assert record["state"] == "timeout" and "5 s" in record["error"]
    assert 5.0 <= record["wall_s"] < 30.0  # the limit counts from the run's start, its master's included
    assert not alive("sleep 300.1"), "a process of the run survived its time limit"
    assert not alive("roscore -p %s" % record["master"].rsplit(":", 1)[1])
    with tarfile.open(fileobj=io.BytesIO(archive)) as tar:
        names = tar.getnames()
        assert "logs/command.log" in names and "logs/roscore.log" in names
        assert b"started" in tar.extractfile("logs/command.log").read()


def test_a_failing_check_is_recorded_with_its_status_and_a_launch_runs_beside_it(tmp_path):
    launch = tmp_path / "talker.launch"
    launch.write_text('<launch><node name="talker" pkg="rostopic" type="rostopic" '
                      'args="pub -r 10 /chatter std_msgs/String hello"/></launch>')
    check = "rostopic echo -n 1 /chatter/data && exit 3"
    record, archive = run_isolated(Run(scenario="c", launch=str(launch), check=check, time_limit=60), str(tmp_path))
    assert record["state"] == "failed" and record["exit_code"] == 3
    assert "check exited with status 3" in record["error"]
    with tarfile.open(fileobj=io.BytesIO(archive)) as tar:
        assert b"hello" in tar.extractfile("logs/check.log").read()  # the launch's talker was heard
    assert not alive("pub -r 10 /chatter"), "the launch's node (in a session of its own) outlived the run"


def test_two_runs_at_once_do_not_see_each_others_topics(tmp_path):
    # each publishes its own name latched and reads back what its master has: only its own
    command = ("rostopic pub -l /who std_msgs/String %s & sleep 1.5; "
               "heard=$(rostopic echo -n 1 /who/data | head -1 | tr -d '\"'); "
               "echo \"{\\\"heard\\\": \\\"$heard\\\", \\\"topics\\\": $(rostopic list | grep -c who)}\"")
    records = {}

    def one(name):
        records[name] = run_isolated(Run(scenario=name, command=command % name, time_limit=60), str(tmp_path))[0]
    threads = [threading.Thread(target=one, args=(n,)) for n in ("left", "right")]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    for name in ("left", "right"):
        assert records[name]["state"] == "ok", records[name]
        assert records[name]["result"]["heard"] == name
        assert records[name]["result"]["topics"] == 1
    assert records["left"]["master"] != records["right"]["master"]


def test_the_last_json_object_line_is_the_result():
    assert last_json_line('{"a": 1}\nlog\n{"b": 2}\n[3]\n{bad\n') == {"b": 2}
    assert last_json_line("nothing here") is None


def test_a_run_whose_owner_dies_is_stopped_by_its_reaper(tmp_path):
    # the command comes through the environment: the owner's own command line must not match
    owner = subprocess.Popen([sys.executable, "-c", (
        "import os; from sim_batch.isolated_run import run_isolated; from sim_batch.scenario import Run; "
        "run_isolated(Run(scenario='o', command=os.environ['RUN_COMMAND'], time_limit=600), %r)" % str(tmp_path))],
        env=dict(os.environ, RUN_COMMAND="sleep 300.21; true"))
    deadline = time.monotonic() + 30
    while not alive("sleep 300.21") and time.monotonic() < deadline:
        time.sleep(0.1)
    assert alive("sleep 300.21"), "the run did not start"
    owner.kill()  # as a Ray worker killed mid-run: no finally, no stop()
    owner.wait()
    deadline = time.monotonic() + 15
    while alive("sleep 300.21") and time.monotonic() < deadline:
        time.sleep(0.1)
    assert not alive("sleep 300.21"), "the orphaned run's processes live on"
