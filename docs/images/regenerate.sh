#!/usr/bin/env bash
# Regenerates the README's images with the built binary (llvmpipe, so any host gives the same).
# Usage: docs/images/regenerate.sh [build/src/kinema]
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
kinema=${1:-$root/build/src/kinema}
export LIBGL_ALWAYS_SOFTWARE=1 MESA_GL_VERSION_OVERRIDE=3.3
cd "$root"  # the editor shows the path it was given: keep it short
bvh=../shared/data/bvh/cmu_01_01_first720.bvh
tmp=$(mktemp -d)  # the user's preferences (window size, UI scale) stay out of it
XDG_STATE_HOME=$tmp XDG_CONFIG_HOME=$tmp xvfb-run -a -s "-screen 0 1280x800x24" "$kinema" edit "$bvh" --size 1280x720 \
  --frame-count 5 --screenshot "$root/docs/images/editor.png"
rm -rf "$tmp"
# The editor at UI scale 1 and at the presentation preset (issue 18) on a 1600x1000 screen.
for shot in editor_scale1 editor_presentation; do
  tmp=$(mktemp -d)
  XDG_STATE_HOME=$tmp XDG_CONFIG_HOME=$tmp xvfb-run -a -s "-screen 0 1600x1000x24" "$kinema" edit "$bvh" --size 1600x1000 \
    --script "$root/docs/images/$shot.jsonl" --screenshot "$root/docs/images/$shot.png"
  rm -rf "$tmp"
done
"$kinema" render "$bvh" --frame 240 --select LeftArm --size 960x540 --out "$root/docs/images/render_cmu_frame240.png"
"$kinema" render ../shared/data/gltf/CesiumMan.glb --time 1 --bones xray --size 960x540 --out "$root/docs/images/skinned_cesium_man.png"
"$kinema" render ../shared/data/gltf/Fox.glb --clip 2 --time 0.6 --camera 60,15 --size 960x540 --out "$root/docs/images/skinned_fox.png"
# File > Import Motion onto Character...'s bone-map dialog on the default character (issue 21).
tmp=$(mktemp -d)
XDG_STATE_HOME=$tmp XDG_CONFIG_HOME=$tmp sh "$root/tests/tools/xvfb_run.sh" 1600x1000x24 "$kinema" edit --size 1400x900 \
  --script "$root/docs/images/import_motion.jsonl" --frame-count 20 --screenshot "$root/docs/images/import_motion.png"
rm -rf "$tmp"
# The foot contacts on the timeline and the Clean Up window (issue 21), on the CMU take
# retargeted onto the default character (the .kinema keeps its contacts and bone map).
tmp=$(mktemp -d)
"$kinema" retarget "$bvh" --out "$tmp/cmu_on_default.kinema"
XDG_STATE_HOME=$tmp XDG_CONFIG_HOME=$tmp sh "$root/tests/tools/xvfb_run.sh" 1600x1000x24 "$kinema" edit "$tmp/cmu_on_default.kinema" \
  --size 1400x900 --script "$root/docs/images/foot_contacts.jsonl" --frame-count 20 --screenshot "$tmp/contacts.png"
# The strip and the timeline under it, the whole width.
convert "$tmp/contacts.png" -gravity South -crop 1400x150+0+0 +repage "$root/docs/images/foot_contacts_timeline.png"
XDG_STATE_HOME=$tmp XDG_CONFIG_HOME=$tmp sh "$root/tests/tools/xvfb_run.sh" 1600x1000x24 "$kinema" edit "$tmp/cmu_on_default.kinema" \
  --size 1400x900 --script "$root/docs/images/clean_up.jsonl" --frame-count 16 --screenshot "$root/docs/images/clean_up_motion.png"
rm -rf "$tmp"
# The CMU take and the default character playing it after `kinema retarget` (issue 21), frame 150.
tmp=$(mktemp -d)
"$kinema" retarget "$bvh" --out "$tmp/cmu_on_default.kinema" --fix-feet
"$kinema" render "$bvh" --frame 150 --size 560x640 --camera 30,10 --out "$tmp/source.png"
"$kinema" render "$tmp/cmu_on_default.kinema" --frame 150 --size 560x640 --camera 30,10 --out "$tmp/target.png"
convert "$tmp/source.png" "$tmp/target.png" +append "$root/docs/images/retarget_cmu_default.png"
rm -rf "$tmp"
# The editor's FK gizmo and IK drag, posed by replaying recorded input (kinema edit --script);
# XDG folders point away from the user's recent files and recovery files.
tmp=$(mktemp -d)
for shot in editor_fk_gizmo editor_ik_drag; do
  XDG_STATE_HOME=$tmp XDG_CONFIG_HOME=$tmp xvfb-run -a -s "-screen 0 1280x800x24" "$kinema" edit --size 1280x720 \
    --script "$root/docs/images/$shot.jsonl" --frame-count 40 --screenshot "$root/docs/images/$shot.png"
done
rm -rf "$tmp"
# Lattice edit mode (issue 22): a lattice added to the default character, the top layer's
# middle column box-selected and moved up with G, Y (the head follows), the view orbited.
tmp=$(mktemp -d)
XDG_STATE_HOME=$tmp XDG_CONFIG_HOME=$tmp sh "$root/tests/tools/xvfb_run.sh" 1280x800x24 "$kinema" edit --size 1280x800 \
  --script "$root/docs/images/lattice_edit.jsonl" --frame-count 56 --screenshot "$root/docs/images/lattice_edit.png"
rm -rf "$tmp"
# The timeline with the keyframe diamonds of the selected joint (issue 9).
tmp=$(mktemp -d)
XDG_STATE_HOME=$tmp XDG_CONFIG_HOME=$tmp xvfb-run -a -s "-screen 0 1280x800x24" "$kinema" edit \
  --size 1280x800 --script "$root/docs/images/editor_timeline_keys.jsonl" --screenshot "$root/docs/images/editor_timeline_keys.png"
rm -rf "$tmp"
# The curve editor: the last frame of its README e2e test (tests/editor/curve_editor_e2e_test.cpp).
"$root/build/tests/kinema_tests" --gtest_filter=CurveEditorE2e.ReadmeScreenshotNormalizedWithABezierKey
cp "$root/build/curve_editor_e2e/curve_editor_readme.png" "$root/docs/images/curve_editor.png"
# Onion skin + the left hand's motion path on the CMU take (editor_onion_path.jsonl).
tmp=$(mktemp -d)
XDG_STATE_HOME=$tmp XDG_CONFIG_HOME=$tmp xvfb-run -a -s "-screen 0 1280x800x24" "$kinema" edit "$bvh" --size 1280x800 \
  --script "$root/docs/images/editor_onion_path.jsonl" --screenshot "$root/docs/images/editor_onion_path.png"
rm -rf "$tmp"
# docs/teaching/ (figures of docs/teaching.md): docs/teaching/regenerate.sh
"$root/docs/teaching/regenerate.sh" "$kinema"
# Teach > Compare Solvers (docs/teaching-editor.md): the editor opened on a preset, stepped by
# recorded keys.
tmp=$(mktemp -d)
XDG_STATE_HOME=$tmp XDG_CONFIG_HOME=$tmp xvfb-run -a -s "-screen 0 1280x800x24" "$kinema" edit --compare fabrik-steps \
  --size 1280x720 --script "$root/docs/images/compare_solvers.jsonl" --frame-count 10 --screenshot "$root/docs/images/compare_solvers.png"
XDG_STATE_HOME=$tmp XDG_CONFIG_HOME=$tmp xvfb-run -a -s "-screen 0 1280x800x24" "$kinema" edit --compare near-root \
  --size 1280x720 --script "$root/docs/images/compare_solvers_near_root.jsonl" --frame-count 10 --screenshot "$root/docs/images/compare_solvers_near_root.png"
rm -rf "$tmp"
# The dope sheet: made by its end-to-end test (a clip written by the test, a box selection).
build=$(cd "$(dirname "$kinema")/.." && pwd)
"$build/tests/kinema_tests" --gtest_filter=DopeSheetE2e.ScreenshotForTheReadme >/dev/null
cp "$build/dope_sheet_e2e/dope_sheet.png" "$root/docs/images/dope_sheet.png"
# L-system plants (issue 24): the seed's derivation, and a stochastic bush, rendered by Kinema.
tmp=$(mktemp -d)
"$kinema" lsystem "$root/docs/examples/lsystems/seed_plant.lsys" --generations 5 --choices 0,0,0,1,0,1,1,1 --out "$tmp/seed.kinema"
"$kinema" render "$tmp/seed.kinema" --out "$root/docs/images/lsystem_seed_plant.png" --size 480x480 --bones none --camera 0,10,7
"$kinema" lsystem "$root/docs/examples/lsystems/bush.lsys" --generations 6 --seed 3 --segment-length 0.3 --out "$tmp/bush.gltf"
"$kinema" render "$tmp/bush.gltf" --out "$root/docs/images/lsystem_bush.png" --size 640x480 --bones none --camera 0,12,6.6
# Game of Life (issue 24): the demo's snapshot sheet.
"$kinema" demo life --out "$tmp/life" --size 640x400 >/dev/null
cp "$tmp/life/snapshots.png" "$root/docs/images/life_snapshots.png"
rm -rf "$tmp"
# Boids (issue 24): priority allocation against the naive average.
tmp=$(mktemp -d)
"$kinema" demo boids --out "$tmp/boids" --size 960x640 >/dev/null
cp "$tmp/boids/priority.png" "$root/docs/images/boids_priority.png"
cp "$tmp/boids/average.png" "$root/docs/images/boids_average.png"
rm -rf "$tmp"
# Deformers and the face (issue 22): the default character with a lattice (before / after),
# a bend, a twist and a taper, and its four expression shapes at full weight.
tmp=$(mktemp -d)
python3 "$root/docs/images/deformer_scenes.py" "$root/assets/default_character.kinema" "$tmp"
for n in rest lattice bend twist taper; do
  "$kinema" render "$tmp/$n.kinema" --bones none --camera 35,10 --size 400x560 --out "$tmp/$n.png"
  convert "$tmp/$n.png" -crop 240x300+80+130 +repage "$tmp/c_$n.png"
done
convert "$tmp/c_rest.png" "$tmp/c_lattice.png" +append "$root/docs/images/deform_lattice.png"
convert "$tmp/c_rest.png" "$tmp/c_bend.png" "$tmp/c_twist.png" "$tmp/c_taper.png" +append "$root/docs/images/deform_bend_twist_taper.png"
for n in neutral jaw_open smile brow_raise blink; do
  "$kinema" render "$tmp/face_$n.kinema" --bones none --camera 0,0,3.2 --size 1200x1600 --out "$tmp/face_$n.png"
  convert "$tmp/face_$n.png" -crop 220x220+490+60 +repage "$tmp/c_face_$n.png"
done
convert "$tmp"/c_face_{neutral,jaw_open,smile,brow_raise,blink}.png +append "$root/docs/images/face_shapes.png"
rm -rf "$tmp"
# Issue 24: a crowd of CesiumMen round an obstacle (kinema simulate + render) and the editor's
# Crowd panel with one member's impulse vectors.
"$root/docs/images/crowd_pictures.sh" "$kinema"
# Issue 23: Fox's swinging tail and a ragdoll fall, baked by `kinema simulate` and rendered.
"$root/docs/images/physics_strips.sh" "$kinema"
# Issue 23: a collision capsule on Fox's left thigh for its dynamic tail (Simulate > Add
# Collision Capsule), drawn in the 3D view; Teach > Stiff Springs as it opens.
tmp=$(mktemp -d)
XDG_STATE_HOME=$tmp XDG_CONFIG_HOME=$tmp sh "$root/tests/tools/xvfb_run.sh" 1280x800x24 "$kinema" edit ../shared/data/gltf/Fox.glb \
  --size 1280x720 --script "$root/docs/images/fox_capsule.jsonl" --screenshot "$root/docs/images/fox_capsule.png"
XDG_STATE_HOME=$tmp XDG_CONFIG_HOME=$tmp sh "$root/tests/tools/xvfb_run.sh" 1280x800x24 "$kinema" edit \
  --size 1280x720 --script "$root/docs/images/stiff_springs_window.jsonl" --screenshot "$root/docs/images/stiff_springs_window.png"
rm -rf "$tmp"
# Issue 24: particles from a joint, the L-system plant growing and swaying (strips and GIFs).
"$root/docs/images/procedural_figures.sh" "$kinema"
