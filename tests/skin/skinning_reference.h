#pragma once
// A plain scalar linear blend skinning in double precision, written straight from the
// formula (p' = sum w_i M_i p, n' = normalize(sum w_i inverse(M_i)^T n)): what the
// SIMD job is held to. Also random skinning inputs for property tests.
#include <algorithm>
#include <cstdint>
#include <random>
#include <vector>

#include "core/math.h"
#include "test_support.h"

namespace kinema::test {

struct ReferenceSkinned {
  glm::dvec3 position;
  glm::dvec3 normalSum;    // sum w_i invT(M_i) n, before normalising
  double positionScale;    // sum w_i (|A_i| |p| + |t_i|): the size of the terms summed
  double normalScale;      // sum w_i |invT(M_i) n|
};

inline ReferenceSkinned referenceLinearBlend(const glm::vec3& p, const glm::vec3& n, const uint16_t* joints,
                                             const float* weights, int stride, const glm::mat4* matrices) {
  ReferenceSkinned r{glm::dvec3(0.0), glm::dvec3(0.0), 0.0, 0.0};
  for (int k = 0; k < stride; ++k) {
    const glm::dmat4 m(matrices[joints[k]]);
    const double w = weights[k];
    const glm::dvec4 q = m * glm::dvec4(glm::dvec3(p), 1.0);
    r.position += w * glm::dvec3(q);
    const glm::dmat3 a(m);
    double norm = 0;
    for (int c = 0; c < 3; ++c) norm += glm::dot(a[c], a[c]);
    r.positionScale += std::abs(w) * (std::sqrt(norm) * glm::length(glm::dvec3(p)) + glm::length(glm::dvec3(m[3])));
    const glm::dvec3 nn = glm::transpose(glm::inverse(a)) * glm::dvec3(n);
    r.normalSum += w * nn;
    r.normalScale += std::abs(w) * glm::length(nn);
  }
  return r;
}

// Weights for `stride` influences: positive, summing to 1, largest first, with a zero
// tail now and then (as files pad them).
inline void randomWeights(std::mt19937& rng, int stride, float* out) {
  std::uniform_real_distribution<float> u(0.01f, 1.0f);
  std::bernoulli_distribution pad(0.25);
  const int used = pad(rng) && stride > 1 ? 1 + static_cast<int>(rng() % (stride - 1)) : stride;
  float sum = 0;
  for (int k = 0; k < stride; ++k) sum += out[k] = k < used ? u(rng) : 0.0f;
  for (int k = 0; k < stride; ++k) out[k] /= sum;
  std::sort(out, out + stride, [](float a, float b) { return a > b; });
}

// A rotation times `scale` plus a translation (a rigid rig's skinning matrix).
inline glm::mat4 randomSimilarity(std::mt19937& rng, float scale) {
  std::uniform_real_distribution<float> t(-2.0f, 2.0f);
  glm::mat4 m = glm::mat4_cast(randomRotation(rng)) * scale;
  m[3] = glm::vec4(t(rng), t(rng), t(rng), 1.0f);
  return m;
}

// Any well-conditioned affine matrix: rotation, non-uniform scale and shear.
inline glm::mat4 randomAffine(std::mt19937& rng) {
  std::uniform_real_distribution<float> e(-0.4f, 0.4f), s(0.5f, 2.0f), t(-2.0f, 2.0f);
  glm::mat3 a = glm::mat3_cast(randomRotation(rng)) * glm::mat3(s(rng), e(rng), e(rng), e(rng), s(rng), e(rng), e(rng),
                                                                 e(rng), s(rng));
  glm::mat4 m(a);
  m[3] = glm::vec4(t(rng), t(rng), t(rng), 1.0f);
  return m;
}

inline glm::vec3 randomPoint(std::mt19937& rng, float extent) {
  std::uniform_real_distribution<float> u(-extent, extent);
  return glm::vec3(u(rng), u(rng), u(rng));
}

}  // namespace kinema::test
