#!/usr/bin/env bash
# Regenerates the README's images with the built binary (llvmpipe, so any host gives the same).
# Usage: docs/images/regenerate.sh [build/src/kinema]
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
kinema=${1:-$root/build/src/kinema}
export LIBGL_ALWAYS_SOFTWARE=1 MESA_GL_VERSION_OVERRIDE=3.3
cd "$root"  # the editor shows the path it was given: keep it short
bvh=../shared/data/bvh/cmu_01_01_first720.bvh
xvfb-run -a -s "-screen 0 1280x800x24" "$kinema" edit "$bvh" --frame-count 5 --screenshot "$root/docs/images/editor.png"
"$kinema" render "$bvh" --frame 240 --select LeftArm --size 960x540 --out "$root/docs/images/render_cmu_frame240.png"
"$kinema" render ../shared/data/gltf/CesiumMan.glb --time 1 --bones xray --size 960x540 --out "$root/docs/images/skinned_cesium_man.png"
"$kinema" render ../shared/data/gltf/Fox.glb --clip 2 --time 0.6 --camera 60,15 --size 960x540 --out "$root/docs/images/skinned_fox.png"
# The editor's FK gizmo and IK drag, posed by replaying recorded input (kinema edit --script);
# XDG folders point away from the user's recent files and recovery files.
tmp=$(mktemp -d)
for shot in editor_fk_gizmo editor_ik_drag; do
  XDG_STATE_HOME=$tmp XDG_CONFIG_HOME=$tmp xvfb-run -a -s "-screen 0 1280x800x24" "$kinema" edit \
    --script "$root/docs/images/$shot.jsonl" --frame-count 40 --screenshot "$root/docs/images/$shot.png"
done
rm -rf "$tmp"
# The timeline with the keyframe diamonds of the selected joint (issue 9).
tmp=$(mktemp -d)
XDG_STATE_HOME=$tmp XDG_CONFIG_HOME=$tmp xvfb-run -a -s "-screen 0 1280x800x24" "$kinema" edit \
  --size 1280x800 --script "$root/docs/images/editor_timeline_keys.jsonl" --screenshot "$root/docs/images/editor_timeline_keys.png"
rm -rf "$tmp"
