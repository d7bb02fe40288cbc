#!/usr/bin/python3
"""Expected values for BvhSixOrders in tests/io/bvh_test.cpp.

Builds the same small BVH text as sixOrderBvh() in that test for each of the six rotation
orders and evaluates frame 1 with the independent FK in bvh_fk_reference.py (numpy, no Kinema
code). Prints one C++ initializer per order:
  {"ORDER", Hips world rotation rows (9), Arm world rotation rows (9), Arm position (3),
   Arm_End position (3)}
Run: /usr/bin/python3 tests/tools/bvh_six_orders.py
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import bvh_fk_reference as ref  # noqa: E402

ROOT = {"X": 30, "Y": -50, "Z": 70}
ARM = {"X": -20, "Y": 35, "Z": 110}


def six_order_bvh(order):
    ch = "".join(" %srotation" % a for a in order)
    root = " ".join(str(ROOT[a]) for a in order)
    arm = " ".join(str(ARM[a]) for a in order)
    return ("HIERARCHY\n"
            "ROOT Hips\n"
            "{\n"
            "  OFFSET 1 2 3\n"
            "  CHANNELS 6 Xposition Yposition Zposition" + ch + "\n"
            "  JOINT Arm\n"
            "  {\n"
            "    OFFSET 1 2 0.5\n"
            "    CHANNELS 3" + ch + "\n"
            "    End Site\n"
            "    {\n"
            "      OFFSET 0.5 1 -1\n"
            "    }\n"
            "  }\n"
            "}\n"
            "MOTION\n"
            "Frames: 2\n"
            "Frame Time: 0.1\n"
            "0 0 0 0 0 0 0 0 0\n"
            "0.5 -1 2 " + root + " " + arm + "\n")


def fmt(values):
    return ", ".join("%.9g" % v for v in values)


for order in ["XYZ", "XZY", "YXZ", "YZX", "ZXY", "ZYX"]:
    joints, _, frames = ref.parse(six_order_bvh(order))
    world = ref.world_matrices(joints, frames[1])
    names = [j["name"] for j in joints]
    assert names == ["Hips", "Arm", "Arm_End"], names
    print('    {"%s",\n     {%s},\n     {%s},\n     {%s},\n     {%s}},' % (
        order, fmt(world[0][:3, :3].flatten()), fmt(world[1][:3, :3].flatten()),
        fmt(world[1][:3, 3]), fmt(world[2][:3, 3])))
