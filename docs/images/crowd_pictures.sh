#!/bin/sh
# Issue 24's crowd pictures, made by Kinema: 40 CesiumMen walking round a sphere to a goal,
# run by `kinema simulate` into a glTF of 40 skinned characters and the obstacle, rendered as a
# frame strip (docs/images/crowd_walk_strip.png: frames 0, 48, ... 240: ten seconds) and a GIF
# (docs/images/crowd_walk.gif); and the editor on the
# same crowd with the Crowd panel and one member's impulse vectors close up
# (docs/images/crowd_editor.png). Usage: crowd_pictures.sh BUILD/src/kinema
set -eu
kinema=$1
root=$(cd "$(dirname "$0")/../.." && pwd)
data="$root/../shared/data"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

"$kinema" convert "$data/gltf/CesiumMan.glb" "$tmp/cesium.kinema"
python3 - "$tmp/cesium.kinema" "$tmp/crowd.kinema" <<'PY'
import json, sys
d = json.load(open(sys.argv[1]))
d["simulation"] = {"crowds": [{"name": "crowd", "members": 40, "seed": 4, "spawn_centre": [-8, 0, 6],
                               "goal": [14, 0, 6], "debug_member": 11,
                               "obstacles": {"spheres": [{"centre": [2.5, 0, 6], "radius": 2.5}]}}]}
json.dump(d, open(sys.argv[2], "w"))
PY
"$kinema" simulate "$tmp/crowd.kinema" --frames 0:240 --out "$tmp/crowd.glb" 2>/dev/null
mkdir -p "$tmp/strip"
"$kinema" render "$tmp/crowd.glb" --frames 0:240 --size 400x300 --camera 0,60,30 --bones none --out "$tmp/strip/frame_%04d.png" 2>/dev/null
montage $(ls "$tmp"/strip/frame_*.png | awk 'NR % 48 == 1') -tile x1 -geometry +0+0 "$root/docs/images/crowd_walk_strip.png"
# The GIF (docs/images/crowd_walk.gif): every third frame at 8 fps, ten seconds, when ffmpeg is there.
if command -v ffmpeg >/dev/null 2>&1; then
  mkdir -p "$tmp/gif"
  for f in $(ls "$tmp"/strip/frame_*.png | awk 'NR % 3 == 1'); do cp "$f" "$tmp/gif/"; done
  ffmpeg -y -loglevel error -framerate 8 -pattern_type glob -i "$tmp/gif/frame_*.png" \
    -vf "split[a][b];[a]palettegen=reserve_transparent=0[p];[b][p]paletteuse" "$root/docs/images/crowd_walk.gif"
else
  echo "crowd_pictures.sh: ffmpeg is not installed (apt-get install ffmpeg): no crowd_walk.gif" >&2
fi

mkdir -p "$tmp/home"
XDG_STATE_HOME="$tmp/home" XDG_CONFIG_HOME="$tmp/home" sh "$root/tests/tools/xvfb_run.sh" 1920x1200x24 "$kinema" edit \
  "$tmp/crowd.kinema" --size 1600x900 --script "$root/docs/images/crowd_editor.jsonl" --frame-count 40 \
  --screenshot "$root/docs/images/crowd_editor.png"
