#!/usr/bin/env bash
# Editor frame time on llvmpipe while a clip plays (600 frames): the CMU take (shared data)
# with the onion skin off, then on (2 ghosts before, 2 after: Alt+O), at 1280x800 and
# 1600x1000 (or the one size given), and an empty ImGui frame of the same size; each size
# ends with the ratios of the medians to the empty frame's, against each of its runs (the
# issue 20 bound: at most 1.5).
# Preferences, recovery files and caches go to a temporary folder.
# Usage: bench/editor/playback_frame_times.sh [build/src/kinema] [file.bvh] [WIDTHxHEIGHT]
set -euo pipefail
# KINEMA_EDIT_OPTIONS: more options for the measured runs (not the empty frame), e.g.
# "--redraw whole" to time drawing every frame whole (the default on llvmpipe: changed only).
read -r -a extra <<< "${KINEMA_EDIT_OPTIONS:-}"
root=$(cd "$(dirname "$0")/../.." && pwd)
kinema=${1:-$root/build/src/kinema}
file=${2:-$root/../shared/data/bvh/cmu_01_01_first720.bvh}
sizes=${3:-"1280x800 1600x1000"}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
# The same playback with Alt+O pressed before Space.
sed 's/{"frame": 3, "type": "key", "key": "SPACE"}/{"frame": 3, "type": "key", "key": "O", "mods": ["alt"]}\n{"frame": 4, "type": "key", "key": "SPACE"}/' \
  "$root/bench/editor/playback.jsonl" > "$tmp/onion.jsonl"
run() {  # size [options...]
  local size=$1
  shift
  XDG_STATE_HOME=$tmp XDG_CONFIG_HOME=$tmp XDG_CACHE_HOME=$tmp XDG_DATA_HOME=$tmp \
    LIBGL_ALWAYS_SOFTWARE=1 MESA_GL_VERSION_OVERRIDE=3.3 \
    sh "$root/tests/tools/xvfb_run.sh" "${size}x24" "$kinema" edit "$file" --size "$size" --report-frame-times "$@" 2>&1
}
. "$root/bench/editor/empty_frame_ratio.sh"
for size in $sizes; do
  echo "$size playback, onion skin off:"; run "$size" --script "$root/bench/editor/playback.jsonl" ${extra[@]+"${extra[@]}"} | tee "$tmp/off.txt"
  echo "$size playback, onion skin on (4 ghosts):"; run "$size" --script "$tmp/onion.jsonl" ${extra[@]+"${extra[@]}"} | tee "$tmp/on.txt"
  echo "$size empty ImGui frame:"; empties "$size" --script "$root/bench/editor/playback.jsonl"
  ratio "$tmp/off.txt" "$size playback, onion skin off / empty frame" "$tmp"/empty[0-9]*.txt
  ratio "$tmp/on.txt" "$size playback, onion skin on / empty frame" "$tmp"/empty[0-9]*.txt
done
