#include "skin/linear_blend_skinning.h"

#include <cmath>
#include <vector>

#include "skin/skinning_job_checks.h"

#if defined(__SSE2__) || defined(_M_X64)
#include <emmintrin.h>
#define KINEMA_SKIN_SSE2 1
#endif
// GCC and Clang on x86 compile the AVX2 + FMA loop for those instructions alone (target
// attribute), so the library stays baseline x86-64.
#if KINEMA_SKIN_SSE2 && (defined(__GNUC__) || defined(__clang__)) && (defined(__x86_64__) || defined(__i386__))
#include <immintrin.h>

#include <cstring>
#define KINEMA_SKIN_AVX2 1
#define KINEMA_TARGET_AVX2 __attribute__((target("avx2,fma")))
#endif

namespace kinema {

namespace {

// Per-joint matrices copied 16-byte aligned, so the blend's loads fold into its multiplies
// (SSE arithmetic takes only aligned memory operands); a copy of a few hundred joints is
// nothing next to the vertices.
struct alignas(64) JointMatrix {
  float c[4][4];
};
// A per-joint normal matrix, three columns padded to four floats (a cache line each too).
struct alignas(64) NormalMatrix {
  float c[3][4];
};

// Which normals a loop computes: none, the blended skinning matrix applied to them (the
// shared-similarity shortcut), or blended per-joint normal matrices. A template argument,
// so each loop carries only its own case.
enum class NormalMode { None, Blended, PerJoint };

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

// The normal's output: normalised, or scaled by `scale` (1/s^2 under the shared-similarity
// shortcut, which blends M_i = s^2 inverseTranspose(M_i) instead of the normal matrices).
inline __m128 finishNormal(__m128 n, bool normalize, __m128 scale) {
  return normalize ? normalize3(n) : _mm_mul_ps(n, scale);
}

// One loop for every stride; `Stride` > 0 fixes it at compile time so the influence loop
// unrolls (strides 1..4 and 8 are the common ones), 0 reads it from `stride`.
// normalMats == nullptr: normals use the blended skinning matrix (see sharedSimilarity).
template <int Stride, NormalMode Mode>
void skinLoop(const LinearBlendSkinningJob& job, int stride, const JointMatrix* mats, const NormalMatrix* normalMats,
              float normalScale) {
  const int s = Stride > 0 ? Stride : stride;
  const size_t step = job.influenceStride > 0 ? job.influenceStride : s;
  const uint16_t* joints = job.influenceJoints;
  const float* weights = job.influenceWeights;
  const float* in = &job.positions[0].x;
  float* out = &job.outPositions[0].x;
  const float* nin = job.normals ? &job.normals[0].x : nullptr;
  float* nout = job.normals ? &job.outNormals[0].x : nullptr;
  const bool normalize = job.normalizeNormals;
  const __m128 scale = _mm_set1_ps(normalScale);
  const int count = job.vertexCount;  // a local: the output stores could alias the job
  for (int v = 0; v < count; ++v, joints += step, weights += step) {
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
    if (Mode == NormalMode::None) continue;
    const float* n = nin + 3 * static_cast<size_t>(v);
    if (Mode == NormalMode::PerJoint) {
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
    storeVec3(nout + 3 * static_cast<size_t>(v), finishNormal(rn, normalize, scale));
  }
}


#if KINEMA_SKIN_AVX2
// The same loop on AVX2 + FMA, compiled for those instructions only here and chosen at run
// time. A 4x4 matrix is two 256-bit halves (columns 0-1, 2-3): per influence one weight
// broadcast and two fused multiply-adds (the SSE2 loop needs two instructions for the
// broadcast and eight for the blend). The position transform keeps separate multiplies
// and adds in glm's order (the file is built with -ffp-contract=off), so a one-influence
// vertex gives exactly glm's M * p on both paths.
KINEMA_TARGET_AVX2 inline void storeVec3Avx2(float* out, __m128 v) {
  _mm_storel_pi(reinterpret_cast<__m64*>(out), v);
  const int z = _mm_extract_ps(v, 2);  // vextractps to memory
  std::memcpy(out + 2, &z, sizeof z);
}

// Two normals (one per 128-bit lane) normalised at once: half the shuffles and Newton
// steps per vertex. Same arithmetic as the SSE2 normalize3, with the step fused.
KINEMA_TARGET_AVX2 inline __m256 normalize3x2(__m256 v) {
  const __m256 sq = _mm256_mul_ps(v, v);
  const __m256 len2 = _mm256_add_ps(_mm256_add_ps(_mm256_permute_ps(sq, 0x00), _mm256_permute_ps(sq, 0x55)),
                                    _mm256_permute_ps(sq, 0xAA));
  const __m256 y = _mm256_rsqrt_ps(len2);
  // One Newton step: y (3 - x y^2) / 2.
  const __m256 inv = _mm256_mul_ps(_mm256_mul_ps(_mm256_set1_ps(0.5f), y),
                                   _mm256_fnmadd_ps(_mm256_mul_ps(len2, y), y, _mm256_set1_ps(3.0f)));
  return _mm256_and_ps(_mm256_mul_ps(v, inv), _mm256_cmp_ps(len2, _mm256_set1_ps(1e-36f), _CMP_GT_OQ));
}

// Everything for vertex v but the normal's normalisation: stores the position, returns
// the blended normal (unused for NormalMode::None).
template <int Stride, NormalMode Mode>
KINEMA_TARGET_AVX2 inline __m128 skinVertexAvx2(const float* in, float* out, const float* nin, const uint16_t* joints,
                                                const float* weights, int s, size_t v, const JointMatrix* mats,
                                                const NormalMatrix* normalMats) {
  __m256 w = _mm256_broadcast_ss(weights);
  const float* m = mats[joints[0]].c[0];
  __m256 c01 = _mm256_mul_ps(w, _mm256_load_ps(m));
  __m256 c23 = _mm256_mul_ps(w, _mm256_load_ps(m + 8));
  for (int k = 1; k < s; ++k) {
    w = _mm256_broadcast_ss(weights + k);
    m = mats[joints[k]].c[0];
    c01 = _mm256_fmadd_ps(w, _mm256_load_ps(m), c01);
    c23 = _mm256_fmadd_ps(w, _mm256_load_ps(m + 8), c23);
  }
  const __m128 c0 = _mm256_castps256_ps128(c01), c1 = _mm256_extractf128_ps(c01, 1);
  const __m128 c2 = _mm256_castps256_ps128(c23), c3 = _mm256_extractf128_ps(c23, 1);
  const float* p = in + 3 * v;
  const __m128 r = _mm_add_ps(_mm_add_ps(_mm_mul_ps(c0, _mm_broadcast_ss(p)), _mm_mul_ps(c1, _mm_broadcast_ss(p + 1))),
                              _mm_add_ps(_mm_mul_ps(c2, _mm_broadcast_ss(p + 2)), c3));
  storeVec3Avx2(out + 3 * v, r);
  if (Mode == NormalMode::None) return r;
  const float* n = nin + 3 * v;
  __m128 n0 = c0, n1 = c1, n2 = c2;
  if (Mode == NormalMode::PerJoint) {
    w = _mm256_broadcast_ss(weights);
    const float* nm = normalMats[joints[0]].c[0];
    __m256 n01 = _mm256_mul_ps(w, _mm256_load_ps(nm));
    n2 = _mm_mul_ps(_mm256_castps256_ps128(w), _mm_load_ps(nm + 8));
    for (int k = 1; k < s; ++k) {
      w = _mm256_broadcast_ss(weights + k);
      nm = normalMats[joints[k]].c[0];
      n01 = _mm256_fmadd_ps(w, _mm256_load_ps(nm), n01);
      n2 = _mm_fmadd_ps(_mm256_castps256_ps128(w), _mm_load_ps(nm + 8), n2);
    }
    n0 = _mm256_castps256_ps128(n01);
    n1 = _mm256_extractf128_ps(n01, 1);
  }
  return _mm_fmadd_ps(n2, _mm_broadcast_ss(n + 2),
                      _mm_fmadd_ps(n1, _mm_broadcast_ss(n + 1), _mm_mul_ps(n0, _mm_broadcast_ss(n))));
}

template <int Stride, NormalMode Mode>
KINEMA_TARGET_AVX2 void skinLoopAvx2(const LinearBlendSkinningJob& job, int stride, const JointMatrix* mats,
                                     const NormalMatrix* normalMats, float normalScale) {
  const int s = Stride > 0 ? Stride : stride;
  const size_t step = job.influenceStride > 0 ? job.influenceStride : s;
  const uint16_t* joints = job.influenceJoints;
  const float* weights = job.influenceWeights;
  const float* in = &job.positions[0].x;
  float* out = &job.outPositions[0].x;
  const float* nin = job.normals ? &job.normals[0].x : nullptr;
  float* nout = job.normals ? &job.outNormals[0].x : nullptr;
  const size_t count = static_cast<size_t>(job.vertexCount);  // a local: the stores could alias the job
  size_t v = 0;
  if (Mode != NormalMode::None && job.normalizeNormals) {
    // Pairs of vertices, their normals normalised together. Each vertex's inputs are read
    // before its outputs are written, so in-place skinning still works.
    for (; v + 1 < count; v += 2) {
      const __m128 a = skinVertexAvx2<Stride, Mode>(in, out, nin, joints + v * step, weights + v * step, s, v, mats,
                                                    normalMats);
      const __m128 b = skinVertexAvx2<Stride, Mode>(in, out, nin, joints + (v + 1) * step, weights + (v + 1) * step,
                                                    s, v + 1, mats, normalMats);
      const __m256 ab = normalize3x2(_mm256_insertf128_ps(_mm256_castps128_ps256(a), b, 1));
      storeVec3Avx2(nout + 3 * v, _mm256_castps256_ps128(ab));
      storeVec3Avx2(nout + 3 * v + 3, _mm256_extractf128_ps(ab, 1));
    }
  }
  const __m128 scale = _mm_set1_ps(normalScale);
  for (; v < count; ++v) {
    const __m128 rn =
        skinVertexAvx2<Stride, Mode>(in, out, nin, joints + v * step, weights + v * step, s, v, mats, normalMats);
    if (Mode == NormalMode::None) continue;
    const __m128 n = job.normalizeNormals
                         ? _mm256_castps256_ps128(normalize3x2(_mm256_castps128_ps256(rn)))
                         : _mm_mul_ps(rn, scale);
    storeVec3Avx2(nout + 3 * v, n);
  }
}

bool cpuHasAvx2Fma() {
  static const bool has = __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma");
  return has;
}
#endif

#else  // Portable scalar loop for targets without SSE2 (same arithmetic, one lane at a time).

template <int Stride, NormalMode /*Mode: read at run time here*/>
void skinLoop(const LinearBlendSkinningJob& job, int stride, const JointMatrix* /*aligned copy, unused*/,
              const NormalMatrix* normalMats, float normalScale) {
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
    if (!job.normalizeNormals) {
      job.outNormals[v] = n * normalScale;
      continue;
    }
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

// The loop instantiations: strides 1..4 and 8 fixed at compile time, times the normal mode.
struct Sse2Loop {
  template <int Stride, NormalMode Mode>
  static void run(const LinearBlendSkinningJob& job, int stride, const JointMatrix* mats, const NormalMatrix* nm,
                  float normalScale) {
    skinLoop<Stride, Mode>(job, stride, mats, nm, normalScale);
  }
};
#if KINEMA_SKIN_AVX2
struct Avx2Loop {
  template <int Stride, NormalMode Mode>
  static void run(const LinearBlendSkinningJob& job, int stride, const JointMatrix* mats, const NormalMatrix* nm,
                  float normalScale) {
    skinLoopAvx2<Stride, Mode>(job, stride, mats, nm, normalScale);
  }
};
#endif

template <class Loop, NormalMode Mode>
void dispatchStride(const LinearBlendSkinningJob& job, const JointMatrix* mats, const NormalMatrix* nm,
                    float normalScale) {
  switch (job.influencesPerVertex) {
    case 1: Loop::template run<1, Mode>(job, 1, mats, nm, normalScale); break;
    case 2: Loop::template run<2, Mode>(job, 2, mats, nm, normalScale); break;
    case 3: Loop::template run<3, Mode>(job, 3, mats, nm, normalScale); break;
    case 4: Loop::template run<4, Mode>(job, 4, mats, nm, normalScale); break;
    case 8: Loop::template run<8, Mode>(job, 8, mats, nm, normalScale); break;
    default: Loop::template run<0, Mode>(job, job.influencesPerVertex, mats, nm, normalScale); break;
  }
}

template <class Loop>
void dispatch(const LinearBlendSkinningJob& job, NormalMode mode, const JointMatrix* mats, const NormalMatrix* nm,
              float normalScale) {
  switch (mode) {
    case NormalMode::None: dispatchStride<Loop, NormalMode::None>(job, mats, nm, normalScale); break;
    case NormalMode::Blended: dispatchStride<Loop, NormalMode::Blended>(job, mats, nm, normalScale); break;
    case NormalMode::PerJoint: dispatchStride<Loop, NormalMode::PerJoint>(job, mats, nm, normalScale); break;
  }
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
  // Unnormalised normals under the shortcut: the blended M_i are s^2 times the normal
  // matrices, so divide by s^2 (|column 0 of M_0|^2).
  float normalScale = 1.0f;
  if (normals && !normalMats) {
    const float s2 = glm::dot(glm::vec3(jointMatrices[0][0]), glm::vec3(jointMatrices[0][0]));
    normalScale = 1.0f / s2;
  }
  const JointMatrix* mats = sc.matrices.data();
  const NormalMode mode = !normals ? NormalMode::None : normalMats ? NormalMode::PerJoint : NormalMode::Blended;
#if KINEMA_SKIN_AVX2
  if (allowAvx2 && cpuHasAvx2Fma()) {
    dispatch<Avx2Loop>(*this, mode, mats, normalMats, normalScale);
    return true;
  }
#endif
  dispatch<Sse2Loop>(*this, mode, mats, normalMats, normalScale);
  return true;
}

}  // namespace kinema
