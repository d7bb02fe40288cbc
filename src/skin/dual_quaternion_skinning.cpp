#include "skin/dual_quaternion_skinning.h"

#include <cmath>
#include <vector>

#include "skin/skinning_decomposition.h"
#include "skin/skinning_job_checks.h"

#if defined(__SSE2__) || defined(_M_X64)
#include <emmintrin.h>
#define KINEMA_DQS_SSE2 1
#endif

namespace kinema {

namespace {

// A skinning matrix split as M p = R (S p) + t (skinning_decomposition.h), laid out so
// the SIMD blend loads each part with one aligned load.
struct alignas(16) JointDualQuaternion {
  float real[4];  // x, y, z, w
  float dual[4];
  float scale[3][4];  // S, column-major, columns padded to four floats
};

JointDualQuaternion decompose(const glm::mat4& m, bool sharedUniform) {
  const glm::mat3 a(m);
  // A = s Q with Q orthogonal (sharedSimilarity): R = A / s directly.
  const SkinningDecomposition split =
      sharedUniform ? decomposeSkinningMatrix(m, a / glm::length(a[0])) : decomposeSkinningMatrix(m);
  const glm::quat& q = split.real;
  const glm::quat& d = split.dual;
  JointDualQuaternion out;
  out.real[0] = q.x, out.real[1] = q.y, out.real[2] = q.z, out.real[3] = q.w;
  out.dual[0] = d.x, out.dual[1] = d.y, out.dual[2] = d.z, out.dual[3] = d.w;
  const glm::mat3& s = split.stretch;
  for (int c = 0; c < 3; ++c) {
    for (int k = 0; k < 3; ++k) out.scale[c][k] = s[c][k];
    out.scale[c][3] = 0.0f;
  }
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

// The blended dual quaternion (b0, be) and stretch (sm, column-major 3x3) of one vertex.
struct Blend {
  float b0[4], be[4], sm[3][4];
};

#if KINEMA_DQS_SSE2
// SSE2: each part is one register; the shortest-arc sign is applied by flipping the
// weight's sign bit (no branch: the sign is as random as the rotations).
template <int Stride, bool Stretch>
inline void blend(const uint16_t* joints, const float* weights, int s, const JointDualQuaternion* dq, Blend& out) {
  const JointDualQuaternion& first = dq[joints[0]];
  const __m128 fr = _mm_load_ps(first.real);
  const __m128 signBit = _mm_set1_ps(-0.0f);
  __m128 b0 = _mm_setzero_ps(), be = _mm_setzero_ps(), s0 = b0, s1 = b0, s2 = b0;
  for (int k = 0; k < (Stride > 0 ? Stride : s); ++k) {
    const JointDualQuaternion& j = dq[joints[k]];
    const __m128 r = _mm_load_ps(j.real);
    __m128 dot = _mm_mul_ps(r, fr);
    dot = _mm_add_ps(dot, _mm_shuffle_ps(dot, dot, _MM_SHUFFLE(2, 3, 0, 1)));
    dot = _mm_add_ps(dot, _mm_shuffle_ps(dot, dot, _MM_SHUFFLE(1, 0, 3, 2)));
    const __m128 w = _mm_set1_ps(weights[k]);
    const __m128 ws = _mm_xor_ps(w, _mm_and_ps(dot, signBit));
    b0 = _mm_add_ps(b0, _mm_mul_ps(ws, r));
    be = _mm_add_ps(be, _mm_mul_ps(ws, _mm_load_ps(j.dual)));
    if (Stretch) {
      s0 = _mm_add_ps(s0, _mm_mul_ps(w, _mm_load_ps(j.scale[0])));
      s1 = _mm_add_ps(s1, _mm_mul_ps(w, _mm_load_ps(j.scale[1])));
      s2 = _mm_add_ps(s2, _mm_mul_ps(w, _mm_load_ps(j.scale[2])));
    }
  }
  _mm_storeu_ps(out.b0, b0);
  _mm_storeu_ps(out.be, be);
  if (Stretch) {
    _mm_storeu_ps(out.sm[0], s0);
    _mm_storeu_ps(out.sm[1], s1);
    _mm_storeu_ps(out.sm[2], s2);
  }
}
#else
template <int Stride, bool Stretch>
inline void blend(const uint16_t* joints, const float* weights, int s, const JointDualQuaternion* dq, Blend& out) {
  const JointDualQuaternion& first = dq[joints[0]];
  out = Blend{};
  for (int k = 0; k < (Stride > 0 ? Stride : s); ++k) {
    const JointDualQuaternion& j = dq[joints[k]];
    // Shortest arc: q and -q are the same rotation; blend the one on the first's side.
    const float dot = j.real[0] * first.real[0] + j.real[1] * first.real[1] + j.real[2] * first.real[2] +
                      j.real[3] * first.real[3];
    const float w = std::signbit(dot) ? -weights[k] : weights[k];
    for (int c = 0; c < 4; ++c) {
      out.b0[c] += w * j.real[c];
      out.be[c] += w * j.dual[c];
    }
    if (Stretch)
      for (int c = 0; c < 3; ++c)
        for (int r = 0; r < 3; ++r) out.sm[c][r] += weights[k] * j.scale[c][r];
  }
}
#endif

// Stretch false: every S is the uniform `sharedScale` (no per-vertex stretch blend).
template <int Stride, bool Stretch>
void dqsLoop(const DualQuaternionSkinningJob& job, int stride, const JointDualQuaternion* dq, float sharedScale) {
  const int s = Stride > 0 ? Stride : stride;
  const size_t step = job.influenceStride > 0 ? job.influenceStride : s;
  Blend b;
  for (int v = 0; v < job.vertexCount; ++v) {
    const uint16_t* joints = job.influenceJoints + static_cast<size_t>(v) * step;
    blend<Stride, Stretch>(joints, job.influenceWeights + static_cast<size_t>(v) * step, s, dq, b);
    float len2 = b.b0[0] * b.b0[0] + b.b0[1] * b.b0[1] + b.b0[2] * b.b0[2] + b.b0[3] * b.b0[3];
    if (!(len2 > 0.0f)) {  // only when every weight is zero: follow the first joint
      const JointDualQuaternion& first = dq[joints[0]];
      for (int c = 0; c < 4; ++c) b.b0[c] = first.real[c], b.be[c] = first.dual[c];
      len2 = 1.0f;
    }
    const float inv = 1.0f / std::sqrt(len2);
    const glm::vec3 q(b.b0[0] * inv, b.b0[1] * inv, b.b0[2] * inv), e(b.be[0] * inv, b.be[1] * inv, b.be[2] * inv);
    const float qw = b.b0[3] * inv, ew = b.be[3] * inv;
    // The normalised dual quaternion's translation: 2 (w_r e - w_e q + q x e); its dual
    // part's component along the real part is dropped, as Kavan's normalisation does.
    const glm::vec3 t = 2.0f * (qw * e - ew * q + glm::cross(q, e));
    const glm::vec3& p = job.positions[v];
    glm::mat3 stretch(sharedScale);
    if (Stretch)
      stretch = glm::mat3(b.sm[0][0], b.sm[0][1], b.sm[0][2], b.sm[1][0], b.sm[1][1], b.sm[1][2], b.sm[2][0],
                          b.sm[2][1], b.sm[2][2]);
    const glm::vec3 ps = Stretch ? stretch * p : sharedScale * p;
    job.outPositions[v] = rotate(q, qw, ps) + t;
    if (!job.normals) continue;
    glm::vec3 n = job.normals[v];
    if (Stretch) n = normalMatrixOf(glm::mat4(stretch)) * n;
    n = rotate(q, qw, n);
    const float nl2 = glm::dot(n, n);
    job.outNormals[v] = nl2 > 0.0f ? n / std::sqrt(nl2) : glm::vec3(0.0f);
  }
}

template <bool Stretch>
void dqsDispatch(const DualQuaternionSkinningJob& job, const JointDualQuaternion* dq, float sharedScale) {
  switch (job.influencesPerVertex) {
    case 1: dqsLoop<1, Stretch>(job, 1, dq, sharedScale); break;
    case 2: dqsLoop<2, Stretch>(job, 2, dq, sharedScale); break;
    case 3: dqsLoop<3, Stretch>(job, 3, dq, sharedScale); break;
    case 4: dqsLoop<4, Stretch>(job, 4, dq, sharedScale); break;
    case 8: dqsLoop<8, Stretch>(job, 8, dq, sharedScale); break;
    default: dqsLoop<0, Stretch>(job, job.influencesPerVertex, dq, sharedScale); break;
  }
}

}  // namespace

std::string DualQuaternionSkinningJob::validate() const {
  return validateSkinningArrays(positions, normals, vertexCount, influenceJoints, influenceWeights,
                                influencesPerVertex, influenceStride, jointMatrices, jointCount, outPositions,
                                outNormals);
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
  if (sharedUniform) dqsDispatch<false>(*this, dq.data(), sharedScale);
  else dqsDispatch<true>(*this, dq.data(), 0.0f);
  return true;
}

}  // namespace kinema
