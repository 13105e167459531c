"""The simulator's packages keep their shape (docs/ARCHITECTURE.md):

- bullet_sim_core has no ROS in it: its sources include no ROS header and its library links no ROS
  library (Debian installs ROS headers under /usr/include, so the build alone would not stop one);
  nor have navigation_core and hector_style_mapping_core (the SLAM core both mapping nodes build on);
- dependencies point one way: core <- plugins <- ros_control <- node, and only bullet_sim_ros_control
  depends on sim_control;
- no product package depends on a test-only package (they may list one as a test_depend);
- every package's package.xml declares the workspace packages its CMakeLists.txt finds.

Run after building the workspace: /usr/bin/python3 -m pytest tests/test_package_layout.py
"""
import glob
import os
import re
import subprocess
import xml.etree.ElementTree as ET

import pytest
from catkin_pkg.packages import find_packages

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
SRC = os.path.join(ROOT, 'src')
CORE = os.path.join(SRC, 'bullet_sim_core')
TEST_ONLY = {'bullet_sim_testing'}

# What the core may include: the C++ library, and the non-ROS libraries it is built on.
ALLOWED_INCLUDE = re.compile(
    r'^(bullet_sim_core/|Bullet|bt[A-Z]|Eigen/|tinyxml2\.h|urdf_parser/|urdf_model/|console_bridge/|assimp/|'
    r'opencv2/|gtest/|[a-z_]+(\.h)?$)')
ROS_LIBRARY = re.compile(r'lib(ros|roscpp|rosconsole|rostime|roslib|tf2|cpp_common|xmlrpcpp|message_filters)')


def core_sources():
    for folder in ('include', 'src', 'test', 'bench'):
        for path in glob.glob(os.path.join(CORE, folder, '**', '*.*'), recursive=True):
            if path.endswith(('.h', '.cpp')):
                yield path


# Package name -> its folder; packages may sit in sub-folders (src/names/, src/pioneer_gazebo_ros/).
PACKAGE_DIRS = {package.name: os.path.join(SRC, path) for path, package in find_packages(SRC).items()}


def manifest(package):
    """(run/build dependencies, test dependencies) of the package's package.xml."""
    root = ET.parse(os.path.join(PACKAGE_DIRS[package], 'package.xml')).getroot()
    depends = {e.text.strip() for e in root if e.tag in ('depend', 'build_depend', 'exec_depend', 'build_export_depend')}
    tests = {e.text.strip() for e in root if e.tag == 'test_depend'}
    return depends, tests


def workspace_packages():
    return sorted(PACKAGE_DIRS)


def test_the_core_includes_no_ros_header():
    offenders = []
    for path in core_sources():
        with open(path) as f:
            for number, line in enumerate(f, 1):
                m = re.match(r'\s*#\s*include\s*[<"]([^>"]+)[>"]', line)
                if m and not ALLOWED_INCLUDE.match(m.group(1)):
                    offenders.append('%s:%d: %s' % (os.path.relpath(path, ROOT), number, m.group(1)))
    assert offenders == [], 'ROS (or unexpected) headers in bullet_sim_core:\n' + '\n'.join(offenders)
    assert len(list(core_sources())) > 20  # the scan really looked at the core


def test_the_core_library_links_no_ros_library():
    library = os.path.join(ROOT, 'devel', 'lib', 'libbullet_sim_core.so')
    assert os.path.isfile(library), 'build the workspace first (scripts/setup): no ' + library
    needed = [line.split('[')[1].rstrip(']') for line in
              subprocess.check_output(['readelf', '-d', library], text=True).splitlines() if '(NEEDED)' in line]
    assert any('Bullet' in n for n in needed), needed  # the check reads the right file
    assert [n for n in needed if ROS_LIBRARY.search(n)] == []


def includes_outside(package, allowed):
    """(sources scanned, 'file:line: header' for each #include of the package's C++ not matching `allowed`)."""
    folder = os.path.join(SRC, package)
    sources = [p for sub in ('include', 'src', 'test', 'bench')
               for p in glob.glob(os.path.join(folder, sub, '**', '*.*'), recursive=True) if p.endswith(('.h', '.cpp'))]
    offenders = []
    for path in sources:
        with open(path) as f:
            for number, line in enumerate(f, 1):
                m = re.match(r'\s*#\s*include\s*[<"]([^>"]+)[>"]', line)
                if m and not re.match(allowed, m.group(1)):
                    offenders.append('%s:%d: %s' % (os.path.relpath(path, ROOT), number, m.group(1)))
    return sources, offenders


def test_the_navigation_core_is_plain_cpp():
    """navigation_core (costmaps, planners) includes only the C++ library and its own headers, and
    its manifest names no ROS package."""
    sources, offenders = includes_outside('navigation_core', r'^(navigation_core/|gtest/|[a-z_]+$)')
    assert offenders == [], 'non-standard headers in navigation_core:\n' + '\n'.join(offenders)
    assert len(sources) >= 6  # the scan really looked at the package
    depends, tests = manifest('navigation_core')
    assert depends == set() and tests == {'gtest'}, (depends, tests)


def test_the_hector_core_is_ros_free():
    """hector_style_mapping_core (grids, scan matching, the SLAM loop; odometry_slam builds on it too)
    includes only the C++ library, Eigen and its own headers, its manifest names no package but
    Eigen, and its library links no ROS library."""
    sources, offenders = includes_outside('hector_style_mapping_core', r'^(hector_style_mapping_core/|Eigen/|gtest/|[a-z_]+$)')
    assert offenders == [], 'ROS (or unexpected) headers in hector_style_mapping_core:\n' + '\n'.join(offenders)
    assert len(sources) >= 30  # the scan really looked at the package
    depends, tests = manifest('hector_style_mapping_core')
    assert depends == {'eigen'} and tests == {'gtest'}, (depends, tests)
    library = os.path.join(ROOT, 'devel', 'lib', 'libhector_style_mapping_core.so')
    assert os.path.isfile(library), 'build the workspace first (scripts/setup): no ' + library
    needed = [line.split('[')[1].rstrip(']') for line in
              subprocess.check_output(['readelf', '-d', library], text=True).splitlines() if '(NEEDED)' in line]
    assert any('libstdc++' in n for n in needed), needed  # the check reads the right file
    assert [n for n in needed if ROS_LIBRARY.search(n)] == []


def test_both_slam_nodes_build_on_the_hector_core():
    """hector_style_mapping and odometry_slam depend on hector_style_mapping_core as a package, and it
    on neither of them."""
    assert {'hector_style_mapping', 'odometry_slam'} - set(workspace_packages()) == set()
    for package in ('hector_style_mapping', 'odometry_slam'):
        assert 'hector_style_mapping_core' in manifest(package)[0], package
    assert set(workspace_packages()) & manifest('hector_style_mapping_core')[0] == set()


def test_simulator_dependencies_point_one_way():
    order = ['bullet_sim_core', 'bullet_sim_plugins', 'bullet_sim_ros_control', 'bullet_sim']
    for i, package in enumerate(order):
        depends, _ = manifest(package)
        later = [p for p in order[i + 1:] if p in depends]
        assert later == [], '%s depends on %s, which builds on it' % (package, later)
    for package in order[1:]:
        assert order[order.index(package) - 1] in manifest(package)[0], package
    users = [p for p in workspace_packages() if 'sim_control' in manifest(p)[0] and p.startswith('bullet_sim')]
    assert users == ['bullet_sim_ros_control']


def test_no_product_package_depends_on_a_test_package():
    for package in workspace_packages():
        depends, _ = manifest(package)
        assert not (depends & TEST_ONLY), '%s depends on %s' % (package, depends & TEST_ONLY)
    assert manifest('m_robot_gazebo')[1] >= {'bullet_sim_testing'}  # tests may use it


@pytest.mark.parametrize('package', workspace_packages())
def test_cmake_finds_only_declared_workspace_packages(package):
    cmake = os.path.join(PACKAGE_DIRS[package], 'CMakeLists.txt')
    with open(cmake) as f:
        text = f.read()
    found = set()
    for block in re.findall(r'find_package\(\s*catkin\s+REQUIRED\s+COMPONENTS([^)]*)\)', text):
        found |= set(block.split())
    declared = set.union(*manifest(package))
    ours = set(workspace_packages())
    assert (found & ours) - declared == set(), '%s finds undeclared packages' % package
