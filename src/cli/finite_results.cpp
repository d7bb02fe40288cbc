#include "cli/finite_results.h"

#include <cmath>
#include <cstdio>

namespace kinema::cli {

namespace {

std::string formatTime(double time) {
  char buf[48];
  std::snprintf(buf, sizeof buf, "%g", time);
  return buf;
}

// Long names (a file may hold a joint named with megabytes) are cut so the line stays short.
std::string cutName(const std::string& name) {
  constexpr size_t kMax = 60;
  if (name.size() <= kMax) return name;
  size_t end = kMax;
  while (end > 0 && (static_cast<unsigned char>(name[end]) & 0xC0) == 0x80) --end;  // whole UTF-8 characters
  return name.substr(0, end) + "\xE2\x80\xA6";
}

}  // namespace

int firstNonFiniteJoint(const std::vector<glm::mat4>& world) {
  for (size_t j = 0; j < world.size(); ++j) {
    const float* m = glm::value_ptr(world[j]);
    for (int k = 0; k < 16; ++k)
      if (!std::isfinite(m[k])) return static_cast<int>(j);
  }
  return -1;
}

std::string jointLabel(const Scene& scene, int joint) {
  if (scene.nodeOfJoint.empty()) return "joint '" + cutName(scene.skeleton.names[joint]) + "' (" + std::to_string(joint) + ")";
  const int node = scene.nodeOfJoint[joint];
  const bool named = node < static_cast<int>(scene.nodeNames.size()) && !scene.nodeNames[node].empty();
  return "joint '" + cutName(named ? scene.nodeNames[node] : scene.skeleton.names[joint]) + "' (node " +
         std::to_string(node) + ")";
}

std::string nonFiniteWorldError(const Scene& scene, const std::vector<glm::mat4>& world, double time) {
  const int joint = firstNonFiniteJoint(world);
  if (joint < 0) return {};
  return scene.source + ": " + jointLabel(scene, joint) + ": the world transform at t = " + formatTime(time) +
         " s is not finite (offsets, translations or scales along its chain overflow float)";
}

std::string nonFiniteVerticesError(const Scene& scene, const std::vector<DeformedPrimitive>& deformed, double time) {
  for (const DeformedPrimitive& d : deformed) {
    for (size_t v = 0; v < d.positions.size(); ++v) {
      if (isFinite(d.positions[v])) continue;
      const MeshInstance& inst = scene.meshInstances[d.instance];
      return scene.source + ": mesh " + std::to_string(inst.mesh) + " primitive " + std::to_string(d.primitive) +
             " on " + jointLabel(scene, inst.joint) + ": vertex " + std::to_string(v) + " at t = " + formatTime(time) +
             " s is not finite (its skin's joint or bind matrices overflow float)";
    }
  }
  return {};
}

}  // namespace kinema::cli
