#!/usr/bin/env python3
"""Writes the IK-drag replay script for one window size from a --dump-state taken at that
size after Numpad 1 and Home (front view, framed): the left hand is clicked on its bone
(half way to the fingertip, selecting Hand.L), Shift+I adds an IK target there, and the
target's handle is dragged around a closed loop (two laps of a circle),
scaled with the view (pixels per metre at the hand). The layout moves the 3D view when the
panels change, so the pixels are derived from the dump instead of written by hand.
Usage: make_ik_drag_script.py STATE.json WIDTHxHEIGHT > ik_drag_WxH.jsonl"""
import json
import math
import sys

import dump_camera  # bench/editor/dump_camera.py, beside this script

# The loop's pixels are for a hand-to-fingertip bone 40.66 px long (the 1280x800 view) and
# scale with it; 600 frames, one mouse move each.
LOOP_BONE_PIXELS = 40.66
FRAMES = 600


def loop_offsets():
    # Two laps of an 18 px circle that starts and ends at the handle (its centre below it).
    radius = 18.0
    out = []
    for i in range(FRAMES):
        a = 2 * math.pi * 2 * i / FRAMES
        out.append((-radius * math.sin(a), radius * (1 - math.cos(a))))
    return out


def project(dump, name):
    joint = next(j for j in dump["joints"] if j["name"] == name)
    return dump_camera.pixel(dump, joint["world_position"])


def main():
    dump = json.load(open(sys.argv[1]))
    size = sys.argv[2]
    hand, tip = project(dump, "Hand.L"), project(dump, "Fingertip.L")
    scale = math.dist(hand, tip) / LOOP_BONE_PIXELS
    bone = ((hand[0] + tip[0]) / 2, (hand[1] + tip[1]) / 2)
    r = lambda v: round(v, 2)
    print(f"# kinema edit --size {size} --script: an IK target on the left hand, dragged in a loop for "
          f"{FRAMES} frames (written by bench/editor/make_ik_drag_script.py)")
    events = [
        {"frame": 1, "type": "key", "key": "KP_1"},
        {"frame": 2, "type": "key", "key": "HOME"},
        {"frame": 3, "type": "mouse_move", "x": r(bone[0]), "y": r(bone[1])},
        {"frame": 4, "type": "button_down", "button": "left"},
        {"frame": 5, "type": "button_up", "button": "left"},
        {"frame": 6, "type": "key_down", "key": "LEFT_SHIFT"},
        {"frame": 7, "type": "key", "key": "I"},
        {"frame": 8, "type": "key_up", "key": "LEFT_SHIFT"},
        {"frame": 9, "type": "mouse_move", "x": r(hand[0]), "y": r(hand[1])},
        {"frame": 10, "type": "button_down", "button": "left"},
    ]
    for i, (dx, dy) in enumerate(loop_offsets()):
        events.append({"frame": 11 + i, "type": "mouse_move", "x": r(hand[0] + dx * scale), "y": r(hand[1] + dy * scale)})
    events.append({"frame": 11 + FRAMES, "type": "button_up", "button": "left"})
    for e in events:
        print(json.dumps(e))


main()
