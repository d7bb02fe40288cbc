#!/bin/sh
# Issue 23's pictures, rendered by Kinema: Fox's tail made dynamic and baked by
# `kinema simulate` (docs/images/fox_tail_strip.png), and the default character falling as a
# ragdoll from a push (docs/images/ragdoll_fall_strip.png). Frame strips: every 6th frame,
# side by side (ImageMagick's montage). Usage: physics_strips.sh BUILD/src/kinema
set -eu
kinema=$1
root=$(cd "$(dirname "$0")/../.." && pwd)
data="$root/../shared/data"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

# Fox: the Survey clip (the fox looks around), its tail a spring chain.
"$kinema" convert "$data/gltf/Fox.glb" "$tmp/fox.kinema"
python3 - "$tmp/fox.kinema" <<'PY'
import json, sys
p = sys.argv[1]
d = json.load(open(p))
d["simulation"] = {"spring_chains": [{"name": "tail", "joints": ["b_Tail01_012", "b_Tail02_013"],
                                      "stiffness": 25, "damping": 2, "gravity": [0, -981, 0], "radius": 1}]}
json.dump(d, open(p, "w"))
PY
"$kinema" simulate "$tmp/fox.kinema" --frames 0:60 --out "$tmp/fox_tail.kinema"
mkdir -p "$tmp/fox"
"$kinema" render "$tmp/fox_tail.kinema" --frames 12:60 --size 260x260 --camera 90,10 --out "$tmp/fox/frame_%04d.png"
montage $(ls "$tmp"/fox/frame_*.png | awk 'NR % 6 == 1') -tile x1 -geometry +0+0 "$root/docs/images/fox_tail_strip.png"

# The default character: a ragdoll from frame 0, its hips pushed sideways and up.
python3 - "$root/assets/default_character.kinema" "$tmp/fall.kinema" <<'PY'
import json, sys
d = json.load(open(sys.argv[1]))
d["clips"] = [{"name": "push", "frame_time": 1 / 30, "channels": [
    {"joint": "Hips", "target": "translation", "interpolation": "linear",
     "times": [0.0, 1 / 30], "values": [[-0.08, 0.95, 0.0], [0.0, 1.0, 0.0]]}]}]
d["simulation"] = {"ragdolls": [{"name": "fall", "root": "Hips", "start_frame": 1}]}
json.dump(d, open(sys.argv[2], "w"))
PY
"$kinema" simulate "$tmp/fall.kinema" --frames 0:72 --out "$tmp/fall_baked.kinema"
mkdir -p "$tmp/fall"
"$kinema" render "$tmp/fall_baked.kinema" --frames 0:72 --size 260x260 --camera 60,10,4.5 --out "$tmp/fall/frame_%04d.png"
montage $(ls "$tmp"/fall/frame_*.png | awk 'NR % 6 == 1') -tile x1 -geometry +0+0 "$root/docs/images/ragdoll_fall_strip.png"
