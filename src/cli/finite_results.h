#pragma once
#include <string>
#include <vector>

#include "core/math.h"
#include "scene/scene.h"
#include "evaluation/scene_deformation.h"

namespace kinema::cli {

// Checks on what a command computed before it prints or draws it: a chain whose offsets,
// translations or scales overflow float (3e38 per joint, scale 1e30 per joint) gives inf or
// NaN world transforms, which must end in a one-line error (exit 1), never in JSON `null`.

// The first joint (parent-first order, so the topmost one of a chain) whose world
// transform holds a number that is not finite, or -1 when all are finite.
int firstNonFiniteJoint(const std::vector<glm::mat4>& world);

// How messages name a joint: 'NAME' as the file spells it (cut to 60 characters with
// "…"), and for glTF its node index.
std::string jointLabel(const Scene& scene, int joint);

// "" when every world transform is finite; otherwise the one-line error naming the file,
// the joint and the time, e.g. "walk.bvh: joint 'J2' (2): the world transform at t = 0 s is
// not finite (offsets, translations or scales along its chain overflow float)".
std::string nonFiniteWorldError(const Scene& scene, const std::vector<glm::mat4>& world, double time);

// "" when every deformed vertex is finite; otherwise the one-line error naming the file, the
// mesh and the joint (node) it hangs from.
std::string nonFiniteVerticesError(const Scene& scene, const std::vector<DeformedPrimitive>& deformed, double time);

}  // namespace kinema::cli
