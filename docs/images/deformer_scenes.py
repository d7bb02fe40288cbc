#!/usr/bin/env python3
"""Writes the .kinema scenes the README's deformer pictures are rendered from (issue 22):
the default character (assets/default_character.kinema) with one deformer each, and with
each face shape at full weight. Usage: deformer_scenes.py ASSET OUTDIR"""
import json, sys

asset, out = sys.argv[1], sys.argv[2]
base = json.load(open(asset))

def save(name, deformers=None, weights=None):
    j = json.loads(json.dumps(base))
    inst = j["mesh_instances"][0]
    if deformers: inst["deformers"] = deformers
    if weights: inst["morph_weights"] = weights
    json.dump(j, open(f"{out}/{name}.kinema", "w"))

# A 3x4x3 lattice around the chest and head; its middle layers pushed out (a barrel) and the
# top layer sheared forward.
counts = [3, 4, 3]
origin = [-0.25, 1.05, -0.16]
size = [0.5, 0.8, 0.32]
points = []
for k in range(counts[2]):
    for j in range(counts[1]):
        for i in range(counts[0]):
            s, t, u = i / (counts[0] - 1), j / (counts[1] - 1), k / (counts[2] - 1)
            p = [origin[0] + s * size[0], origin[1] + t * size[1], origin[2] + u * size[2]]
            if j in (1, 2):  # the middle layers: 1.4 times wider about the centre line
                p[0] = 1.4 * p[0]
                p[2] = -0.0 + 1.4 * (p[2] - (origin[2] + 0.5 * size[2])) + origin[2] + 0.5 * size[2]
            if j == 3:
                p[2] += 0.12
            points += p
lattice = {"counts": counts, "origin": origin, "axes": [[size[0], 0, 0], [0, size[1], 0], [0, 0, size[2]]],
           "points": points}
save("lattice", [{"name": "cage", "type": "lattice", "lattice": lattice}])
save("bend", [{"name": "bend", "type": "bend", "axis": {"axis": "y", "origin": [0, 0.95, 0], "low": 0, "high": 0.85, "amount": 1.0}}])
save("twist", [{"name": "twist", "type": "twist", "axis": {"axis": "y", "origin": [0, 0.95, 0], "low": 0, "high": 0.6, "amount": 1.4}}])
save("taper", [{"name": "taper", "type": "taper", "axis": {"axis": "y", "origin": [0, 0.9, 0], "low": 0, "high": 0.6, "amount": 1.6}}])
save("rest")
for i, shape in enumerate(["jaw_open", "smile", "brow_raise", "blink"]):
    w = [0, 0, 0, 0]
    w[i] = 1
    save("face_" + shape, weights=w)
save("face_neutral")
