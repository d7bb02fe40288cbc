#include "deform/ffd_lattice.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/math.h"
#include "deform/bernstein.h"

namespace kinema {
namespace {

glm::mat3 boxMatrix(const FfdLattice& lattice) {
  return glm::mat3(lattice.axes[0], lattice.axes[1], lattice.axes[2]);
}

}  // namespace

glm::vec3 FfdLattice::restPoint(int i, int j, int k) const {
  const float s = static_cast<float>(i) / static_cast<float>(counts[0] - 1);
  const float t = static_cast<float>(j) / static_cast<float>(counts[1] - 1);
  const float u = static_cast<float>(k) / static_cast<float>(counts[2] - 1);
  return origin + s * axes[0] + t * axes[1] + u * axes[2];
}

std::string FfdLattice::validate() const {
  for (int a = 0; a < 3; ++a)
    if (counts[a] < kLatticeMinPoints || counts[a] > kLatticeMaxPoints)
      return "lattice counts must be 2 to 8 points per axis (axis " + std::to_string(a) + " has " +
             std::to_string(counts[a]) + ")";
  if (static_cast<int>(points.size()) != pointCount())
    return "lattice has " + std::to_string(points.size()) + " points, its counts need " +
           std::to_string(pointCount());
  if (!isFinite(origin) || !isFinite(axes[0]) || !isFinite(axes[1]) || !isFinite(axes[2]))
    return "lattice box is not finite";
  const double volume = std::abs(glm::determinant(glm::dmat3(glm::dvec3(axes[0]), glm::dvec3(axes[1]),
                                                             glm::dvec3(axes[2]))));
  const double scale = glm::length(glm::dvec3(axes[0])) * glm::length(glm::dvec3(axes[1])) *
                       glm::length(glm::dvec3(axes[2]));
  if (!(volume > 1e-9 * scale) || !(volume > 0.0)) return "lattice box is flat (its axes span no volume)";
  for (size_t p = 0; p < points.size(); ++p)
    if (!isFinite(points[p])) return "lattice point " + std::to_string(p) + " is not finite";
  return "";
}

FfdLattice makeLattice(const int counts[3], const glm::vec3& origin, const glm::vec3 axes[3]) {
  FfdLattice lattice;
  for (int a = 0; a < 3; ++a) {
    lattice.counts[a] = std::clamp(counts[a], kLatticeMinPoints, kLatticeMaxPoints);
    lattice.axes[a] = axes[a];
  }
  lattice.origin = origin;
  lattice.points.resize(lattice.pointCount());
  for (int k = 0; k < lattice.counts[2]; ++k)
    for (int j = 0; j < lattice.counts[1]; ++j)
      for (int i = 0; i < lattice.counts[0]; ++i) lattice.points[lattice.index(i, j, k)] = lattice.restPoint(i, j, k);
  return lattice;
}

FfdLattice fitLattice(const std::vector<glm::vec3>& positions, const std::vector<int>& selection,
                      const int counts[3], float padding) {
  glm::vec3 lo(std::numeric_limits<float>::max()), hi(-std::numeric_limits<float>::max());
  bool any = false;
  auto take = [&](const glm::vec3& p) {
    if (!isFinite(p)) return;
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
    any = true;
  };
  if (selection.empty()) {
    for (const glm::vec3& p : positions) take(p);
  } else {
    for (int v : selection)
      if (v >= 0 && v < static_cast<int>(positions.size())) take(positions[v]);
  }
  if (!any) {
    lo = glm::vec3(-0.5f);
    hi = glm::vec3(0.5f);
  }
  const glm::vec3 extent = hi - lo;
  // A single point still gets a box (a millimetre), so the lattice can be inverted.
  const float largest = std::max({extent.x, extent.y, extent.z, 1e-3f});
  const float pad = largest * std::max(padding, 0.0f);
  lo -= glm::vec3(pad);
  hi += glm::vec3(pad);
  // A flat side (a plane of points) is thickened to 1 % of the largest side.
  for (int a = 0; a < 3; ++a)
    if (hi[a] - lo[a] < 0.01f * largest) {
      const float mid = 0.5f * (lo[a] + hi[a]);
      lo[a] = mid - 0.005f * largest;
      hi[a] = mid + 0.005f * largest;
    }
  const glm::vec3 size = hi - lo;
  const glm::vec3 axes[3] = {{size.x, 0, 0}, {0, size.y, 0}, {0, 0, size.z}};
  return makeLattice(counts, lo, axes);
}

glm::vec3 latticeCoordinates(const FfdLattice& lattice, const glm::vec3& p) {
  return glm::inverse(boxMatrix(lattice)) * (p - lattice.origin);
}

glm::vec3 evaluateLattice(const FfdLattice& lattice, const glm::vec3& stu) {
  float bs[kLatticeMaxPoints], bt[kLatticeMaxPoints], bu[kLatticeMaxPoints];
  bernsteinBasis(lattice.counts[0] - 1, stu.x, bs);
  bernsteinBasis(lattice.counts[1] - 1, stu.y, bt);
  bernsteinBasis(lattice.counts[2] - 1, stu.z, bu);
  glm::dvec3 sum(0.0);
  for (int k = 0; k < lattice.counts[2]; ++k)
    for (int j = 0; j < lattice.counts[1]; ++j)
      for (int i = 0; i < lattice.counts[0]; ++i)
        sum += double(bs[i]) * double(bt[j]) * double(bu[k]) * glm::dvec3(lattice.points[lattice.index(i, j, k)]);
  return glm::vec3(sum);
}

std::string FfdJob::validate() const {
  if (!lattice) return "FfdJob: no lattice";
  if (std::string e = lattice->validate(); !e.empty()) return "FfdJob: " + e;
  if (count < 0) return "FfdJob: negative point count";
  if (count > 0 && (!positions || !outPositions)) return "FfdJob: positions and outPositions are needed";
  if (!isFinite(frame) || std::abs(glm::determinant(glm::mat3(frame))) < 1e-12f)
    return "FfdJob: the lattice frame is not an invertible finite transform";
  return "";
}

bool FfdJob::run() const {
  if (!validate().empty()) return false;
  const FfdLattice& l = *lattice;
  const int nx = l.counts[0], ny = l.counts[1], nz = l.counts[2], nyz = ny * nz;
  // Displacements of the control points from their rest places (the sum then gives each
  // point's displacement: exact zero for an undisturbed lattice whatever the rounding), one
  // float array per coordinate laid out [i][j + ny k], so the first contraction below runs
  // over nyz contiguous floats that the compiler vectorises.
  std::vector<float> moved(3 * static_cast<size_t>(nx) * nyz);
  float* dx = moved.data();
  float* dy = dx + nx * nyz;
  float* dz = dy + nx * nyz;
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i) {
        const glm::vec3 d = l.points[l.index(i, j, k)] - l.restPoint(i, j, k);
        const int at = i * nyz + j + ny * k;
        dx[at] = d.x;
        dy[at] = d.y;
        dz[at] = d.z;
      }
  const glm::mat3 toLattice = glm::inverse(boxMatrix(l));
  const glm::mat4 fromFrame = glm::inverse(frame);
  const glm::mat3 frameLinear(frame);
  const bool identityFrame = frame == glm::mat4(1.0f);

  float bs[kLatticeMaxPoints], bt[kLatticeMaxPoints], bu[kLatticeMaxPoints];
  float rx[kLatticeMaxPoints * kLatticeMaxPoints], ry[kLatticeMaxPoints * kLatticeMaxPoints],
      rz[kLatticeMaxPoints * kLatticeMaxPoints];
  for (int v = 0; v < count; ++v) {
    const glm::vec3 p = positions[v];
    const glm::vec3 q = identityFrame ? p : glm::vec3(fromFrame * glm::vec4(p, 1.0f));
    const glm::vec3 stu = glm::clamp(toLattice * (q - l.origin), glm::vec3(0.0f), glm::vec3(1.0f));
    bernsteinBasis(nx - 1, stu.x, bs);
    bernsteinBasis(ny - 1, stu.y, bt);
    bernsteinBasis(nz - 1, stu.z, bu);
    // The tensor sum one axis at a time: nx*ny*nz + ny*nz + nz multiply-adds per coordinate.
    for (int jk = 0; jk < nyz; ++jk) rx[jk] = ry[jk] = rz[jk] = 0.0f;
    for (int i = 0; i < nx; ++i) {
      const float b = bs[i];
      const float *px = dx + i * nyz, *py = dy + i * nyz, *pz = dz + i * nyz;
      for (int jk = 0; jk < nyz; ++jk) {
        rx[jk] += b * px[jk];
        ry[jk] += b * py[jk];
        rz[jk] += b * pz[jk];
      }
    }
    glm::vec3 displacement(0.0f);
    for (int k = 0; k < nz; ++k) {
      glm::vec3 column(0.0f);
      for (int j = 0; j < ny; ++j) column += bt[j] * glm::vec3(rx[j + ny * k], ry[j + ny * k], rz[j + ny * k]);
      displacement += bu[k] * column;
    }
    if (weights) displacement *= weights[v];
    outPositions[v] = p + (identityFrame ? displacement : frameLinear * displacement);
  }
  return true;
}

}  // namespace kinema
