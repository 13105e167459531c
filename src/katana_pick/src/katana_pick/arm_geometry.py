"""The Katana 450 6M90A's dimensions and joint limits as the IK needs them, and reading them
from the robot's URDF (katana_description), which also checks that the URDF has the shape the
IK assumes: a pan axis, three parallel lift axes and a tool frame on the roll axis.
"""
import math
from dataclasses import dataclass
from typing import Tuple

from katana_pick.urdf_joints import chain, read_joints

BASE_LINK = 'katana_base_link'
TOOL_FRAME = 'katana_gripper_tool_frame'
ARM_JOINTS = ('katana_motor1_pan_joint', 'katana_motor2_lift_joint', 'katana_motor3_lift_joint',
              'katana_motor4_lift_joint', 'katana_motor5_wrist_roll_joint')

# Axes in the joints' own frames, as katana_description writes them: the lift axes are -y so that
# positive angles lift (the upper arm's angle is its elevation, as in the tutorial).
_EXPECTED_AXES = ((0.0, 0.0, 1.0), (0.0, -1.0, 0.0), (0.0, -1.0, 0.0), (0.0, -1.0, 0.0), (1.0, 0.0, 0.0))
_TOLERANCE = 1e-9


@dataclass(frozen=True)
class JointLimits:
    lower: float
    upper: float


@dataclass(frozen=True)
class KatanaGeometry:
    """Lengths in metres; katana_description's numbers (a test checks that they agree)."""
    shoulder_height: float = 0.2015   # base to the lift axis of motor 2
    upper_arm: float = 0.19           # motor 2 to motor 3
    forearm: float = 0.139            # motor 3 to motor 4
    wrist_to_tool: float = 0.1473     # motor 4 to the tool frame, along the gripper's axis
    limits: Tuple[JointLimits, ...] = (JointLimits(-3.025, 2.891), JointLimits(-0.135, 2.168),
                                       JointLimits(-2.221, 2.054), JointLimits(-2.033, 1.876),
                                       JointLimits(-2.993, 2.871))
    joint_names: Tuple[str, ...] = ARM_JOINTS


def _close(a, b):
    return all(abs(x - y) <= _TOLERANCE for x, y in zip(a, b))


def geometry_from_urdf(urdf_xml: str) -> KatanaGeometry:
    """The geometry of the arm in a URDF string; ValueError says what does not fit the IK."""
    path = chain(read_joints(urdf_xml), BASE_LINK, TOOL_FRAME)
    moving = [j for j in path if j.type != 'fixed']
    if tuple(j.name for j in moving) != ARM_JOINTS:
        raise ValueError('expected the joints %s from %s to %s, found %s'
                         % (', '.join(ARM_JOINTS), BASE_LINK, TOOL_FRAME, ', '.join(j.name for j in moving)))
    for j, axis in zip(moving, _EXPECTED_AXES):
        if j.type != 'revolute' or not _close(j.axis, axis):
            raise ValueError('%s: expected a revolute joint about %s, found %s about %s'
                             % (j.name, axis, j.type, j.axis))
        if j.lower is None or j.upper is None or not j.lower < j.upper:
            raise ValueError('%s: expected lower < upper limits' % j.name)
    for j in path:
        if not _close(j.rpy, (0.0, 0.0, 0.0)):
            raise ValueError('%s: expected no rotation in its origin, found rpy %s' % (j.name, j.rpy))
    if path[:len(moving)] != moving:
        raise ValueError('expected only fixed joints after %s, found %s'
                         % (ARM_JOINTS[-1], ', '.join(j.name for j in path)))
    pan, shoulder, elbow, wrist = path[0], path[1], path[2], path[3]
    if not _close(pan.xyz[:2], (0.0, 0.0)):
        raise ValueError('%s: expected it on the base\'s z axis, found origin %s' % (pan.name, pan.xyz))
    if not _close(shoulder.xyz, (0.0, 0.0, 0.0)):
        raise ValueError('%s: expected it at the pan joint, found origin %s' % (shoulder.name, shoulder.xyz))
    # Everything from the elbow on lies along the arm's x axis.
    for j in path[2:]:
        if not _close(j.xyz[1:], (0.0, 0.0)):
            raise ValueError('%s: expected its origin on the x axis of %s, found %s' % (j.name, j.parent, j.xyz))
    return KatanaGeometry(shoulder_height=pan.xyz[2], upper_arm=elbow.xyz[0], forearm=wrist.xyz[0],
                          wrist_to_tool=sum(j.xyz[0] for j in path[4:]),
                          limits=tuple(JointLimits(j.lower, j.upper) for j in moving))


def reach(geometry: KatanaGeometry) -> float:
    """How far the tool frame can be from the shoulder axis: the arm stretched out."""
    return geometry.upper_arm + geometry.forearm + geometry.wrist_to_tool


def within_limits(geometry: KatanaGeometry, q, tolerance=1e-9) -> bool:
    return all(lim.lower - tolerance <= v <= lim.upper + tolerance and math.isfinite(v)
               for v, lim in zip(q, geometry.limits))
