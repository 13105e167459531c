#!/usr/bin/env python3
"""Skid-steer (and diff-drive) turning, bullet_sim against PyBullet, side by side.

  scripts/bench_skid_steer.py [--vehicles m_robot,re510,skid4,pioneer] [--cases turn,straight,arc]
      [--seconds 30] [--jobs 2] [--json FILE] [--ours PATH] [--no-hull] [--show-commands]

Run after `. scripts/env.sh` (xacro finds the description packages through ROS_PACKAGE_PATH;
`scripts/setup --bench` makes the venv with PyBullet and builds bench_skid_steer). Each vehicle
(the URDF its launch files spawn, xacro-expanded) is driven by its own <gazebo> drive plugin's
numbers: the wheel joints, wheelSeparation, wheelDiameter and torque. For each case the wheel
speeds are the plugin's, (v -+ w * separation / 2) / (diameter / 2), left minus, commanded as
velocity motors with the plugin's torque from 0.5 s after the spawn on, in
  ours:     src/bullet_sim_core/bench/bench_skid_steer (bullet_sim's PhysicsWorld),
  pybullet: scripts/bench_skid_steer_pybullet.py --implicit-cylinder (the URDF's cylinders as
            Bullet cylinders, the shape bullet_sim uses),
  hull:     the same without --implicit-cylinder (PyBullet's default 32-sided hulls; shown, not
            judged),
  disc:     pybullet with the collision cylinders cut to 2 mm discs about their mid-plane, as
            the Pioneer's wheels are made (--disc-cylinders 0.002): a Bullet cylinder lying on
            the floor touches it on one rim edge, a disc in its mid-plane, which is where
            bullet_sim's cylinder contact puts a level wheel's. The judged reference by default
            (--reference disc): on one rim edge, PyBullet's wide wheels push the RE510 sideways
            and forward while it turns on the spot (-0.10 m/s, where a symmetric vehicle cannot
            move), which is a fault of the reference, not physics; --reference cylinder judges
            against the 'pybullet' runs instead,
all with the same ground (friction 1), the same link friction (<mu1>/<mu2>), 1 ms steps.

Why the heading columns. In Bullet's Featherstone solver (PyBullet's, and bullet_sim's before
the fix) every contact gets its two friction directions from the contact normal alone (world x
and y on a flat floor) and the friction cone is applied to the two impulses each scaled by its
own row's effective mass. A wheel's longitudinal row is light (the wheel can spin) and its
lateral row heavy (the whole vehicle has to move), so when those rows line up with the wheels
the clamped friction points sideways and a skid steer hardly turns; at 45 degrees both rows
see the same mix and the friction opposes the slip, as Coulomb's law has it. PyBullet's yaw
rate therefore repeats every 90 degrees of heading. So every turn and arc is run for SECONDS
from heading 0 (as the robots are spawned) and averaged separately over the times the heading
(mod 90) is within 45 +- 7.5 degrees ('@45') and within 0 +- 7.5 degrees ('@0'), from 1 s after
the command on. Straight runs keep their heading 0 and are averaged from 1 s to the end.

The verdict compares ours at 0 degrees (what every test and launch file sees) and at 45 degrees
with PyBullet at 45 degrees, the heading where PyBullet's friction treats the wheels' two
directions alike: PASS when within +-10 %. A quantity commanded zero (the forward speed of a
turn on the spot, the yaw rate of a straight run) passes when the two differ by less than 10 %
of the wheels' rim speed (resp. of that rim speed over half the separation). The 'coulomb'
column of a turn on the spot is the rigid-body answer with Coulomb friction and equal wheel
loads: w_cmd / (1 + (L/B)^2) for wheels at +-L along and +-B across (a turn rate is lower than
commanded because the wheels must slide sideways: that is physics, not a fault).
"""
import argparse
import concurrent.futures
import json
import math
import os
import shlex
import subprocess
import sys
import tempfile
import xml.etree.ElementTree as ET

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
OURS = os.path.join(ROOT, 'devel', 'lib', 'bullet_sim_core', 'bench_skid_steer')
PYBULLET_SCRIPT = os.path.join(ROOT, 'scripts', 'bench_skid_steer_pybullet.py')
VENV_PYTHON = os.path.join(ROOT, '.venv', 'bin', 'python3')
XACRO = os.path.join(ROOT, '.venv', 'bin', 'xacro')

# Vehicle: its description and the height its launch file spawns it at (m).
VEHICLES = {
    'm_robot': ('src/m_robot_description/urdf/m_robot.xacro', 0.1),
    're510': ('src/simple_vehicle_description/urdf/simple_vehicle.xacro', 0.0),
    'skid4': ('src/bullet_sim_core/bench/skid4.urdf', 0.0),
    'pioneer': ('src/pioneer_gazebo_ros/pioneer_description/urdf/pioneer3dx.xacro', 0.0),
}
# Case: (forward speed m/s, yaw rate rad/s) of the cmd_vel.
CASES = {'turn': (0.0, 0.5), 'straight': (0.3, 0.0), 'arc': (0.3, 0.3)}
SETTLE = 0.5      # s the wheels are held while the vehicle lands
WINDOW = 1.0      # s after the command before averaging
TRACE_BIN = 0.01  # s
GATE_HALF = 7.5   # degrees
MIN_GATED = 0.5   # s of samples a gated mean needs
TOLERANCE = 0.10


def expand(vehicle, outdir):
    path, z = VEHICLES[vehicle]
    src = os.path.join(ROOT, path)
    if not src.endswith('.xacro'):
        return src, z
    out = os.path.join(outdir, vehicle + '.urdf')
    xacro = XACRO if os.path.exists(XACRO) else 'xacro'
    with open(out, 'w') as f:
        subprocess.run([xacro, src], stdout=f, check=True)
    return out, z


def drive_of(urdf):
    """The drive plugin's wheels and numbers: (left joints, right joints, separation, diameter,
    torque, kind), with gazebo_plugins' parameter names."""
    root = ET.parse(urdf).getroot()
    for plugin in root.iter('plugin'):
        fn = plugin.get('filename', '')
        get = lambda tag, default=None: (plugin.find(tag).text.strip() if plugin.find(tag) is not None else default)
        if 'skid_steer' in fn:
            left = [get('leftFrontJoint'), get('leftRearJoint')]
            right = [get('rightFrontJoint'), get('rightRearJoint')]
            torque = float(get('torque', '15'))
            kind = 'skid steer'
        elif 'diff_drive' in fn:
            left, right = [get('leftJoint')], [get('rightJoint')]
            torque = float(get('wheelTorque', get('torque', '5')))
            kind = 'diff drive'
        else:
            continue
        return left, right, float(get('wheelSeparation')), float(get('wheelDiameter')), torque, kind, root
    sys.exit('bench_skid_steer: no skid steer or diff drive plugin in ' + urdf)


def coulomb_turn(root, left, right, w_cmd):
    """Rigid-body turn-on-the-spot rate with Coulomb friction and equal loads, or None when the
    wheels are not a symmetric four (a diff drive turns at the commanded rate)."""
    origins = {}
    for j in root.findall('joint'):
        o = j.find('origin')
        xyz = [float(v) for v in (o.get('xyz', '0 0 0') if o is not None else '0 0 0').split()]
        origins[j.get('name')] = xyz
    wheels = [origins.get(n) for n in left + right]
    if len(wheels) != 4 or None in wheels:
        return w_cmd
    half_l = sum(abs(w[0]) for w in wheels) / 4
    half_b = sum(abs(w[1]) for w in wheels) / 4
    return w_cmd / (1 + (half_l / half_b) ** 2)


def engine_command(engine, urdf, z, torque, speeds, seconds, ours):
    args = [urdf, '--z', repr(z), '--torque', repr(torque), '--settle', repr(SETTLE),
            '--seconds', repr(seconds), '--window', '0', '--trace', repr(TRACE_BIN)]
    for joint, speed in speeds:
        args += ['--joint', '%s=%.9g' % (joint, speed)]
    if engine == 'ours':
        return [ours] + args
    python = VENV_PYTHON if os.path.exists(VENV_PYTHON) else sys.executable
    extra = {'pybullet': ['--implicit-cylinder'], 'hull': [],
             'disc': ['--implicit-cylinder', '--disc-cylinders', '0.002']}[engine]
    return [python, PYBULLET_SCRIPT] + args + extra


def run(cmd):
    out = subprocess.run(cmd, capture_output=True, text=True)
    lines = [l for l in out.stdout.splitlines() if l.startswith('{')]
    if out.returncode != 0 or not lines:
        raise RuntimeError('%s failed (%d): %s' % (shlex.join(cmd), out.returncode, out.stderr.strip()[-400:]))
    return json.loads(lines[-1])


def averages(trace, gate_center):
    """Means of yaw rate and forward speed over the bins from WINDOW s after the command on,
    if gate_center is set only those with heading (mod 90) within gate_center +- GATE_HALF."""
    rows = []
    for t, yaw_rate, forward, heading in trace:
        if t < WINDOW - 1e-9:
            continue
        if gate_center is not None:
            h = math.degrees(heading) % 90.0
            if abs(h - gate_center) > GATE_HALF and abs(h - 90.0 - gate_center) > GATE_HALF:
                continue
        rows.append((yaw_rate, forward))
    if len(rows) * TRACE_BIN < MIN_GATED - 1e-9:
        return None
    return (sum(r[0] for r in rows) / len(rows), sum(r[1] for r in rows) / len(rows))


def verdict(ours, ref, commanded, scale):
    if ours is None or ref is None:
        return 'n/a', 'n/a'
    if commanded != 0:
        ratio = ours / ref if ref != 0 else float('inf')
        return '%.3f' % ratio, 'PASS' if abs(ratio - 1) <= TOLERANCE else 'FAIL'
    diff = abs(ours - ref)
    return 'd=%.3f' % diff, 'PASS' if diff <= TOLERANCE * scale else 'FAIL'


def fmt(x):
    return '   n/a' if x is None else '%+.3f' % x


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument('--vehicles', default='m_robot,re510,skid4,pioneer')
    ap.add_argument('--cases', default='turn,straight,arc')
    ap.add_argument('--seconds', type=float, default=30.0, help='length of the turn and arc runs (s)')
    ap.add_argument('--jobs', type=int, default=2)
    ap.add_argument('--json', help='also write every run\'s averages to this file')
    ap.add_argument('--ours', default=OURS, help='the bench_skid_steer executable')
    ap.add_argument('--no-hull', action='store_true', help='skip PyBullet\'s default (convex hull) runs')
    ap.add_argument('--no-disc', action='store_true', help='skip PyBullet\'s runs with disc wheels')
    ap.add_argument('--show-commands', action='store_true', help='print every engine command line')
    ap.add_argument('--reference', choices=('disc', 'cylinder'), default='disc',
                    help='PyBullet runs the verdict compares with (default disc: wheels touch in their mid-plane)')
    args = ap.parse_args()
    vehicles = args.vehicles.split(',')
    cases = args.cases.split(',')
    if args.reference == 'disc' and args.no_disc:
        ap.error('--no-disc needs --reference cylinder')
    reference = 'disc' if args.reference == 'disc' else 'pybullet'
    engines = ['ours', 'pybullet'] + ([] if args.no_hull else ['hull']) + ([] if args.no_disc else ['disc'])

    tmp = tempfile.mkdtemp(prefix='bench_skid_steer_')
    jobs = {}
    setups = {}
    for v in vehicles:
        urdf, z = expand(v, tmp)
        left, right, sep, diameter, torque, kind, root = drive_of(urdf)
        setups[v] = (urdf, z, left, right, sep, diameter, torque, kind, root)
        for c in cases:
            lin, ang = CASES[c]
            speeds = ([(j, (lin - ang * sep / 2) / (diameter / 2)) for j in left] +
                      [(j, (lin + ang * sep / 2) / (diameter / 2)) for j in right])
            seconds = args.seconds if ang != 0 else 5.0
            for e in engines:
                jobs[(v, c, e)] = engine_command(e, urdf, z, torque, speeds, seconds, args.ours)

    results = {}
    with concurrent.futures.ThreadPoolExecutor(max_workers=max(1, args.jobs)) as pool:
        futures = {pool.submit(run, cmd): key for key, cmd in jobs.items()}
        for f in concurrent.futures.as_completed(futures):
            results[futures[f]] = f.result()

    print('bullet_sim vs PyBullet: mean yaw rate (rad/s) and forward speed (m/s) of the root link; '
          'ours/ref within +-%d %% = PASS; ref = PyBullet %s' % (round(TOLERANCE * 100), {
              'disc': 'with the wheels touching in their mid-plane (disc)',
              'pybullet': 'with the URDF\'s cylinders (pyb)'}[reference]))
    print('@45 / @0: averaged while the heading (mod 90 deg) is within +-%.1f deg of 45 / 0; '
          'straight runs at their spawn heading 0' % GATE_HALF)
    header = ('%-8s %-8s %-7s %7s %8s | %8s %8s %8s %7s %5s %7s %5s | %8s %8s %8s %8s'
              % ('vehicle', 'case', 'qty', 'command', 'coulomb', 'ours@0', 'ours@45', 'ref@45',
                 'ours@0/', '', 'ours@45', '', 'pyb@45', 'pyb@0', 'hull@45', 'hull@0'))
    print(header)
    print('%-8s %-8s %-7s %7s %8s | %8s %8s %8s %7s %5s %7s %5s |' % ('', '', '', '', '', '', '', '',
                                                                     'ref@45', '', '/ref@45', ''))
    dump = {}
    failures = 0
    for v in vehicles:
        urdf, z, left, right, sep, diameter, torque, kind, root = setups[v]
        for c in cases:
            lin, ang = CASES[c]
            turning = ang != 0
            got = {}
            for e in engines:
                r = results[(v, c, e)]
                if turning:
                    got[e + '@45'] = averages(r['trace'], 45.0)
                    got[e + '@0'] = averages(r['trace'], 0.0)
                else:
                    got[e + '@0'] = averages(r['trace'], None)
                    got[e + '@45'] = None
                dump['%s/%s/%s' % (v, c, e)] = {k: got[k] for k in got if k.startswith(e)}
            ref_key = reference + ('@45' if turning else '@0')
            rim = abs(ang) * sep / 2
            for qi, (qty, commanded) in enumerate((('yaw', ang), ('forward', lin))):
                value = lambda k: None if got.get(k) is None else got[k][qi]
                scale = rim if qty == 'forward' else abs(lin) / (sep / 2)
                coulomb = ''
                if c == 'turn' and qty == 'yaw':
                    coulomb = '%+.3f' % (coulomb_turn(root, left, right, ang) if kind == 'skid steer' else ang)
                r0, v0 = verdict(value('ours@0'), value(ref_key), commanded, scale)
                if turning:
                    r45, v45 = verdict(value('ours@45'), value(ref_key), commanded, scale)
                else:
                    r45, v45 = '', ''
                failures += (v0 == 'FAIL') + (v45 == 'FAIL')
                print('%-8s %-8s %-7s %+7.3f %8s | %8s %8s %8s %7s %5s %7s %5s | %8s %8s %8s %8s'
                      % (v, c, qty, commanded, coulomb, fmt(value('ours@0')),
                         fmt(value('ours@45')) if turning else '', fmt(value(ref_key)), r0, v0, r45, v45,
                         fmt(value('pybullet@45' if turning else 'pybullet@0')),
                         fmt(value('pybullet@0')) if turning else '',
                         fmt(value('hull@45')) if turning and 'hull' in engines else '',
                         fmt(value('hull@0')) if 'hull' in engines else ''))
    print('%d FAIL' % failures if failures else 'all PASS')
    print('reproduce: . scripts/env.sh && %s' % shlex.join(['python3', os.path.relpath(__file__, ROOT)] + sys.argv[1:]))
    if args.show_commands:
        for key, cmd in jobs.items():
            print('  %s: %s' % ('/'.join(key), shlex.join(cmd)))
    if args.json:
        with open(args.json, 'w') as f:
            json.dump(dump, f, indent=1)
    return 1 if failures else 0


if __name__ == '__main__':
    sys.exit(main())
