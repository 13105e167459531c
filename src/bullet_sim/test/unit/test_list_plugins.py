"""bullet_sim_node --list-plugins: every plugin library the node can simulate, including the ones that
register from libraries the node never calls by name (bullet_sim_ros_control), which a linker that
drops unreferenced libraries would lose."""
import os
import subprocess

NODE = os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', '..', '..', '..', 'devel', 'lib', 'bullet_sim',
                    'bullet_sim_node')


def test_the_node_lists_gazebo_ros_plugins_by_library_name():
    assert os.path.isfile(NODE), 'build the workspace first (scripts/setup): no ' + NODE
    out = subprocess.run([NODE, '--list-plugins'], stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
                         timeout=30)
    assert out.returncode == 0, out.stderr
    assert out.stdout.split() == sorted([
        'libgazebo_grasp_fix.so', 'libgazebo_ros_camera.so', 'libgazebo_ros_control.so', 'libgazebo_ros_diff_drive.so',
        'libgazebo_ros_gpu_laser.so', 'libgazebo_ros_katana_gripper.so', 'libgazebo_ros_laser.so',
        'libgazebo_ros_skid_steer_drive.so'])
