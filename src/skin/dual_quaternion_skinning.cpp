#include "skin/dual_quaternion_skinning.h"

#include <cmath>
#include <vector>

#include "skin/skinning_job_checks.h"

namespace kinema {

namespace {

// A skinning matrix split as M p = R (S p) + t: the rigid part (R, t) as a unit dual
// quaternion (real = R, dual = 0.5 (0, t) R) and the rest S = R^T A (A = M's upper 3x3).
struct JointDualQuaternion {
  float real[4];  // x, y, z, w
  float dual[4];
  float scale[9];  // S, column-major
};

// The rotation of A's polar decomposition A = R P (P symmetric positive): the rotation
// nearest A, so S = R^T A is as close to a pure stretch as A allows. Higham's iteration
// R <- (R + R^-T) / 2 in double, which converges quadratically; a reflection (det < 0) is
// turned into a rotation by negating R, which moves the sign into S.
glm::mat3 nearestRotation(const glm::mat3& a) {
  glm::dmat3 r(a);
  const double det = glm::determinant(r);
  if (!(std::abs(det) > 1e-30) || !std::isfinite(det)) {
    // Singular (a zero scale): any rotation gives A = R (R^T A); Gram-Schmidt keeps what
    // direction information the columns still have.
    glm::dvec3 x = glm::length(r[0]) > 0 ? glm::normalize(r[0]) : glm::dvec3(1, 0, 0);
    glm::dvec3 y = r[1] - glm::dot(r[1], x) * x;
    if (!(glm::length(y) > 1e-12)) y = std::abs(x.x) < 0.9 ? glm::dvec3(1, 0, 0) - x.x * x : glm::dvec3(0, 1, 0) - x.y * x;
    y = glm::normalize(y);
    return glm::mat3(glm::dmat3(x, y, glm::cross(x, y)));
  }
  for (int it = 0; it < 30; ++it) {
    const glm::dmat3 next = 0.5 * (r + glm::transpose(glm::inverse(r)));
    double change = 0;
    for (int c = 0; c < 3; ++c) change += glm::dot(next[c] - r[c], next[c] - r[c]);
    r = next;
    if (change < 1e-24) break;
  }
  if (det < 0) r = -r;
  return glm::mat3(r);
}

JointDualQuaternion decompose(const glm::mat4& m, bool sharedUniform) {
  const glm::mat3 a(m);
  glm::mat3 r;
  if (sharedUniform) {
    // A = s Q with Q orthogonal (sharedSimilarity): R = A / s directly.
    r = a / glm::length(a[0]);
  } else {
    r = nearestRotation(a);
  }
  const glm::quat q = glm::normalize(glm::quat_cast(r));
  const glm::vec3 t(m[3]);
  const glm::quat d = 0.5f * (glm::quat(0.0f, t.x, t.y, t.z) * q);
  JointDualQuaternion out;
  out.real[0] = q.x, out.real[1] = q.y, out.real[2] = q.z, out.real[3] = q.w;
  out.dual[0] = d.x, out.dual[1] = d.y, out.dual[2] = d.z, out.dual[3] = d.w;
  const glm::mat3 s = glm::transpose(glm::mat3_cast(q)) * a;
  for (int c = 0; c < 3; ++c)
    for (int k = 0; k < 3; ++k) out.scale[3 * c + k] = s[c][k];
  return out;
}

std::vector<JointDualQuaternion>& scratchFor(int joints) {
  thread_local std::vector<JointDualQuaternion> scratch;  // grows to the largest skin, then reused
  if (scratch.size() < static_cast<size_t>(joints)) scratch.resize(joints);
  return scratch;
}

// Rotates v by the unit quaternion (q, w): v + 2 q x (q x v + w v).
inline glm::vec3 rotate(const glm::vec3& q, float w, const glm::vec3& v) {
  return v + 2.0f * glm::cross(q, glm::cross(q, v) + w * v);
}

// sharedScale > 0: every S is that uniform scale (no per-vertex stretch blend).
template <int Stride>
void dqsLoop(const DualQuaternionSkinningJob& job, int stride, const JointDualQuaternion* dq, float sharedScale) {
  const int s = Stride > 0 ? Stride : stride;
  for (int v = 0; v < job.vertexCount; ++v) {
    const uint16_t* joints = job.influenceJoints + static_cast<size_t>(v) * s;
    const float* weights = job.influenceWeights + static_cast<size_t>(v) * s;
    const JointDualQuaternion& first = dq[joints[0]];
    float b0[4] = {0, 0, 0, 0}, be[4] = {0, 0, 0, 0}, sm[9] = {0, 0, 0, 0, 0, 0, 0, 0, 0};
    for (int k = 0; k < s; ++k) {
      const JointDualQuaternion& j = dq[joints[k]];
      // Shortest arc: q and -q are the same rotation; blend the one on the first's side.
      const float dot = j.real[0] * first.real[0] + j.real[1] * first.real[1] + j.real[2] * first.real[2] +
                        j.real[3] * first.real[3];
      const float w = dot < 0.0f ? -weights[k] : weights[k];
      for (int c = 0; c < 4; ++c) {
        b0[c] += w * j.real[c];
        be[c] += w * j.dual[c];
      }
      if (sharedScale <= 0.0f)
        for (int c = 0; c < 9; ++c) sm[c] += weights[k] * j.scale[c];
    }
    float len2 = b0[0] * b0[0] + b0[1] * b0[1] + b0[2] * b0[2] + b0[3] * b0[3];
    if (!(len2 > 0.0f)) {  // only when every weight is zero: follow the first joint
      for (int c = 0; c < 4; ++c) b0[c] = first.real[c], be[c] = first.dual[c];
      len2 = 1.0f;
    }
    const float inv = 1.0f / std::sqrt(len2);
    const glm::vec3 q(b0[0] * inv, b0[1] * inv, b0[2] * inv), e(be[0] * inv, be[1] * inv, be[2] * inv);
    const float qw = b0[3] * inv, ew = be[3] * inv;
    // The normalised dual quaternion's translation: 2 (w_r e - w_e q + q x e); its dual
    // part's component along the real part is dropped, as Kavan's normalisation does.
    const glm::vec3 t = 2.0f * (qw * e - ew * q + glm::cross(q, e));
    const glm::vec3& p = job.positions[v];
    const glm::mat3 stretch = sharedScale > 0.0f ? glm::mat3(sharedScale)
                                                 : glm::mat3(sm[0], sm[1], sm[2], sm[3], sm[4], sm[5], sm[6], sm[7], sm[8]);
    const glm::vec3 ps = sharedScale > 0.0f ? sharedScale * p : stretch * p;
    job.outPositions[v] = rotate(q, qw, ps) + t;
    if (!job.normals) continue;
    glm::vec3 n = job.normals[v];
    if (sharedScale <= 0.0f) n = normalMatrixOf(glm::mat4(stretch)) * n;
    n = rotate(q, qw, n);
    const float nl2 = glm::dot(n, n);
    job.outNormals[v] = nl2 > 0.0f ? n / std::sqrt(nl2) : glm::vec3(0.0f);
  }
}

}  // namespace

std::string DualQuaternionSkinningJob::validate() const {
  return validateSkinningArrays(positions, normals, vertexCount, influenceJoints, influenceWeights,
                                influencesPerVertex, jointMatrices, jointCount, outPositions, outNormals);
}

bool DualQuaternionSkinningJob::run() const {
  if (!validate().empty()) return false;
  if (vertexCount == 0) return true;
  // One shared uniform scale without reflection (the usual rig): S = s I for every joint,
  // so the stretch phase is a multiplication by s.
  bool sharedUniform = sharedSimilarity(jointMatrices, jointCount);
  for (int j = 0; j < jointCount && sharedUniform; ++j)
    sharedUniform = glm::determinant(glm::mat3(jointMatrices[j])) > 0.0f;
  const float sharedScale = sharedUniform ? glm::length(glm::vec3(jointMatrices[0][0])) : 0.0f;
  std::vector<JointDualQuaternion>& dq = scratchFor(jointCount);
  for (int j = 0; j < jointCount; ++j) dq[j] = decompose(jointMatrices[j], sharedUniform);
  switch (influencesPerVertex) {
    case 1: dqsLoop<1>(*this, 1, dq.data(), sharedScale); break;
    case 2: dqsLoop<2>(*this, 2, dq.data(), sharedScale); break;
    case 3: dqsLoop<3>(*this, 3, dq.data(), sharedScale); break;
    case 4: dqsLoop<4>(*this, 4, dq.data(), sharedScale); break;
    case 8: dqsLoop<8>(*this, 8, dq.data(), sharedScale); break;
    default: dqsLoop<0>(*this, influencesPerVertex, dq.data(), sharedScale); break;
  }
  return true;
}

}  // namespace kinema
