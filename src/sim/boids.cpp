#include "sim/boids.h"

#include <algorithm>
#include <cmath>

#include "core/math.h"

namespace kinema {

namespace {

// Signed distance from p to an axis-aligned box and the outward direction there.
float boxDistance(const BoidBox& b, const glm::vec3& p, glm::vec3& normal) {
  const glm::vec3 centre = 0.5f * (b.min + b.max), half = 0.5f * (b.max - b.min);
  const glm::vec3 q = glm::abs(p - centre) - half;
  const glm::vec3 outside = glm::max(q, glm::vec3(0.0f));
  const float outsideLength = glm::length(outside);
  if (outsideLength > 0.0f) {
    normal = glm::sign(p - centre) * outside / outsideLength;
    return outsideLength;
  }
  // Inside: the nearest face.
  int axis = 0;
  if (q.y > q[axis]) axis = 1;
  if (q.z > q[axis]) axis = 2;
  normal = glm::vec3(0.0f);
  normal[axis] = p[axis] >= centre[axis] ? 1.0f : -1.0f;
  return q[axis];
}

// The grid cell of a position; clamped so members far away (or a runaway) stay defined.
glm::ivec3 cellOf(const glm::vec3& p, float cell) {
  const glm::vec3 c = glm::clamp(glm::floor(p / cell), glm::vec3(-1e9f), glm::vec3(1e9f));
  return glm::ivec3(c);
}

uint32_t hashCell(int x, int y, int z, uint32_t mask) {
  const uint32_t h = static_cast<uint32_t>(x) * 73856093u ^ static_cast<uint32_t>(y) * 19349663u ^
                     static_cast<uint32_t>(z) * 83492791u;
  return h & mask;
}

}  // namespace

const char* toString(BoidImpulse impulse) {
  switch (impulse) {
    case BoidImpulse::Avoidance: return "avoidance";
    case BoidImpulse::Separation: return "separation";
    case BoidImpulse::Alignment: return "alignment";
    case BoidImpulse::Cohesion: return "cohesion";
    case BoidImpulse::Goal: return "goal";
  }
  return "";
}

std::string BoidsSettings::validate() const {
  for (float v : {separationDistance, neighbourRadius, maxSpeed, maxAcceleration})
    if (!(v > 0.0f) || !std::isfinite(v))
      return "separation distance, neighbour radius, max speed and max acceleration must be finite and > 0";
  for (float v : {separationWeight, alignmentWeight, cohesionWeight, avoidanceWeight, avoidanceDistance, goalWeight, cruiseSpeed})
    if (!(v >= 0.0f) || !std::isfinite(v)) return "weights, the avoidance distance and the cruise speed must be finite and >= 0";
  if (!(fieldOfViewDegrees > 0.0f && fieldOfViewDegrees <= 360.0f)) return "the field of view must be in (0, 360] degrees";
  if (cruiseSpeed > maxSpeed) return "the cruise speed must not pass the max speed";
  if (!isFinite(goal)) return "the goal is not finite";
  for (const BoidSphere& s : spheres)
    if (!isFinite(s.centre) || !(s.radius > 0.0f) || !std::isfinite(s.radius)) return "an obstacle sphere needs a finite centre and radius > 0";
  for (const BoidBox& b : boxes)
    if (!isFinite(b.min) || !isFinite(b.max) || b.min.x > b.max.x || b.min.y > b.max.y || b.min.z > b.max.z)
      return "an obstacle box needs finite corners with min <= max";
  return "";
}

glm::vec3 allocateAcceleration(const glm::vec3* impulses, int count, float budget, AccelerationAllocation mode,
                               glm::vec3* granted) {
  glm::vec3 total(0.0f);
  if (mode == AccelerationAllocation::Priority) {
    float left = budget;
    for (int i = 0; i < count; ++i) {
      const float asked = glm::length(impulses[i]);
      if (asked <= left) {
        granted[i] = impulses[i];
        left -= asked;
      } else {
        granted[i] = left > 0.0f ? impulses[i] * (left / asked) : glm::vec3(0.0f);
        left = 0.0f;
      }
      total += granted[i];
    }
    return total;
  }
  int active = 0;
  for (int i = 0; i < count; ++i) active += glm::length(impulses[i]) > 0.0f;
  const float share = active > 0 ? 1.0f / static_cast<float>(active) : 0.0f;
  for (int i = 0; i < count; ++i) total += share * impulses[i];
  const float length = glm::length(total);
  const float shorten = length > budget ? budget / length : 1.0f;
  for (int i = 0; i < count; ++i) granted[i] = share * shorten * impulses[i];
  return total * shorten;
}

std::string BoidsStepJob::validate() const {
  if (!settings || !positions || !velocities) return "missing settings, positions or velocities";
  if (std::string bad = settings->validate(); !bad.empty()) return bad;
  if (positions->size() != velocities->size()) return "positions and velocities differ in count";
  if (&outPositions == positions || &outVelocities == velocities) return "the outputs must not be the inputs";
  if (!(dt > 0.0f && dt <= 1.0f)) return "the time step must be in (0, 1] seconds";
  if (debugBoid >= static_cast<int>(positions->size())) return "the debug member is not in the flock";
  return "";
}

bool BoidsStepJob::run() {
  if (!validate().empty()) return false;
  const BoidsSettings& s = *settings;
  const std::vector<glm::vec3>& p = *positions;
  const std::vector<glm::vec3>& v = *velocities;
  const int n = static_cast<int>(p.size());
  outPositions.resize(n);
  outVelocities.resize(n);
  const float radius2 = s.neighbourRadius * s.neighbourRadius;
  const float cosHalfView = std::cos(glm::radians(0.5f * s.fieldOfViewDegrees));
  const float separationRange = 2.0f * s.separationDistance;
  const float cell = std::max(s.neighbourRadius, separationRange);

  // The grid: members counting-sorted by the hash of their cell (spatial hashing).
  uint32_t mask = 0;
  if (s.search == NeighbourSearch::Grid) {
    uint32_t buckets = 1;
    while (buckets < 2u * static_cast<uint32_t>(std::max(n, 1))) buckets <<= 1;
    mask = buckets - 1;
    cellStart_.assign(buckets + 1, 0);
    cellOf_.resize(n);
    cellEntries_.resize(n);
    for (int i = 0; i < n; ++i) {
      const glm::ivec3 c = cellOf(p[i], cell);
      cellOf_[i] = hashCell(c.x, c.y, c.z, mask);
      ++cellStart_[cellOf_[i] + 1];
    }
    for (uint32_t b = 0; b < buckets; ++b) cellStart_[b + 1] += cellStart_[b];
    std::vector<int> fill(cellStart_.begin(), cellStart_.end() - 1);
    for (int i = 0; i < n; ++i) cellEntries_[fill[cellOf_[i]]++] = i;
  }

  for (int i = 0; i < n; ++i) {
    const glm::vec3 pi = p[i], vi = v[i];
    const float speed = glm::length(vi);
    const glm::vec3 heading = speed > 1e-6f ? vi / speed : glm::vec3(0.0f);
    glm::vec3 push(0.0f), velocitySum(0.0f), positionSum(0.0f);
    int seen = 0, near = 0;
    auto consider = [&](int j) {
      if (j == i) return;
      const glm::vec3 d = p[j] - pi;
      const float d2 = glm::dot(d, d);
      if (d2 >= radius2) return;
      const float dist = std::sqrt(d2);
      if (dist < separationRange) {
        // Rises from 0 at twice the separation distance to 1 at it, and on past it.
        const float strength = (separationRange - dist) / s.separationDistance;
        const glm::vec3 away = dist > 1e-6f ? -d / dist : glm::vec3(1.0f, 0.0f, 0.0f);
        push += strength * away;
        ++near;
      }
      if (speed > 1e-6f && dist > 1e-6f && glm::dot(heading, d) < cosHalfView * dist) return;  // behind
      velocitySum += v[j];
      positionSum += p[j];
      ++seen;
    };
    if (s.search == NeighbourSearch::Naive) {
      for (int j = 0; j < n; ++j) consider(j);
    } else {
      const glm::ivec3 c = cellOf(pi, cell);
      uint32_t visited[27];
      int visitedCount = 0;
      for (int dz = -1; dz <= 1; ++dz)
        for (int dy = -1; dy <= 1; ++dy)
          for (int dx = -1; dx <= 1; ++dx) {
            const uint32_t b = hashCell(c.x + dx, c.y + dy, c.z + dz, mask);
            if (std::find(visited, visited + visitedCount, b) != visited + visitedCount) continue;  // a hash collision
            visited[visitedCount++] = b;
            for (int k = cellStart_[b]; k < cellStart_[b + 1]; ++k) consider(cellEntries_[k]);
          }
    }
    glm::vec3 desired[kBoidImpulseCount] = {};
    // Avoidance: the seed's finite repulsion field around each obstacle.
    for (const BoidSphere& o : s.spheres) {
      const glm::vec3 d = pi - o.centre;
      const float centreDistance = glm::length(d);
      const float surface = centreDistance - o.radius;
      if (surface < s.avoidanceDistance) {
        const glm::vec3 out = centreDistance > 1e-6f ? d / centreDistance : glm::vec3(0, 1, 0);
        desired[0] += s.avoidanceWeight * s.maxAcceleration * (1.0f - surface / s.avoidanceDistance) * out;
      }
    }
    for (const BoidBox& b : s.boxes) {
      glm::vec3 out;
      const float surface = boxDistance(b, pi, out);
      if (surface < s.avoidanceDistance)
        desired[0] += s.avoidanceWeight * s.maxAcceleration * (1.0f - surface / s.avoidanceDistance) * out;
    }
    if (near > 0) desired[1] = s.separationWeight * s.maxAcceleration * push;
    if (seen > 0) {
      desired[2] = s.alignmentWeight * (velocitySum / static_cast<float>(seen) - vi);
      desired[3] = s.cohesionWeight * (positionSum / static_cast<float>(seen) - pi);
    }
    if (s.hasGoal) {
      const glm::vec3 toGoal = s.goal - pi;
      const float distance = glm::length(toGoal);
      const glm::vec3 want = distance > 1e-6f ? toGoal * (std::min(s.maxSpeed, distance) / distance) : glm::vec3(0.0f);
      desired[4] = s.goalWeight * (want - vi);
    } else if (speed > 1e-6f) {
      desired[4] = s.goalWeight * (s.cruiseSpeed - speed) * heading;
    }
    if (s.planar)
      for (glm::vec3& d : desired) d.y = 0.0f;
    glm::vec3 granted[kBoidImpulseCount];
    const glm::vec3 a = allocateAcceleration(desired, kBoidImpulseCount, s.maxAcceleration, s.allocation, granted);
    glm::vec3 vn = vi + a * dt;
    if (s.planar) vn.y = 0.0f;
    const float vnLength = glm::length(vn);
    if (vnLength > s.maxSpeed) vn *= s.maxSpeed / vnLength;
    outVelocities[i] = vn;
    outPositions[i] = pi + vn * dt;
    if (i == debugBoid) {
      for (int k = 0; k < kBoidImpulseCount; ++k) debug.desired[k] = desired[k], debug.granted[k] = granted[k];
      debug.acceleration = a;
      debug.neighbours = seen;
    }
  }
  return true;
}

}  // namespace kinema
