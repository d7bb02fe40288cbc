#include "render/skeleton_renderer.h"

#include <algorithm>
#include <cmath>
#include <cstddef>

#include "render/closed_surface.h"
#include "render/frame_pass_timer.h"
#include "render/mesh_renderer.h"
#include "render/shader_sources.h"
#include "render/shape_meshes.h"

namespace kinema {

namespace {

// Dashes of about kDashPixels with equal gaps, counted on the line's length on screen (so
// they look alike at any zoom); 8 when an end is behind the camera.
int dashCount(const glm::vec3& a, const glm::vec3& b, const glm::mat4& viewProjection, int width, int height) {
  constexpr float kDashPixels = 5.0f;
  const glm::vec4 ca = viewProjection * glm::vec4(a, 1.0f), cb = viewProjection * glm::vec4(b, 1.0f);
  if (!(ca.w > 1e-6f && cb.w > 1e-6f)) return 8;
  const glm::vec2 size(static_cast<float>(width), static_cast<float>(height));
  const glm::vec2 pa = glm::vec2(ca) / ca.w * 0.5f * size, pb = glm::vec2(cb) / cb.w * 0.5f * size;
  const float pixels = glm::length(pb - pa);
  if (!std::isfinite(pixels)) return 8;
  return static_cast<int>(std::clamp((pixels / kDashPixels + 1.0f) * 0.5f, 2.0f, 2000.0f));
}

}  // namespace

SkeletonRenderer::~SkeletonRenderer() {
  for (ShapeBuffers* s : {&bone_, &sphere_, &ghostBone_, &ghostSphere_, &sphereCard_, &ghostSphereCard_}) {
    if (s->vao) glDeleteVertexArrays(1, &s->vao);
    if (s->vertices) glDeleteBuffers(1, &s->vertices);
    if (s->indices) glDeleteBuffers(1, &s->indices);
    if (s->instances) glDeleteBuffers(1, &s->instances);
  }
  if (lineVao_) glDeleteVertexArrays(1, &lineVao_);
  if (lineVertices_) glDeleteBuffers(1, &lineVertices_);
}

std::string SkeletonRenderer::init() {
  std::string error = shaded_.build("shaded", shaders::shaded_vert, shaders::shaded_frag);
  if (error.empty()) error = faceted_.build("faceted", shaders::faceted_vert, shaders::faceted_frag);
  if (error.empty()) error = impostor_.build("sphere_impostor", shaders::sphere_impostor_vert, shaders::sphere_impostor_frag);
  if (error.empty()) error = lines_.build("lines", shaders::lines_vert, shaders::lines_frag);
  if (error.empty()) error = overlay_.init();
  if (!error.empty()) return error;
  createShape(bone_, makeOctahedralBone());
  createShape(sphere_, makeSphere(16, 10));
  createShape(ghostBone_, makeOctahedralBone());
  createShape(ghostSphere_, makeSphere(16, 10));
  createShape(sphereCard_, makeSquare());
  createShape(ghostSphereCard_, makeSquare());

  glGenVertexArrays(1, &lineVao_);
  glGenBuffers(1, &lineVertices_);
  glBindVertexArray(lineVao_);
  glBindBuffer(GL_ARRAY_BUFFER, lineVertices_);
  glEnableVertexAttribArray(0);
  glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, sizeof(LineVertex), reinterpret_cast<void*>(offsetof(LineVertex, position)));
  glEnableVertexAttribArray(1);
  glVertexAttribPointer(1, 4, GL_FLOAT, GL_FALSE, sizeof(LineVertex), reinterpret_cast<void*>(offsetof(LineVertex, color)));
  glBindVertexArray(0);
  const GLenum status = glGetError();
  if (status != GL_NO_ERROR) return "OpenGL error " + std::to_string(status) + " while creating the renderer's buffers";
  return {};
}

void SkeletonRenderer::createShape(ShapeBuffers& shape, const ShapeMesh& triangles) {
  // Interleaved position + normal per vertex, indexed; a second buffer holds per-instance matrix + colour.
  const IndexedShapeMesh mesh = weldVertices(triangles);
  std::vector<float> data;
  data.reserve(mesh.positions.size() * 6);
  for (size_t i = 0; i < mesh.positions.size(); ++i)
    for (const glm::vec3& v : {mesh.positions[i], mesh.normals[i]}) data.insert(data.end(), {v.x, v.y, v.z});
  shape.indexCount = static_cast<int>(mesh.indices.size());
  shape.boxMin = shape.boxMax = mesh.positions.empty() ? glm::vec3(0.0f) : mesh.positions[0];
  for (const glm::vec3& p : mesh.positions) shape.boxMin = glm::min(shape.boxMin, p), shape.boxMax = glm::max(shape.boxMax, p);
  glGenVertexArrays(1, &shape.vao);
  glGenBuffers(1, &shape.vertices);
  glGenBuffers(1, &shape.indices);
  glGenBuffers(1, &shape.instances);
  glBindVertexArray(shape.vao);
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, shape.indices);
  glBufferData(GL_ELEMENT_ARRAY_BUFFER, static_cast<GLsizeiptr>(mesh.indices.size() * sizeof(unsigned int)),
               mesh.indices.data(), GL_STATIC_DRAW);
  glBindBuffer(GL_ARRAY_BUFFER, shape.vertices);
  glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(data.size() * sizeof(float)), data.data(), GL_STATIC_DRAW);
  glEnableVertexAttribArray(0);
  glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, 6 * sizeof(float), nullptr);
  glEnableVertexAttribArray(1);
  glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, 6 * sizeof(float), reinterpret_cast<void*>(3 * sizeof(float)));
  glBindBuffer(GL_ARRAY_BUFFER, shape.instances);
  const GLsizei stride = 20 * sizeof(float);  // mat4 + vec4
  for (int c = 0; c < 5; ++c) {
    glEnableVertexAttribArray(2 + c);
    glVertexAttribPointer(2 + c, 4, GL_FLOAT, GL_FALSE, stride, reinterpret_cast<void*>(c * 4 * sizeof(float)));
    glVertexAttribDivisor(2 + c, 1);
  }
  glBindVertexArray(0);
}

void SkeletonRenderer::uploadInstances(ShapeBuffers& shape, const std::vector<glm::mat4>& matrices,
                                       const std::vector<glm::vec4>& colors) {
  instanceScratch_.clear();
  for (size_t i = 0; i < matrices.size(); ++i) {
    const float* m = glm::value_ptr(matrices[i]);
    instanceScratch_.insert(instanceScratch_.end(), m, m + 16);
    const float* c = glm::value_ptr(colors[i]);
    instanceScratch_.insert(instanceScratch_.end(), c, c + 4);
  }
  glBindVertexArray(shape.vao);
  glBindBuffer(GL_ARRAY_BUFFER, shape.instances);
  glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(instanceScratch_.size() * sizeof(float)),
               instanceScratch_.data(), GL_STREAM_DRAW);
}

SkeletonRenderer::Prepared SkeletonRenderer::prepareInstances(ShapeBuffers& shape, ShapeBuffers* impostorCard,
                                                               const std::vector<glm::mat4>& matrices,
                                                               const std::vector<glm::vec4>& colors,
                                                               const ScreenRegion& region, bool frontFacesOnly) {
  shapeMatrices_.clear(), shapeColors_.clear(), impostorMatrices_.clear(), impostorColors_.clear();
  bool allInFront = true;
  for (size_t i = 0; i < matrices.size() && i < colors.size(); ++i) {
    if (region.culls() && !region.boxMayCover(matrices[i], shape.boxMin, shape.boxMax)) continue;
    const bool inFront =
        frontFacesOnly && boxInFrontOfNearPlane(region.viewProjection * matrices[i], shape.boxMin, shape.boxMax);
    if (inFront && impostorCard) {
      impostorMatrices_.push_back(matrices[i]);
      impostorColors_.push_back(colors[i]);
    } else {
      allInFront = allInFront && inFront;
      shapeMatrices_.push_back(matrices[i]);
      shapeColors_.push_back(colors[i]);
    }
  }
  Prepared p;
  p.shapes = static_cast<GLsizei>(shapeMatrices_.size());
  p.impostors = static_cast<GLsizei>(impostorMatrices_.size());
  // The shapes are closed and wound outward (shape_meshes.h): front faces alone while
  // every one is wholly in front of the near plane.
  p.cullShapes = frontFacesOnly && allInFront;
  if (p.shapes > 0) uploadInstances(shape, shapeMatrices_, shapeColors_);
  if (p.impostors > 0) uploadInstances(*impostorCard, impostorMatrices_, impostorColors_);
  return p;
}

void SkeletonRenderer::setLitMatrices(const glm::mat4& viewProjection, const glm::mat4& view) {
  for (const ShaderProgram* p : {&shaded_, &faceted_}) {
    glUseProgram(p->id());
    glUniformMatrix4fv(p->uniform("uViewProjection"), 1, GL_FALSE, glm::value_ptr(viewProjection));
    glUniformMatrix4fv(p->uniform("uView"), 1, GL_FALSE, glm::value_ptr(view));
  }
}

void SkeletonRenderer::drawPrepared(ShapeBuffers& shape, ShapeBuffers* impostorCard, const Prepared& prepared,
                                    const ShaderProgram& lit) {
  if (prepared.shapes > 0) {
    glUseProgram(lit.id());
    if (prepared.cullShapes) {
      glEnable(GL_CULL_FACE);
      glCullFace(GL_BACK);
    }
    glBindVertexArray(shape.vao);
    glDrawElementsInstanced(GL_TRIANGLES, shape.indexCount, GL_UNSIGNED_INT, nullptr, prepared.shapes);
    if (prepared.cullShapes) glDisable(GL_CULL_FACE);
  }
  if (prepared.impostors > 0 && impostorCard) {
    // One card per sphere: each of its pixels once.
    glUseProgram(impostor_.id());
    glDisable(GL_CULL_FACE);
    glBindVertexArray(impostorCard->vao);
    glDrawElementsInstanced(GL_TRIANGLES, impostorCard->indexCount, GL_UNSIGNED_INT, nullptr, prepared.impostors);
  }
}

void SkeletonRenderer::drawGrid(const FrameDescription& frame, const glm::mat4& viewProjection) {
  const float cell = gridCellSize(frame.sceneRadius);
  // Reach past the skeleton, and past the point the camera looks at, whichever is further.
  const float reach = std::max(frame.sceneRadius * 2.5f, glm::length(frame.camera.target) + frame.sceneRadius * 2.0f);
  if (cell != gridCacheCell_ || reach != gridCacheReach_ || gridCache_.empty()) {
    gridCache_ = makeGridLines(cell, reach);
    gridCacheCell_ = cell;
    gridCacheReach_ = reach;
    glBindBuffer(GL_ARRAY_BUFFER, lineVertices_);
    glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(gridCache_.size() * sizeof(LineVertex)), gridCache_.data(),
                 GL_STATIC_DRAW);
  }
  if (frame.lineScale > 1.0f) {  // wide lines: triangles (core profiles draw GL_LINES 1 px wide)
    OverlayDrawList wide;
    for (size_t i = 0; i + 1 < gridCache_.size(); i += 2)
      wide.addLine(gridCache_[i].position, gridCache_[i + 1].position, gridCache_[i].color, frame.lineScale,
                   OverlayDrawList::Layer::Scene);
    overlay_.draw(wide, viewProjection, frame.width, frame.height);
    return;
  }
  glUseProgram(lines_.id());
  glUniformMatrix4fv(lines_.uniform("uViewProjection"), 1, GL_FALSE, glm::value_ptr(viewProjection));
  glBindVertexArray(lineVao_);
  glDrawArrays(GL_LINES, 0, static_cast<GLsizei>(gridCache_.size()));
}

void SkeletonRenderer::drawGhosts(const std::vector<SkeletonDrawList>& ghosts, const glm::mat4& viewProjection,
                                  const glm::mat4& view, const ScreenRegion& region, bool frontFacesOnly) {
  // All ghosts in one instance list per shape, uploaded and drawn once.
  for (int k = 0; k < 2; ++k) {
    ghostMatrices_[k].clear();
    ghostColors_[k].clear();
  }
  for (const SkeletonDrawList& g : ghosts) {
    ghostMatrices_[0].insert(ghostMatrices_[0].end(), g.boneMatrices.begin(), g.boneMatrices.end());
    ghostColors_[0].insert(ghostColors_[0].end(), g.boneColors.begin(), g.boneColors.end());
    ghostMatrices_[1].insert(ghostMatrices_[1].end(), g.jointMatrices.begin(), g.jointMatrices.end());
    ghostColors_[1].insert(ghostColors_[1].end(), g.jointColors.begin(), g.jointColors.end());
  }
  setLitMatrices(viewProjection, view);
  Prepared bones = prepareInstances(ghostBone_, nullptr, ghostMatrices_[0], ghostColors_[0], region, frontFacesOnly);
  Prepared joints =
      prepareInstances(ghostSphere_, &ghostSphereCard_, ghostMatrices_[1], ghostColors_[1], region, frontFacesOnly);
  // One blended pass with back faces culled: the shapes are closed and wound outward
  // (shape_meshes.h), so a bone blends once where it is seen, at the cost of one pass only.
  bones.cullShapes = joints.cullShapes = true;
  glEnable(GL_DEPTH_TEST);
  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  drawPrepared(ghostBone_, nullptr, bones, faceted_);
  drawPrepared(ghostSphere_, &ghostSphereCard_, joints, shaded_);
  glDisable(GL_CULL_FACE);
  glDisable(GL_BLEND);
  glDepthFunc(GL_LESS);
}

void SkeletonRenderer::draw(const FrameDescription& frame) {
  if (frame.width <= 0 || frame.height <= 0) return;
  auto mark = [&frame](const char* pass) {
    if (frame.timer) frame.timer->mark(pass);
  };
  glViewport(frame.x, frame.y, frame.width, frame.height);
  // The scissor box stays on for the whole frame when it is limited (a partial redraw);
  // else only for the clears, which must not reach past the view.
  const PixelRect viewRect{frame.x, frame.y, frame.x + frame.width, frame.y + frame.height};
  const bool limited = !frame.limit.empty();
  const PixelRect box = limited ? viewRect.intersected(frame.limit) : viewRect;
  if (box.empty()) return;
  glScissor(box.x0, box.y0, box.width(), box.height());
  auto scissorForClears = [limited](bool on) {
    if (limited || on) glEnable(GL_SCISSOR_TEST);
    else glDisable(GL_SCISSOR_TEST);
  };
  glDepthMask(GL_TRUE);
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  if (frame.clear) {
    scissorForClears(true);
    glClearColor(frame.background.r, frame.background.g, frame.background.b, frame.background.a);
    glClearDepth(1.0);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  }
  scissorForClears(false);
  glDisable(GL_BLEND);
  glDisable(GL_CULL_FACE);  // thin octahedra seen edge-on; the shader lights back faces too
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  mark("3D view: clear");

  const float aspect = static_cast<float>(frame.width) / static_cast<float>(frame.height);
  const glm::mat4 view = frame.camera.view();
  const glm::mat4 projection = frame.camera.projection(aspect);
  const glm::mat4 viewProjection = projection * view;
  glUseProgram(impostor_.id());
  glUniformMatrix4fv(impostor_.uniform("uView"), 1, GL_FALSE, glm::value_ptr(view));
  glUniformMatrix4fv(impostor_.uniform("uProjection"), 1, GL_FALSE, glm::value_ptr(projection));
  glUniform1i(impostor_.uniform("uOrthographic"), frame.camera.orthographic);
  // A partial redraw leaves out what cannot reach the scissor box (screen_culling.h).
  const ScreenRegion region{viewProjection, viewRect, limited ? box : PixelRect{}};
  if (frame.showGrid) drawGrid(frame, viewProjection);
  mark("3D view: grid");
  if (frame.meshes && frame.meshes->renderer)
    frame.meshes->renderer->draw(frame.meshes->frame, viewProjection, view, &region, frame.frontFacesOnly);
  mark("3D view: mesh");
  if (frame.meshes && frame.meshes->renderer && frame.meshGhosts && !frame.meshGhosts->empty())
    frame.meshes->renderer->drawGhosts(*frame.meshGhosts, viewProjection, view);
  mark("3D view: mesh ghosts");
  if (frame.skeleton && frame.bones != BoneDisplay::None) {
    setLitMatrices(viewProjection, view);
    const bool xray = frame.bones == BoneDisplay::XRay;
    // Made ready once, drawn once or (x-ray) twice: re-filling a buffer a queued draw reads
    // makes llvmpipe finish the frame so far first.
    const Prepared bones = prepareInstances(bone_, nullptr, frame.skeleton->boneMatrices, frame.skeleton->boneColors,
                                            region, frame.frontFacesOnly);
    const Prepared joints = prepareInstances(sphere_, &sphereCard_, frame.skeleton->jointMatrices,
                                             frame.skeleton->jointColors, region, frame.frontFacesOnly);
    if (xray) {
      // On top of the meshes (or, without any, of the grid): fresh depth, a depth-only pass, then the nearest bone surfaces
      // blended by their colours' alpha (SkeletonStyle::xRay()) so the body still shows through.
      scissorForClears(true);
      glClear(GL_DEPTH_BUFFER_BIT);
      scissorForClears(false);
      glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
      drawPrepared(bone_, nullptr, bones, faceted_);
      drawPrepared(sphere_, &sphereCard_, joints, shaded_);
      glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
      glDepthFunc(GL_LEQUAL);
      glEnable(GL_BLEND);
      glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    }
    drawPrepared(bone_, nullptr, bones, faceted_);
    drawPrepared(sphere_, &sphereCard_, joints, shaded_);
    if (xray) {
      glDisable(GL_BLEND);
      glDepthFunc(GL_LESS);
    }
    // Thin dashed relationship lines where a joint is not connected to its parent: hidden
    // by bodies like the bones, on top of everything with them in x-ray.
    if (!frame.skeleton->relationships.empty()) {
      OverlayDrawList dashed;
      for (const SkeletonDrawList::Relationship& r : frame.skeleton->relationships)
        dashed.addDashedLine(r.from, r.to, dashCount(r.from, r.to, viewProjection, frame.width, frame.height), r.color,
                             frame.lineScale, xray ? OverlayDrawList::Layer::OnTop : OverlayDrawList::Layer::Scene);
      overlay_.draw(dashed, viewProjection, frame.width, frame.height);
    }
  }
  mark("3D view: bones");
  if (frame.ghosts && !frame.ghosts->empty()) drawGhosts(*frame.ghosts, viewProjection, view, region, frame.frontFacesOnly);
  mark("3D view: bone ghosts");
  if (frame.overlay && frame.lineScale != 1.0f) {
    OverlayDrawList scaled = *frame.overlay;
    scaled.scaleWidths(frame.lineScale);
    overlay_.draw(scaled, viewProjection, frame.width, frame.height);
  } else if (frame.overlay) {
    overlay_.draw(*frame.overlay, viewProjection, frame.width, frame.height);
  }
  glBindVertexArray(0);
  glUseProgram(0);
  glDisable(GL_SCISSOR_TEST);
  mark("3D view: overlay");
}

}  // namespace kinema
