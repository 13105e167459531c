#!/usr/bin/env python3
"""Runs every test of the workspace and prints one summary line per suite, then a total.

gtest binaries built by catkin_add_gtest, pytest on the pure-Python unit tests (tests/ and
PKG/test/unit of every package under src/), every rostest launch file PKG/test/*.test (each
starts its own roscore), and every tutorial walkthrough PKG/test/walkthrough/test_*.py (pytest
driving real processes in a new user's home; each file a suite of its own).
Results are read back from the runners' JUnit XML files, so a crash that writes no result
counts as a failure. Exit status is 0 only if everything passed and at least one test ran.

The gtests, rostests and the pytest suite run --jobs at a time (default: one per core): each
rostest has its own roscore on a free port and most of a simulation test's time is waiting, so
two at once on two cores take about 0.75 of the time. The walkthroughs run after them: they use
the default master port and type the tutorials' `killall roscore` and `killall gzserver`, and the
simulator of every rostest is named gzserver too. Where the machine allows namespaces (root,
unshare), each walkthrough runs in a PID and network namespace of its own, where those commands
reach only what it started and its master's port is its own, two at a time; otherwise one by one.
Rostests never run beside a walkthrough (the Katana tests' sim-time bounds failed under that
load). Lines are printed as suites end.

Usage: run_tests.py [--only SUBSTRING] [--jobs N]
"""
import argparse
import concurrent.futures
import glob
import os
import subprocess
import sys
import threading
import time
import xml.etree.ElementTree as ET

from catkin_pkg.packages import find_packages

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
RESULTS = os.path.join(ROOT, "test_results")
PRINTING = threading.Lock()


def junit_counts(path):
    """(passed, failed, skipped) from a JUnit XML file; a missing or unreadable file is one failure."""
    try:
        root = ET.parse(path).getroot()
    except (OSError, ET.ParseError):
        return 0, 1, 0
    passed = failed = skipped = 0
    for case in root.iter("testcase"):
        if case.find("failure") is not None or case.find("error") is not None:
            failed += 1
        elif case.find("skipped") is not None:
            skipped += 1
        else:
            passed += 1
    if passed + failed + skipped == 0:
        failed = 1  # a suite that ran nothing is a broken suite
    return passed, failed, skipped


def counts_of(xml_path):
    """A rostest's own file counts its test nodes; the rosunit-*.xml files beside it count
    the cases inside them, which is what we report when they exist."""
    if os.path.basename(xml_path).startswith("rostest-"):
        details = glob.glob(os.path.join(os.path.dirname(xml_path), "rosunit-*.xml"))
        if details:
            node_counts = junit_counts(xml_path)
            totals = [sum(c) for c in zip(*(junit_counts(d) for d in details))]
            totals[1] = max(totals[1], node_counts[1])  # a node that died without its cases
            return tuple(totals)
    return junit_counts(xml_path)


def run(name, cmd, xml_path, env=None, timeout=900):
    start = time.time()
    log_path = os.path.join(RESULTS, "logs", name.replace("/", "_") + ".log")
    os.makedirs(os.path.dirname(log_path), exist_ok=True)
    with open(log_path, "w") as log:
        try:
            code = subprocess.call(cmd, stdout=log, stderr=subprocess.STDOUT, env=env, timeout=timeout, cwd=ROOT)
        except subprocess.TimeoutExpired:
            code = "timeout"
    passed, failed, skipped = counts_of(xml_path)
    if code not in (0, "timeout") and failed == 0:
        failed = 1  # the runner failed without saying which test
    if code == "timeout":
        failed += 1
    status = "ok" if failed == 0 else "FAILED (log: %s)" % os.path.relpath(log_path, ROOT)
    report = "%-55s %3d passed, %d failed, %d skipped  %5.1fs  %s\n" % (
        name, passed, failed, skipped, time.time() - start, status)
    if failed:
        with open(log_path) as log:
            report += "".join("    | " + line for line in log.readlines()[-40:])
    with PRINTING:  # a suite's line and its log's tail together, whichever suites end meanwhile
        sys.stdout.write(report)
        sys.stdout.flush()
    return passed, failed, skipped


def stop_walkthrough_leftovers():
    """A walkthrough killed at its time limit cannot stop what it started; its processes carry
    TUTORIAL_WALKTHROUGH_SESSION in their environment (tutorial_walkthroughs' user_session.py)."""
    for pid in filter(str.isdigit, os.listdir("/proc")):
        try:
            with open("/proc/%s/environ" % pid, "rb") as f:
                if any(v.startswith(b"TUTORIAL_WALKTHROUGH_SESSION=") for v in f.read().split(b"\0")):
                    os.kill(int(pid), 9)
        except OSError:
            pass


def in_own_namespaces(cmd):
    """cmd in new PID and network namespaces (its own /proc, its own loopback), bash as its PID 1:
    bash reaps the orphans that `killall` leaves, so a tutorial's poll for them ending sees them
    gone. Its nodes name themselves localhost, which the new loopback answers for."""
    return ["unshare", "--pid", "--fork", "--mount-proc", "--net", "--kill-child", "bash", "-c",
            'ip link set lo up && export ROS_HOSTNAME=localhost && "$@"; exit $?', "_"] + cmd


def namespaces_work():
    try:
        return subprocess.run(in_own_namespaces(["true"]), capture_output=True, timeout=30).returncode == 0
    except (OSError, subprocess.TimeoutExpired):
        return False


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--only", default="", help="run only suites whose name contains this")
    parser.add_argument("--jobs", type=int, default=os.cpu_count() or 1,
                        help="suites run at once (default: the number of cores); walkthroughs two at most")
    args = parser.parse_args()
    os.makedirs(RESULTS, exist_ok=True)
    suites = []

    for binary in sorted(glob.glob(os.path.join(ROOT, "devel", "lib", "*", "test_*"))):
        if os.access(binary, os.X_OK) and not binary.endswith(".py"):
            name = "gtest " + os.path.relpath(binary, os.path.join(ROOT, "devel", "lib"))
            xml = os.path.join(RESULTS, "gtest", os.path.basename(binary) + ".xml")
            suites.append((name, [binary, "--gtest_output=xml:" + xml], xml))

    # Packages may sit in sub-folders of src/ (src/names/, src/pioneer_gazebo_ros/).
    packages = sorted((package.name, os.path.join(ROOT, "src", path))
                      for path, package in find_packages(os.path.join(ROOT, "src")).items())
    unit_dirs = [d for d in [os.path.join(ROOT, "tests")] + [os.path.join(folder, "test", "unit") for _, folder in packages]
                 if glob.glob(os.path.join(d, "test_*.py"))]
    if unit_dirs:
        xml = os.path.join(RESULTS, "pytest.xml")
        # The name also names the log file: the folders are counted, not listed.
        suites.append(("pytest tests/ and src/PKG/test/unit/ (%d folders)" % len(unit_dirs),
                       [sys.executable, "-m", "pytest", "-q", "-p", "no:cacheprovider", "--junitxml=" + xml] + unit_dirs,
                       xml))

    rostest_env = dict(os.environ, ROS_TEST_RESULTS_DIR=os.path.join(RESULTS, "rostest"))
    launches = [(package, launch) for package, folder in packages
                for launch in sorted(glob.glob(os.path.join(folder, "test", "*.test")))]
    for package, launch in launches:
        test = os.path.splitext(os.path.basename(launch))[0]
        base = os.path.join(RESULTS, "rostest", package + "." + test)
        xml = os.path.join(base, package, "rostest-test_%s.xml" % test)
        suites.append(("rostest %s %s.test" % (package, test),
                       ["rostest", "--results-base-dir", base, package, test + ".test"], xml))

    for package, folder in packages:
        for walkthrough in sorted(glob.glob(os.path.join(folder, "test", "walkthrough", "test_*.py"))):
            test = os.path.splitext(os.path.basename(walkthrough))[0]
            xml = os.path.join(RESULTS, "walkthrough", test + ".xml")
            suites.append(("walkthrough %s" % test,
                           # -x: a walkthrough's steps build on each other; after a failed one the rest says nothing
                           [sys.executable, "-m", "pytest", "-q", "-x", "-p", "no:cacheprovider", "--junitxml=" + xml,
                            walkthrough], xml))

    chosen = [suite for suite in suites if args.only in suite[0]]
    for _, _, xml in chosen:
        for stale in glob.glob(os.path.join(os.path.dirname(xml), "*.xml")):
            os.remove(stale)

    def run_suite(suite):
        name, cmd, xml = suite
        return run(name, cmd, xml, env=rostest_env if name.startswith("rostest") else None)

    walkthroughs = [suite for suite in chosen if suite[0].startswith("walkthrough")]
    shared = [suite for suite in chosen if suite not in walkthroughs]
    # The pytest suite is the longest: started first, it does not end the run alone.
    shared.sort(key=lambda suite: not suite[0].startswith("pytest"))
    apart = bool(walkthroughs) and args.jobs > 1 and namespaces_work()

    def run_walkthrough(suite):
        name, cmd, xml = suite
        if apart:  # everything it started ends with its namespace
            return run(name, in_own_namespaces(cmd), xml)
        counts = run(name, cmd, xml)
        stop_walkthrough_leftovers()
        return counts

    totals = [0, 0, 0]
    with concurrent.futures.ThreadPoolExecutor(max_workers=max(1, args.jobs)) as pool:
        for counts in pool.map(run_suite, shared):
            totals = [t + n for t, n in zip(totals, counts)]
    with concurrent.futures.ThreadPoolExecutor(max_workers=2 if apart else 1) as pool:
        for counts in pool.map(run_walkthrough, walkthroughs):
            totals = [t + n for t, n in zip(totals, counts)]
    print()
    print("%d passed, %d failed, %d skipped" % tuple(totals))
    return 0 if totals[1] == 0 and totals[0] > 0 else 1


if __name__ == "__main__":
    sys.exit(main())
