#include "skin/linear_blend_skinning.h"

#include <cmath>
#include <vector>

#include "skin/skinning_job_checks.h"

#if defined(__SSE2__) || defined(_M_X64)
#include <emmintrin.h>
#define KINEMA_SKIN_SSE2 1
#endif

namespace kinema {

namespace {

// Per-joint matrices copied 16-byte aligned, so the blend's loads fold into its multiplies
// (SSE arithmetic takes only aligned memory operands); a copy of a few hundred joints is
// nothing next to the vertices.
struct alignas(16) JointMatrix {
  float c[4][4];
};
// A per-joint normal matrix, three columns padded to four floats.
struct alignas(16) NormalMatrix {
  float c[3][4];
};

#if KINEMA_SKIN_SSE2

// Stores the x, y, z lanes of v (a 16-byte store would overrun the last vertex).
inline void storeVec3(float* out, __m128 v) {
  _mm_storel_pi(reinterpret_cast<__m64*>(out), v);
  _mm_store_ss(out + 2, _mm_movehl_ps(v, v));
}

// v / |v.xyz|, or zero for a zero vector (a degenerate normal stays degenerate, not NaN).
// The reciprocal square root estimate (12 bits) refined by one Newton step is good to a
// few float ulps, well inside 1e-6, at a fraction of sqrt + divide. Packed instructions
// only: the scalar forms (rsqrtss, movss between registers) merge into their destination
// register, a dependency on whatever wrote it last.
inline __m128 normalize3(__m128 v) {
  const __m128 sq = _mm_mul_ps(v, v);
  const __m128 len2 = _mm_add_ps(_mm_add_ps(_mm_shuffle_ps(sq, sq, _MM_SHUFFLE(0, 0, 0, 0)),
                                            _mm_shuffle_ps(sq, sq, _MM_SHUFFLE(1, 1, 1, 1))),
                                 _mm_shuffle_ps(sq, sq, _MM_SHUFFLE(2, 2, 2, 2)));
  const __m128 y = _mm_rsqrt_ps(len2);
  // y (1.5 - 0.5 x y^2)
  const __m128 inv =
      _mm_mul_ps(y, _mm_sub_ps(_mm_set1_ps(1.5f), _mm_mul_ps(_mm_mul_ps(_mm_set1_ps(0.5f), len2), _mm_mul_ps(y, y))));
  return _mm_and_ps(_mm_mul_ps(v, inv), _mm_cmpgt_ps(len2, _mm_set1_ps(1e-36f)));
}

// One loop for every stride; `Stride` > 0 fixes it at compile time so the influence loop
// unrolls (strides 1..4 and 8 are the common ones), 0 reads it from `stride`.
// normalMats == nullptr: normals use the blended skinning matrix (see sharedSimilarity).
template <int Stride>
void skinLoop(const LinearBlendSkinningJob& job, int stride, const JointMatrix* mats, const NormalMatrix* normalMats) {
  const int s = Stride > 0 ? Stride : stride;
  const size_t step = job.influenceStride > 0 ? job.influenceStride : s;
  const uint16_t* joints = job.influenceJoints;
  const float* weights = job.influenceWeights;
  const float* in = &job.positions[0].x;
  float* out = &job.outPositions[0].x;
  const float* nin = job.normals ? &job.normals[0].x : nullptr;
  float* nout = job.normals ? &job.outNormals[0].x : nullptr;
  for (int v = 0; v < job.vertexCount; ++v, joints += step, weights += step) {
    // The blended matrix sum_i w_i M_i, column by column.
    __m128 w = _mm_set1_ps(weights[0]);
    const JointMatrix* m = mats + static_cast<size_t>(joints[0]);
    __m128 c0 = _mm_mul_ps(w, _mm_load_ps(m->c[0]));
    __m128 c1 = _mm_mul_ps(w, _mm_load_ps(m->c[1]));
    __m128 c2 = _mm_mul_ps(w, _mm_load_ps(m->c[2]));
    __m128 c3 = _mm_mul_ps(w, _mm_load_ps(m->c[3]));
    for (int k = 1; k < s; ++k) {
      w = _mm_set1_ps(weights[k]);
      m = mats + static_cast<size_t>(joints[k]);
      c0 = _mm_add_ps(c0, _mm_mul_ps(w, _mm_load_ps(m->c[0])));
      c1 = _mm_add_ps(c1, _mm_mul_ps(w, _mm_load_ps(m->c[1])));
      c2 = _mm_add_ps(c2, _mm_mul_ps(w, _mm_load_ps(m->c[2])));
      c3 = _mm_add_ps(c3, _mm_mul_ps(w, _mm_load_ps(m->c[3])));
    }
    const float* p = in + 3 * static_cast<size_t>(v);
    const __m128 r = _mm_add_ps(_mm_add_ps(_mm_mul_ps(c0, _mm_set1_ps(p[0])), _mm_mul_ps(c1, _mm_set1_ps(p[1]))),
                                _mm_add_ps(_mm_mul_ps(c2, _mm_set1_ps(p[2])), c3));
    storeVec3(out + 3 * static_cast<size_t>(v), r);
    if (!nin) continue;
    const float* n = nin + 3 * static_cast<size_t>(v);
    if (normalMats) {
      w = _mm_set1_ps(weights[0]);
      const NormalMatrix* nm = normalMats + static_cast<size_t>(joints[0]);
      c0 = _mm_mul_ps(w, _mm_load_ps(nm->c[0]));
      c1 = _mm_mul_ps(w, _mm_load_ps(nm->c[1]));
      c2 = _mm_mul_ps(w, _mm_load_ps(nm->c[2]));
      for (int k = 1; k < s; ++k) {
        w = _mm_set1_ps(weights[k]);
        nm = normalMats + static_cast<size_t>(joints[k]);
        c0 = _mm_add_ps(c0, _mm_mul_ps(w, _mm_load_ps(nm->c[0])));
        c1 = _mm_add_ps(c1, _mm_mul_ps(w, _mm_load_ps(nm->c[1])));
        c2 = _mm_add_ps(c2, _mm_mul_ps(w, _mm_load_ps(nm->c[2])));
      }
    }
    const __m128 rn = _mm_add_ps(_mm_add_ps(_mm_mul_ps(c0, _mm_set1_ps(n[0])), _mm_mul_ps(c1, _mm_set1_ps(n[1]))),
                                 _mm_mul_ps(c2, _mm_set1_ps(n[2])));
    storeVec3(nout + 3 * static_cast<size_t>(v), normalize3(rn));
  }
}

#else  // Portable scalar loop for targets without SSE2 (same arithmetic, one lane at a time).

template <int Stride>
void skinLoop(const LinearBlendSkinningJob& job, int stride, const JointMatrix* /*aligned copy, unused*/,
              const NormalMatrix* normalMats) {
  const int s = Stride > 0 ? Stride : stride;
  const size_t step = job.influenceStride > 0 ? job.influenceStride : s;
  for (int v = 0; v < job.vertexCount; ++v) {
    const uint16_t* joints = job.influenceJoints + static_cast<size_t>(v) * step;
    const float* weights = job.influenceWeights + static_cast<size_t>(v) * step;
    glm::mat4 m(0.0f);
    for (int k = 0; k < s; ++k) m += weights[k] * job.jointMatrices[joints[k]];
    job.outPositions[v] = glm::vec3(m * glm::vec4(job.positions[v], 1.0f));
    if (!job.normals) continue;
    glm::mat3 nm(m);
    if (normalMats) {
      nm = glm::mat3(0.0f);
      for (int k = 0; k < s; ++k) {
        const NormalMatrix& j = normalMats[joints[k]];
        for (int c = 0; c < 3; ++c) nm[c] += weights[k] * glm::vec3(j.c[c][0], j.c[c][1], j.c[c][2]);
      }
    }
    const glm::vec3 n = nm * job.normals[v];
    const float len2 = glm::dot(n, n);
    job.outNormals[v] = len2 > 0.0f ? n / std::sqrt(len2) : glm::vec3(0.0f);
  }
}

#endif

// Scratch for the aligned per-joint matrices: grows to the largest skeleton seen on this
// thread and is then reused, so a run allocates at most once.
struct Scratch {
  std::vector<JointMatrix> matrices;
  std::vector<NormalMatrix> normals;
};
Scratch& scratch() {
  thread_local Scratch s;
  return s;
}

}  // namespace

std::string LinearBlendSkinningJob::validate() const {
  return validateSkinningArrays(positions, normals, vertexCount, influenceJoints, influenceWeights,
                                influencesPerVertex, influenceStride, jointMatrices, jointCount, outPositions,
                                outNormals);
}

bool LinearBlendSkinningJob::run() const {
  if (!validate().empty()) return false;
  if (vertexCount == 0) return true;
  // Normals need inverseTranspose(M_i) per joint. When every M_i is a rotation times one
  // shared uniform scale s (rigid rigs, the usual case), inverseTranspose(M_i) = M_i / s^2
  // for all i, so sum_i w_i inverseTranspose(M_i) n is (1/s^2) times the blended matrix
  // applied to n and the normalisation removes the factor: no per-joint matrices needed.
  Scratch& sc = scratch();
  if (sc.matrices.size() < static_cast<size_t>(jointCount)) sc.matrices.resize(jointCount);
  for (int j = 0; j < jointCount; ++j)
    for (int c = 0; c < 4; ++c)
      for (int r = 0; r < 4; ++r) sc.matrices[j].c[c][r] = jointMatrices[j][c][r];
  const NormalMatrix* normalMats = nullptr;
  if (normals && !sharedSimilarity(jointMatrices, jointCount)) {
    if (sc.normals.size() < static_cast<size_t>(jointCount)) sc.normals.resize(jointCount);
    for (int j = 0; j < jointCount; ++j) {
      const glm::mat3 n = normalMatrixOf(jointMatrices[j]);
      for (int c = 0; c < 3; ++c) {
        for (int r = 0; r < 3; ++r) sc.normals[j].c[c][r] = n[c][r];
        sc.normals[j].c[c][3] = 0.0f;
      }
    }
    normalMats = sc.normals.data();
  }
  const JointMatrix* mats = sc.matrices.data();
  switch (influencesPerVertex) {
    case 1: skinLoop<1>(*this, 1, mats, normalMats); break;
    case 2: skinLoop<2>(*this, 2, mats, normalMats); break;
    case 3: skinLoop<3>(*this, 3, mats, normalMats); break;
    case 4: skinLoop<4>(*this, 4, mats, normalMats); break;
    case 8: skinLoop<8>(*this, 8, mats, normalMats); break;
    default: skinLoop<0>(*this, influencesPerVertex, mats, normalMats); break;
  }
  return true;
}

}  // namespace kinema
