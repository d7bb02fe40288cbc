#!/usr/bin/env bash
# Editor frame time on llvmpipe: the default character during a 600-frame IK drag, against an
# empty ImGui frame of the same size and frame count, at 1280x800 and 1600x1000 (or the one
# size given). The drag scripts come from make_ik_drag_script.py; each run's --dump-state is
# checked for the IK target it adds, so a script that misses the hand fails here instead of
# timing a box select. Preferences, recovery files and caches go to a temporary folder.
# Each size ends with the ratio of the medians, against each of the empty frame's runs (the
# issue 20 bound: at most 1.5).
# Usage: bench/editor/frame_times.sh [build/src/kinema] [WIDTHxHEIGHT]
set -euo pipefail
# KINEMA_EDIT_OPTIONS: more options for the measured runs (not the empty frame), e.g.
# "--redraw whole" to time drawing every frame whole (the default on llvmpipe: changed only).
read -r -a extra <<< "${KINEMA_EDIT_OPTIONS:-}"
root=$(cd "$(dirname "$0")/../.." && pwd)
kinema=${1:-$root/build/src/kinema}
sizes=${2:-"1280x800 1600x1000"}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
run() {  # size script [options...]
  local size=$1 script=$2
  shift 2
  XDG_STATE_HOME=$tmp XDG_CONFIG_HOME=$tmp XDG_CACHE_HOME=$tmp XDG_DATA_HOME=$tmp \
    LIBGL_ALWAYS_SOFTWARE=1 MESA_GL_VERSION_OVERRIDE=3.3 \
    sh "$root/tests/tools/xvfb_run.sh" "${size}x24" "$kinema" edit --size "$size" --script "$script" --report-frame-times "$@" 2>&1
}
. "$root/bench/editor/empty_frame_ratio.sh"
for size in $sizes; do
  script=$root/bench/editor/ik_drag_$size.jsonl
  echo "$size IK drag:"
  run "$size" "$script" --dump-state "$tmp/state.json" ${extra[@]+"${extra[@]}"} | tee "$tmp/drag.txt"
  if ! python3 -c 'import json,sys; sys.exit(0 if len(json.load(open(sys.argv[1]))["ik_targets"]) == 1 else 1)' "$tmp/state.json"; then
    echo "frame_times.sh: $script added no IK target (it missed the hand: regenerate it with make_ik_drag_script.py)" >&2
    exit 1
  fi
  echo "$size empty ImGui frame:"
  empties "$size" "$script"
  ratio "$tmp/drag.txt" "$size IK drag / empty frame" "$tmp"/empty[0-9]*.txt
done
