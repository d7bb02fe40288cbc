#!/usr/bin/env bash
# Editor frame time on llvmpipe at 1280x800 while a clip plays (600 frames): the CMU take
# (shared data) with the onion skin off, then on (2 ghosts before, 2 after: Alt+O).
# Usage: bench/editor/playback_frame_times.sh [build/src/kinema] [file.bvh]
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
kinema=${1:-$root/build/src/kinema}
file=${2:-$root/../shared/data/bvh/cmu_01_01_first720.bvh}
tmp=$(mktemp -d)
# The same playback with Alt+O pressed before Space.
sed 's/{"frame": 3, "type": "key", "key": "SPACE"}/{"frame": 3, "type": "key", "key": "O", "mods": ["alt"]}\n{"frame": 4, "type": "key", "key": "SPACE"}/' \
  "$root/bench/editor/playback_1280x800.jsonl" > "$tmp/onion.jsonl"
run() {
  XDG_STATE_HOME=$tmp XDG_CONFIG_HOME=$tmp LIBGL_ALWAYS_SOFTWARE=1 MESA_GL_VERSION_OVERRIDE=3.3 \
    xvfb-run -a -s "-screen 0 1280x800x24" "$kinema" edit "$file" --size 1280x800 --report-frame-times "$@" 2>&1
}
echo "playback, onion skin off:"; run --script "$root/bench/editor/playback_1280x800.jsonl"
echo "playback, onion skin on (4 ghosts):"; run --script "$tmp/onion.jsonl"
rm -rf "$tmp"
