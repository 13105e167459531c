#!/usr/bin/env python3
"""PyBullet's side of the skid-steer benchmark: one vehicle, one set of wheel speeds.

  bench_skid_steer_pybullet.py URDF --torque T --joint NAME=RAD_PER_S [--joint ...] [--z 0]
      [--yaw 0] [--settle 0.5] [--seconds 4] [--window 1] [--gate CENTER,HALF [--gate-seconds 1]]
      [--trace BIN_SECONDS] [--contacts] [--implicit-cylinder]

The counterpart of src/bullet_sim_core/bench/bench_skid_steer.cpp, with the same protocol and the
same JSON line: a flat ground plane (friction 1), the URDF (xacro-expanded) with its root link
frame spawned at (0, 0, Z) heading YAW degrees, gravity -9.8, 1 ms steps. The wheels are held
at 0 rad/s for SETTLE seconds while the vehicle lands, then each --joint gets its velocity
command for up to SECONDS: a velocity motor (VELOCITY_CONTROL with its default velocity gain 1:
the same btMultiBodyJointMotor bullet_sim's setJointMotor makes) limited to T N m. Averaged are
the yaw rate and the forward speed (the root link frame's velocity along its own x) from WINDOW
seconds after the command on; with --gate only while the heading (mod 90 degrees) is within
CENTER +- HALF degrees, stopping once GATE_SECONDS of such samples are in.

Made equal to bullet_sim on purpose:
- inertias from the URDF (URDF_USE_INERTIA_FROM_FILE), fixed links merged
  (URDF_MERGE_FIXED_LINKS), no self collision, no damping (PyBullet's default 0.04 off);
- friction: every link gets the mean of its <gazebo reference><mu1>/<mu2> (default 1, as
  bullet_sim reads them; PyBullet itself ignores <gazebo>), the ground 1.0. PyBullet
  multiplies the two coefficients and bullet_sim takes the smaller; with a ground of 1 and
  links <= 1 both give the link's value. No friction anchors (PyBullet sets them only for a
  URDF <contact><friction_anchor/>, which these URDFs do not have);
- every joint without a command turns freely (its default velocity motor switched off).
Cylinders: PyBullet's loadURDF turns a URDF cylinder into a 32-sided convex hull unless
--implicit-cylinder (URDF_USE_IMPLICIT_CYLINDER) asks for Bullet's btCylinderShapeZ, the shape
bullet_sim uses. Diagnostic: --disc-cylinders L loads a copy of the URDF whose collision
cylinders are L m long, discs in their mid-plane (the Pioneer's wheels are made that way), so
that a wheel touches the ground in its mid-plane instead of on one rim edge.
"""
import argparse
import json
import math
import importlib
import os
import sys
import tempfile
import xml.etree.ElementTree as ET

from bench_pybullet import quiet  # the scripts folder: sys.path[0] when run

DT = 0.001
GRAVITY = -9.8


def gazebo_friction(root):
    """{link name: mean of <mu1>, <mu2>} from the <gazebo reference> blocks (default 1)."""
    mu = {}
    for g in root.findall('gazebo'):
        ref = g.get('reference')
        m1, m2 = g.find('mu1'), g.find('mu2')
        if not ref or (m1 is None and m2 is None):
            continue
        a = float(m1.text) if m1 is not None else 1.0
        b = float(m2.text) if m2 is not None else 1.0
        mu[ref] = 0.5 * (a + b)
    return mu


def heading_mod_90(heading):
    return math.degrees(heading) % 90.0


def parse_args():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument('urdf')
    ap.add_argument('--torque', type=float, required=True, help='motor limit per wheel (N m)')
    ap.add_argument('--joint', action='append', default=[], help='NAME=RAD_PER_S, repeatable')
    ap.add_argument('--z', type=float, default=0.0, help='spawn height of the root link frame (m)')
    ap.add_argument('--yaw', type=float, default=0.0, help='spawn heading (degrees)')
    ap.add_argument('--settle', type=float, default=0.5)
    ap.add_argument('--seconds', type=float, default=4.0)
    ap.add_argument('--window', type=float, default=1.0, help='averaging starts this long after the command')
    ap.add_argument('--gate', help='CENTER,HALF: average only at headings (mod 90 degrees) within CENTER +- HALF')
    ap.add_argument('--gate-seconds', type=float, default=1.0)
    ap.add_argument('--trace', type=float, default=0.0,
                    help='also report [t, yaw rate, forward speed, heading] in bins of this many seconds')
    ap.add_argument('--contacts', action='store_true', help='also report the contact points with the ground')
    ap.add_argument('--implicit-cylinder', action='store_true')
    ap.add_argument('--disc-cylinders', type=float, metavar='LENGTH',
                    help='diagnostic: collision cylinders shortened to LENGTH m, about their mid-plane')
    args = ap.parse_args()
    args.gate_center = args.gate_half = None
    if args.gate:
        args.gate_center, args.gate_half = (float(x) for x in args.gate.split(','))
    return args


def main():
    args = parse_args()
    p = quiet(importlib.import_module, 'pybullet')

    tree = ET.parse(args.urdf)
    root = tree.getroot()
    urdf = args.urdf
    if args.disc_cylinders:
        for cylinder in root.findall('./link/collision/geometry/cylinder'):
            cylinder.set('length', repr(args.disc_cylinders))
        handle, urdf = tempfile.mkstemp(suffix='.urdf', dir=os.path.dirname(os.path.abspath(args.urdf)))
        os.close(handle)
        tree.write(urdf)
    friction = gazebo_friction(root)
    commands = {}
    for item in args.joint:
        name, _, speed = item.partition('=')
        commands[name] = float(speed)

    c = quiet(p.connect, p.DIRECT)
    p.setGravity(0, 0, GRAVITY, physicsClientId=c)
    p.setTimeStep(DT, physicsClientId=c)
    plane = p.createMultiBody(0, p.createCollisionShape(p.GEOM_PLANE, physicsClientId=c), physicsClientId=c)
    p.changeDynamics(plane, -1, lateralFriction=1.0, physicsClientId=c)
    flags = p.URDF_USE_INERTIA_FROM_FILE | p.URDF_MERGE_FIXED_LINKS
    if args.implicit_cylinder:
        flags |= p.URDF_USE_IMPLICIT_CYLINDER
    try:
        body = quiet(p.loadURDF, urdf, basePosition=[0, 0, args.z],
                          baseOrientation=p.getQuaternionFromEuler([0, 0, math.radians(args.yaw)]),
                          flags=flags, physicsClientId=c)
    finally:
        if urdf != args.urdf:
            os.unlink(urdf)

    names = {-1: p.getBodyInfo(body, physicsClientId=c)[0].decode()}  # PyBullet link index -> URDF link
    joint_index = {}
    for j in range(p.getNumJoints(body, physicsClientId=c)):
        info = p.getJointInfo(body, j, physicsClientId=c)
        names[j] = info[12].decode()
        joint_index[info[1].decode()] = j
    missing = [n for n in commands if n not in joint_index]
    if missing:
        sys.exit('bench_skid_steer_pybullet: no joint named %s in %s' % (', '.join(missing), args.urdf))
    for link, name in names.items():
        p.changeDynamics(body, link, lateralFriction=friction.get(name, 1.0), rollingFriction=0.0,
                         spinningFriction=0.0, restitution=0.0, linearDamping=0.0, angularDamping=0.0,
                         physicsClientId=c)
    commanded = {joint_index[n] for n in commands}
    for j in range(p.getNumJoints(body, physicsClientId=c)):
        if p.getJointInfo(body, j, physicsClientId=c)[2] in (p.JOINT_REVOLUTE, p.JOINT_PRISMATIC):
            # Commanded wheels hold still while the vehicle lands; the other joints turn freely.
            p.setJointMotorControl2(body, j, p.VELOCITY_CONTROL, targetVelocity=0.0,
                                    force=args.torque if j in commanded else 0.0, physicsClientId=c)

    # PyBullet reports the base's inertial (COM) frame; the root link frame sits at this offset.
    inertial_pos, inertial_orn = p.getDynamicsInfo(body, -1, physicsClientId=c)[3:5]
    com_to_link = p.invertTransform(inertial_pos, inertial_orn)

    def root_state():
        pos, orn = p.getBasePositionAndOrientation(body, physicsClientId=c)
        lin, ang = p.getBaseVelocity(body, physicsClientId=c)
        lpos, lorn = p.multiplyTransforms(pos, orn, com_to_link[0], com_to_link[1])
        r = [lpos[i] - pos[i] for i in range(3)]
        v = [lin[0] + ang[1] * r[2] - ang[2] * r[1],
             lin[1] + ang[2] * r[0] - ang[0] * r[2],
             lin[2] + ang[0] * r[1] - ang[1] * r[0]]
        return lpos, lorn, v, ang

    settle_steps = int(round(args.settle / DT))
    steps = int(round(args.seconds / DT))
    window_start = int(round(args.window / DT))
    gate_steps = int(round(args.gate_seconds / DT))
    trace_steps = int(round(args.trace / DT)) if args.trace > 0 else 0
    for _ in range(settle_steps):
        p.stepSimulation(physicsClientId=c)
    for name, speed in commands.items():
        p.setJointMotorControl2(body, joint_index[name], p.VELOCITY_CONTROL, targetVelocity=speed,
                                force=args.torque, physicsClientId=c)

    yaw_sum = fwd_sum = lat_sum = 0.0
    zs, tilts = [], []
    trace, bin_yaw, bin_fwd = [], 0.0, 0.0
    heading = last_yaw = p.getEulerFromQuaternion(root_state()[1])[2]
    done = 0
    for i in range(steps):
        p.stepSimulation(physicsClientId=c)
        done = i + 1
        pos, orn, v, w = root_state()
        yaw = p.getEulerFromQuaternion(orn)[2]
        heading += math.remainder(yaw - last_yaw, 2 * math.pi)
        last_yaw = yaw
        hx, hy = math.cos(yaw), math.sin(yaw)
        forward = v[0] * hx + v[1] * hy
        if trace_steps:
            bin_yaw += w[2]
            bin_fwd += forward
            if (i + 1) % trace_steps == 0:
                trace.append([round((i + 1) * DT, 4), bin_yaw / trace_steps, bin_fwd / trace_steps, heading])
                bin_yaw = bin_fwd = 0.0
        if i + 1 < window_start:
            continue
        if args.gate and abs(heading_mod_90(heading) - args.gate_center) > args.gate_half:
            continue
        yaw_sum += w[2]
        fwd_sum += forward
        lat_sum += -v[0] * hy + v[1] * hx
        zs.append(pos[2])
        tilts.append(math.acos(max(-1.0, min(1.0, p.getMatrixFromQuaternion(orn)[8]))))
        if args.gate and len(zs) >= gate_steps and not trace_steps:
            break
    n = len(zs)
    out = {'engine': 'pybullet' + ('-implicit-cylinder' if args.implicit_cylinder else '') +
                     ('-disc-cylinders' if args.disc_cylinders else ''),
           'samples': n, 'end_time': done * DT}
    if n:
        z_mean = sum(zs) / n
        out.update({
            'yaw_rate': yaw_sum / n,
            'forward_speed': fwd_sum / n,
            'lateral_speed': lat_sum / n,
            'z_mean': z_mean,
            'z_std': math.sqrt(sum((z - z_mean) ** 2 for z in zs) / n),
            'z_ptp': max(zs) - min(zs),
            'tilt_max': max(tilts),
        })
    else:
        out.update({'yaw_rate': None, 'forward_speed': None})
    if trace_steps:
        out['trace'] = trace
    if args.contacts:
        per_link = {}
        for cp in p.getContactPoints(bodyA=body, bodyB=plane, physicsClientId=c):
            entry = per_link.setdefault(names[cp[3]], {'points': 0, 'normal_force': 0.0, 'list': []})
            entry['points'] += 1
            entry['normal_force'] += cp[9]
            entry['list'].append({'world': [round(x, 5) for x in cp[5]], 'depth': cp[8], 'normal_force': cp[9]})
        out['contacts'] = per_link
    p.disconnect(c)
    print(json.dumps(out))


if __name__ == '__main__':
    main()
