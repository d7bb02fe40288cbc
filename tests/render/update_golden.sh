#!/usr/bin/env bash
# Regenerates the golden images in tests/render/golden/ with the built binary, on llvmpipe
# (LIBGL_ALWAYS_SOFTWARE=1 forces it even on a GPU host). LOOK at every image before committing.
# Usage: tests/render/update_golden.sh [build/src/kinema]
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
kinema=${1:-$root/build/src/kinema}
golden=$root/tests/render/golden
export LIBGL_ALWAYS_SOFTWARE=1 MESA_GL_VERSION_OVERRIDE=3.3
"$kinema" render --size 320x240 --out "$golden/default_character.png"
"$kinema" render "$root/../shared/data/bvh/cmu_01_01_first720.bvh" --frame 240 --select LeftArm --size 320x240 \
  --out "$golden/cmu_01_01_frame240.png"
"$kinema" render "$root/../shared/data/gltf/CesiumMan.glb" --time 1 --size 320x240 --out "$golden/cesium_man_t1.png"
"$(dirname "$kinema")/../tests/kinema_overlay_sample" "$golden/overlay_gizmo.png" egl
# The posed default character is rendered in-process (the test poses named joints itself).
KINEMA_UPDATE_GOLDEN=1 "$(dirname "$kinema")/../tests/kinema_tests" --gtest_filter='DefaultCharacterRender.*'
