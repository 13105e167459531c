"""The joints of a URDF robot, and the chain of joints between two of its links.

Read with ElementTree: urdf_parser_py (urdfdom_py) is not in Debian 12, and the IK and the KDL
chain need only the joints' kinematics and limits.
"""
import math
import xml.etree.ElementTree as ET
from dataclasses import dataclass
from typing import Dict, List, Optional, Tuple

Vector3 = Tuple[float, float, float]


@dataclass(frozen=True)
class UrdfJoint:
    name: str
    type: str                # revolute, continuous, prismatic, fixed, ...
    parent: str
    child: str
    xyz: Vector3             # origin of the joint frame in the parent link's frame
    rpy: Vector3             # its orientation (fixed-axis roll, pitch, yaw)
    axis: Vector3            # in the joint frame; URDF's default is x
    lower: Optional[float] = None
    upper: Optional[float] = None
    effort: Optional[float] = None
    velocity: Optional[float] = None

    @property
    def moves(self):
        return self.type in ('revolute', 'continuous', 'prismatic')


def _vector(element, attribute, default):
    if element is None or element.get(attribute) is None:
        return default
    values = tuple(float(v) for v in element.get(attribute).split())
    if len(values) != 3 or not all(math.isfinite(v) for v in values):
        raise ValueError('expected three finite numbers in %s="%s"' % (attribute, element.get(attribute)))
    return values


def _number(element, attribute):
    if element is None or element.get(attribute) is None:
        return None
    return float(element.get(attribute))


def read_joints(urdf_xml: str) -> Dict[str, UrdfJoint]:
    """Every joint of the robot, by name."""
    robot = ET.fromstring(urdf_xml)
    joints = {}
    for j in robot.findall('joint'):
        parent, child = j.find('parent'), j.find('child')
        if parent is None or child is None:
            raise ValueError('joint %s: expected <parent> and <child>' % j.get('name'))
        origin, limit = j.find('origin'), j.find('limit')
        joints[j.get('name')] = UrdfJoint(
            name=j.get('name'), type=j.get('type'), parent=parent.get('link'), child=child.get('link'),
            xyz=_vector(origin, 'xyz', (0.0, 0.0, 0.0)), rpy=_vector(origin, 'rpy', (0.0, 0.0, 0.0)),
            axis=_vector(j.find('axis'), 'xyz', (1.0, 0.0, 0.0)),
            lower=_number(limit, 'lower'), upper=_number(limit, 'upper'),
            effort=_number(limit, 'effort'), velocity=_number(limit, 'velocity'))
    return joints


def chain(joints: Dict[str, UrdfJoint], root: str, tip: str) -> List[UrdfJoint]:
    """The joints from link root down to link tip, in order (fixed ones included)."""
    by_child = {j.child: j for j in joints.values()}
    path, link = [], tip
    while link != root:
        if link not in by_child:
            raise ValueError('link %s is not below link %s' % (tip, root))
        path.append(by_child[link])
        link = by_child[link].parent
    return path[::-1]
