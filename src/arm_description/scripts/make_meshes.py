#!/usr/bin/python3
"""Writes the dual arm's visual meshes, meshes/<link>.stl, as binary STL (numpy only).

The report designed its meshes in a CAD program; ours are made here from rounded boxes
(a box's Minkowski sum with a sphere, which also gives spheres and capsules), sized from
the same numbers as urdf/arm.xacro. Every mesh is in its link's frame, in metres, so the
xacro uses it with origin 0 and scale 1. Output is deterministic: running this again gives
identical files.

Usage: make_meshes.py [--out DIR] [--segments N]    (DIR defaults to ../meshes)
"""
import argparse
import os
import struct

import numpy as np

# Sizes in metres; keep in step with the properties at the top of urdf/arm.xacro.
TORSO = (0.20, 0.34, 0.60)       # torso_depth, torso_width, torso_height
TORSO_Z = 1.20                   # torso centre above the base_link origin (the ground)
PEDESTAL_RADIUS = 0.06
FOOT = (0.40, 0.40, 0.05)
HEAD_RADIUS = 0.10
WIDTH = 0.10                     # shoulder block: width x width x height1
HEIGHT1 = 0.10
ARM_RADIUS = 0.045               # upper arm
ARM_LENGTH = 0.30                # shoulder axis to elbow axis
ELBOW_RADIUS = 0.05
ELBOW_WIDTH = 0.09
FOREARM_RADIUS = 0.04
FOREARM_LENGTH = 0.31            # elbow axis to fingertips
HAND = (0.03, 0.08, 0.09)        # thickness (x), width (y), length (z)


def rounded_box(center, size, radius, segments):
    """Triangles (n, 3, 3) of a box of outer `size` with edges rounded by `radius`.

    A UV sphere of `radius` whose vertices are pushed out by the inner half extents along
    the signs of their normals; the sphere has vertices on its three middle planes (the
    counts below are multiples of 4 and 2), so the pushed-out sphere stays closed.
    With size all 2*radius it is a sphere; with two of them 2*radius, a capsule.
    """
    inner = np.maximum(np.asarray(size, float) / 2.0 - radius, 0.0)
    n_lon = 4 * max(1, segments // 4)
    n_lat = 2 * max(1, segments // 4)
    theta = np.linspace(0.0, np.pi, n_lat + 1)            # from +z to -z
    phi = np.linspace(0.0, 2.0 * np.pi, n_lon + 1)[:-1]
    rings = []
    for t in theta:
        n = np.stack([np.sin(t) * np.cos(phi), np.sin(t) * np.sin(phi), np.full_like(phi, np.cos(t))], axis=1)
        n[np.abs(n) < 1e-12] = 0.0
        rings.append(np.asarray(center, float) + radius * n + inner * np.sign(n))
    tris = []
    for i in range(n_lat):
        a, b = rings[i], rings[i + 1]
        for j in range(n_lon):
            k = (j + 1) % n_lon
            if i > 0:                       # the first ring is the pole: skip the degenerate one
                tris.append((a[j], b[j], a[k]))
            if i < n_lat - 1:
                tris.append((a[k], b[j], b[k]))
    return np.array(tris)


def rotate_x(tris, angle):
    c, s = np.cos(angle), np.sin(angle)
    r = np.array([[1.0, 0.0, 0.0], [0.0, c, -s], [0.0, s, c]])
    return tris @ r.T


def lathe(profile, segments):
    """Triangles of the surface of revolution about z of `profile`, a list of (radius, z)
    from the top (radius 0) to the bottom (radius 0)."""
    n_lon = 4 * max(1, segments // 4)
    phi = np.linspace(0.0, 2.0 * np.pi, n_lon + 1)[:-1]
    rings = [np.stack([r * np.cos(phi), r * np.sin(phi), np.full_like(phi, z)], axis=1) for r, z in profile]
    tris = []
    for i in range(len(rings) - 1):
        a, b = rings[i], rings[i + 1]
        for j in range(n_lon):
            k = (j + 1) % n_lon
            tris.append((a[j], b[j], a[k]))
            tris.append((a[k], b[j], b[k]))
    return np.array(tris)    # triangles on the axis are degenerate; write_binary_stl drops them


def cylinder_y(center, radius, length, rim, segments):
    """A cylinder along y with rims rounded by `rim` (the elbow cover)."""
    h = length / 2.0
    arc = np.linspace(0.0, np.pi / 2.0, max(2, segments // 4) + 1)
    top = [(radius - rim + rim * np.sin(t), h - rim + rim * np.cos(t)) for t in arc]
    profile = [(0.0, h)] + top + [(r, -z) for r, z in reversed(top)] + [(0.0, -h)]
    return rotate_x(lathe(profile, segments), -np.pi / 2.0) + np.asarray(center, float)


def link_meshes(segments):
    """{link name: triangles} for every link with a visual mesh."""
    torso_d, torso_w, torso_h = TORSO
    torso_bottom = TORSO_Z - torso_h / 2.0
    base = np.concatenate([
        rounded_box((0, 0, TORSO_Z), TORSO, 0.04, segments),
        rounded_box((0, 0, FOOT[2] / 2.0), FOOT, 0.015, segments),
        rounded_box((0, 0, torso_bottom / 2.0 + 0.01), (2 * PEDESTAL_RADIUS, 2 * PEDESTAL_RADIUS, torso_bottom),
                    PEDESTAL_RADIUS, segments),
        rounded_box((0, 0, TORSO_Z + torso_h / 2.0 + 0.03), (0.08, 0.08, 0.06), 0.04, segments),          # neck
        rounded_box((0, 0, TORSO_Z + torso_h / 2.0 + 0.06 + HEAD_RADIUS), (2 * HEAD_RADIUS,) * 3, HEAD_RADIUS,
                    segments),
    ])
    shoulder = rounded_box((0, 0, HEIGHT1 / 2.0), (WIDTH, WIDTH, HEIGHT1), 0.025, segments)
    arm = rounded_box((0, 0, -ARM_LENGTH / 2.0), (2 * ARM_RADIUS, 2 * ARM_RADIUS, ARM_LENGTH + 2 * ARM_RADIUS),
                      ARM_RADIUS, segments)
    elbow = cylinder_y((0, 0, 0), ELBOW_RADIUS, ELBOW_WIDTH, 0.01, segments)
    hand_len = HAND[2]
    forearm_len = FOREARM_LENGTH - hand_len
    forearm = np.concatenate([
        rounded_box((0, 0, -forearm_len / 2.0), (2 * FOREARM_RADIUS, 2 * FOREARM_RADIUS, forearm_len),
                    FOREARM_RADIUS * 0.9, segments),
        rounded_box((0, 0, -(FOREARM_LENGTH - hand_len / 2.0)), HAND, 0.012, segments),
    ])
    return {"base_link": base, "shoulder": shoulder, "arm": arm, "elbow": elbow, "forearm": forearm}


def write_binary_stl(path, tris, name):
    tris = np.asarray(tris, dtype=np.float64)
    normals = np.cross(tris[:, 1] - tris[:, 0], tris[:, 2] - tris[:, 0])
    lengths = np.linalg.norm(normals, axis=1, keepdims=True)
    keep = lengths[:, 0] > 1e-14                       # drop degenerate triangles
    tris, normals = tris[keep], normals[keep] / lengths[keep]
    record = np.zeros(len(tris), dtype=[("n", "<f4", 3), ("v", "<f4", (3, 3)), ("attr", "<u2")])
    record["n"] = normals
    record["v"] = tris
    header = ("binary STL %s, made by arm_description/scripts/make_meshes.py" % name).encode("ascii")[:80]
    with open(path, "wb") as f:
        f.write(header.ljust(80, b" "))
        f.write(struct.pack("<I", len(tris)))
        f.write(record.tobytes())
    return len(tris)


def main():
    here = os.path.dirname(os.path.abspath(__file__))
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--out", default=os.path.join(here, "..", "meshes"), help="output folder")
    parser.add_argument("--segments", type=int, default=24, help="segments around a round edge (multiple of 4)")
    args = parser.parse_args()
    os.makedirs(args.out, exist_ok=True)
    for name, tris in link_meshes(args.segments).items():
        path = os.path.join(args.out, name + ".stl")
        count = write_binary_stl(path, tris, name)
        lo, hi = tris.reshape(-1, 3).min(axis=0), tris.reshape(-1, 3).max(axis=0)
        print("%-28s %5d triangles, bounds [%s] .. [%s]" % (os.path.relpath(path), count,
              " ".join("%.3f" % v for v in lo), " ".join("%.3f" % v for v in hi)))


if __name__ == "__main__":
    main()
