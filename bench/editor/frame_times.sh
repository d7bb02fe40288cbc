#!/usr/bin/env bash
# Editor frame time on llvmpipe at 1280x800: the default character during a 600-frame IK
# drag, against an empty ImGui frame of the same size and frame count.
# Usage: bench/editor/frame_times.sh [build/src/kinema]
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
kinema=${1:-$root/build/src/kinema}
tmp=$(mktemp -d)
run() {
  XDG_STATE_HOME=$tmp XDG_CONFIG_HOME=$tmp LIBGL_ALWAYS_SOFTWARE=1 MESA_GL_VERSION_OVERRIDE=3.3 \
    xvfb-run -a -s "-screen 0 1280x800x24" "$kinema" edit --size 1280x800 \
    --script "$root/bench/editor/ik_drag_1280x800.jsonl" --report-frame-times "$@" 2>&1
}
echo "IK drag:"; run
echo "empty ImGui frame:"; run --empty-frame
rm -rf "$tmp"
