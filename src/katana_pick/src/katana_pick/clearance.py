"""Whether a move through the air keeps what the gripper holds (a can, or the open fingers) clear
of the cans standing on the table and of the tower.

A free move is sent as joint-space via points, which the controller interpolates joint by joint:
the tool does not follow a line, so the path is sampled in joint space and each sample's parts
placed by forward kinematics. A part is an upright cylinder: its axis, its bottom and its radius.
A carried can is one (`Held`: grasped on its axis, it keeps its pitch while carried); the open
fingers are several, along each finger where the URDF puts it (`OpenFingers`). An obstacle is an
upright can, or the tower, by its axis and top. Near an obstacle (axes closer than both radii and
the margin) a part's bottom must be above the obstacle's top by the margin.
"""
import math
from dataclasses import dataclass
from typing import Optional, Sequence, Tuple

import numpy as np

from katana_pick.arm_geometry import KatanaGeometry


@dataclass(frozen=True)
class Obstacle:
    x: float
    y: float
    top: float      # m above the table
    radius: float


@dataclass(frozen=True)
class Part:
    x: float
    y: float
    bottom: float   # m above the table
    radius: float


@dataclass(frozen=True)
class Held:
    """What hangs from the tool frame: its bottom `drop` below it, `radius` around its vertical."""
    drop: float
    radius: float

    @property
    def reach(self) -> float:
        """How far from the tool frame, sideways or down, any part reaches at most."""
        return max(self.drop, self.radius)

    def part_arrays(self, geometry: KatanaGeometry, qs: np.ndarray):
        """The parts at each row of joints qs (N x 5): x, y, bottom, radius, each N x parts."""
        x, y, z = _tool_positions(geometry, qs)
        return x[:, None], y[:, None], (z - self.drop)[:, None], np.full((len(qs), 1), self.radius)


@dataclass(frozen=True)
class OpenFingers:
    """The two fingers opened to `angle` (rad, katana_description's finger joints), as points
    along each finger's centre line, each the finger box's cross-section wide and deep as it lies
    at that pose. katana_description's numbers (a test checks them against KDL's forward
    kinematics of the URDF): the hinges 0.0573 m behind the tool frame along the gripper's axis,
    0.03 m to either side of it in the plane the roll turns, 0.08 m fingers, 0.008 x 0.02 m boxes.
    Open at 0.30 rad they reach 0.058 m to the side and only 0.019 m ahead of the tool frame: no
    one radius round the tool frame fits both (docs/KATANA.md, "Cause found")."""
    angle: float
    hinges_behind_tool: float = 0.0573
    hinge_offset: float = 0.03
    length: float = 0.08
    half_thickness: float = 0.004   # across the finger, in the plane it opens in
    half_height: float = 0.01       # along the hinge's axis
    points: int = 5                 # along each finger, hinge to tip: 0.02 m apart, under the margin

    @property
    def reach(self) -> float:
        """How far from the tool frame, sideways or down, any part reaches at most: the farther
        end of a finger's centre line (the hinge or the tip), and the box's half sizes."""
        tip = (self.length * math.cos(self.angle) - self.hinges_behind_tool,
               self.hinge_offset + self.length * math.sin(self.angle))
        return (max(math.hypot(self.hinges_behind_tool, self.hinge_offset), math.hypot(*tip))
                + self.half_thickness + self.half_height)

    def frames(self, geometry: KatanaGeometry, qs: np.ndarray):
        """Each finger link's frame at each row of joints qs (N x 5, the arm's), in
        katana_base_link: its origin at the hinge, its x along the finger, y across it, z along
        the hinge; each N x 2 (right, left) x 3."""
        x, y, z = _tool_positions(geometry, qs)
        pan, elevation, roll = qs[:, 0], qs[:, 1] + qs[:, 2] + qs[:, 3], qs[:, 4]
        zero = np.zeros_like(pan)
        radial = np.stack([np.cos(pan), np.sin(pan), zero], axis=1)
        side = np.stack([-np.sin(pan), np.cos(pan), zero], axis=1)
        vertical = np.array([0.0, 0.0, 1.0])
        axis = np.cos(elevation)[:, None] * radial + np.sin(elevation)[:, None] * vertical
        up = -np.sin(elevation)[:, None] * radial + np.cos(elevation)[:, None] * vertical
        # The roll turns the hinges' offset and their axis about the gripper's axis.
        across = np.cos(roll)[:, None] * side + np.sin(roll)[:, None] * up
        hinge_axis = -np.sin(roll)[:, None] * side + np.cos(roll)[:, None] * up
        sign = np.array([-1.0, 1.0])[None, :, None]  # the right finger at -y opens towards -y, the left towards +y
        c, s = math.cos(self.angle), math.sin(self.angle)
        tool = np.stack([x, y, z], axis=1)[:, None, :]
        hinge = tool - self.hinges_behind_tool * axis[:, None, :] + sign * self.hinge_offset * across[:, None, :]
        along = c * axis[:, None, :] + sign * s * across[:, None, :]
        thick = c * across[:, None, :] - sign * s * axis[:, None, :]
        return hinge, along, thick, np.broadcast_to(hinge_axis[:, None, :], hinge.shape)

    def fingers(self, geometry: KatanaGeometry, q: Sequence[float]):
        """frames at one pose: [(hinge, along, across, hinge axis)] for the right, then the left finger."""
        arrays = self.frames(geometry, np.array([q], dtype=float))
        return [tuple(tuple(a[0, f]) for a in arrays) for f in range(2)]

    def part_arrays(self, geometry: KatanaGeometry, qs: np.ndarray):
        hinge, along, thick, height = self.frames(geometry, qs)
        # How far the box's cross-section (x long, y thick, z high) reaches from its centre line,
        # sideways and down.
        radius = (self.half_thickness * np.hypot(thick[..., 0], thick[..., 1])
                  + self.half_height * np.hypot(height[..., 0], height[..., 1]))
        depth = self.half_thickness * np.abs(thick[..., 2]) + self.half_height * np.abs(height[..., 2])
        s = np.linspace(0.0, self.length, self.points)
        p = hinge[:, :, None, :] + s[None, None, :, None] * along[:, :, None, :]  # N x finger x point x 3
        n = len(qs)
        return (p[..., 0].reshape(n, -1), p[..., 1].reshape(n, -1),
                (p[..., 2] - depth[:, :, None]).reshape(n, -1),
                np.broadcast_to(radius[:, :, None], p.shape[:3]).reshape(n, -1))

    def parts(self, geometry: KatanaGeometry, q: Sequence[float]) -> Tuple[Part, ...]:
        return _parts_at(self, geometry, q)


def _tool_positions(geometry: KatanaGeometry, qs: np.ndarray):
    """katana_ik.forward's tool frame (x, y, z) for each row of qs, as arrays."""
    g = geometry
    upper = qs[:, 1]
    fore = upper + qs[:, 2]
    gripper = fore + qs[:, 3]
    plane_x = g.upper_arm * np.cos(upper) + g.forearm * np.cos(fore) + g.wrist_to_tool * np.cos(gripper)
    z = g.shoulder_height + g.upper_arm * np.sin(upper) + g.forearm * np.sin(fore) + g.wrist_to_tool * np.sin(gripper)
    return plane_x * np.cos(qs[:, 0]), plane_x * np.sin(qs[:, 0]), z


def _parts_at(held, geometry, q):
    x, y, bottom, radius = held.part_arrays(geometry, np.array([q], dtype=float))
    return tuple(Part(*(float(a[0, k]) for a in (x, y, bottom, radius))) for k in range(x.shape[1]))


def path_conflict(geometry: KatanaGeometry, joint_points: Sequence[Sequence[float]], held,
                  obstacles: Sequence[Obstacle], margin: float = 0.01,
                  max_joint_step: float = 0.02) -> Optional[str]:
    """None if the held thing clears every obstacle along the joint-space path through
    joint_points (straight lines between them, as the controller interpolates); else where it
    first does not, for a PlanError. held: a Held or OpenFingers, anything with part_arrays and a
    reach."""
    if not obstacles:
        return None
    for a, b in zip(joint_points, joint_points[1:]):
        a, b = np.asarray(a, dtype=float), np.asarray(b, dtype=float)
        n = max(1, int(math.ceil(np.max(np.abs(b - a)) / max_joint_step)))
        qs = a + (b - a) * (np.arange(n + 1) / n)[:, None]
        # The parts are placed only where the tool frame comes within their reach of an obstacle.
        tx, ty, tz = _tool_positions(geometry, qs)
        if not any(np.any((tz - held.reach < o.top + margin) & (np.hypot(tx - o.x, ty - o.y) < held.reach + o.radius + margin))
                   for o in obstacles):
            continue
        x, y, bottom, radius = held.part_arrays(geometry, qs)
        hit = np.zeros(x.shape + (len(obstacles),), dtype=bool)  # sample x part x obstacle
        for j, o in enumerate(obstacles):
            hit[..., j] = (np.hypot(x - o.x, y - o.y) < radius + o.radius + margin) & (bottom < o.top + margin)
        if hit.any():
            k, part, j = np.argwhere(hit)[0]  # the first sample, then part, then obstacle
            o = obstacles[j]
            return ('passes %.3f m above the top of the can at (%.3f, %.3f) (%.3f m high), at (%.3f, %.3f); '
                    'at least %.3f m needed' % (bottom[k, part] - o.top, o.x, o.y, o.top, x[k, part], y[k, part], margin))
    return None


def tower_and_cans(tower: Tuple[float, float], level: int, standing: Sequence[Tuple[float, float]],
                   can_height: float, can_radius: float) -> Tuple[Obstacle, ...]:
    """The tower (`level` cans high; none at level 0) and the cans standing on the table."""
    found = [Obstacle(x, y, can_height, can_radius) for x, y in standing]
    if level > 0:
        found.append(Obstacle(tower[0], tower[1], level * can_height, can_radius))
    return tuple(found)
