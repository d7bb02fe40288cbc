#!/usr/bin/python3
"""Independent values for tests/io/gltf_animation_test.cpp: reads a glTF/GLB with numpy
(no Kinema code) and prints one animation channel's keys and its value at given times,
following the glTF 2.0 spec: STEP holds the previous key, LINEAR interpolates translation/
scale/weights linearly and rotations by shortest-arc slerp.

  gltf_channel_values.py FILE ANIMATION CHANNEL TIME...
"""
import base64
import json
import os
import struct
import sys

import numpy as np

COMPONENTS = {"SCALAR": 1, "VEC2": 2, "VEC3": 3, "VEC4": 4, "MAT4": 16}
DTYPES = {5120: np.int8, 5121: np.uint8, 5122: np.int16, 5123: np.uint16, 5125: np.uint32, 5126: np.float32}


def load(path):
    raw = open(path, "rb").read()
    bin_chunk = None
    if raw[:4] == b"glTF":
        json_len = struct.unpack_from("<I", raw, 12)[0]
        doc = json.loads(raw[20:20 + json_len])
        off = 20 + json_len
        if off < len(raw):
            bin_len = struct.unpack_from("<I", raw, off)[0]
            bin_chunk = raw[off + 8:off + 8 + bin_len]
    else:
        doc = json.loads(raw)
    buffers = []
    for b in doc.get("buffers", []):
        uri = b.get("uri")
        if uri is None:
            buffers.append(bin_chunk)
        elif uri.startswith("data:"):
            buffers.append(base64.b64decode(uri.split(",", 1)[1]))
        else:
            buffers.append(open(os.path.join(os.path.dirname(path), uri), "rb").read())
    return doc, buffers


def accessor(doc, buffers, index):
    a = doc["accessors"][index]
    n = COMPONENTS[a["type"]]
    dt = np.dtype(DTYPES[a["componentType"]])
    bv = doc["bufferViews"][a["bufferView"]]
    stride = bv.get("byteStride", dt.itemsize * n)
    base = bv.get("byteOffset", 0) + a.get("byteOffset", 0)
    data = buffers[bv["buffer"]]
    out = np.array([np.frombuffer(data, dt, n, base + i * stride) for i in range(a["count"])], dtype=np.float64)
    if a.get("normalized"):
        out = {np.uint8: out / 255, np.uint16: out / 65535, np.int8: np.maximum(out / 127, -1),
               np.int16: np.maximum(out / 32767, -1)}[DTYPES[a["componentType"]]]
    return out


def slerp(a, b, u):
    a = a / np.linalg.norm(a)
    b = b / np.linalg.norm(b)
    d = np.dot(a, b)
    if d < 0:
        b, d = -b, -d
    if d > 0.9995:
        r = a + u * (b - a)
        return r / np.linalg.norm(r)
    th = np.arccos(d)
    return (np.sin((1 - u) * th) * a + np.sin(u * th) * b) / np.sin(th)


def value(times, values, path, interp, t):
    if t <= times[0]:
        return values[0]
    if t >= times[-1]:
        return values[-1]
    k = np.searchsorted(times, t, side="right") - 1
    if interp == "STEP" or t == times[k]:
        return values[k]
    u = (t - times[k]) / (times[k + 1] - times[k])
    if path == "rotation":
        return slerp(values[k], values[k + 1], u)
    return (1 - u) * values[k] + u * values[k + 1]


def main():
    path, anim, chan = sys.argv[1], int(sys.argv[2]), int(sys.argv[3])
    doc, buffers = load(path)
    a = doc["animations"][anim]
    c = a["channels"][chan]
    s = a["samplers"][c["sampler"]]
    times = accessor(doc, buffers, s["input"])[:, 0]
    values = accessor(doc, buffers, s["output"])
    interp = s.get("interpolation", "LINEAR")
    path_ = c["target"]["path"]
    if path_ == "weights":  # one row per key, one column per morph target
        values = values.reshape(len(times), -1)
    print(f"node {c['target']['node']} {path_} {interp}, {len(times)} keys from {times[0]:.9g} to {times[-1]:.9g}")
    for t in sys.argv[4:]:
        t = float(t)
        print(f"t={t:.9g}:", " ".join(f"{x:.9g}" for x in value(times, values, path_, interp, t)))
    for k in range(min(len(times), 8)):
        print(f"key {k} t={times[k]:.9g}:", " ".join(f"{x:.9g}" for x in values[k]))


if __name__ == "__main__":
    main()
