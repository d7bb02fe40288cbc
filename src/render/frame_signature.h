#pragma once
#include <cstdint>

namespace kinema {

struct FrameDescription;

// A 64-bit digest (FNV-1a) of everything a FrameDescription makes SkeletonRenderer::draw
// show: camera, viewport, switches, the skeleton's and ghosts' instances, the overlay, and
// the meshes' poses, morph weights and ghost tints (not the uploaded meshes themselves: mix
// in the upload's revision). Equal digests on two frames: the same picture (barring a 2^-64
// collision), so the editor can show the kept one instead of drawing it again.
uint64_t frameSignature(const FrameDescription& frame);

// The same digest of everything apart from the elements SceneDamageJob compares one by one
// (the skeleton's and its ghosts' bones, joints and relationship lines, the overlay, and the
// vertices of meshes posed on the CPU, MeshFrame::posed): camera, viewport, switches, grid,
// the number of skeleton ghosts, the mesh ghosts, the
// meshes' joints and morph weights when they are not posed on the CPU, and how many
// primitives are deformed on the CPU (MeshFrame::deformed; their vertices are compared).
uint64_t frameSettingsSignature(const FrameDescription& frame);

}  // namespace kinema
