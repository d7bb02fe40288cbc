#pragma once
#include <string>
#include <vector>

#include "core/math.h"

namespace kinema {

constexpr int kLatticeMinPoints = 2;  // per axis: a trilinear lattice
constexpr int kLatticeMaxPoints = 8;  // per axis: Bernstein degree 7

// A free-form deformation lattice (Sederberg & Parry 1986). At rest its control points sit on
// a regular grid in a parallelepiped: P_ijk = origin + (i/L) S + (j/M) T + (k/N) U, with
// L, M, N = counts - 1. Moving them to P'_ijk moves a point with lattice coordinates (s,t,u)
// to sum_ijk B_i^L(s) B_j^M(t) B_k^N(u) P'_ijk. All positions are in the space of the mesh the
// lattice deforms (model space, metres for the default character).
struct FfdLattice {
  int counts[3] = {2, 2, 2};      // control points along S, T, U: 2..8 each
  glm::vec3 origin{0.0f};         // the rest corner P_000
  glm::vec3 axes[3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};  // S, T, U: the rest box's edges
  std::vector<glm::vec3> points;  // deformed P'_ijk, counts[0] * counts[1] * counts[2]

  int pointCount() const { return counts[0] * counts[1] * counts[2]; }
  // Flat index of P_ijk: i fastest (i + L'(j + M'k), L' = counts[0], M' = counts[1]).
  int index(int i, int j, int k) const { return i + counts[0] * (j + counts[1] * k); }
  // Where P_ijk sits at rest.
  glm::vec3 restPoint(int i, int j, int k) const;
  // Empty when usable: counts within 2..8, one finite point per grid node, finite axes
  // spanning a box of non-zero volume. Otherwise one sentence naming the problem.
  std::string validate() const;
};

// A lattice at rest over the given box (every point at its rest place).
FfdLattice makeLattice(const int counts[3], const glm::vec3& origin, const glm::vec3 axes[3]);

// A lattice at rest around an axis-aligned box holding `positions` (those listed in
// `selection`, or all when it is empty), padded on each side by `padding` times the box's
// largest extent so no fitted point sits on the boundary; a flat side gets that padding too.
// Empty positions give a unit box at the origin.
FfdLattice fitLattice(const std::vector<glm::vec3>& positions, const std::vector<int>& selection,
                      const int counts[3], float padding = 0.05f);

// The lattice coordinates (s, t, u) of p: origin + s S + t T + u U = p. Inside the box all
// three are in [0, 1].
glm::vec3 latticeCoordinates(const FfdLattice& lattice, const glm::vec3& p);

// The deformed position of the point with lattice coordinates stu (the trivariate Bernstein
// sum, evaluated as written; the reference the job below is tested against).
glm::vec3 evaluateLattice(const FfdLattice& lattice, const glm::vec3& stu);

// Deforms a flat array of points by a lattice. A point inside the rest box goes to the
// Bernstein sum of its coordinates; a point outside moves by the displacement at its
// coordinates clamped to the box (as Blender's lattice modifier does), so the deformation
// is continuous across the boundary and far points are not flung by the polynomials.
// `frame` places the lattice: mesh space = frame * lattice space (its parent joint's motion
// since the lattice was fitted; identity for a lattice parented to the world). `weights`
// (optional, 0..1 per point) blends each point between where it was and where the lattice
// takes it. In-place (outPositions == positions) is allowed.
struct FfdJob {
  const FfdLattice* lattice = nullptr;
  const glm::vec3* positions = nullptr;
  int count = 0;
  const float* weights = nullptr;
  glm::mat4 frame{1.0f};  // rigid (rotation + translation)
  glm::vec3* outPositions = nullptr;

  std::string validate() const;
  bool run() const;
};

}  // namespace kinema
