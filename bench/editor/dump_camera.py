"""The window pixel of a world point in a `kinema edit --dump-state`: the dumped camera (eye,
target, vertical field of view, Y up, perspective) over the dumped viewport rectangle, as
the editor projects it. Shared by the bench scripts that derive clicks from a dump."""
import math


def pixel(dump, world):
    c, vp = dump["camera"], dump["viewport"]
    eye, target = c["eye"], c["target"]
    sub = lambda a, b: [x - y for x, y in zip(a, b)]
    dot = lambda a, b: sum(x * y for x, y in zip(a, b))
    cross = lambda a, b: [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]
    unit = lambda a: [x / math.sqrt(dot(a, a)) for x in a]
    forward = unit(sub(target, eye))
    right = unit(cross(forward, [0.0, 1.0, 0.0]))
    up = cross(right, forward)
    p = sub(world, eye)
    depth = dot(p, forward)
    half = math.tan(math.radians(c["fov_y"]) / 2)
    nx = dot(p, right) / (depth * half * vp["width"] / vp["height"])
    ny = dot(p, up) / (depth * half)
    return vp["x"] + (nx * 0.5 + 0.5) * vp["width"], vp["y"] + (0.5 - ny * 0.5) * vp["height"]
