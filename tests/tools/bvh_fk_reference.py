#!/usr/bin/python3
"""Independent BVH forward kinematics, used to derive expected values for Kinema's tests.

Shares no code with Kinema. Semantics (docs/architecture.md of the project):
  local = T * R
  R     = the channel rotations multiplied in file order, angles in degrees
          ("Zrotation Xrotation Yrotation" -> Rz @ Rx @ Ry)
  T     = the joint's OFFSET, each component REPLACED by its position channel when present
  world = world(parent) @ local
End Sites become joints named "<parent>_End" whose local transform is their OFFSET.

Usage:
  bvh_fk_reference.py FILE FRAME [JOINT ...] [--matrix]
prints, for each named joint (all joints when none is named), its world position and, with
--matrix, its 3x3 world rotation (rows), with 9 significant digits.
"""
import sys

import numpy as np


def rot(axis, degrees):
    a = np.radians(degrees)
    c, s = np.cos(a), np.sin(a)
    if axis == "X":
        return np.array([[1, 0, 0], [0, c, -s], [0, s, c]])
    if axis == "Y":
        return np.array([[c, 0, s], [0, 1, 0], [-s, 0, c]])
    return np.array([[c, -s, 0], [s, c, 0], [0, 0, 1]])


def parse(text):
    """Returns (joints, frame_time, frames); joints = list of dicts in file order."""
    lines = text.replace("\r\n", "\n").replace("\r", "\n").split("\n")
    words = []
    motion_at = None
    for i, line in enumerate(lines):
        parts = line.split()
        if parts and parts[0] == "MOTION":
            motion_at = i
            break
        words.extend(parts)
    assert words[0] == "HIERARCHY" and motion_at is not None
    joints, stack, column, k = [], [], 0, 1
    while k < len(words):
        w = words[k]
        if w == "}":
            stack.pop()
            k += 1
            continue
        parent = stack[-1] if stack else -1
        if w in ("ROOT", "JOINT"):
            name = words[k + 1]
            assert words[k + 2] == "{", "names with spaces are not supported here"
            assert words[k + 3] == "OFFSET"
            offset = [float(x) for x in words[k + 4:k + 7]]
            assert words[k + 7] == "CHANNELS"
            n = int(words[k + 8])
            channels = words[k + 9:k + 9 + n]
            k += 9 + n
        elif w == "End":
            assert words[k + 1] == "Site" and words[k + 2] == "{" and words[k + 3] == "OFFSET"
            name = joints[parent]["name"] + "_End"
            offset = [float(x) for x in words[k + 4:k + 7]]
            channels = []
            k += 7
        else:
            raise ValueError("unexpected word " + w)
        joints.append(dict(name=name, parent=parent, offset=offset, channels=channels, column=column))
        column += len(channels)
        stack.append(len(joints) - 1)
    rest = [l.strip() for l in lines[motion_at + 1:] if l.strip()]
    assert rest[0].startswith("Frames:") and rest[1].startswith("Frame Time:")
    frame_time = float(rest[1][len("Frame Time:"):])
    frames = [[float(x) for x in l.split()] for l in rest[2:]]
    return joints, frame_time, frames


def world_matrices(joints, row):
    world = []
    for j in joints:
        t = np.array(j["offset"], dtype=float)
        r = np.eye(3)
        for c, name in enumerate(j["channels"]):
            v = row[j["column"] + c]
            axis, kind = name[0].upper(), name[1:].lower()
            if kind == "position":
                t["XYZ".index(axis)] = v
            else:
                r = r @ rot(axis, v)
        local = np.eye(4)
        local[:3, :3] = r
        local[:3, 3] = t
        world.append(local if j["parent"] < 0 else world[j["parent"]] @ local)
    return world


def main(argv):
    matrix = "--matrix" in argv
    args = [a for a in argv if a != "--matrix"]
    path, frame, wanted = args[0], int(args[1]), args[2:]
    with open(path, "rb") as f:
        joints, _, frames = parse(f.read().decode("latin-1"))
    world = world_matrices(joints, frames[frame])
    for j, m in zip(joints, world):
        if wanted and j["name"] not in wanted:
            continue
        p = m[:3, 3]
        print("%s position {%.9g, %.9g, %.9g}" % (j["name"], p[0], p[1], p[2]))
        if matrix:
            r = m[:3, :3]
            print("%s rotation rows {%s}" % (j["name"], ", ".join("%.9g" % x for x in r.flatten())))


if __name__ == "__main__":
    main(sys.argv[1:])
