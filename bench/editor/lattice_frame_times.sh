#!/usr/bin/env bash
# Editor frame time on llvmpipe while a lattice point is dragged (issue 22): the default
# character with a 3x3x3 lattice added to its body (Properties > Deformers > Add Lattice), in
# lattice edit mode (Tab), one control point (the right side's middle, front layer) clicked
# and moved with G around two laps of a circle for 600 frames: every frame re-runs the FFD
# on the body's vertices on the CPU (morphs, skinning, deformers) and draws the cage. Against
# an empty ImGui frame of the same size and frame count. A first run (Tab, A) dumps the
# points' world positions and the camera; the point's pixel is projected from them, so the
# script never clicks a layout guess; the timed run's --dump-state is checked for the one
# selected point. Usage: bench/editor/lattice_frame_times.sh [build/src/kinema] [WIDTHxHEIGHT]
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
kinema=${1:-$root/build/src/kinema}
size=${2:-1280x800}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
run() {  # script [options...]
  local script=$1
  shift
  XDG_STATE_HOME=$tmp XDG_CONFIG_HOME=$tmp XDG_CACHE_HOME=$tmp XDG_DATA_HOME=$tmp \
    LIBGL_ALWAYS_SOFTWARE=1 MESA_GL_VERSION_OVERRIDE=3.3 \
    sh "$root/tests/tools/xvfb_run.sh" "${size}x24" "$kinema" edit --size "$size" --script "$script" "$@" 2>&1
}
start='{"frame": 1, "type": "key", "key": "KP_1"}
{"frame": 2, "type": "key", "key": "HOME"}
{"frame": 3, "type": "mouse_move", "item": "Properties/Deformers/Add Lattice"}
{"frame": 4, "type": "button_down", "button": "left"}
{"frame": 5, "type": "button_up", "button": "left"}'
printf '%s\n{"frame": 8, "type": "command", "id": "lattice.edit"}\n{"frame": 9, "type": "command", "id": "lattice.select_all"}\n' \
  "$start" > "$tmp/probe.jsonl"
run "$tmp/probe.jsonl" --dump-state "$tmp/probe.json" > /dev/null
python3 - "$tmp/probe.json" "$start" "$root/bench/editor" > "$tmp/drag.jsonl" <<'PY'
import json, math, sys
sys.path.insert(0, sys.argv[3])
import dump_camera  # bench/editor/dump_camera.py
d = json.load(open(sys.argv[1]))
edit = d["lattice_edit"]
assert edit.get("points") == 27, f"no 3x3x3 lattice in edit mode: {edit}"
point = 2 + 3 * (1 + 3 * 2)  # index(2, 1, 2): i fastest
x, y = dump_camera.pixel(d, edit["selected_positions"][point])
print(sys.argv[2])
events = [{"frame": 8, "type": "command", "id": "lattice.edit"},
          {"frame": 9, "type": "mouse_move", "x": round(x, 2), "y": round(y, 2)},
          {"frame": 10, "type": "button_down", "button": "left"},
          {"frame": 11, "type": "button_up", "button": "left"},
          {"frame": 12, "type": "key", "key": "G"}]
frames, radius = 600, 30.0
for i in range(frames):
    a = 2 * math.pi * 2 * (i + 1) / frames
    events.append({"frame": 13 + i, "type": "mouse_move", "x": round(x - radius * math.sin(a), 2),
                   "y": round(y + radius * (1 - math.cos(a)), 2)})
events.append({"frame": 13 + frames, "type": "key", "key": "ESCAPE"})
for e in events:
    print(json.dumps(e))
PY
echo "$size lattice point drag:"
run "$tmp/drag.jsonl" --report-frame-times --dump-state "$tmp/state.json" | tee "$tmp/drag.txt"
python3 - "$tmp/state.json" <<'PY'
import json, sys
e = json.load(open(sys.argv[1]))["lattice_edit"]
if e.get("selected") != [23]:
    sys.exit(f"lattice_frame_times.sh: the click missed point 23 (selected {e.get('selected')})")
PY
echo "$size empty ImGui frame:"
# The same frames and mouse moves; without panels there is no button to name.
grep -v '"item"' "$tmp/drag.jsonl" > "$tmp/empty.jsonl"
run "$tmp/empty.jsonl" --report-frame-times --empty-frame | tee "$tmp/empty.txt"
python3 - "$tmp/drag.txt" "$tmp/empty.txt" "$size lattice drag / empty frame" <<'PY'
import re, sys
def median(path):
    m = re.findall(r"median ([0-9.]+) ms", open(path).read())
    return float(m[-1]) if m else float("nan")
a, b = median(sys.argv[1]), median(sys.argv[2])
print(f"{sys.argv[3]}: {a:.2f} / {b:.2f} ms = {a / b:.2f}x")
PY
