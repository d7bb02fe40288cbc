#include "skin/default_body_mesh.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include "core/default_character.h"
#include "core/forward_kinematics.h"

namespace kinema {

namespace {

using glm::dvec3;

// Polynomial smooth minimum: equals min(a, b) when they differ by more than k and rounds
// the crease between two shapes into a fillet about k wide where they meet.
double smoothMin(double a, double b, double k) {
  const double h = std::max(k - std::abs(a - b), 0.0) / k;
  return std::min(a, b) - h * h * k * 0.25;
}

// A capsule whose radius goes linearly from ra at a to rb at b. Not an exact distance
// (the radius is taken at the nearest axis point), close enough for gently tapered limbs.
struct TaperedCapsule {
  dvec3 a, b;
  double ra, rb;
  double distance(const dvec3& p) const {
    const dvec3 ab = b - a;
    const double t = std::clamp(glm::dot(p - a, ab) / glm::dot(ab, ab), 0.0, 1.0);
    return glm::length(p - (a + t * ab)) - (ra + t * (rb - ra));
  }
};

// An axis-aligned ellipsoid; the distance is the first-order estimate f / |grad f| of
// f = |q / radii| - 1, exact on the surface, which is all the polygoniser needs.
struct Ellipsoid {
  dvec3 centre, radii;
  double distance(const dvec3& p) const {
    const dvec3 q = p - centre;
    const double k0 = glm::length(q / radii);
    const double k1 = glm::length(q / (radii * radii));
    if (k1 <= 0.0) return -std::min(radii.x, std::min(radii.y, radii.z));
    return k0 * (k0 - 1.0) / k1;
  }
};

// The shapes of the centre and the left side (+X), placed on the default skeleton's joints.
struct BodyShape {
  Ellipsoid pelvis, waist, chest, head, hand, calfMuscle;
  TaperedCapsule neck, shoulder, upperArm, forearm, thigh, shin, foot;

  double distance(const dvec3& q) const {
    const dvec3 p(std::abs(q.x), q.y, q.z);  // the fold: the right side mirrors the left
    double torso = smoothMin(pelvis.distance(p), waist.distance(p), 0.10);
    torso = smoothMin(torso, chest.distance(p), 0.10);
    torso = smoothMin(torso, shoulder.distance(p), 0.06);
    double headAndNeck = smoothMin(neck.distance(p), head.distance(p), 0.04);
    // Small blends where a limb continues along the same axis: a wide smooth-min bulges a
    // ring (up to k/4) out of the elbow and knee.
    double arm = smoothMin(upperArm.distance(p), forearm.distance(p), 0.008);
    arm = smoothMin(arm, hand.distance(p), 0.025);
    double leg = smoothMin(thigh.distance(p), shin.distance(p), 0.008);
    leg = smoothMin(leg, calfMuscle.distance(p), 0.04);
    leg = smoothMin(leg, foot.distance(p), 0.04);
    double body = smoothMin(torso, headAndNeck, 0.05);
    body = smoothMin(body, arm, 0.05);
    body = smoothMin(body, leg, 0.06);
    return std::max(body, -p.y);  // flat soles on the ground
  }
};

BodyShape makeBodyShape() {
  const Skeleton s = makeDefaultCharacter();
  const std::vector<glm::mat4> world = computeWorld(s, Pose::rest(s));
  auto at = [&](const char* name) { return dvec3(world[s.find(name)][3]); };
  const dvec3 hips = at("Hips"), chest = at("Chest"), upperChest = at("UpperChest");
  const dvec3 neck = at("Neck"), head = at("Head"), headTop = at("HeadTop");
  const dvec3 upperArm = at("UpperArm.L"), lowerArm = at("LowerArm.L"), hand = at("Hand.L");
  const dvec3 fingertip = at("Fingertip.L");
  const dvec3 upperLeg = at("UpperLeg.L"), lowerLeg = at("LowerLeg.L"), foot = at("Foot.L");
  const dvec3 toeTip = at("ToeTip.L");

  BodyShape b;
  b.pelvis = {hips + dvec3(0.0, -0.02, -0.005), {0.165, 0.12, 0.105}};
  b.waist = {dvec3(0.0, 0.5 * (hips.y + upperChest.y) - 0.02, 0.0), {0.135, 0.13, 0.095}};
  b.chest = {dvec3(0.0, chest.y + 0.10, 0.01), {0.175, 0.15, 0.11}};
  b.shoulder = {dvec3(0.04, upperArm.y - 0.04, -0.005), upperArm, 0.07, 0.05};
  b.neck = {dvec3(0.0, upperChest.y + 0.07, -0.01), dvec3(0.0, head.y + 0.02, head.z), 0.05, 0.048};
  const double headHeight = 0.5 * (headTop.y - head.y) + 0.005;
  b.head = {dvec3(0.0, headTop.y - headHeight, head.z + 0.015), {0.082, headHeight, 0.097}};
  (void)neck;
  b.upperArm = {upperArm, lowerArm, 0.048, 0.037};
  b.forearm = {lowerArm, hand, 0.037, 0.028};
  // A mitten, flat in Y (palms down in the T-pose), from the wrist to the fingertip.
  b.hand = {dvec3(0.5 * (hand.x + fingertip.x) - 0.005, hand.y - 0.003, hand.z), {0.5 * (fingertip.x - hand.x) + 0.01, 0.026, 0.047}};
  b.thigh = {upperLeg, lowerLeg, 0.085, 0.055};
  b.shin = {lowerLeg, foot + dvec3(0.0, 0.01, 0.0), 0.055, 0.037};
  b.calfMuscle = {dvec3(upperLeg.x, lowerLeg.y - 0.14, lowerLeg.z - 0.015), {0.05, 0.12, 0.055}};
  // Heel to toes; the half-space y >= 0 cuts the sole flat.
  b.foot = {dvec3(foot.x, 0.045, foot.z - 0.02), dvec3(toeTip.x, 0.035, toeTip.z - 0.025), 0.047, 0.036};
  return b;
}

const BodyShape& bodyShape() {
  static const BodyShape shape = makeBodyShape();
  return shape;
}

// Rounded to 1e-5 (a hundredth of a millimetre; normals to 1e-5 of unit length) so the
// committed .kinema file prints short numbers and exact zeros on the mirror plane.
glm::vec3 quantised(const dvec3& v) { return glm::vec3(glm::round(v * 1e5) / 1e5); }

dvec3 gradientAt(const dvec3& p) {
  const double e = 1e-4;
  return dvec3(defaultBodySignedDistance(p + dvec3(e, 0, 0)) - defaultBodySignedDistance(p - dvec3(e, 0, 0)),
               defaultBodySignedDistance(p + dvec3(0, e, 0)) - defaultBodySignedDistance(p - dvec3(0, e, 0)),
               defaultBodySignedDistance(p + dvec3(0, 0, e)) - defaultBodySignedDistance(p - dvec3(0, 0, e))) /
         (2.0 * e);
}

}  // namespace

double defaultBodySignedDistance(const glm::dvec3& p) { return bodyShape().distance(p); }

// Surface nets: one vertex in every grid cell the surface crosses, one quad around every
// grid edge whose ends differ in sign, joining the four cells that share that edge. The
// grid is symmetric about x = 0 (no sample on the plane), so the mesh mirrors too.
MeshPrimitive makeDefaultBodyMesh() {
  const double h = kDefaultBodyCellSize;
  const int nx = 2 * static_cast<int>(std::ceil(0.97 / h));  // x from -0.97 to 0.97, even count
  const dvec3 lo(-0.5 * (nx - 1) * h, -2.0 * h + 0.5 * h, -0.16);
  const int ny = static_cast<int>(std::ceil((1.86 - lo.y) / h)) + 1;
  const int nz = static_cast<int>(std::ceil((0.26 - lo.z) / h)) + 1;
  auto node = [&](int i, int j, int k) { return lo + dvec3(i, j, k) * h; };
  auto nodeIndex = [&](int i, int j, int k) { return (static_cast<size_t>(k) * ny + j) * nx + i; };

  std::vector<double> field(static_cast<size_t>(nx) * ny * nz);
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i) field[nodeIndex(i, j, k)] = defaultBodySignedDistance(node(i, j, k));
  auto inside = [&](size_t n) { return field[n] < 0.0; };

  // Cells are named by their lowest corner.
  MeshPrimitive mesh;
  std::vector<int> cellVertex(field.size(), -1);
  static const int corner[8][3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}, {0, 0, 1}, {1, 0, 1}, {0, 1, 1}, {1, 1, 1}};
  static const int edge[12][2] = {{0, 1}, {2, 3}, {4, 5}, {6, 7}, {0, 2}, {1, 3}, {4, 6}, {5, 7}, {0, 4}, {1, 5}, {2, 6}, {3, 7}};
  for (int k = 0; k + 1 < nz; ++k)
    for (int j = 0; j + 1 < ny; ++j)
      for (int i = 0; i + 1 < nx; ++i) {
        std::array<double, 8> f;
        std::array<dvec3, 8> x;
        int insideCount = 0;
        for (int c = 0; c < 8; ++c) {
          const int ci = i + corner[c][0], cj = j + corner[c][1], ck = k + corner[c][2];
          f[c] = field[nodeIndex(ci, cj, ck)];
          x[c] = node(ci, cj, ck);
          insideCount += f[c] < 0.0;
        }
        if (insideCount == 0 || insideCount == 8) continue;
        // The mean of the edge crossings, then one Newton step onto the surface, kept in the cell.
        dvec3 sum(0.0);
        int crossings = 0;
        for (const auto& e : edge) {
          if ((f[e[0]] < 0.0) == (f[e[1]] < 0.0)) continue;
          const double t = f[e[0]] / (f[e[0]] - f[e[1]]);
          sum += x[e[0]] + t * (x[e[1]] - x[e[0]]);
          ++crossings;
        }
        dvec3 p = sum / static_cast<double>(crossings);
        const dvec3 g = gradientAt(p);
        const double g2 = glm::dot(g, g);
        if (g2 > 1e-12) p -= defaultBodySignedDistance(p) * g / g2;
        const double margin = 1e-3 * h;
        p = glm::clamp(p, x[0] + margin, x[7] - margin);
        cellVertex[nodeIndex(i, j, k)] = mesh.vertexCount();
        mesh.positions.push_back(quantised(p));
      }

  // Quads: for an edge along axis a, the four cells around it in counter-clockwise order
  // seen from +a, so the quad faces +a; flipped when the edge runs from outside to inside.
  auto cell = [&](int i, int j, int k) { return cellVertex[nodeIndex(i, j, k)]; };
  auto emitQuad = [&](int q0, int q1, int q2, int q3, bool facesPositive) {
    if (!facesPositive) std::swap(q1, q3);
    const glm::vec3 &p0 = mesh.positions[q0], &p1 = mesh.positions[q1], &p2 = mesh.positions[q2], &p3 = mesh.positions[q3];
    // Split along the shorter diagonal (a flatter, better-shaped pair of triangles).
    if (glm::distance(p0, p2) <= glm::distance(p1, p3)) {
      mesh.indices.insert(mesh.indices.end(), {uint32_t(q0), uint32_t(q1), uint32_t(q2), uint32_t(q0), uint32_t(q2), uint32_t(q3)});
    } else {
      mesh.indices.insert(mesh.indices.end(), {uint32_t(q0), uint32_t(q1), uint32_t(q3), uint32_t(q1), uint32_t(q2), uint32_t(q3)});
    }
  };
  for (int k = 1; k + 1 < nz; ++k)
    for (int j = 1; j + 1 < ny; ++j)
      for (int i = 1; i + 1 < nx; ++i) {
        const bool in = inside(nodeIndex(i, j, k));
        if (i + 1 < nx && in != inside(nodeIndex(i + 1, j, k)))  // x edge: cells around in (y, z)
          emitQuad(cell(i, j - 1, k - 1), cell(i, j, k - 1), cell(i, j, k), cell(i, j - 1, k), in);
        if (j + 1 < ny && in != inside(nodeIndex(i, j + 1, k)))  // y edge: cells around in (z, x)
          emitQuad(cell(i - 1, j, k - 1), cell(i - 1, j, k), cell(i, j, k), cell(i, j, k - 1), in);
        if (k + 1 < nz && in != inside(nodeIndex(i, j, k + 1)))  // z edge: cells around in (x, y)
          emitQuad(cell(i - 1, j - 1, k), cell(i, j - 1, k), cell(i, j, k), cell(i - 1, j, k), in);
      }

  mesh.normals.reserve(mesh.positions.size());
  for (const glm::vec3& p : mesh.positions) {
    const dvec3 g = gradientAt(dvec3(p));
    const double len = glm::length(g);
    mesh.normals.push_back(len > 1e-12 ? quantised(g / len) : glm::vec3(0.0f, 1.0f, 0.0f));
  }
  return mesh;
}

}  // namespace kinema
