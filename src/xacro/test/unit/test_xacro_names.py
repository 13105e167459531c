"""xacro's old names as launch files use them in command=: `xacro.py` and `xacro --inorder` print
exactly the URDF that `xacro` prints on stdout (anything more would end up in robot_description),
and their notes go to stderr only."""
import os
import stat
import subprocess
import xml.etree.ElementTree as ET

import pytest

PACKAGE = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))

SMALL = """<?xml version="1.0"?>
<robot name="small" xmlns:xacro="http://www.ros.org/wiki/xacro">
  <xacro:property name="length" value="0.4"/>
  <xacro:macro name="box_link" params="name size">
    <link name="${name}"><visual><geometry><box size="${size} 0.1 0.1"/></geometry></visual></link>
  </xacro:macro>
  <xacro:box_link name="base" size="${length}"/>
  <xacro:box_link name="arm" size="${length / 2}"/>
  <joint name="elbow" type="revolute">
    <parent link="base"/><child link="arm"/>
    <origin xyz="${length} 0 0" rpy="0 0 ${pi/2}"/>
    <limit effort="1" velocity="1" lower="-1" upper="1"/>
  </joint>
</robot>
"""


def run(script, *args):
    return subprocess.run([os.path.join(PACKAGE, script)] + list(args), capture_output=True, text=True, timeout=60)


@pytest.fixture(scope='module')
def small_xacro(tmp_path_factory):
    path = tmp_path_factory.mktemp('xacro') / 'small.xacro'
    path.write_text(SMALL)
    return str(path)


@pytest.fixture(scope='module')
def reference(small_xacro):
    done = run('xacro', small_xacro)
    assert done.returncode == 0, done.stderr
    robot = ET.fromstring(done.stdout)  # a URDF and nothing else
    assert robot.get('name') == 'small'
    assert [link.get('name') for link in robot.findall('link')] == ['base', 'arm']  # the macros ran
    assert robot.find("joint/origin").attrib == {'xyz': '0.4 0 0', 'rpy': '0 0 1.5707963267948966'}
    return done.stdout


@pytest.mark.parametrize('script', ['xacro', 'xacro.py'])
def test_is_an_executable_in_the_package_folder(script):
    # `$(find xacro)/NAME` runs it directly, `rosrun xacro NAME` finds it by its execute bit
    path = os.path.join(PACKAGE, script)
    assert os.path.isfile(path)
    assert os.stat(path).st_mode & stat.S_IXUSR and os.access(path, os.X_OK)


@pytest.mark.parametrize('args', [['xacro.py'], ['xacro.py', '--inorder'], ['xacro', '--inorder'],
                                  ['xacro.py', '-i']])
def test_old_forms_print_exactly_what_xacro_prints(args, small_xacro, reference):
    done = run(args[0], *(args[1:] + [small_xacro]))
    assert done.returncode == 0, done.stderr
    assert done.stdout == reference


def test_notes_go_to_stderr(small_xacro):
    done = run('xacro.py', '--inorder', small_xacro)
    assert 'xacro.py: deprecated name' in done.stderr
    assert 'in-order processing became default' in done.stderr  # xacro 1.13's own note on --inorder
    assert 'deprecated' not in done.stdout


def test_errors_still_fail(tmp_path):
    broken = tmp_path / 'broken.xacro'
    broken.write_text('<robot name="b" xmlns:xacro="http://www.ros.org/wiki/xacro"><xacro:nothing/></robot>')
    done = run('xacro.py', '--inorder', str(broken))
    assert done.returncode != 0
    assert done.stdout == ''
