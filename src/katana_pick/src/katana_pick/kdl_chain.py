"""A PyKDL chain between two links of a URDF, built as kdl_parser_py builds its tree (which is
not in Debian 12): each joint becomes a segment whose joint turns about the axis at the joint's
origin, with the origin as the segment's tip frame. Used to check the IK against KDL's forward
kinematics and to compare it with KDL's numerical solvers.
"""
import PyKDL

from katana_pick.urdf_joints import chain, read_joints


def _kdl_joint(j):
    if j.type == 'fixed':
        return PyKDL.Joint(j.name, PyKDL.Joint.Fixed)
    origin = PyKDL.Frame(PyKDL.Rotation.RPY(*j.rpy), PyKDL.Vector(*j.xyz))
    axis = origin.M * PyKDL.Vector(*j.axis)
    kinds = {'revolute': PyKDL.Joint.RotAxis, 'continuous': PyKDL.Joint.RotAxis, 'prismatic': PyKDL.Joint.TransAxis}
    if j.type not in kinds:
        raise ValueError('joint %s: type %s has no KDL counterpart here' % (j.name, j.type))
    return PyKDL.Joint(j.name, origin.p, axis, kinds[j.type])


def kdl_chain(urdf_xml: str, root: str, tip: str):
    """(PyKDL.Chain from link root to link tip, [the moving joints' UrdfJoint, in chain order])."""
    joints = chain(read_joints(urdf_xml), root, tip)
    result = PyKDL.Chain()
    for j in joints:
        origin = PyKDL.Frame(PyKDL.Rotation.RPY(*j.rpy), PyKDL.Vector(*j.xyz))
        result.addSegment(PyKDL.Segment(j.child, _kdl_joint(j), origin))
    return result, [j for j in joints if j.moves]
