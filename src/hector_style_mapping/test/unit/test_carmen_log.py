"""CARMEN logs: the reader (FLASER, ROBOTLASER1, bad lines) and the bag they become."""
import gzip
import math
import os
import subprocess
import sys

import pytest
import rosbag

from hector_style_mapping_tools.carmen import CarmenLogError, flaser_increment, read_log, saturation_range
from hector_style_mapping_tools.carmen_bag import write_bag


def flaser(ranges, x=1.0, y=2.0, theta=0.5, stamp=10.0):
    return 'FLASER %d %s %.9g %.9g %.9g 0 0 0 %.9g host %.9g\n' % (len(ranges), ' '.join('%g' % r for r in ranges), x, y,
                                                        theta, stamp, stamp)


def write(tmp_path, text, name='log.txt'):
    path = str(tmp_path / name)
    with (gzip.open(path, 'wt') if name.endswith('.gz') else open(path, 'w')) as f:
        f.write(text)
    return path


def test_flaser_geometry_pose_and_stamp(tmp_path):
    text = '# a comment\nPARAM robot_frontlaser_offset 0.2 nohost 0\nODOM 0 0 0 0 0 0 1 h 1\n'
    text += flaser([1.0] * 180, x=1.0, y=2.0, theta=math.pi / 2, stamp=12.5)
    log = read_log(write(tmp_path, text, 'log.gz'))
    assert log.skipped == 1 and log.front_laser_offset == pytest.approx(0.2)
    (scan,) = log.scans
    assert scan.stamp == pytest.approx(12.5)
    assert scan.angle_min == pytest.approx(-math.pi / 2)
    assert scan.angle_increment == pytest.approx(math.radians(1.0))
    assert scan.laser_pose == pytest.approx((1.0, 2.0, math.pi / 2))
    # The robot's centre is 0.2 m behind the laser along the heading (+y here).
    assert scan.robot_pose == pytest.approx((1.0, 1.8, math.pi / 2))


def test_flaser_beam_spacing_follows_carmens_sick_modes():
    assert flaser_increment(180) == pytest.approx(math.radians(1.0))
    assert flaser_increment(181) == pytest.approx(math.radians(1.0))
    assert flaser_increment(361) == pytest.approx(math.radians(0.5))
    assert flaser_increment(360) == pytest.approx(math.radians(0.5))


def test_robotlaser1_gives_its_own_geometry_and_both_poses(tmp_path):
    ranges = ' '.join(['2.0'] * 5)
    line = ('ROBOTLASER1 0 -1.0 2.0 0.5 30.0 0.01 0 5 %s 2 7 8 1.0 2.0 0.1 0.9 1.9 0.1 0 0 0 0 0 33.0 host 33.0\n'
            % ranges)
    (scan,) = read_log(write(tmp_path, line)).scans
    assert (scan.angle_min, scan.angle_increment, scan.max_range) == pytest.approx((-1.0, 0.5, 30.0))
    assert scan.laser_pose == pytest.approx((1.0, 2.0, 0.1))
    assert scan.robot_pose == pytest.approx((0.9, 1.9, 0.1))
    assert scan.stamp == pytest.approx(33.0)


@pytest.mark.parametrize('line, says', [
    ('FLASER 180 1 2 3\n', 'FLASER ranges: expected 180 numbers from field 3'),
    ('FLASER 3 1 2 x 0 0 0 0 0 0 1 h 1\n', 'FLASER ranges: expected numbers'),
    ('FLASER three 1 2 3\n', 'FLASER: expected a beam count in field 2'),
    ('FLASER 3 1 2 3 0 0\n', 'FLASER pose and timestamp: expected 7 numbers'),
])
def test_a_bad_line_is_named_by_file_line_and_field(tmp_path, line, says):
    path = write(tmp_path, flaser([1.0, 2.0, 3.0]) + line)
    with pytest.raises(CarmenLogError) as error:
        read_log(path)
    assert '%s:2: ' % path in str(error.value)
    assert says in str(error.value)


def test_the_bag_has_scans_with_no_return_as_inf_the_mount_and_the_truth(tmp_path):
    text = 'PARAM robot_frontlaser_offset 0.1 nohost 0\n'
    text += flaser([1.0, 50.0, 2.0], x=0.0, y=0.0, theta=0.0, stamp=0.0)
    text += flaser([1.5, 3.0, 50.0], x=0.5, y=0.0, theta=0.1, stamp=0.2)
    log = read_log(write(tmp_path, text))
    assert saturation_range(log) == pytest.approx(50.0)
    bag_path = str(tmp_path / 'log.bag')
    count, max_range, shift = write_bag(log, bag_path)
    assert (count, max_range, shift) == (2, pytest.approx(50.0), pytest.approx(1.0))  # stamps must be > 0
    with rosbag.Bag(bag_path) as bag:
        messages = {}
        for topic, msg, _ in bag.read_messages():
            messages.setdefault(topic, []).append(msg)
    scans, truth, (mount,) = messages['/scan'], messages['/ground_truth'], messages['/tf_static']
    assert [list(s.ranges) for s in scans] == [[1.0, math.inf, 2.0], [1.5, 3.0, math.inf]]
    assert scans[0].range_max == pytest.approx(50.0) and scans[0].header.frame_id == 'laser'
    assert scans[0].angle_max == pytest.approx(math.pi / 2)  # 3 beams: one at each end of the 180 degrees
    assert [s.header.stamp.to_sec() for s in scans] == pytest.approx([1.0, 1.2])
    assert [t.header.stamp for t in truth] == [s.header.stamp for s in scans]
    # The robot's centre 0.1 m behind the laser.
    assert truth[1].pose.pose.position.x == pytest.approx(0.5 - 0.1 * math.cos(0.1))
    assert 2 * math.atan2(truth[1].pose.pose.orientation.z, truth[1].pose.pose.orientation.w) == pytest.approx(0.1)
    (t,) = mount.transforms
    assert (t.header.frame_id, t.child_frame_id, t.transform.translation.x) == ('base_link', 'laser', pytest.approx(0.1))


def test_a_log_without_scans_is_refused(tmp_path):
    log = read_log(write(tmp_path, 'ODOM 0 0 0 0 0 0 1 h 1\n'))
    with pytest.raises(ValueError, match='no laser scans'):
        write_bag(log, str(tmp_path / 'empty.bag'))


def test_a_log_cut_short_keeps_the_scans_before_the_cut(tmp_path):
    whole = flaser([1.0, 2.0, 3.0], stamp=1.0) + flaser([1.5, 2.5, 3.5], stamp=2.0)
    path = write(tmp_path, whole + flaser([1.0, 2.0, 3.0], stamp=3.0)[:20])
    log = read_log(path)
    assert [s.stamp for s in log.scans] == [1.0, 2.0]
    assert '%s:3: ' % path in log.truncated and 'cut short' in log.truncated
    # The same bad line with its end is not a cut: it is an error.
    with pytest.raises(CarmenLogError, match=':3: '):
        read_log(write(tmp_path, whole + flaser([1.0, 2.0, 3.0], stamp=3.0)[:20] + '\n', 'whole.txt'))


def test_a_gz_log_cut_short_keeps_the_scans_before_the_cut(tmp_path):
    text = ''.join(flaser([1.0 + i, 2.0, 3.0], stamp=float(i)) for i in range(2000))
    path = write(tmp_path, text, 'log.gz')
    with open(path, 'rb') as f:
        data = f.read()
    with open(path, 'wb') as f:
        f.write(data[:len(data) // 2])
    log = read_log(path)
    assert 0 < len(log.scans) < 2000
    assert [s.stamp for s in log.scans] == [float(i) for i in range(len(log.scans))]
    assert 'compressed file ends early' in log.truncated


def test_stamps_going_back_are_kept_and_counted(tmp_path):
    text = ''.join(flaser([1.0, 2.0, 3.0], stamp=t) for t in (1.0, 2.0, 1.5, 3.0, 2.9))
    log = read_log(write(tmp_path, text))
    assert [s.stamp for s in log.scans] == [1.0, 2.0, 1.5, 3.0, 2.9]
    assert log.stamps_back == [3, 5]


def test_readings_that_are_not_numbers_stay_out_of_the_saturation_range(tmp_path):
    log = read_log(write(tmp_path, flaser([1.0, float('nan'), 7.5]) + flaser([float('inf'), 2.0, 3.0], stamp=11.0)))
    assert saturation_range(log) == pytest.approx(7.5)
    bag_path = str(tmp_path / 'log.bag')
    write_bag(log, bag_path)
    with rosbag.Bag(bag_path) as bag:
        ranges = [list(msg.ranges) for _, msg, _ in bag.read_messages(topics=['/scan'])]
    # NaN stays an erroneous reading and inf no return (REP 117); 7.5, the saturation value, is no return too.
    assert math.isnan(ranges[0][1]) and ranges[0][2] == math.inf and ranges[1][0] == math.inf
    assert ranges[0][0] == 1.0 and ranges[1][1:] == [2.0, 3.0]


def test_carmen_to_bag_warns_of_a_cut_and_writes_what_came_before(tmp_path):
    script = os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', '..', 'scripts', 'carmen_to_bag')
    whole = flaser([1.0, 2.0, 3.0], stamp=1.0) + flaser([1.5, 2.5, 3.5], stamp=0.5)
    log_path = write(tmp_path, whole + 'FLASER 3 1.0 2')
    bag_path = str(tmp_path / 'cut.bag')
    run = subprocess.run([sys.executable, script, log_path, bag_path], capture_output=True, text=True, timeout=60)
    assert run.returncode == 0, run.stderr
    assert 'warning: %s:3: ' % log_path in run.stderr and 'the 2 scans before it are in the bag' in run.stderr
    assert '1 scan is stamped before the scan before it in the log (first at %s:2)' % log_path in run.stderr
    with rosbag.Bag(bag_path) as bag:
        assert [msg.header.stamp.to_sec() for _, msg, _ in bag.read_messages(topics=['/scan'])] == \
            pytest.approx([0.5, 1.0])  # stamp order: the log's second scan first
