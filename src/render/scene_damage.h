#pragma once
#include <cstdint>
#include <vector>

#include "core/math.h"
#include "render/overlay_draw_list.h"
#include "render/pixel_rect.h"
#include "render/skeleton_draw_list.h"
#include "evaluation/scene_deformation.h"

namespace kinema {

struct FrameDescription;
struct Scene;

// What one frame of the 3D view showed, element by element: kept by SceneDamageJob to find
// the pixels the next frame changes. Positions are world space, as drawn.
struct SceneSnapshot {
  bool valid = false;       // false: nothing kept (the next frame redraws the whole view)
  uint64_t settings = 0;    // frameSettingsSignature of the frame
  SkeletonDrawList skeleton;
  std::vector<SkeletonDrawList> ghosts;  // onion-skin skeletons (FrameDescription::ghosts)
  OverlayDrawList overlay;
  std::vector<DeformedPrimitive> posed;     // MeshFrame::posed, when the meshes were drawn from it
  std::vector<DeformedPrimitive> deformed;  // MeshFrame::deformed (instances with deformers)
};

// The part of the 3D view (FrameDescription x, y, width, height: framebuffer pixels, rows
// from the bottom) that differs between the picture `last` describes and `frame`'s, so a
// software rasteriser can draw that rectangle alone over the previous picture (the partial
// redraw of Blender 2.7's "Triple Buffer" window draw method). Elements are compared one by
// one: a bone, joint sphere (of the skeleton or one of its onion-skin ghosts), relationship
// line, overlay line, handle or screen shape that
// changed adds its old and new screen bounds; a mesh vertex whose position or normal
// changed (posed on the CPU, MeshFrame::posed, or deformed there, MeshFrame::deformed) adds
// the old and new positions of every triangle around it. Anything else (camera, viewport,
// switches, mesh ghosts, morphs or joints of meshes not posed on the CPU, a different number
// of elements, a point behind the camera, deformers run in the vertex shader) redraws the
// whole view.
// Conservative: bounds are grown by line widths, handle radii and a margin of
// kSceneDamageMargin pixels, and clipped to the view.
constexpr int kSceneDamageMargin = 3;

struct SceneDamageJob {
  const FrameDescription* frame = nullptr;  // the frame about to be drawn
  // The scene the meshes were uploaded from (its triangles' indices), when
  // frame->meshes->frame.posed or .deformed is set; may be null otherwise.
  const Scene* scene = nullptr;
  SceneSnapshot* last = nullptr;  // in: the picture the view shows; out: `frame`'s
  PixelRect out;                  // the damaged part of the view; empty: nothing changed

  bool validate() const { return frame && last; }
  // Fills `out` and replaces *last with `frame`'s snapshot. False (and the whole view in
  // `out`) when the inputs are missing.
  bool run();
};

}  // namespace kinema
