#!/usr/bin/env python3
"""PyBullet's step rate on the benchmark arm with the PD torque law of physics_bench (issue 2).

  bench_pybullet.py URDF [seconds_of_sim=20] [repeats=3]

Same model (src/bullet_sim_core/bench/arm5.urdf, fixed to the world), same 1 ms step, gravity
-9.8, same controller as src/bullet_sim_core/bench/physics_bench.cpp: every step reads the joint
states, computes tau = clamp(kp (q* - q) + kd (dq* - dq), +-effort limit) towards
q* = A sin(2 pi f t) and applies it with TORQUE_CONTROL, then stepSimulation(). The default
velocity motors are disabled (VELOCITY_CONTROL, force 0) so the torque is all there is, and
the multibody's default 0.04 linear/angular damping is set to 0 as in bullet_sim. Inertias
come from the URDF (URDF_USE_INERTIA_FROM_FILE), as bullet_sim uses them. The <gazebo> laser
block is ignored by PyBullet.

Needs pybullet (scripts/requirements-bench.txt, installed by `scripts/setup --bench`).
Output (parsed by scripts/bench):
  pybullet steps/s: X
  pybullet real-time factor: Y
  pybullet tracking RMS error: Z rad
"""
import ctypes
import math
import os
import sys
import time

# Keep equal to physics_bench.cpp. Joint order: shoulder_pan, shoulder_lift, elbow,
# wrist_pitch, wrist_roll.
KP = [200.0, 300.0, 150.0, 30.0, 5.0]
KD = [10.0, 15.0, 8.0, 1.0, 0.1]
AMPLITUDE = [0.8, 0.5, 0.7, 0.6, 1.0]  # rad
FREQUENCY = [0.2, 0.25, 0.3, 0.4, 0.5]  # Hz
SETTLE_TIME = 1.0  # s: errors before this are start-up transient
DT = 0.001


def load(p, urdf, extra_flags=0):
    """A fresh DIRECT world with the arm; returns (client, body, moving joint indices, limits)."""
    client = p.connect(p.DIRECT)
    p.setGravity(0, 0, -9.8, physicsClientId=client)
    p.setTimeStep(DT, physicsClientId=client)
    body = p.loadURDF(urdf, useFixedBase=True, flags=p.URDF_USE_INERTIA_FROM_FILE | extra_flags,
                      physicsClientId=client)
    p.changeDynamics(body, -1, linearDamping=0.0, angularDamping=0.0, physicsClientId=client)
    joints, limits = [], []
    for j in range(p.getNumJoints(body, physicsClientId=client)):
        info = p.getJointInfo(body, j, physicsClientId=client)
        if info[2] in (p.JOINT_REVOLUTE, p.JOINT_PRISMATIC):
            joints.append(j)
            limits.append(info[10] if info[10] > 0 else 1e9)  # jointMaxForce
    # Disable the default velocity motors: otherwise they hold every joint in place.
    p.setJointMotorControlArray(body, joints, p.VELOCITY_CONTROL, forces=[0.0] * len(joints),
                                physicsClientId=client)
    return client, body, joints, limits


def run_once(p, urdf, sim_seconds, extra_flags=0, split_timing=False):
    """Returns (steps, wall s, RMS error, max error, per-joint RMS, s inside stepSimulation)."""
    client, body, joints, limits = load(p, urdf, extra_flags)
    n = len(joints)
    steps = int(round(sim_seconds / DT))
    omega = [2.0 * math.pi * FREQUENCY[j % 5] for j in range(n)]
    amp = [AMPLITUDE[j % 5] for j in range(n)]
    kp = [KP[j % 5] for j in range(n)]
    kd = [KD[j % 5] for j in range(n)]
    sum_sq = 0.0
    joint_sq = [0.0] * n
    samples = 0
    max_err = 0.0
    tau = [0.0] * n
    get_states, set_control, step = p.getJointStates, p.setJointMotorControlArray, p.stepSimulation
    torque = p.TORQUE_CONTROL
    step_seconds = 0.0
    clock = time.perf_counter
    start = clock()
    for i in range(steps):
        t = i * DT
        states = get_states(body, joints, physicsClientId=client)
        settled = t >= SETTLE_TIME
        for j in range(n):
            s, c = math.sin(omega[j] * t), math.cos(omega[j] * t)
            q, dq = states[j][0], states[j][1]
            err = amp[j] * s - q
            u = kp[j] * err + kd[j] * (amp[j] * omega[j] * c - dq)
            tau[j] = max(-limits[j], min(limits[j], u))
            if settled:
                sum_sq += err * err
                joint_sq[j] += err * err
                samples += 1
                max_err = max(max_err, abs(err))
        set_control(body, joints, torque, forces=tau, physicsClientId=client)
        if split_timing:
            before = clock()
            step(physicsClientId=client)
            step_seconds += clock() - before
        else:
            step(physicsClientId=client)
    wall = clock() - start
    p.disconnect(client)
    rms = math.sqrt(sum_sq / samples) if samples else 0.0
    joint_rms = [math.sqrt(x * n / samples) if samples else 0.0 for x in joint_sq]
    return steps, wall, rms, max_err, joint_rms, step_seconds


def flush_c_stdout():
    """PyBullet prints through C stdio; flush it so its lines do not land inside ours."""
    sys.stdout.flush()
    try:
        ctypes.CDLL(None).fflush(None)
    except (OSError, AttributeError):
        pass


def quiet(fn, *args, **kwargs):
    """Runs fn with the C library's stdout (PyBullet's banner and URDF chatter) sent to /dev/null."""
    flush_c_stdout()
    saved = os.dup(1)
    devnull = os.open(os.devnull, os.O_WRONLY)
    try:
        os.dup2(devnull, 1)
        return fn(*args, **kwargs)
    finally:
        flush_c_stdout()
        os.dup2(saved, 1)
        os.close(saved)
        os.close(devnull)


def main(argv):
    if len(argv) < 2 or len(argv) > 4:
        print("usage: bench_pybullet.py URDF [seconds_of_sim=20] [repeats=3]", file=sys.stderr)
        return 2
    urdf = argv[1]
    seconds = float(argv[2]) if len(argv) > 2 else 20.0
    repeats = int(argv[3]) if len(argv) > 3 else 3
    if seconds <= SETTLE_TIME or repeats < 1:
        print("bench_pybullet: expected seconds_of_sim > %g and repeats >= 1" % SETTLE_TIME, file=sys.stderr)
        return 2
    try:
        import pybullet as p
    except ImportError:
        print("bench_pybullet: pybullet is not installed; run scripts/setup --bench "
              "(it installs scripts/requirements-bench.txt into .venv)", file=sys.stderr)
        return 1
    client, body, joints, _ = load(p, urdf)
    print("pybullet (API %s) model: %d moving joints of %d, fixed base" %
          (p.getAPIVersion(), len(joints), p.getNumJoints(body, physicsClientId=client)))
    p.disconnect(client)

    run_once(p, urdf, 1.5)  # warm-up
    rates, first = [], None
    for i in range(repeats):
        steps, wall, rms, max_err, joint_rms, _ = run_once(p, urdf, seconds)
        first = first or (rms, max_err, joint_rms)
        rates.append(steps / wall)
        print("  run %d: %d steps in %.3f s wall = %.0f steps/s" % (i + 1, steps, wall, steps / wall))
    rates.sort()
    median = rates[len(rates) // 2]
    split = run_once(p, urdf, seconds, 0, True)
    merged_steps, merged_wall = quiet(run_once, p, urdf, seconds, p.URDF_MERGE_FIXED_LINKS)[0:2]
    print("pybullet steps/s: %.0f" % median)
    print("pybullet us/step: %.2f" % (1e6 / median))
    print("pybullet real-time factor: %.1f" % (median * DT))
    print("pybullet tracking RMS error: %.4f rad (max %.4f rad, after %g s)" % (first[0], first[1], SETTLE_TIME))
    print("pybullet per-joint RMS error (rad): " + " ".join("%.4f" % e for e in first[2]))
    print("pybullet physics share: %.2f us/step in stepSimulation() = %.0f steps/s without control" %
          (1e6 * split[5] / split[0], split[0] / split[5]))
    print("pybullet steps/s with URDF_MERGE_FIXED_LINKS (1 run): %.0f" % (merged_steps / merged_wall))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
