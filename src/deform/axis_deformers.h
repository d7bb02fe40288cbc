#pragma once
#include <string>

#include "core/math.h"

namespace kinema {

// Barr's global deformations (Barr 1984, "Global and local deformations of solid
// primitives"): bend, twist and taper along one axis of the mesh's space.
enum class AxisDeformerKind { Bend, Twist, Taper };
enum class DeformAxis { X = 0, Y = 1, Z = 2 };

const char* toString(AxisDeformerKind kind);
bool fromString(const std::string& s, AxisDeformerKind& out);
const char* toString(DeformAxis axis);
bool fromString(const std::string& s, DeformAxis& out);

// One deformer. Coordinates are taken relative to `origin` in the deformer's space (mesh
// space, or a joint's when parented; see DeformerStack): a = the coordinate along `axis`,
// b = along the next axis (X -> Y -> Z -> X, the direction a bend turns towards), c = the
// third. The deformer acts on a in [low, high] (metres from origin, low < high); H = high - low
// and h = clamp(a - low, 0, H).
//  Twist  turns a point about the axis by amount * h / H radians (right-handed about +axis):
//         nothing below low, the full angle above high.
//  Taper  scales b and c by 1 + (amount - 1) * h / H: 1 at low, `amount` (> 0 ... any real)
//         at high and above.
//  Bend   curves the range into a circular arc of `amount` radians turning from +axis towards
//         +b, so the bent range keeps its length along the axis; below low nothing moves,
//         above high points follow the arc's end tangent rigidly.
struct AxisDeformer {
  AxisDeformerKind kind = AxisDeformerKind::Bend;
  DeformAxis axis = DeformAxis::Y;
  glm::vec3 origin{0.0f};
  float low = 0.0f, high = 1.0f;
  float amount = 0.0f;  // Bend, Twist: radians over the range; Taper: the scale at high

  // Empty when usable (finite values, low < high); otherwise one sentence.
  std::string validate() const;
};

// The deformed position of p (the closed forms above; valid() assumed).
glm::vec3 applyAxisDeformer(const AxisDeformer& deformer, const glm::vec3& p);

}  // namespace kinema
