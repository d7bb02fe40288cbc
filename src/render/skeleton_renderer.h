#pragma once
#include <string>
#include <vector>

#include "render/camera.h"
#include "render/grid_lines.h"
#include "render/overlay_renderer.h"
#include "render/pixel_rect.h"
#include "render/screen_culling.h"
#include "render/shader_program.h"
#include "render/shape_meshes.h"
#include "render/skeleton_draw_list.h"

namespace kinema {

class FramePassTimer;
struct MeshDraw;
struct MeshGhost;

// How bones show over meshes: not at all, depth-tested like any surface (hidden inside a
// body), or x-ray: on top of everything, blended by the bone colours' alpha (draw with
// SkeletonStyle::xRay() for semi-transparent bones).
enum class BoneDisplay { None, On, XRay };

// Everything one frame shows; the renderer keeps no scene state between frames.
struct FrameDescription {
  const SkeletonDrawList* skeleton = nullptr;  // may be null: grid only
  OrbitCamera camera;
  int x = 0, y = 0, width = 0, height = 0;  // viewport in the bound framebuffer, pixels
  float sceneRadius = 1.0f;                 // sizes the grid
  bool showGrid = true;
  glm::vec4 background{0.235f, 0.235f, 0.235f, 1.0f};  // Blender's viewport grey
  // false: the caller has already cleared the viewport to `background` and depth 1 (a
  // window cleared whole), so draw() skips its own clear, which a software rasteriser pays
  // for pixel by pixel when it is limited to part of the framebuffer.
  bool clear = true;
  // Non-empty: only these framebuffer pixels are touched (cleared when `clear`, drawn), the
  // rest of the view keeps what it showed; the view still maps x, y, width, height. A partial
  // redraw (SceneDamageJob) draws the whole scene limited to the part that changed.
  PixelRect limit;
  const MeshDraw* meshes = nullptr;  // shaded (skinned) meshes, drawn before the bones; may be null
  BoneDisplay bones = BoneDisplay::On;
  const OverlayDrawList* overlay = nullptr;             // gizmos, handles, ...; drawn last
  // Onion-skin ghosts: whole skeletons blended by their colours' alpha after the bones,
  // depth-tested against the scene, front faces only (each bone blends once). May be null.
  const std::vector<SkeletonDrawList>* ghosts = nullptr;
  // The grid's and the overlay's line widths and marker sizes, times their pixels (the
  // editor's presentation preset makes them thicker for a projector); 1 = as built.
  float lineScale = 1.0f;
  // Onion-skin ghosts of the meshes (MeshRenderer::drawGhosts), drawn right after the meshes
  // with their renderer (so before the bones, whose x-ray pass would clear the body's depth).
  // Needs `meshes`; may be null.
  const std::vector<MeshGhost>* meshGhosts = nullptr;
  // While the view moves (a drag, playback: one sample per pixel, viewport_quality.h): closed
  // shapes (bones, joint spheres, meshes that bound a solid, closed_surface.h) are drawn
  // without their back faces where the near plane does not cut them. Seen from outside, a
  // closed surface shows front faces only, so the picture is the same but for silhouette
  // pixels that a back face's edge took, and a software rasteriser fills half the triangles.
  // Joint spheres in front of the near plane are then drawn as impostors (shaders/
  // sphere_impostor.*: a card per joint, the sphere found per pixel), as Blender's overlay.
  bool frontFacesOnly = false;
  // Measurement only (kinema edit --report-frame-passes): each pass is marked on it. May be null.
  FramePassTimer* timer = nullptr;
};

// Draws grid, axes, bones and joints with OpenGL 3.3 core into whatever framebuffer is
// bound (a window's, an FBO): it knows nothing of windows or contexts. Create, init() and
// destroy it with the same context current.
class SkeletonRenderer {
 public:
  SkeletonRenderer() = default;
  ~SkeletonRenderer();
  SkeletonRenderer(const SkeletonRenderer&) = delete;
  SkeletonRenderer& operator=(const SkeletonRenderer&) = delete;

  // Compiles the embedded shaders and uploads the shape meshes. Empty string on success.
  std::string init();
  void draw(const FrameDescription& frame);

 private:
  struct ShapeBuffers {
    GLuint vao = 0, vertices = 0, indices = 0, instances = 0;
    int indexCount = 0;  // welded (weldVertices): each corner shaded once per instance
    glm::vec3 boxMin{0.0f}, boxMax{0.0f};  // the shape's bounds in its own space
  };
  void createShape(ShapeBuffers& shape, const ShapeMesh& mesh);
  // Instances of a closed shape made ready to draw (drawPrepared), possibly more than once:
  // those that cannot reach a partial redraw's limit left out; with `frontFacesOnly`, those
  // wholly in front of the near plane go to `impostorCard` where given (joint spheres drawn
  // by sphere_impostor.*), and the shape's own are drawn without back faces when every one
  // of them is in front. Uploads the instance buffers.
  struct Prepared {
    GLsizei shapes = 0, impostors = 0;
    bool cullShapes = false;
  };
  Prepared prepareInstances(ShapeBuffers& shape, ShapeBuffers* impostorCard, const std::vector<glm::mat4>& matrices,
                            const std::vector<glm::vec4>& colors, const ScreenRegion& region, bool frontFacesOnly);
  // Draws them: the shapes with `lit` (faceted_ or shaded_, its matrices set by setLitMatrices), the
  // impostors with impostor_.
  void drawPrepared(ShapeBuffers& shape, ShapeBuffers* impostorCard, const Prepared& prepared, const ShaderProgram& lit);
  // Sets both lit programs' view and projection for this frame.
  void setLitMatrices(const glm::mat4& viewProjection, const glm::mat4& view);
  void uploadInstances(ShapeBuffers& shape, const std::vector<glm::mat4>& matrices, const std::vector<glm::vec4>& colors);
  void drawGrid(const FrameDescription& frame, const glm::mat4& viewProjection);
  void drawGhosts(const std::vector<SkeletonDrawList>& ghosts, const glm::mat4& viewProjection, const glm::mat4& view,
                  const ScreenRegion& region, bool frontFacesOnly);

  ShaderProgram shaded_, lines_;
  ShaderProgram faceted_;   // bones: flat faces lit once per vertex (shaders/faceted.*)
  ShaderProgram impostor_;  // joint spheres while the view moves (shaders/sphere_impostor.*)
  OverlayRenderer overlay_;
  ShapeBuffers bone_, sphere_;
  ShapeBuffers sphereCard_, ghostSphereCard_;  // the impostors' cards (makeSquare), own instance buffers
  // The ghosts' own instance buffers, uploaded once a frame: re-filling a buffer that a
  // queued draw still reads makes llvmpipe finish the frame so far first.
  ShapeBuffers ghostBone_, ghostSphere_;
  std::vector<glm::mat4> ghostMatrices_[2];
  std::vector<glm::vec4> ghostColors_[2];
  GLuint lineVao_ = 0, lineVertices_ = 0;
  std::vector<LineVertex> gridCache_;
  float gridCacheCell_ = 0.0f, gridCacheReach_ = 0.0f;
  std::vector<float> instanceScratch_;
  std::vector<glm::mat4> shapeMatrices_, impostorMatrices_;  // prepareInstances' two groups
  std::vector<glm::vec4> shapeColors_, impostorColors_;
};

}  // namespace kinema
