"""Analytic inverse kinematics of the Katana 450 6M90A by the tutorial's triangle method.

The target is the tool frame's position (x, y, z in katana_base_link) and the gripper's pitch:
the elevation of the gripper's axis above the horizontal, its horizontal part pointing away from
the base's axis (-pi/2 points straight down, 0 straight out, pi/2 up, beyond +-pi/2 back towards
the base). The five arm joints give the tool position, the pitch and a roll about the gripper's
axis, which does not move the tool frame: the roll is free (kept from the seed unless given).

How: the pan turns the arm's vertical plane to the target. In that plane the wrist axis lies
wrist_to_tool behind the tool frame along the gripper's axis; shoulder, elbow and wrist make a
triangle with sides upper arm, forearm and the shoulder-wrist distance, whose angles come from
the law of cosines (the tutorial's alpha at the shoulder and beta at the elbow). The wrist lift
then makes the lift angles add up to the pitch. Unlike the tutorial, which approximates the
gripper by a fixed bend, this solves for the tool frame exactly.

Branches: elbow up or down, each with the pan towards the target or turned by pi with the arm
leaning back over its base (the shoulder flipped); an angle may also be shifted by 2 pi if that
keeps it inside its limits. Of the solutions within all joint limits, the one closest to the seed
is returned; when there is none, IkError says why (out of reach by how much, or which joint limit).

Joint angles follow katana_description: zero is the arm stretched out along x, positive lift
angles lift, and the three lift angles add up to the gripper's pitch.
"""
import math
from typing import List, Optional, Sequence, Tuple

from katana_pick.arm_geometry import KatanaGeometry

_TWO_PI = 2.0 * math.pi
# Rounding in a target made by forward kinematics can put a stretched arm a few 1e-16 m out of
# reach, or a joint a few 1e-16 rad past its limit; within this, it counts as reachable.
_SLACK = 1e-9


class IkError(ValueError):
    """No joint angles put the tool frame on the target; the message says why."""


def _finite(name, value):
    try:
        v = float(value)
    except (TypeError, ValueError):
        raise IkError('%s is %r: expected a number' % (name, value)) from None
    if not math.isfinite(v):
        raise IkError('%s is %s: expected a finite number' % (name, v))
    return v


def _fit_into_limits(value, lower, upper, seed):
    """value, or value shifted by whole turns, inside [lower, upper] and closest to seed; None if no
    shift fits."""
    k_low = math.ceil((lower - _SLACK - value) / _TWO_PI)
    k_high = math.floor((upper + _SLACK - value) / _TWO_PI)
    if k_low > k_high:
        return None
    best = None
    for k in range(k_low, k_high + 1):
        v = min(max(value + k * _TWO_PI, lower), upper)
        if best is None or abs(v - seed) < abs(best - seed):
            best = v
    return best


def _limit_excess(value, lower, upper):
    """How far value (over all its whole-turn shifts) stays outside [lower, upper], in rad."""
    centre = 0.5 * (lower + upper)
    v = centre + math.remainder(value - centre, _TWO_PI)
    return max(lower - v, v - upper, 0.0)


def _triangle_branches(g: KatanaGeometry, x, y, z, pitch, pan_seed):
    """Raw (pan, lift2, lift3, lift4) of each branch that the arm's lengths allow, with its name,
    and for each branch they do not allow, how far out of reach the wrist centre is (m)."""
    a, b, c = g.upper_arm, g.forearm, g.wrist_to_tool
    radial = math.hypot(x, y)
    # On the pan axis every pan angle is as good: keep the seed's.
    pan = math.atan2(y, x) if radial > 1e-12 else pan_seed
    solutions, misses = [], []
    for flipped in (False, True):
        # Leaning back, the target lies behind the arm's plane origin and the pitch is mirrored.
        plane_pan = pan + math.pi if flipped else pan
        plane_x = -radial if flipped else radial
        elevation = math.pi - pitch if flipped else pitch
        # The wrist centre, in the arm's plane, from the shoulder.
        wx = plane_x - c * math.cos(elevation)
        wz = z - g.shoulder_height - c * math.sin(elevation)
        d = math.hypot(wx, wz)
        if d > a + b + _SLACK or d < abs(a - b) - _SLACK:
            misses.append((d, d - (a + b) if d > a + b else d - abs(a - b)))
            continue
        d = min(max(d, abs(a - b), 1e-12), a + b)
        # The tutorial's triangle: alpha at the shoulder, beta at the elbow (law of cosines).
        alpha = math.acos(min(1.0, max(-1.0, (a * a + d * d - b * b) / (2 * a * d))))
        beta = math.acos(min(1.0, max(-1.0, (a * a + b * b - d * d) / (2 * a * b))))
        gamma = math.atan2(wz, wx)  # the wrist's elevation seen from the shoulder (the tutorial's -dip)
        for elbow_up in (True, False):
            s = 1.0 if elbow_up else -1.0
            lift2 = gamma + s * alpha
            lift3 = -s * (math.pi - beta)
            lift4 = elevation - lift2 - lift3
            name = ('elbow up' if elbow_up else 'elbow down') + (', shoulder flipped' if flipped else '')
            solutions.append((name, (plane_pan, lift2, lift3, lift4)))
    return solutions, misses


def solutions(g: KatanaGeometry, x, y, z, pitch, seed: Sequence[float] = (0.0,) * 5,
              roll: Optional[float] = None) -> List[Tuple[str, Tuple[float, ...]]]:
    """Every branch's joint angles (5) within the joint limits, named ('elbow up', 'elbow down,
    shoulder flipped', ...), each shifted by whole turns to lie closest to the seed; the closest
    to the seed first."""
    return _solve(g, x, y, z, pitch, seed, roll)[0]


def solve(g: KatanaGeometry, x, y, z, pitch, seed: Sequence[float] = (0.0,) * 5,
          roll: Optional[float] = None, flipped: Optional[bool] = None) -> Tuple[float, ...]:
    """The five arm joint angles that put the tool frame at (x, y, z) with the given pitch,
    within the joint limits and closest to seed; IkError if there are none. flipped, if given:
    only the branches with the shoulder flipped (True) or not (False)."""
    found, why_not = _solve(g, x, y, z, pitch, seed, roll)
    if flipped is not None and found:
        kept = [f for f in found if ('shoulder flipped' in f[0]) == flipped]
        if not kept:
            why_not = ('target (%.3f, %.3f, %.3f) m with pitch %.3f rad is reachable only with the shoulder %s '
                       '(%s), which would turn the gripper half a turn about its axis'
                       % (x, y, z, pitch, 'not flipped' if flipped else 'flipped', found[0][0]))
        found = kept
    if not found:
        raise IkError(why_not)
    return found[0][1]


def is_flipped(g: KatanaGeometry, q: Sequence[float]) -> bool:
    """Whether the arm leans over its base (the shoulder flipped): the tool frame behind the
    plane the pan joint turns the arm in."""
    upper, fore, gripper = q[1], q[1] + q[2], q[1] + q[2] + q[3]
    return g.upper_arm * math.cos(upper) + g.forearm * math.cos(fore) + g.wrist_to_tool * math.cos(gripper) < 0


def _solve(g, x, y, z, pitch, seed, roll):
    x, y, z, pitch = (_finite(n, v) for n, v in (('target x', x), ('target y', y), ('target z', z),
                                                 ('target pitch', pitch)))
    if len(seed) != 5:
        raise IkError('seed has %d angles: expected 5 (%s)' % (len(seed), ', '.join(g.joint_names)))
    seed = [_finite('seed ' + name, v) for name, v in zip(g.joint_names, seed)]
    roll = seed[4] if roll is None else _finite('target roll', roll)
    target = 'target (%.3f, %.3f, %.3f) m with pitch %.3f rad' % (x, y, z, pitch)

    branches, misses = _triangle_branches(g, x, y, z, pitch, seed[0])
    if not branches:
        d, excess = min(misses, key=lambda m: abs(m[1]))
        a, b = g.upper_arm, g.forearm
        return [], ('%s is out of reach by %.3f m: the wrist axis would be %.3f m from the shoulder, '
                    'and the upper arm and forearm reach from %.3f to %.3f m'
                    % (target, abs(excess), d, abs(a - b), a + b))

    found, violations = [], []
    for name, raw in branches:
        q, violation = [], None
        for i, value in enumerate(raw + (roll,)):
            lim = g.limits[i]
            fitted = _fit_into_limits(value, lim.lower, lim.upper, seed[i])
            if fitted is None:
                violation = '%s needs %s = %.3f rad, %.3f rad outside [%.3f, %.3f]' % (
                    name, g.joint_names[i], math.remainder(value, _TWO_PI),
                    _limit_excess(value, lim.lower, lim.upper), lim.lower, lim.upper)
                break
            q.append(fitted)
        if violation:
            violations.append(violation)
        else:
            found.append((name, tuple(q)))
    found.sort(key=lambda named: sum((v - s) ** 2 for v, s in zip(named[1], seed)))
    return found, '%s is reachable only outside the joint limits: %s' % (target, '; '.join(violations))


def forward(g: KatanaGeometry, q: Sequence[float]) -> Tuple[float, float, float, float]:
    """The tool frame's (x, y, z) in katana_base_link and the gripper's pitch for the arm's
    joint angles q (5; the roll does not move the tool frame)."""
    pan = q[0]
    # Elevations of the upper arm, the forearm and the gripper's axis in the arm's plane.
    upper, fore, gripper = q[1], q[1] + q[2], q[1] + q[2] + q[3]
    plane_x = g.upper_arm * math.cos(upper) + g.forearm * math.cos(fore) + g.wrist_to_tool * math.cos(gripper)
    z = (g.shoulder_height + g.upper_arm * math.sin(upper) + g.forearm * math.sin(fore)
         + g.wrist_to_tool * math.sin(gripper))
    # Pitch counts the horizontal part of the gripper's axis as positive away from the base's
    # axis, so a tool frame behind the arm's plane origin mirrors it.
    pitch = gripper if plane_x >= 0 else math.pi - gripper
    return plane_x * math.cos(pan), plane_x * math.sin(pan), z, math.remainder(pitch, _TWO_PI)


def gripper_pitch(x, y, direction: Sequence[float]) -> float:
    """The pitch (as solve takes it) of a gripper whose axis points along direction (3 numbers,
    in katana_base_link) with its tool frame at (x, y, ...)."""
    dx, dy, dz = direction
    radial = math.hypot(x, y)
    outward = (dx * x + dy * y) / radial if radial > 1e-12 else math.hypot(dx, dy)
    return math.atan2(dz, outward)
