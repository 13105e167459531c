"""Whether a move through the air keeps what the gripper holds (a can, or the open fingers) clear
of the cans standing on the table and of the tower.

A free move is sent as joint-space via points, which the controller interpolates joint by joint:
the tool does not follow a line, so the path is sampled in joint space and each sample's tool
position taken by forward kinematics. What hangs from the gripper is modelled as an upright
cylinder on the tool frame's vertical (the can is grasped on its axis and keeps its pitch while
carried): its bottom `drop` below the tool frame, `radius` wide. An obstacle is an upright can,
or the tower, by its axis and top. Near an obstacle (axes closer than both radii and the margin)
the held thing's bottom must be above the obstacle's top by the margin.
"""
import math
from dataclasses import dataclass
from typing import Optional, Sequence, Tuple

from katana_pick import katana_ik
from katana_pick.arm_geometry import KatanaGeometry


@dataclass(frozen=True)
class Obstacle:
    x: float
    y: float
    top: float      # m above the table
    radius: float


@dataclass(frozen=True)
class Held:
    """What hangs from the tool frame: its bottom `drop` below it, `radius` around its vertical."""
    drop: float
    radius: float


def path_conflict(geometry: KatanaGeometry, joint_points: Sequence[Sequence[float]], held: Held,
                  obstacles: Sequence[Obstacle], margin: float = 0.01,
                  max_joint_step: float = 0.02) -> Optional[str]:
    """None if the held thing clears every obstacle along the joint-space path through
    joint_points (straight lines between them, as the controller interpolates); else where it
    does not, for a PlanError."""
    for a, b in zip(joint_points, joint_points[1:]):
        n = max(1, int(math.ceil(max(abs(u - v) for u, v in zip(a, b)) / max_joint_step)))
        for k in range(n + 1):
            q = [u + (v - u) * k / n for u, v in zip(a, b)]
            x, y, z, _ = katana_ik.forward(geometry, q)
            bottom = z - held.drop
            for o in obstacles:
                if math.hypot(x - o.x, y - o.y) < held.radius + o.radius + margin and bottom < o.top + margin:
                    return ('passes %.3f m above the top of the can at (%.3f, %.3f) (%.3f m high), at (%.3f, %.3f); '
                            'at least %.3f m needed' % (bottom - o.top, o.x, o.y, o.top, x, y, margin))
    return None


def tower_and_cans(tower: Tuple[float, float], level: int, standing: Sequence[Tuple[float, float]],
                   can_height: float, can_radius: float) -> Tuple[Obstacle, ...]:
    """The tower (`level` cans high; none at level 0) and the cans standing on the table."""
    found = [Obstacle(x, y, can_height, can_radius) for x, y in standing]
    if level > 0:
        found.append(Obstacle(tower[0], tower[1], level * can_height, can_radius))
    return tuple(found)
