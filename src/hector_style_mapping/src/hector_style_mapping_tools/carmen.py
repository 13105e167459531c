"""CARMEN laser logs (the format of Radish's datasets) read into scans with their logged poses.

A log is text, one message per line. The laser lines are

  FLASER n r1 .. rn x y theta odom_x odom_y odom_theta timestamp host logger_timestamp
  ROBOTLASER1 type start_angle fov resolution max_range accuracy remission_mode n r1 .. rn
              m v1 .. vm laser_x laser_y laser_theta x y theta tv rv fwd side turn timestamp host logger_timestamp

(RLASER is FLASER's rear twin). FLASER carries no scanner geometry: n readings over 180 degrees from
-90 degrees counter-clockwise, CARMEN's guess, 1 degree apart for 180 or 181 beams, 0.5 for 360 or
361. `x y theta` is the laser's pose in the log's world frame; in Radish's "corrected" logs that
pose was corrected by the authors' SLAM and serves as ground truth. Other lines (ODOM, PARAM, NEFF,
comments) are skipped, except PARAM robot_frontlaser_offset and robot_rearlaser_offset (the
lasers' distances ahead of and behind the robot's centre).

A log cut short (a last line without its end, or a .gz that stops early, as an interrupted download
leaves it) keeps the scans before the cut and says where it was cut (`CarmenLog.truncated`); a
malformed line anywhere else is an error. Stamps that go back are kept as logged and counted
(`CarmenLog.stamps_back`; the Intel log has 4, by up to 0.9 s): a bag plays them in stamp order.
"""
import gzip
import math
from dataclasses import dataclass, field
from typing import List, Optional


class CarmenLogError(ValueError):
    """A line that is not what its message type says: names the file, line and field."""


@dataclass
class CarmenScan:
    stamp: float                 # s: the message's timestamp field
    ranges: List[float]          # m, in beam order
    angle_min: float             # rad
    angle_increment: float       # rad
    laser_pose: tuple            # (x, y, theta) of the laser in the log's world frame
    robot_pose: tuple            # (x, y, theta) of the robot (base) in the log's world frame
    max_range: Optional[float] = None  # m, when the line says (ROBOTLASER1)
    kind: str = 'FLASER'
    line: int = 0                # its line in the log


@dataclass
class CarmenLog:
    scans: List[CarmenScan] = field(default_factory=list)
    front_laser_offset: float = 0.0  # m the front laser sits ahead of the robot's centre
    rear_laser_offset: float = 0.0   # m the rear laser sits behind it
    skipped: int = 0                 # lines of other types
    truncated: Optional[str] = None  # where and how the log was cut short, if it was
    stamps_back: List[int] = field(default_factory=list)  # lines of scans stamped before the scan before them


def flaser_increment(n):
    """CARMEN's guess at an old-style scan's beam spacing: 180 degrees over n beams, 1 or 0.5 degree
    for the SICK's 180/181 and 360/361 beam modes (an odd count has a beam at each end)."""
    return math.pi / (n - 1 if n % 2 == 1 else n)


def _numbers(words, first, count, where, what):
    if first + count > len(words):
        raise CarmenLogError('%s: %s: expected %d numbers from field %d, the line has only %d fields'
                             % (where, what, count, first + 1, len(words)))
    try:
        return [float(w) for w in words[first:first + count]]
    except ValueError as e:
        raise CarmenLogError('%s: %s: expected numbers: %s' % (where, what, e)) from None


def _count(words, index, where, what):
    try:
        n = int(words[index])
    except (IndexError, ValueError):
        raise CarmenLogError('%s: %s: expected a beam count in field %d' % (where, what, index + 1)) from None
    if n < 2:
        raise CarmenLogError('%s: %s: expected at least 2 beams, got %d' % (where, what, n))
    return n


def _flaser(words, where, laser_offset):
    n = _count(words, 1, where, words[0])
    ranges = _numbers(words, 2, n, where, words[0] + ' ranges')
    x, y, theta, _, _, _, stamp = _numbers(words, 2 + n, 7, where, words[0] + ' pose and timestamp')
    # The logged pose is the laser's, looking ahead of (FLASER) or behind (RLASER) the robot, whose
    # centre is laser_offset behind the laser along the laser's heading.
    robot_theta = theta if words[0] == 'FLASER' else theta - math.pi
    robot = (x - laser_offset * math.cos(theta), y - laser_offset * math.sin(theta),
             math.atan2(math.sin(robot_theta), math.cos(robot_theta)))
    return CarmenScan(stamp, ranges, -math.pi / 2, flaser_increment(n), (x, y, theta), robot, None, words[0])


def _robotlaser1(words, where):
    start, _, resolution, max_range = _numbers(words, 2, 4, where, 'ROBOTLASER1 scanner geometry')
    n = _count(words, 8, where, 'ROBOTLASER1')
    ranges = _numbers(words, 9, n, where, 'ROBOTLASER1 ranges')
    try:
        m = int(words[9 + n])
    except (IndexError, ValueError):
        raise CarmenLogError('%s: ROBOTLASER1: expected the remission count after the %d ranges' % (where, n)) from None
    if m < 0:
        raise CarmenLogError('%s: ROBOTLASER1: expected a remission count >= 0, got %d' % (where, m))
    rest = 10 + n + m
    lx, ly, lt, rx, ry, rt = _numbers(words, rest, 6, where, 'ROBOTLASER1 laser and robot poses')
    (stamp,) = _numbers(words, rest + 11, 1, where, 'ROBOTLASER1 timestamp')
    return CarmenScan(stamp, ranges, start, resolution, (lx, ly, lt), (rx, ry, rt), max_range, 'ROBOTLASER1')


def _scan(words, where, log, lasers):
    """The scan on a line of one of `lasers`' types, None for any other line (PARAMs are noted in `log`)."""
    if words[0] == 'PARAM' and len(words) >= 3 and words[1] == 'robot_frontlaser_offset':
        log.front_laser_offset = _numbers(words, 2, 1, where, 'PARAM robot_frontlaser_offset')[0]
    elif words[0] == 'PARAM' and len(words) >= 3 and words[1] == 'robot_rearlaser_offset':
        log.rear_laser_offset = _numbers(words, 2, 1, where, 'PARAM robot_rearlaser_offset')[0]
    elif words[0] in lasers and words[0] == 'FLASER':
        return _flaser(words, where, log.front_laser_offset)
    elif words[0] in lasers and words[0] == 'RLASER':
        return _flaser(words, where, log.rear_laser_offset)
    elif words[0] in lasers and words[0] == 'ROBOTLASER1':
        return _robotlaser1(words, where)
    else:
        log.skipped += 1
    return None


def read_log(path, lasers=('FLASER', 'ROBOTLASER1')):
    """The laser scans of a CARMEN log (plain or .gz), in file order. `lasers`: the message types to
    take (RLASER too if asked). Raises CarmenLogError naming the file and line of a malformed one,
    except a last line cut short (see the module's doc)."""
    log = CarmenLog()
    opener = gzip.open if path.endswith('.gz') else open
    number = 0
    try:
        with opener(path, 'rt', errors='replace') as f:
            for number, line in enumerate(f, 1):
                words = line.split()
                if not words or words[0].startswith('#'):
                    continue
                where = '%s:%d' % (path, number)
                try:
                    scan = _scan(words, where, log, lasers)
                except CarmenLogError as e:
                    if line.endswith('\n'):
                        raise
                    log.truncated = '%s (the file ends in this line: cut short?)' % e
                    break
                if scan is None:
                    continue
                scan.line = number
                if log.scans and scan.stamp < log.scans[-1].stamp:
                    log.stamps_back.append(number)
                log.scans.append(scan)
    except EOFError as e:  # gzip: the compressed stream stops early
        log.truncated = '%s: the compressed file ends early, after line %d (%s)' % (path, number, e)
    return log


def saturation_range(log):
    """The range a scanner reports for "no return" when the log does not say: the largest reading
    in the log (SICK scanners report their maximum, 81.83 m in the Intel log, 50 m in ACES')."""
    largest = [max(finite) for finite in ([r for r in s.ranges if math.isfinite(r)]
                                          for s in log.scans if s.max_range is None) if finite]
    return max(largest) if largest else None
