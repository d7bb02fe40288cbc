#pragma once
#include <string>
#include <vector>

#include "core/mesh.h"

namespace kinema {

// The default character's expression shapes, in this order (morph target index = position).
extern const std::vector<std::string> kDefaultFaceShapeNames;  // jaw_open, smile, brow_raise, blink

// Where the default character's face features sit on its head (bind space = the T-pose's
// world space, metres, facing +Z): points on the head's front, mirrored pairs on +x.
struct DefaultFaceLandmarks {
  float chinY = 0.0f, mouthY = 0.0f, eyeY = 0.0f, browY = 0.0f;  // heights
  float mouthX = 0.0f, eyeX = 0.0f, browX = 0.0f;                // +x of the left feature
  // The head's front surface point at (x, y): on the ellipsoid the body's head is built from.
  float frontZ(float x, float y) const;
  float centerY = 0.0f, centerZ = 0.0f;
  float radius[3] = {0.0f, 0.0f, 0.0f};
};
DefaultFaceLandmarks defaultFaceLandmarks();

// Adds the four expression shapes to `body` (the default character's body primitive, in bind
// space) as morph targets, each made by the project's own deformers and baked with
// shapeFromDeformation ("Apply deformer as shape"): soft pulls around vertices picked next
// to the landmarks (the seed's "seed vertex"), the jaw limited by a weight map to below the
// mouth. jaw_open drops and pulls back the chin; smile lifts and widens the mouth corners;
// brow_raise lifts both brows; blink pushes the eyes' fronts down and in. Weights 0..1.
void addDefaultFaceShapes(MeshPrimitive& body);

}  // namespace kinema
