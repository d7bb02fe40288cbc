#include "render/scene_damage.h"

#include <algorithm>
#include <cstring>
#include <limits>

#include "core/mesh.h"
#include "scene/scene.h"
#include "render/frame_signature.h"
#include "render/mesh_renderer.h"
#include "render/shape_meshes.h"
#include "render/skeleton_renderer.h"

namespace kinema {
namespace {

// Local bounds of a drawn shape (its instance matrix takes them to the world).
struct LocalBox {
  glm::vec3 min{std::numeric_limits<float>::max()}, max{-std::numeric_limits<float>::max()};
};
LocalBox boxOf(const ShapeMesh& mesh) {
  LocalBox b;
  for (const glm::vec3& p : mesh.positions) b.min = glm::min(b.min, p), b.max = glm::max(b.max, p);
  return b;
}
const LocalBox& boneBox() {
  static const LocalBox box = boxOf(makeOctahedralBone());
  return box;
}
const LocalBox& sphereBox() {
  static const LocalBox box{glm::vec3(-1.0f), glm::vec3(1.0f)};  // unit sphere: makeSphere's vertices lie on it
  return box;
}

// Screen bounds in framebuffer pixels of world points; `behind` is set by a point at or
// behind the camera plane (its projection is meaningless: the caller redraws everything).
struct ScreenBounds {
  glm::mat4 viewProjection{1.0f};
  double x = 0, y = 0, w = 1, h = 1;  // the view in framebuffer pixels
  double minX = std::numeric_limits<double>::max(), minY = minX;
  double maxX = -std::numeric_limits<double>::max(), maxY = maxX;
  bool behind = false;

  glm::dvec2 pixel(const glm::vec3& p) {
    const glm::vec4 c = viewProjection * glm::vec4(p, 1.0f);
    if (!(c.w > 1e-6f)) {
      behind = true;
      return {0, 0};
    }
    return {x + (double(c.x) / c.w * 0.5 + 0.5) * w, y + (double(c.y) / c.w * 0.5 + 0.5) * h};
  }
  void addPixel(const glm::dvec2& p, double grow) {
    minX = std::min(minX, p.x - grow), maxX = std::max(maxX, p.x + grow);
    minY = std::min(minY, p.y - grow), maxY = std::max(maxY, p.y + grow);
  }
  void addPoint(const glm::vec3& p, double grow = 0.0) { addPixel(pixel(p), grow); }
  void addBox(const glm::mat4& m, const LocalBox& b) {
    for (int k = 0; k < 8; ++k)
      addPoint(glm::vec3(m * glm::vec4(k & 1 ? b.max.x : b.min.x, k & 2 ? b.max.y : b.min.y, k & 4 ? b.max.z : b.min.z, 1.0f)));
  }
  // Overlay shapes in pixels from the view's top left corner.
  void addViewPixel(const glm::vec2& p, double grow) { addPixel({x + p.x, y + h - p.y}, grow); }
};

template <typename T>
bool same(const T& a, const T& b) {
  return std::memcmp(&a, &b, sizeof(T)) == 0;
}

bool sameLine(const OverlayDrawList::Line& a, const OverlayDrawList::Line& b) {
  return same(a.a, b.a) && same(a.b, b.b) && same(a.color, b.color) && a.widthPixels == b.widthPixels && a.layer == b.layer;
}
bool sameHandle(const OverlayDrawList::Handle& a, const OverlayDrawList::Handle& b) {
  return same(a.center, b.center) && a.radiusPixels == b.radiusPixels && same(a.color, b.color) && a.shape == b.shape &&
         a.layer == b.layer && same(a.outline, b.outline);
}
bool sameScreenLine(const OverlayDrawList::ScreenLine& a, const OverlayDrawList::ScreenLine& b) {
  return same(a.a, b.a) && same(a.b, b.b) && same(a.color, b.color) && a.widthPixels == b.widthPixels;
}
bool sameScreenRect(const OverlayDrawList::ScreenRect& a, const OverlayDrawList::ScreenRect& b) {
  return same(a.min, b.min) && same(a.max, b.max) && same(a.fill, b.fill);
}
bool sameRelationship(const SkeletonDrawList::Relationship& a, const SkeletonDrawList::Relationship& b) {
  return same(a.from, b.from) && same(a.to, b.to) && same(a.color, b.color);
}

// Element i of two lists: where it differs, both versions' bounds (a missing one adds none).
template <typename T, typename Same, typename Add>
void compareLists(const std::vector<T>& before, const std::vector<T>& now, Same equal, Add add) {
  const size_t n = std::max(before.size(), now.size());
  for (size_t i = 0; i < n; ++i) {
    const bool inBefore = i < before.size(), inNow = i < now.size();
    if (inBefore && inNow && equal(before[i], now[i])) continue;
    if (inBefore) add(before[i]);
    if (inNow) add(now[i]);
  }
}

// Two drawings with the same number of bones and of joints each (and of ghosts).
bool sameShapeCounts(const SkeletonDrawList& a, const SkeletonDrawList& b) {
  return a.boneMatrices.size() == b.boneMatrices.size() && a.boneColors.size() == b.boneColors.size() &&
         a.jointMatrices.size() == b.jointMatrices.size() && a.jointColors.size() == b.jointColors.size();
}
bool sameShapeCounts(const std::vector<SkeletonDrawList>& a, const std::vector<SkeletonDrawList>& b) {
  if (a.size() != b.size()) return false;
  for (size_t g = 0; g < a.size(); ++g)
    if (!sameShapeCounts(a[g], b[g])) return false;
  return true;
}

// Every bone or joint sphere whose matrix or colour differs: its old and new boxes.
void addChangedShapes(const SkeletonDrawList& a, const SkeletonDrawList& b, ScreenBounds& s) {
  for (size_t i = 0; i < b.boneMatrices.size() && i < b.boneColors.size(); ++i)
    if (!same(a.boneMatrices[i], b.boneMatrices[i]) || !same(a.boneColors[i], b.boneColors[i]))
      s.addBox(a.boneMatrices[i], boneBox()), s.addBox(b.boneMatrices[i], boneBox());
  for (size_t i = 0; i < b.jointMatrices.size() && i < b.jointColors.size(); ++i)
    if (!same(a.jointMatrices[i], b.jointMatrices[i]) || !same(a.jointColors[i], b.jointColors[i]))
      s.addBox(a.jointMatrices[i], sphereBox()), s.addBox(b.jointMatrices[i], sphereBox());
}

// The triangles of one posed primitive around vertices that moved or turned: their corners'
// old and new positions. False when the two cannot be compared (then the whole view).
bool addMovedTriangles(const DeformedPrimitive& before, const DeformedPrimitive& now, const MeshPrimitive& source,
                       ScreenBounds& s) {
  const size_t n = now.positions.size();
  if (before.positions.size() != n || before.normals.size() != now.normals.size() ||
      (!now.normals.empty() && now.normals.size() != n))
    return false;
  std::vector<char> moved(n, 0);
  bool any = false;
  for (size_t v = 0; v < n; ++v)
    if (!same(before.positions[v], now.positions[v]) || (!now.normals.empty() && !same(before.normals[v], now.normals[v])))
      moved[v] = 1, any = true;
  if (!any) return true;
  // Sequential triangles when the primitive has no indices.
  const size_t corners = source.indices.empty() ? n - n % 3 : source.indices.size() - source.indices.size() % 3;
  auto corner = [&](size_t k) -> size_t { return source.indices.empty() ? k : source.indices[k]; };
  std::vector<char> take(n, 0);
  for (size_t t = 0; t < corners; t += 3) {
    const size_t a = corner(t), b = corner(t + 1), c = corner(t + 2);
    if (a >= n || b >= n || c >= n) return false;
    if (moved[a] || moved[b] || moved[c]) take[a] = take[b] = take[c] = 1;
  }
  for (size_t v = 0; v < n; ++v)
    if (take[v]) s.addPoint(before.positions[v]), s.addPoint(now.positions[v]);
  return true;
}

}  // namespace

bool SceneDamageJob::run() {
  if (!validate()) return false;
  const FrameDescription& f = *frame;
  const PixelRect view{f.x, f.y, f.x + std::max(f.width, 0), f.y + std::max(f.height, 0)};
  const uint64_t settings = frameSettingsSignature(f);
  const MeshFrame* meshFrame = f.meshes && f.meshes->renderer ? &f.meshes->frame : nullptr;
  const std::vector<DeformedPrimitive>* posed = meshFrame ? meshFrame->posed : nullptr;
  const std::vector<DeformedPrimitive>* deformed = meshFrame ? meshFrame->deformed : nullptr;
  // The frame's elements, compared with the kept ones, then kept in their place (assigned,
  // so the snapshot's storage is reused frame after frame).
  static const SkeletonDrawList kNoSkeleton;
  static const std::vector<SkeletonDrawList> kNoGhosts;
  static const OverlayDrawList kNoOverlay;
  static const std::vector<DeformedPrimitive> kNoPosed;
  struct Now {
    const SkeletonDrawList& skeleton;
    const std::vector<SkeletonDrawList>& ghosts;
    const OverlayDrawList& overlay;
    const std::vector<DeformedPrimitive>& posed;
    const std::vector<DeformedPrimitive>& deformed;
  } now{f.skeleton ? *f.skeleton : kNoSkeleton, f.ghosts ? *f.ghosts : kNoGhosts, f.overlay ? *f.overlay : kNoOverlay,
        posed ? *posed : kNoPosed, deformed ? *deformed : kNoPosed};
  auto keep = [&] {
    last->valid = true;
    last->settings = settings;
    last->skeleton = now.skeleton;
    last->ghosts = now.ghosts;
    last->overlay = now.overlay;
    last->posed = now.posed;
    last->deformed = now.deformed;
  };

  out = view;
  const bool comparable = last->valid && last->settings == settings && f.width > 0 && f.height > 0 &&
                          (!meshFrame || !meshFrame->gpuDeformers) && ((now.posed.empty() && now.deformed.empty()) || scene) &&
                          sameShapeCounts(last->skeleton, now.skeleton) &&
                          last->skeleton.relationships.size() == now.skeleton.relationships.size() &&
                          sameShapeCounts(last->ghosts, now.ghosts) &&
                          last->posed.size() == now.posed.size() && last->deformed.size() == now.deformed.size();
  if (!comparable) {
    keep();
    return true;
  }
  ScreenBounds s;
  const float aspect = static_cast<float>(f.width) / static_cast<float>(f.height);
  s.viewProjection = f.camera.projection(aspect) * f.camera.view();
  s.x = f.x, s.y = f.y, s.w = f.width, s.h = f.height;
  const double scale = f.lineScale;
  // Bones and joints (instance matrices and colours) of the skeleton and its ghosts.
  addChangedShapes(last->skeleton, now.skeleton, s);
  for (size_t g = 0; g < now.ghosts.size(); ++g) addChangedShapes(last->ghosts[g], now.ghosts[g], s);
  compareLists(last->skeleton.relationships, now.skeleton.relationships, sameRelationship,
               [&](const SkeletonDrawList::Relationship& r) { s.addPoint(r.from, scale), s.addPoint(r.to, scale); });
  // The overlay: widths and radii in pixels (times the line scale, as drawn).
  const OverlayDrawList& oa = last->overlay;
  const OverlayDrawList& ob = now.overlay;
  compareLists(oa.lines, ob.lines, sameLine, [&](const OverlayDrawList::Line& l) {
    const double grow = 0.5 * l.widthPixels * scale + 1.0;
    s.addPoint(l.a, grow), s.addPoint(l.b, grow);
  });
  compareLists(oa.handles, ob.handles, sameHandle, [&](const OverlayDrawList::Handle& h) {
    // Markers up to kMarkerPixels scale with the lines (OverlayDrawList::scaleWidths); an outline adds a few pixels.
    const double radius = h.radiusPixels * (h.radiusPixels <= OverlayDrawList::kMarkerPixels ? scale : 1.0);
    s.addPoint(h.center, radius + 2.0 * scale + 2.0);
  });
  compareLists(oa.screenLines, ob.screenLines, sameScreenLine, [&](const OverlayDrawList::ScreenLine& l) {
    const double grow = 0.5 * l.widthPixels * scale + 1.0;
    s.addViewPixel(l.a, grow), s.addViewPixel(l.b, grow);
  });
  compareLists(oa.screenRects, ob.screenRects, sameScreenRect, [&](const OverlayDrawList::ScreenRect& r) {
    s.addViewPixel(r.min, 2.0 * scale + 1.0), s.addViewPixel(r.max, 2.0 * scale + 1.0);
  });
  // Meshes posed or deformed on the CPU: triangles around the vertices that changed.
  bool meshesComparable = true;
  auto compareMeshes = [&](const std::vector<DeformedPrimitive>& was, const std::vector<DeformedPrimitive>& is) {
    for (size_t i = 0; i < is.size() && meshesComparable; ++i) {
      const DeformedPrimitive& before = was[i];
      const DeformedPrimitive& after = is[i];
      meshesComparable = before.instance == after.instance && before.primitive == after.primitive &&
                         after.instance >= 0 && after.instance < static_cast<int>(scene->meshInstances.size());
      if (!meshesComparable) break;
      const int mesh = scene->meshInstances[after.instance].mesh;
      meshesComparable = mesh >= 0 && mesh < static_cast<int>(scene->meshes.size()) && after.primitive >= 0 &&
                         after.primitive < static_cast<int>(scene->meshes[mesh].primitives.size()) &&
                         addMovedTriangles(before, after, scene->meshes[mesh].primitives[after.primitive], s);
    }
  };
  compareMeshes(last->posed, now.posed);
  compareMeshes(last->deformed, now.deformed);
  keep();
  if (!meshesComparable || s.behind) return true;  // the whole view
  if (s.minX > s.maxX) {
    out = {};  // nothing changed
    return true;
  }
  out = PixelRect::covering(s.minX, s.minY, s.maxX, s.maxY, view).grown(kSceneDamageMargin).intersected(view);
  return true;
}

}  // namespace kinema
