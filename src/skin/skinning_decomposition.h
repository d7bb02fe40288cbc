#pragma once
#include "core/math.h"

namespace kinema {

// How dual quaternion skinning splits a skinning matrix M (model space to model space)
// as M p = R (S p) + t: the rigid part (R, t) as a unit dual quaternion (real = R,
// dual = 0.5 (0, t) R) and the rest S = R^T A (A = M's upper 3x3: scale and shear, blended
// linearly first, Kavan's two-phase scheme). One implementation for both skinning paths:
// the CPU job (dual_quaternion_skinning.cpp) and the GPU's joint texels (render/
// mesh_renderer.cpp packJointTexels), so they deform alike whatever the matrix.
struct SkinningDecomposition {
  glm::quat real{1.0f, 0.0f, 0.0f, 0.0f};  // unit: R
  glm::quat dual{0.0f, 0.0f, 0.0f, 0.0f};  // 0.5 (0, t) real
  glm::mat3 stretch{1.0f};                  // S = R^T A
};

// The rotation nearest A: the rotation of A's polar decomposition A = R P (P symmetric
// positive), so S = R^T A is as close to a pure stretch as A allows (Higham's iteration in
// double). A reflection (det < 0) is negated into a rotation, the sign moving into S. A
// singular A (a joint scaled to zero along an axis, a collapsed bone) has no polar rotation;
// its longest columns are orthonormalised instead, so a joint flattened along one axis keeps
// the rotation it had (A = R diag(1, 0, 1) gives R). A zero matrix gives the identity.
glm::mat3 nearestRotation(const glm::mat3& a);

// M split with R = nearestRotation(A).
SkinningDecomposition decomposeSkinningMatrix(const glm::mat4& m);
// M split with the rotation given: for callers that know A = s Q with Q orthogonal
// (every joint sharing one uniform scale), where R = A / s needs no iteration.
SkinningDecomposition decomposeSkinningMatrix(const glm::mat4& m, const glm::mat3& rotation);

}  // namespace kinema
