#!/bin/sh
# Issue 24's pictures, made by Kinema: sparks from the default character's waving hand
# falling and bouncing (particles_sparks_strip.png, particles_sparks.gif), the seed's
# L-system plant growing generation by generation (lsystem_growth_strip.png), and a bush
# swaying in the wind with noise modifiers on its joints (lsystem_sway_strip.png,
# lsystem_sway.gif). GIFs need ffmpeg (Debian's `ffmpeg`); without it only the strips are
# made. Usage: procedural_figures.sh BUILD/src/kinema
set -eu
kinema=$1
root=$(cd "$(dirname "$0")/../.." && pwd)
out="$root/docs/images"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

# ffmpeg: frames DIR/frame_*.png at RATE fps into a GIF with a palette made from the frames.
gif() {
  if command -v ffmpeg >/dev/null 2>&1; then
    ffmpeg -y -loglevel error -framerate "$2" -pattern_type glob -i "$1/frame_*.png" \
      -vf "split[a][b];[a]palettegen=reserve_transparent=0[p];[b][p]paletteuse" "$3"
  else
    echo "procedural_figures.sh: ffmpeg is not installed (apt-get install ffmpeg): no $3" >&2
  fi
}

# Sparks: the default character raises and lowers its right arm over 3 s; a joint emitter
# on its hand throws sparks upwards in a 30° cone; they fall under gravity and bounce on the
# ground, keeping 55 % of their normal speed.
python3 - "$root/assets/default_character.kinema" "$tmp/sparks.kinema" <<'PY'
import json, math, sys
d = json.load(open(sys.argv[1]))
def about_z(a):
    return [0.0, 0.0, math.sin(a / 2), math.cos(a / 2)]
d["clips"] = [{"name": "wave", "frame_time": 1 / 30, "channels": [
    {"joint": "UpperArm.R", "target": "rotation", "interpolation": "linear",
     "times": [0.0, 1.5, 3.0], "values": [about_z(1.1), about_z(-0.7), about_z(1.1)]}]}]
d["simulation"] = {"particles": [{
    "name": "sparks", "seed": 11, "max_particles": 20000,
    "emitters": [{"kind": "joint", "joint": "Hand.R", "direction": [0, 1, 0], "cone_deg": 30,
                  "speed": {"mean": 2.8, "spread": 0.9},
                  "rate": {"mean": 90, "spread": 30},
                  "lifetime": {"mean": 1.6, "spread": 0.4}}],
    "forces": {"gravity": [0, -9.81, 0], "drag": 0.3, "ground": True, "restitution": 0.55, "friction": 0.2},
    "draw": {"style": "quads", "size": 0.03, "colour": [1.0, 0.62, 0.12, 1.0]}}]}
json.dump(d, open(sys.argv[2], "w"))
PY
"$kinema" simulate "$tmp/sparks.kinema" --frames 0:89 --render "$tmp/sparks" --size 400x300 --camera 25,14,5.2 >/dev/null 2>&1
montage $(ls "$tmp"/sparks/frame_*.png | awk 'NR % 15 == 11') -tile x1 -geometry +0+0 "$out/particles_sparks_strip.png"
mkdir -p "$tmp/sparks_gif"
for f in $(ls "$tmp"/sparks/frame_*.png | awk 'NR % 2 == 1'); do
  convert "$f" -resize 320x240 "$tmp/sparks_gif/$(basename "$f")"
done
gif "$tmp/sparks_gif" 15 "$out/particles_sparks.gif"

# The seed's plant (S->A, A->[+B]fA, A->B, B->fB, B->f@, its own choices) after 2..5
# generations (1 is "A", no segment yet), each drawn from the same camera angle.
mkdir -p "$tmp/grow"
for n in 2 3 4 5; do
  "$kinema" lsystem "$root/docs/examples/lsystems/seed_plant.lsys" --generations $n --choices 0,0,0,1,0,1,1,1 \
    --out "$tmp/grow/gen$n.kinema" >/dev/null
  "$kinema" render "$tmp/grow/gen$n.kinema" --size 240x300 --bones none --camera 0,10,7 --out "$tmp/grow/frame_$n.png" 2>/dev/null
done
montage "$tmp"/grow/frame_*.png -tile x1 -geometry +0+0 "$out/lsystem_growth_strip.png"

# The bush swaying: every branch joint keyed at rest, with a noise modifier (0.15 rad about
# x and z, 0.7 s cells, two octaves, its own seed) on its rotation: wind made of noise.
# (Gradient noise is 0 on whole cells: the strip's frames, every 20th, fall between them.)
"$kinema" lsystem "$root/docs/examples/lsystems/bush.lsys" --generations 6 --seed 3 --segment-length 0.3 \
  --out "$tmp/bush.kinema" >/dev/null
python3 - "$tmp/bush.kinema" <<'PY'
import json, sys
p = sys.argv[1]
d = json.load(open(p))
channels = []
for i, j in enumerate(d["skeleton"]["joints"]):
    if j["parent"] < 0:
        continue
    r = j.get("rotation", [0, 0, 0, 1])
    channels.append({"joint": j["name"], "target": "rotation", "interpolation": "linear",
                     "times": [0.0, 4.0], "values": [r, r],
                     "modifiers": [{"type": "noise", "components": "xz", "strength": 0.15, "scale": 0.7,
                                    "octaves": 2, "seed": i}]})
d["clips"] = [{"name": "wind", "frame_time": 1 / 30, "channels": channels}]
json.dump(d, open(p, "w"))
PY
mkdir -p "$tmp/sway"
"$kinema" render "$tmp/bush.kinema" --frames 0:119 --size 320x240 --bones none --camera 0,12,6.6 \
  --out "$tmp/sway/frame_%04d.png" 2>/dev/null
montage $(ls "$tmp"/sway/frame_*.png | awk 'NR % 20 == 11') -tile x1 -geometry +0+0 "$out/lsystem_sway_strip.png"
mkdir -p "$tmp/sway_gif"
for f in $(ls "$tmp"/sway/frame_*.png | awk 'NR % 2 == 1'); do cp "$f" "$tmp/sway_gif/"; done
gif "$tmp/sway_gif" 15 "$out/lsystem_sway.gif"

# The editor: Hand.R selected, Simulate > Add Particle Emitter, 40 frames on (the Particles
# window open on the new system).
python3 - "$tmp/sparks.kinema" "$tmp/wave.kinema" "$tmp/particles.jsonl" <<'PY'
import json, sys
d = json.load(open(sys.argv[1]))
del d["simulation"]
json.dump(d, open(sys.argv[2], "w"))
events = [{"type": "key", "key": "KP_1"}, {"type": "key", "key": "HOME"},
          {"type": "mouse_move", "item": "Outliner/Hand.R"}, {"type": "button_down", "button": "left"},
          {"type": "button_up", "button": "left"}, {"type": "command", "id": "sim.add_particle_emitter"}]
events += [{"type": "command", "id": "timeline.step_forward"}] * 40
with open(sys.argv[3], "w") as f:
    for i, e in enumerate(events):
        f.write(json.dumps(dict(e, frame=i + 1)) + "\n")
PY
XDG_STATE_HOME=$tmp XDG_CONFIG_HOME=$tmp sh "$root/tests/tools/xvfb_run.sh" 1600x1000x24 "$kinema" edit "$tmp/wave.kinema" \
  --size 1400x900 --script "$tmp/particles.jsonl" --frame-count 52 --screenshot "$out/editor_particles.png" >/dev/null 2>&1
