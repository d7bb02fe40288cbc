#!/usr/bin/python3
"""Independent values for tests/skin/morph_targets_test.cpp: reads a glTF with numpy (no
Kinema code), samples node NODE's "weights" channel at TIME (LINEAR, clamped to the keys),
applies the morph targets of mesh primitive 0 (p = bind + sum_k w_k * delta_k) and the
node's own world transform (T * R * S, the node has no parent in these files), and prints
the weights and the world position of the listed vertices.

  morph_values.py FILE NODE TIME VERTEX...
"""
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from gltf_channel_values import accessor, load  # noqa: E402


def quat_matrix(x, y, z, w):
    n = np.sqrt(x * x + y * y + z * z + w * w)
    x, y, z, w = x / n, y / n, z / n, w / n
    return np.array([[1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)],
                     [2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)],
                     [2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)]])


def main():
    path, node_index, time = sys.argv[1], int(sys.argv[2]), float(sys.argv[3])
    vertices = [int(v) for v in sys.argv[4:]]
    doc, buffers = load(path)
    node = doc["nodes"][node_index]
    mesh = doc["meshes"][node["mesh"]]
    prim = mesh["primitives"][0]
    weights = np.array(node.get("weights", mesh.get("weights", [0.0] * len(prim["targets"]))), dtype=np.float64)
    for anim in doc.get("animations", [])[:1]:
        for ch in anim["channels"]:
            if ch["target"].get("node") != node_index or ch["target"]["path"] != "weights":
                continue
            s = anim["samplers"][ch["sampler"]]
            assert s.get("interpolation", "LINEAR") == "LINEAR"
            times = accessor(doc, buffers, s["input"]).ravel()
            values = accessor(doc, buffers, s["output"]).reshape(len(times), -1)
            t = min(max(time, times[0]), times[-1])
            k = min(np.searchsorted(times, t, side="right"), len(times) - 1)
            if k == 0 or t >= times[-1]:
                weights = values[0 if k == 0 else -1]
            else:
                u = (t - times[k - 1]) / (times[k] - times[k - 1])
                weights = (1 - u) * values[k - 1] + u * values[k]
    pos = accessor(doc, buffers, prim["attributes"]["POSITION"])
    for w, target in zip(weights, prim["targets"]):
        pos = pos + w * accessor(doc, buffers, target["POSITION"])
    r = quat_matrix(*node.get("rotation", [0, 0, 0, 1]))
    s = np.diag(node.get("scale", [1, 1, 1]))
    t = np.array(node.get("translation", [0, 0, 0]))
    print("weights", " ".join(f"{w:.9g}" for w in weights))
    for v in vertices:
        p = r @ s @ pos[v] + t
        print("vertex", v, " ".join(f"{c:.9g}" for c in p))


if __name__ == "__main__":
    main()
