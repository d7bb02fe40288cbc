#include "render/frame_signature.h"

#include <vector>

#include "render/mesh_renderer.h"
#include "render/skeleton_renderer.h"

namespace kinema {
namespace {

struct Digest {
  uint64_t h = 1469598103934665603ull;
  void bytes(const void* data, size_t n) {
    const unsigned char* p = static_cast<const unsigned char*>(data);
    for (size_t i = 0; i < n; ++i) h = (h ^ p[i]) * 1099511628211ull;
  }
  template <typename T>
  void value(const T& v) {  // plain numbers and glm vectors / matrices (tightly packed floats)
    bytes(&v, sizeof(T));
  }
  template <typename T>
  void array(const std::vector<T>& v) {
    value(v.size());
    if (!v.empty()) bytes(v.data(), v.size() * sizeof(T));
  }
  void weights(const std::vector<std::vector<float>>* w) {
    value(w != nullptr);
    if (!w) return;
    value(w->size());
    for (const std::vector<float>& each : *w) array(each);
  }
  void skeleton(const SkeletonDrawList& s) {
    array(s.boneMatrices);
    array(s.boneColors);
    array(s.jointMatrices);
    array(s.jointColors);
    value(s.relationships.size());
    for (const auto& r : s.relationships) value(r.from), value(r.to), value(r.color);
  }
  void overlay(const OverlayDrawList& o) {
    value(o.lines.size());
    for (const auto& l : o.lines) {
      value(l.a), value(l.b), value(l.color), value(l.widthPixels), value(l.layer);
    }
    value(o.handles.size());
    for (const auto& d : o.handles) {
      value(d.center), value(d.radiusPixels), value(d.color), value(d.shape), value(d.layer), value(d.outline);
    }
    value(o.screenLines.size());
    for (const auto& l : o.screenLines) {
      value(l.a), value(l.b), value(l.color), value(l.widthPixels);
    }
    value(o.screenRects.size());
    for (const auto& r : o.screenRects) {
      value(r.min), value(r.max), value(r.fill);
    }
  }
};

// The settings (camera, viewport, switches) and the mesh ghosts, which both digests hold
// (the skeleton ghosts: how many, their shapes compared by SceneDamageJob).
void settingsAndGhosts(Digest& d, const FrameDescription& f) {
  const OrbitCamera& c = f.camera;
  d.value(c.azimuthDeg), d.value(c.elevationDeg), d.value(c.distance), d.value(c.target), d.value(c.fovYDeg);
  d.value(c.nearPlane), d.value(c.farPlane), d.value(c.orthographic);
  d.value(f.x), d.value(f.y), d.value(f.width), d.value(f.height);
  d.value(f.sceneRadius), d.value(f.showGrid), d.value(f.background), d.value(f.bones), d.value(f.lineScale);
  d.value(f.frontFacesOnly);
  d.value(f.skeleton != nullptr);
  d.value(f.overlay != nullptr);
  d.value(f.ghosts ? f.ghosts->size() : size_t(0));
  d.value(f.meshGhosts ? f.meshGhosts->size() : size_t(0));
  if (f.meshGhosts)
    for (const MeshGhost& g : *f.meshGhosts) {
      d.value(g.color);
      d.value(g.world != nullptr);
      if (g.world) d.array(*g.world);
      d.weights(g.morphWeights);
    }
}

}  // namespace

uint64_t frameSettingsSignature(const FrameDescription& f) {
  Digest d;
  settingsAndGhosts(d, f);
  if (f.skeleton) d.array(f.skeleton->boneParents), d.array(f.skeleton->joints);
  const bool meshes = f.meshes && f.meshes->renderer;
  d.value(meshes);
  if (!meshes) return d.h;
  const MeshFrame& m = f.meshes->frame;
  d.value(f.meshes->renderer), d.value(m.weightJoint), d.value(m.posed != nullptr), d.value(m.gpuDeformers != nullptr);
  if (!m.posed) {
    d.value(m.world != nullptr);
    if (m.world) d.array(*m.world);
    d.weights(m.morphWeights);
  }
  d.value(m.deformed ? m.deformed->size() : size_t(0));
  if (m.deformed)
    for (const DeformedPrimitive& p : *m.deformed)
      d.value(p.instance), d.value(p.primitive), d.value(p.positions.size()), d.value(p.normals.size());
  return d.h;
}

uint64_t frameSignature(const FrameDescription& f) {
  // The settings digest plus every element it leaves out.
  Digest d;
  d.value(frameSettingsSignature(f));
  if (f.skeleton) d.skeleton(*f.skeleton);
  if (f.ghosts)
    for (const SkeletonDrawList& g : *f.ghosts) d.skeleton(g);
  if (f.overlay) d.overlay(*f.overlay);
  if (f.meshes && f.meshes->renderer) {
    const MeshFrame& m = f.meshes->frame;
    d.value(m.world != nullptr);
    if (m.world) d.array(*m.world);
    d.weights(m.morphWeights);
    if (m.deformed)
      for (const DeformedPrimitive& p : *m.deformed) d.array(p.positions), d.array(p.normals);
  }
  return d.h;
}

}  // namespace kinema
