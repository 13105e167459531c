"""catkin's own conventions, kept: Debian's catkin_lint finds nothing in src/ at its warning level
(every dependency exported, every target, header and script installed, every package a launch
file uses declared), and every rostest file is registered with add_rostest, so that
`catkin_make run_tests` runs what scripts/run_tests.py runs."""
import glob
import os
import re
import subprocess

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
SRC = os.path.join(ROOT, 'src')



def test_catkin_lint_finds_no_error_or_warning():
    done = subprocess.run(['catkin_lint', '-W1', '--offline', SRC], capture_output=True, text=True, timeout=120)
    problems = [line for line in done.stdout.splitlines() + done.stderr.splitlines()
                if re.search(r': (error|warning): ', line)]
    assert problems == [], '\n'.join(problems)


def test_every_rostest_file_is_registered_with_add_rostest():
    missing = []
    for test in sorted(glob.glob(os.path.join(SRC, '**', 'test', '*.test'), recursive=True)):
        if '/tutorials/' in test:  # a tutorial's own files, copied into a workspace by the walkthroughs
            continue
        package = os.path.dirname(os.path.dirname(test))
        relative = os.path.relpath(test, package)
        with open(os.path.join(package, 'CMakeLists.txt')) as f:
            cmake = f.read()
        if not re.search(r'add_rostest(_gtest)?\((\S+ )?%s[ )]' % re.escape(relative), cmake):
            missing.append(os.path.relpath(test, SRC))
    assert missing == []


# The folders a launch file, a URDF or `$(find pkg)/...` reaches into (catkin_lint does not check
# that they are installed; an install space without them fails at the first roslaunch).
RESOURCE_FOLDERS = {'launch', 'config', 'worlds', 'urdf', 'meshes', 'models', 'rviz', 'maps', 'param', 'boards',
                    'www', 'vendor', 'examples'}


def test_every_resource_folder_is_installed():
    missing = []
    for manifest in sorted(glob.glob(os.path.join(SRC, '**', 'package.xml'), recursive=True)):
        package = os.path.dirname(manifest)
        if '/tutorials/' in package or '/test/' in package:  # tutorials' own files, test data
            continue
        with open(os.path.join(package, 'CMakeLists.txt')) as f:
            installed = ' '.join(re.findall(r'install\(DIRECTORY([^)]*)\)', f.read()))
        for folder in sorted(RESOURCE_FOLDERS & set(os.listdir(package))):
            if not re.search(r'(^|\s)%s/?(\s|$)' % folder, installed):
                missing.append(os.path.relpath(os.path.join(package, folder), SRC))
    assert missing == []
