#include "sim/particles.h"

#include <algorithm>
#include <cmath>

#include "core/math.h"
#include "core/random.h"

namespace kinema {

namespace {

float draw(const RandomRange& r, SplitMix64& random) {
  const double x = r.distribution == RandomDistribution::Uniform ? r.mean + r.spread * random.uniform(-1.0, 1.0)
                                                                 : r.mean + r.spread * random.normal();
  return static_cast<float>(std::max(0.0, x));
}

std::string checkRange(const RandomRange& r, const char* what) {
  if (!std::isfinite(r.mean) || !std::isfinite(r.spread) || r.spread < 0.0f)
    return std::string(what) + " needs a finite mean and a spread >= 0";
  return "";
}

// The exact motion under dv/dt = g + k (w - v) after time tau.
struct Motion {
  glm::vec3 g, w;
  float k;
  float step;  // the whole step, whose decay is computed once for every particle
  float stepDecay;  // exp(-k step)
  void at(const glm::vec3& p0, const glm::vec3& v0, float tau, glm::vec3& p, glm::vec3& v) const {
    if (k == 0.0f) {
      p = p0 + v0 * tau + 0.5f * g * tau * tau;
      v = v0 + g * tau;
      return;
    }
    const glm::vec3 terminal = w + g / k;
    const float decay = tau == step ? stepDecay : std::exp(-k * tau);
    v = terminal + (v0 - terminal) * decay;
    p = p0 + terminal * tau + (v0 - terminal) * ((1.0f - decay) / k);
  }
};

// The last time in [0, hi] still outside (distance >= 0) before the first found contact, on
// the exact path (distance(hi) < 0). Starting outside, the Illinois variant of false position
// keeps a bracket [lo, hi] around the contact and shrinks both ends (a handful of path
// evaluations instead of bisection's 40); starting on the surface, where false position
// cannot move, bisection. Either stops once the bracket is a float step of the whole span.
template <class Distance>
float contactTime(const Motion& m, const glm::vec3& p0, const glm::vec3& v0, float hi, Distance distance) {
  float lo = 0.0f;
  const float span = hi, tolerance = span * 1.2e-7f;  // about one float step at `span`
  glm::vec3 p, v;
  float fLo = distance(p0), fHi = 0.0f;
  if (fLo > 0.0f) {
    m.at(p0, v0, hi, p, v);
    fHi = distance(p);
  }
  int side = 0;  // which end moved last (Illinois halves the other end's value when one end repeats)
  for (int i = 0; i < 40 && hi - lo > tolerance; ++i) {
    float t = 0.5f * (lo + hi);
    if (fLo > 0.0f && fHi < 0.0f) {
      const float secant = lo + (hi - lo) * (fLo / (fLo - fHi));
      if (secant > lo && secant < hi) t = secant;
    }
    if (t <= lo || t >= hi) break;  // lo and hi adjacent floats
    m.at(p0, v0, t, p, v);
    const float f = distance(p);
    if (f >= 0.0f) {
      lo = t, fLo = f;
      if (side > 0) fHi *= 0.5f;
      side = 1;
    } else {
      hi = t, fHi = f;
      if (side < 0) fLo *= 0.5f;
      side = -1;
    }
  }
  return lo;
}

glm::vec3 bounce(const glm::vec3& v, const glm::vec3& n, float restitution, float friction) {
  const float vn = glm::dot(v, n);
  if (vn >= 0.0f) return v;  // already leaving
  const glm::vec3 tangential = v - vn * n;
  return -restitution * vn * n + (1.0f - friction) * tangential;
}

glm::vec3 inCone(const glm::vec3& axisIn, float coneDegrees, SplitMix64& random) {
  const glm::vec3 axis = glm::normalize(axisIn);
  const glm::vec3 helper = std::abs(axis.x) < 0.9f ? glm::vec3(1, 0, 0) : glm::vec3(0, 1, 0);
  const glm::vec3 u = glm::normalize(glm::cross(axis, helper)), w = glm::cross(axis, u);
  const double cosMax = std::cos(glm::radians(static_cast<double>(coneDegrees)));
  const double cosT = 1.0 - random.uniform() * (1.0 - cosMax);  // uniform over the cap's area
  const double sinT = std::sqrt(std::max(0.0, 1.0 - cosT * cosT));
  const double phi = 6.283185307179586 * random.uniform();
  return static_cast<float>(cosT) * axis +
         static_cast<float>(sinT) * (static_cast<float>(std::cos(phi)) * u + static_cast<float>(std::sin(phi)) * w);
}

}  // namespace

const char* toString(EmitterShape shape) {
  switch (shape) {
    case EmitterShape::Point: return "point";
    case EmitterShape::Sphere: return "sphere";
    case EmitterShape::MeshSurface: return "mesh_surface";
    case EmitterShape::Joint: return "joint";
  }
  return "";
}

std::string ParticleForces::validate() const {
  if (!isFinite(gravity) || !isFinite(wind)) return "gravity and wind must be finite";
  if (!(drag >= 0.0f) || !std::isfinite(drag)) return "drag must be a finite number >= 0 (per second)";
  if (!std::isfinite(groundHeight)) return "the ground height must be finite";
  if (!(restitution >= 0.0f && restitution <= 1.0f)) return "restitution must be in [0, 1]";
  if (!(friction >= 0.0f && friction <= 1.0f)) return "friction must be in [0, 1]";
  for (const ParticleSphere& s : spheres)
    if (!isFinite(s.centre) || !(s.radius > 0.0f) || !std::isfinite(s.radius)) return "a collision sphere needs a finite centre and radius > 0";
  return "";
}

std::string ParticleStepJob::validate() const {
  if (!emitters || !forces || !state) return "missing emitters, forces or state";
  if (std::string bad = forces->validate(); !bad.empty()) return bad;
  if (!(dt > 0.0f && dt <= 1.0f)) return "the time step must be in (0, 1] seconds";
  const ParticleState& s = *state;
  const size_t n = s.positions.size();
  if (s.velocities.size() != n || s.ages.size() != n || s.lifetimes.size() != n || s.emitterOf.size() != n)
    return "the particle arrays differ in length";
  for (size_t i = 0; i < emitters->size(); ++i) {
    const ParticleEmitter& e = (*emitters)[i];
    const std::string which = "emitter " + std::to_string(i + 1) + ": ";
    if (!isFinite(e.position) || !isFinite(e.direction) || glm::length(e.direction) < 1e-6f)
      return which + "needs a finite position and a non-zero direction";
    if (!(e.coneDegrees >= 0.0f && e.coneDegrees <= 180.0f)) return which + "the cone half-angle must be in [0, 180] degrees";
    for (const auto& [range, what] : {std::pair<const RandomRange*, const char*>{&e.speed, "speed"}, {&e.rate, "rate"}, {&e.lifetime, "lifetime"}})
      if (std::string bad = checkRange(*range, what); !bad.empty()) return which + bad;
    if (e.shape == EmitterShape::Sphere && !(e.radius > 0.0f)) return which + "a sphere emitter needs a radius > 0";
    if (e.shape == EmitterShape::MeshSurface) {
      if (e.surfaceIndices.empty() || e.surfaceIndices.size() % 3 != 0) return which + "a mesh surface needs whole triangles";
      for (uint32_t v : e.surfaceIndices)
        if (v >= e.surfacePositions.size()) return which + "a triangle names a vertex the surface lacks";
    }
    if (e.shape == EmitterShape::Joint && (!jointWorld || e.joint < 0 || e.joint >= static_cast<int>(jointWorld->size())))
      return which + "a joint emitter needs a joint of jointWorld";
  }
  return "";
}

bool ParticleStepJob::run() {
  if (!validate().empty()) return false;
  ParticleState& s = *state;
  const ParticleForces& f = *forces;
  const Motion motion{f.gravity, f.wind, f.drag, dt, std::exp(-f.drag * dt)};
  const glm::vec3 up(0, 1, 0);
  // Age, and drop the dead (keeping birth order).
  int kept = 0;
  for (int i = 0; i < s.size(); ++i) {
    const float age = s.ages[i] + dt;
    if (age >= s.lifetimes[i]) continue;
    s.positions[kept] = s.positions[i];
    s.velocities[kept] = s.velocities[i];
    s.ages[kept] = age;
    s.lifetimes[kept] = s.lifetimes[i];
    s.emitterOf[kept] = s.emitterOf[i];
    ++kept;
  }
  for (auto* a : {&s.positions, &s.velocities}) a->resize(kept);
  s.ages.resize(kept);
  s.lifetimes.resize(kept);
  s.emitterOf.resize(kept);
  // Move along the exact path, stopping at each contact to bounce.
  for (int i = 0; i < kept; ++i) {
    glm::vec3 p = s.positions[i], v = s.velocities[i];
    float left = dt;
    for (int contact = 0; contact < 8 && left > 0.0f; ++contact) {
      glm::vec3 pe, ve;
      motion.at(p, v, left, pe, ve);
      float when = left;
      glm::vec3 normal(0.0f);
      if (f.ground && pe.y < f.groundHeight) {
        // Resting on the ground (on it, not rising, pulled down): the contact is now, no search.
        const bool resting = p.y == f.groundHeight && v.y <= 0.0f && f.gravity.y + f.drag * (f.wind.y - v.y) <= 0.0f;
        when = resting ? 0.0f : contactTime(motion, p, v, left, [&](const glm::vec3& q) { return q.y - f.groundHeight; });
        normal = up;
      }
      for (const ParticleSphere& sphere : f.spheres) {
        auto outside = [&](const glm::vec3& q) { return glm::length(q - sphere.centre) - sphere.radius; };
        if (outside(pe) >= 0.0f) continue;
        const float t = contactTime(motion, p, v, left, outside);
        if (t < when) {
          when = t;
          glm::vec3 q, w;
          motion.at(p, v, t, q, w);
          normal = glm::normalize(q - sphere.centre);
        }
      }
      if (normal == glm::vec3(0.0f)) {
        p = pe;
        v = ve;
        break;
      }
      motion.at(p, v, when, p, v);
      v = bounce(v, normal, f.restitution, f.friction);
      if (when <= 1e-6f * dt && glm::dot(v, normal) <= 1e-6f) {
        // Resting contact (the bounce left no normal speed): slide for the rest of the step,
        // then stand on the surface again without the speed into it.
        motion.at(p, v, left, p, v);
        if (normal == up && f.ground && p.y < f.groundHeight) p.y = f.groundHeight;
        for (const ParticleSphere& sphere : f.spheres) {
          const glm::vec3 d = p - sphere.centre;
          const float length = glm::length(d);
          if (length < sphere.radius && length > 0.0f) p = sphere.centre + d * (sphere.radius / length);
        }
        const float into = glm::dot(v, normal);
        if (into < 0.0f) v -= into * normal;
        break;
      }
      left -= when;
    }
    if (f.ground && p.y < f.groundHeight) {  // resting contact the loop gave up on
      p.y = f.groundHeight;
      v.y = std::max(v.y, 0.0f);
    }
    s.positions[i] = p;
    s.velocities[i] = v;
  }
  // Emit.
  SplitMix64 random(s.random);
  s.emitCarry.resize(emitters->size(), 0.0f);
  for (size_t e = 0; e < emitters->size(); ++e) {
    const ParticleEmitter& em = (*emitters)[e];
    const double owed = static_cast<double>(s.emitCarry[e]) + static_cast<double>(draw(em.rate, random)) * dt;
    const double whole = std::floor(owed);
    const float carry = static_cast<float>(owed - whole);
    const int count = static_cast<int>(std::min(whole, static_cast<double>(maxParticles)));
    s.emitCarry[e] = carry;
    std::vector<double> cumulative;
    if (em.shape == EmitterShape::MeshSurface) {
      double total = 0.0;
      for (size_t t = 0; t < em.surfaceIndices.size(); t += 3) {
        const glm::vec3 a = em.surfacePositions[em.surfaceIndices[t]], b = em.surfacePositions[em.surfaceIndices[t + 1]],
                        c = em.surfacePositions[em.surfaceIndices[t + 2]];
        total += 0.5 * glm::length(glm::cross(b - a, c - a));
        cumulative.push_back(total);
      }
    }
    for (int k = 0; k < count && s.positions.size() < maxParticles; ++k) {
      glm::vec3 position = em.position, axis = em.direction;
      switch (em.shape) {
        case EmitterShape::Point: break;
        case EmitterShape::Sphere: {
          glm::vec3 q;
          do {
            q = glm::vec3(random.uniform(-1, 1), random.uniform(-1, 1), random.uniform(-1, 1));
          } while (glm::dot(q, q) > 1.0f);
          position = em.position + em.radius * q;
          break;
        }
        case EmitterShape::MeshSurface: {
          const double pick = random.uniform() * cumulative.back();
          const size_t t = std::min(cumulative.size() - 1,
                                    static_cast<size_t>(std::upper_bound(cumulative.begin(), cumulative.end(), pick) - cumulative.begin()));
          const glm::vec3 a = em.surfacePositions[em.surfaceIndices[3 * t]], b = em.surfacePositions[em.surfaceIndices[3 * t + 1]],
                          c = em.surfacePositions[em.surfaceIndices[3 * t + 2]];
          double r1 = random.uniform(), r2 = random.uniform();
          if (r1 + r2 > 1.0) r1 = 1.0 - r1, r2 = 1.0 - r2;  // fold the square onto the triangle
          position = a + static_cast<float>(r1) * (b - a) + static_cast<float>(r2) * (c - a);
          const glm::vec3 n = glm::cross(b - a, c - a);
          if (em.alongNormal && glm::length(n) > 0.0f) axis = n;
          break;
        }
        case EmitterShape::Joint: {
          const glm::mat4& m = (*jointWorld)[em.joint];
          position = glm::vec3(m * glm::vec4(em.position, 1.0f));
          axis = glm::mat3(m) * em.direction;
          break;
        }
      }
      const glm::vec3 velocity = draw(em.speed, random) * inCone(axis, em.coneDegrees, random);
      s.positions.push_back(position);
      s.velocities.push_back(velocity);
      s.ages.push_back(0.0f);
      s.lifetimes.push_back(draw(em.lifetime, random));
      s.emitterOf.push_back(static_cast<uint32_t>(e));
      ++s.emitted;
    }
  }
  s.random = random.state;
  s.time += dt;
  return true;
}

}  // namespace kinema
