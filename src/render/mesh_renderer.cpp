#include "render/mesh_renderer.h"

#include <algorithm>
#include <cstddef>
#include <cstring>

#include "deform/deformer_stack.h"
#include "render/closed_surface.h"
#include "render/gl_context.h"
#include "render/shader_sources.h"
#include "skin/skinning_decomposition.h"
#include "skin/skinning_matrices.h"

namespace kinema {

namespace {

// Vertex layout of the static buffer: position, normal, texcoord.
struct PackedVertex {
  float position[3];
  float normal[3];
  float texcoord[2];
};

glm::mat3 inverseTranspose3(const glm::mat3& m) {
  const float det = glm::determinant(m);
  if (!(std::abs(det) > 1e-30f)) return glm::mat3(0.0f);
  return glm::transpose(glm::inverse(m));
}

GLuint makeBufferTexture(GLuint buffer, GLenum format) {
  GLuint texture = 0;
  glGenTextures(1, &texture);
  glBindTexture(GL_TEXTURE_BUFFER, texture);
  glTexBuffer(GL_TEXTURE_BUFFER, format, buffer);
  glBindTexture(GL_TEXTURE_BUFFER, 0);
  return texture;
}

// Area-weighted vertex normals for display when the file gives none (glTF asks for flat
// shading there; smooth is what a skinned body wants, and the CPU reference has no normals
// to compare against in that case anyway).
std::vector<glm::vec3> displayNormals(const MeshPrimitive& p) {
  std::vector<glm::vec3> n(p.positions.size(), glm::vec3(0.0f));
  for (size_t t = 0; t + 2 < p.indices.size(); t += 3) {
    const uint32_t a = p.indices[t], b = p.indices[t + 1], c = p.indices[t + 2];
    if (a >= n.size() || b >= n.size() || c >= n.size()) continue;
    const glm::vec3 face = glm::cross(p.positions[b] - p.positions[a], p.positions[c] - p.positions[a]);
    n[a] += face;
    n[b] += face;
    n[c] += face;
  }
  for (glm::vec3& v : n) v = glm::length(v) > 0.0f ? glm::normalize(v) : glm::vec3(0.0f, 1.0f, 0.0f);
  return n;
}

// What a mesh pass leaves bound (vertex array, the joint, morph and texture units, the
// program), unbound so the next renderer starts clean.
void unbindMeshDrawState() {
  glBindVertexArray(0);
  glActiveTexture(GL_TEXTURE1);
  glBindTexture(GL_TEXTURE_BUFFER, 0);
  glActiveTexture(GL_TEXTURE2);
  glBindTexture(GL_TEXTURE_2D, 0);
  glActiveTexture(GL_TEXTURE0);
  glBindTexture(GL_TEXTURE_BUFFER, 0);
  glUseProgram(0);
}

// Interleaves positions and normals (one per vertex) with the primitive's texcoords (zero
// where it has none) in the layout the shader reads.
std::vector<PackedVertex> packVertices(const std::vector<glm::vec3>& positions, const std::vector<glm::vec3>& normals,
                                       const MeshPrimitive& src) {
  std::vector<PackedVertex> vertices(positions.size());
  const bool uvs = src.texcoords.size() == positions.size();
  for (size_t v = 0; v < positions.size(); ++v) {
    PackedVertex& out = vertices[v];
    for (int c = 0; c < 3; ++c) {
      out.position[c] = positions[v][c];
      out.normal[c] = normals[v][c];
    }
    const glm::vec2 uv = uvs ? src.texcoords[v] : glm::vec2(0.0f);
    out.texcoord[0] = uv.x;
    out.texcoord[1] = uv.y;
  }
  return vertices;
}

}  // namespace

void packJointTexels(const glm::mat4& m, float* out) {
  const glm::mat3 a(m);
  const glm::mat3 normal = inverseTranspose3(a);
  // The CPU's split (skinning_decomposition.h), so both paths deform alike: A = R * S.
  const SkinningDecomposition split = decomposeSkinningMatrix(m);
  const glm::quat& real = split.real;
  const glm::quat& dual = split.dual;
  const glm::mat3& rest = split.stretch;
  auto put = [&out](const glm::vec4& v) {
    out[0] = v.x;
    out[1] = v.y;
    out[2] = v.z;
    out[3] = v.w;
    out += 4;
  };
  for (int c = 0; c < 4; ++c) put(m[c]);
  for (int c = 0; c < 3; ++c) put(glm::vec4(normal[c], 0.0f));
  put(glm::vec4(real.x, real.y, real.z, real.w));
  put(glm::vec4(dual.x, dual.y, dual.z, dual.w));
  for (int c = 0; c < 3; ++c) put(glm::vec4(rest[c], 0.0f));
}

MeshRenderer::~MeshRenderer() {
  release();
  if (!program_.id()) return;  // init() never succeeded: no GL objects (and maybe no GL loaded)
  const GLuint buffers[] = {jointBuffer_, feedbackBuffer_, emptyBuffer_, ghostBuffer_, cpuBuffer_, cullIndices_};
  glDeleteBuffers(6, buffers);
  const GLuint textures[] = {jointTexture_, emptyTexture_, ghostTexture_};
  glDeleteTextures(3, textures);
  glDeleteFramebuffers(1, &feedbackFbo_);
  glDeleteRenderbuffers(1, &feedbackColor_);
}

void MeshRenderer::release() {
  for (GpuPrimitive& p : primitives_) {
    glDeleteVertexArrays(1, &p.vao);
    glDeleteVertexArrays(1, &p.cpuVao);
    glDeleteVertexArrays(1, &p.deformedVao);
    const GLuint buffers[] = {p.vertices, p.influences, p.indices, p.morphBuffer, p.deformedVertices};
    glDeleteBuffers(5, buffers);
    glDeleteTextures(1, &p.morphTexture);
  }
  primitives_.clear();
  primitivesOfMesh_.clear();
  uploadKey_.clear();
  if (!textures_.empty()) glDeleteTextures(static_cast<GLsizei>(textures_.size()), textures_.data());
  textures_.clear();
  scene_ = nullptr;
}

std::string MeshRenderer::init() {
  // The world position and normal are also captured by transform feedback (deform()).
  std::string error = program_.build("mesh", shaders::mesh_vert, shaders::mesh_frag, {"vWorldPosition", "vWorldNormal"});
  if (error.empty()) error = posedProgram_.build("mesh_posed", shaders::mesh_posed_vert, shaders::mesh_frag);
  if (!error.empty()) return error;
  glGenBuffers(1, &jointBuffer_);
  glBindBuffer(GL_TEXTURE_BUFFER, jointBuffer_);
  glBufferData(GL_TEXTURE_BUFFER, 16, nullptr, GL_STREAM_DRAW);
  jointTexture_ = makeBufferTexture(jointBuffer_, GL_RGBA32F);
  glGenBuffers(1, &ghostBuffer_);
  glBindBuffer(GL_TEXTURE_BUFFER, ghostBuffer_);
  glBufferData(GL_TEXTURE_BUFFER, 16, nullptr, GL_STREAM_DRAW);
  ghostTexture_ = makeBufferTexture(ghostBuffer_, GL_RGBA32F);
  // Samplers must always name a complete texture, also for primitives without morphs.
  glGenBuffers(1, &emptyBuffer_);
  glBindBuffer(GL_TEXTURE_BUFFER, emptyBuffer_);
  const float zero[4] = {0, 0, 0, 0};
  glBufferData(GL_TEXTURE_BUFFER, sizeof zero, zero, GL_STATIC_DRAW);
  emptyTexture_ = makeBufferTexture(emptyBuffer_, GL_RGBA32F);
  glBindBuffer(GL_TEXTURE_BUFFER, 0);
  glGenBuffers(1, &feedbackBuffer_);
  glGenBuffers(1, &cpuBuffer_);
  glGenBuffers(1, &cullIndices_);
  cpuDeformation_ = softwareRasterizer();
  // Draws need a complete framebuffer even with the rasterizer off, and a headless context
  // has none of its own: deform() binds this 1x1 one.
  glGenRenderbuffers(1, &feedbackColor_);
  glBindRenderbuffer(GL_RENDERBUFFER, feedbackColor_);
  glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, 1, 1);
  glGenFramebuffers(1, &feedbackFbo_);
  glBindFramebuffer(GL_FRAMEBUFFER, feedbackFbo_);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, feedbackColor_);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glUseProgram(program_.id());
  glUniform1i(program_.uniform("uJoints"), 0);
  glUniform1i(program_.uniform("uMorphDeltas"), 1);
  glUniform1i(program_.uniform("uBaseColorTexture"), 2);
  glUseProgram(posedProgram_.id());
  glUniform1i(posedProgram_.uniform("uBaseColorTexture"), 2);
  glUseProgram(0);
  const GLenum status = glGetError();
  if (status != GL_NO_ERROR) return "OpenGL error " + std::to_string(status) + " while creating the mesh renderer";
  return {};
}

std::vector<const void*> MeshRenderer::keyOf(const Scene& scene) {
  // A scene replaced by another (moved or copied in) has new array buffers; sizes catch the rest.
  return {&scene,
          scene.meshes.data(), reinterpret_cast<const void*>(scene.meshes.size()),
          scene.skins.data(), reinterpret_cast<const void*>(scene.skins.size()),
          scene.meshInstances.data(), reinterpret_cast<const void*>(scene.meshInstances.size()),
          scene.images.data(), reinterpret_cast<const void*>(scene.images.size())};
}

bool MeshRenderer::needsUpload(const Scene& scene) const { return keyOf(scene) != uploadKey_; }

std::string MeshRenderer::upload(const Scene& scene) {
  release();
  warnings_.clear();
  allNormals_ = true;
  scene_ = &scene;
  uploadKey_ = keyOf(scene);
  primitivesOfMesh_.resize(scene.meshes.size());
  for (size_t m = 0; m < scene.meshes.size(); ++m) {
    const Mesh& mesh = scene.meshes[m];
    for (size_t k = 0; k < mesh.primitives.size(); ++k) {
      const MeshPrimitive& src = mesh.primitives[k];
      GpuPrimitive p;
      p.mesh = static_cast<int>(m);
      p.primitive = static_cast<int>(k);
      p.vertexCount = src.vertexCount();
      p.indexCount = static_cast<int>(src.indices.size());
      p.hasNormals = src.normals.size() == src.positions.size();
      p.skinned = src.skinned();
      p.closed = isClosedOutwardSurface(src.positions, src.indices);
      const std::vector<glm::vec3> normals = p.hasNormals ? src.normals : displayNormals(src);
      const std::vector<PackedVertex> vertices = packVertices(src.positions, normals, src);
      glGenVertexArrays(1, &p.vao);
      glBindVertexArray(p.vao);
      glGenBuffers(1, &p.vertices);
      glBindBuffer(GL_ARRAY_BUFFER, p.vertices);
      glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(vertices.size() * sizeof(PackedVertex)), vertices.data(),
                   GL_STATIC_DRAW);
      glEnableVertexAttribArray(0);
      glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, sizeof(PackedVertex), reinterpret_cast<void*>(offsetof(PackedVertex, position)));
      glEnableVertexAttribArray(1);
      glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, sizeof(PackedVertex), reinterpret_cast<void*>(offsetof(PackedVertex, normal)));
      glEnableVertexAttribArray(2);
      glVertexAttribPointer(2, 2, GL_FLOAT, GL_FALSE, sizeof(PackedVertex), reinterpret_cast<void*>(offsetof(PackedVertex, texcoord)));
      if (p.skinned && src.influenceJoints.size() == static_cast<size_t>(p.vertexCount) * kMaxInfluences &&
          src.influenceWeights.size() == src.influenceJoints.size()) {
        // Per vertex: 8 joint numbers (uint16) then 8 weights (float).
        const size_t stride = kMaxInfluences * (sizeof(uint16_t) + sizeof(float));
        std::vector<unsigned char> data(stride * static_cast<size_t>(p.vertexCount));
        for (int v = 0; v < p.vertexCount; ++v) {
          unsigned char* at = data.data() + stride * v;
          std::memcpy(at, &src.influenceJoints[static_cast<size_t>(v) * kMaxInfluences], kMaxInfluences * sizeof(uint16_t));
          std::memcpy(at + kMaxInfluences * sizeof(uint16_t), &src.influenceWeights[static_cast<size_t>(v) * kMaxInfluences],
                      kMaxInfluences * sizeof(float));
        }
        glGenBuffers(1, &p.influences);
        glBindBuffer(GL_ARRAY_BUFFER, p.influences);
        glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(data.size()), data.data(), GL_STATIC_DRAW);
        const GLsizei s = static_cast<GLsizei>(stride);
        glEnableVertexAttribArray(3);
        glVertexAttribIPointer(3, 4, GL_UNSIGNED_SHORT, s, nullptr);
        glEnableVertexAttribArray(4);
        glVertexAttribIPointer(4, 4, GL_UNSIGNED_SHORT, s, reinterpret_cast<void*>(4 * sizeof(uint16_t)));
        const size_t w = kMaxInfluences * sizeof(uint16_t);
        glEnableVertexAttribArray(5);
        glVertexAttribPointer(5, 4, GL_FLOAT, GL_FALSE, s, reinterpret_cast<void*>(w));
        glEnableVertexAttribArray(6);
        glVertexAttribPointer(6, 4, GL_FLOAT, GL_FALSE, s, reinterpret_cast<void*>(w + 4 * sizeof(float)));
      } else {
        p.skinned = false;
        glVertexAttribI4ui(3, 0, 0, 0, 0);
        glVertexAttribI4ui(4, 0, 0, 0, 0);
        glVertexAttrib4f(5, 0, 0, 0, 0);
        glVertexAttrib4f(6, 0, 0, 0, 0);
      }
      glGenBuffers(1, &p.indices);
      glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, p.indices);
      glBufferData(GL_ELEMENT_ARRAY_BUFFER, static_cast<GLsizeiptr>(src.indices.size() * sizeof(uint32_t)),
                   src.indices.data(), GL_STATIC_DRAW);
      glBindVertexArray(0);
      // The CPU-deformed twin: texcoords and indices from the same buffers; positions and
      // normals are pointed at the frame's deformed vertices when drawn.
      glGenVertexArrays(1, &p.cpuVao);
      glBindVertexArray(p.cpuVao);
      glBindBuffer(GL_ARRAY_BUFFER, p.vertices);
      glEnableVertexAttribArray(2);
      glVertexAttribPointer(2, 2, GL_FLOAT, GL_FALSE, sizeof(PackedVertex), reinterpret_cast<void*>(offsetof(PackedVertex, texcoord)));
      glBindBuffer(GL_ARRAY_BUFFER, cpuBuffer_);
      glEnableVertexAttribArray(0);
      glEnableVertexAttribArray(1);
      glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, p.indices);
      glBindVertexArray(0);
      allNormals_ = allNormals_ && p.hasNormals;

      p.morphCount = std::min(static_cast<int>(src.targets.size()), kMaxMorphTargets);
      if (static_cast<int>(src.targets.size()) > kMaxMorphTargets)
        warnings_.push_back("mesh " + std::to_string(m) + " primitive " + std::to_string(k) + ": only the first " +
                            std::to_string(kMaxMorphTargets) + " of " + std::to_string(src.targets.size()) +
                            " morph targets are drawn");
      if (p.morphCount > 0) {
        p.morphNormals = p.hasNormals;
        for (int t = 0; t < p.morphCount; ++t)
          p.morphNormals = p.morphNormals && src.targets[t].normalDeltas.size() == src.positions.size();
        const int blocks = p.morphCount * (p.morphNormals ? 2 : 1);
        std::vector<glm::vec4> deltas(static_cast<size_t>(blocks) * p.vertexCount, glm::vec4(0.0f));
        for (int t = 0; t < p.morphCount; ++t)
          for (int v = 0; v < p.vertexCount; ++v) {
            const MorphTarget& target = src.targets[t];
            if (v < static_cast<int>(target.positionDeltas.size()))
              deltas[static_cast<size_t>(t) * p.vertexCount + v] = glm::vec4(target.positionDeltas[v], 0.0f);
            if (p.morphNormals)
              deltas[static_cast<size_t>(p.morphCount + t) * p.vertexCount + v] = glm::vec4(target.normalDeltas[v], 0.0f);
          }
        glGenBuffers(1, &p.morphBuffer);
        glBindBuffer(GL_TEXTURE_BUFFER, p.morphBuffer);
        glBufferData(GL_TEXTURE_BUFFER, static_cast<GLsizeiptr>(deltas.size() * sizeof(glm::vec4)), deltas.data(),
                     GL_STATIC_DRAW);
        glBindBuffer(GL_TEXTURE_BUFFER, 0);
        p.morphTexture = makeBufferTexture(p.morphBuffer, GL_RGBA32F);
      }
      primitivesOfMesh_[m].push_back(static_cast<int>(primitives_.size()));
      primitives_.push_back(p);
    }
  }
  for (const TextureImage& image : scene.images) {
    GLuint texture = 0;
    glGenTextures(1, &texture);
    glBindTexture(GL_TEXTURE_2D, texture);
    // Rows go up first-row-first, so glTF's UV origin (the image's top left) is texture t = 0.
    if (image.width > 0 && image.height > 0 &&
        image.rgba.size() == static_cast<size_t>(image.width) * image.height * 4) {
      glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
      glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, image.width, image.height, 0, GL_RGBA, GL_UNSIGNED_BYTE, image.rgba.data());
      glGenerateMipmap(GL_TEXTURE_2D);
      glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
    } else {
      const unsigned char white[4] = {255, 255, 255, 255};
      glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, white);
      glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    }
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    textures_.push_back(texture);
  }
  glBindTexture(GL_TEXTURE_2D, 0);
  skinOffset_.clear();
  long long slots = 0;
  for (const Skin& skin : scene.skins) {
    skinOffset_.push_back(static_cast<int>(std::min<long long>(slots, 1 << 30)));
    slots += static_cast<long long>(skin.joints.size());
  }
  jointSlots_ = static_cast<int>(std::min<long long>(slots, 1 << 30));
  // A file decides these sizes: refuse what the driver's texture buffers cannot hold
  // (at least 65,536 texels: over 4,000 joints) instead of drawing garbage.
  GLint maxTexels = 0;
  glGetIntegerv(GL_MAX_TEXTURE_BUFFER_SIZE, &maxTexels);
  if (slots * kJointTexels > maxTexels) {
    const std::string error = scene.source + ": " + std::to_string(slots) + " skin joints in all, more than the " +
                              std::to_string(maxTexels / kJointTexels) + " this OpenGL driver can skin";
    release();
    uploadKey_ = keyOf(scene);  // tried: not again every frame
    return error;
  }
  for (const GpuPrimitive& p : primitives_)
    if (static_cast<long long>(p.morphCount) * (p.morphNormals ? 2 : 1) * p.vertexCount > maxTexels) {
      const std::string error = scene.source + ": mesh " + std::to_string(p.mesh) + " primitive " +
                                std::to_string(p.primitive) + " has more morph target data than this OpenGL driver's " +
                                std::to_string(maxTexels) + "-texel texture buffers hold";
      release();
      uploadKey_ = keyOf(scene);
      return error;
    }
  const GLenum status = glGetError();
  if (status != GL_NO_ERROR) return "OpenGL error " + std::to_string(status) + " while uploading the meshes";
  return {};
}

void MeshRenderer::appendJointTexels(const std::vector<glm::mat4>& world) {
  // Every skin's matrices, skin after skin; instances index from their skin's offset.
  for (size_t k = 0; k < scene_->skins.size() && k < skinOffset_.size(); ++k) {
    computeSkinningMatrices(scene_->skins[k], world, skinScratch_);
    const size_t at = jointScratch_.size();
    jointScratch_.resize(at + skinScratch_.size() * kJointTexels * 4);
    for (size_t j = 0; j < skinScratch_.size(); ++j) packJointTexels(skinScratch_[j], &jointScratch_[at + j * kJointTexels * 4]);
  }
}

void MeshRenderer::uploadJointMatrices(const MeshFrame& frame) {
  jointScratch_.clear();
  appendJointTexels(*frame.world);
  if (jointScratch_.empty()) jointScratch_.assign(4, 0.0f);
  jointSlotBase_ = 0;
  glBindBuffer(GL_TEXTURE_BUFFER, jointBuffer_);
  glBufferData(GL_TEXTURE_BUFFER, static_cast<GLsizeiptr>(jointScratch_.size() * sizeof(float)), jointScratch_.data(),
               GL_STREAM_DRAW);
  glBindBuffer(GL_TEXTURE_BUFFER, 0);
}

bool MeshRenderer::uploadedMesh(int mesh) const {
  // The scene may have changed since upload() (the editor edits it): draw only what both know.
  return mesh >= 0 && mesh < static_cast<int>(primitivesOfMesh_.size()) && mesh < static_cast<int>(scene_->meshes.size());
}

bool axisStackOnGpu(const DeformerStack& stack) {
  int enabled = 0;
  for (const Deformer& d : stack.deformers) {
    if (!d.enabled) continue;
    if (d.type != DeformerType::Bend && d.type != DeformerType::Twist && d.type != DeformerType::Taper) return false;
    for (const std::vector<float>& w : d.weights)
      if (!w.empty()) return false;
    ++enabled;
  }
  return enabled >= 1 && enabled <= kMaxGpuAxisDeformers;
}

void MeshRenderer::bindAxisDeformers(const MeshFrame& frame, int instance) {
  int count = 0;
  if (frame.gpuDeformers && instance < static_cast<int>(frame.gpuDeformers->size()) &&
      axisStackOnGpu((*frame.gpuDeformers)[instance])) {
    glm::ivec2 kind[kMaxGpuAxisDeformers];
    glm::vec3 origin[kMaxGpuAxisDeformers], range[kMaxGpuAxisDeformers];
    glm::mat4 toLocal[kMaxGpuAxisDeformers], toWorld[kMaxGpuAxisDeformers];
    for (const Deformer& d : (*frame.gpuDeformers)[instance].deformers) {
      if (!d.enabled) continue;
      const AxisDeformer& a = d.axis;
      kind[count] = glm::ivec2(a.kind == AxisDeformerKind::Bend ? 0 : a.kind == AxisDeformerKind::Twist ? 1 : 2,
                               static_cast<int>(a.axis));
      origin[count] = a.origin;
      range[count] = glm::vec3(a.low, a.high, a.amount);
      toWorld[count] = deformerFrame(d, frame.world);
      toLocal[count] = glm::inverse(toWorld[count]);  // the CPU's DeformerStackJob does the same
      ++count;
    }
    glUniform2iv(shading_->uniform("uAxisKind"), count, glm::value_ptr(kind[0]));
    glUniform3fv(shading_->uniform("uAxisOrigin"), count, glm::value_ptr(origin[0]));
    glUniform3fv(shading_->uniform("uAxisRange"), count, glm::value_ptr(range[0]));
    glUniformMatrix4fv(shading_->uniform("uAxisToLocal"), count, GL_FALSE, glm::value_ptr(toLocal[0]));
    glUniformMatrix4fv(shading_->uniform("uAxisToWorld"), count, GL_FALSE, glm::value_ptr(toWorld[0]));
  }
  glUniform1i(shading_->uniform("uAxisCount"), count);
}

void MeshRenderer::bindInstance(const MeshFrame& frame, int instance, const GpuPrimitive& p, bool weightsView) {
  const MeshInstance& inst = scene_->meshInstances[instance];
  bindAxisDeformers(frame, instance);
  const bool skinned = p.skinned && inst.skin >= 0 && inst.skin < static_cast<int>(skinOffset_.size()) &&
                       inst.skin < static_cast<int>(scene_->skins.size());
  const int method = !skinned ? 0 : inst.skinning == SkinningMethod::DualQuaternion ? 2 : 1;
  glUniform1i(shading_->uniform("uSkinning"), method);
  // The skin's joints start at its offset in the joint buffer: a buffer texture view per
  // skin would need GL 4.3, so the texel offset goes in through the joint numbers instead.
  const glm::mat4 model = inst.joint >= 0 && inst.joint < static_cast<int>(frame.world->size())
                              ? (*frame.world)[inst.joint]
                              : glm::mat4(1.0f);
  glUniformMatrix4fv(shading_->uniform("uModel"), 1, GL_FALSE, glm::value_ptr(model));
  const glm::mat3 normal = inverseTranspose3(glm::mat3(model));
  glUniformMatrix3fv(shading_->uniform("uModelNormal"), 1, GL_FALSE, glm::value_ptr(normal));
  glUniform1i(shading_->uniform("uJointOffset"), skinned ? jointSlotBase_ + skinOffset_[inst.skin] : 0);

  int weightJoint = -1;
  if (weightsView && frame.weightJoint >= 0) {
    if (skinned) {
      const std::vector<int>& joints = scene_->skins[inst.skin].joints;
      const auto it = std::find(joints.begin(), joints.end(), frame.weightJoint);
      weightJoint = it == joints.end() ? -2 : static_cast<int>(it - joints.begin());
    } else {
      weightJoint = inst.joint == frame.weightJoint ? 0 : -2;  // rigid: all or nothing
    }
  }
  glUniform1i(shading_->uniform("uWeightJoint"), weightJoint);
  glUniform1i(shading_->uniform("uShowWeights"), weightsView && frame.weightJoint >= 0);

  // Morph weights: the frame's, else the instance's, else the mesh's defaults (glTF order).
  const Mesh& mesh = scene_->meshes[inst.mesh];
  const std::vector<float>* weights = &mesh.morphWeights;
  if (!inst.morphWeights.empty()) weights = &inst.morphWeights;
  if (frame.morphWeights && instance < static_cast<int>(frame.morphWeights->size()) &&
      !(*frame.morphWeights)[instance].empty())
    weights = &(*frame.morphWeights)[instance];
  float w[kMaxMorphTargets] = {};
  for (int k = 0; k < p.morphCount && k < static_cast<int>(weights->size()); ++k) w[k] = (*weights)[k];
  glUniform1fv(shading_->uniform("uMorphWeights"), kMaxMorphTargets, w);
  glUniform1i(shading_->uniform("uMorphCount"), p.morphCount);
  glUniform1i(shading_->uniform("uVertexCount"), p.vertexCount);
  glUniform1i(shading_->uniform("uMorphHasNormals"), p.morphNormals);
  glActiveTexture(GL_TEXTURE1);
  glBindTexture(GL_TEXTURE_BUFFER, p.morphTexture ? p.morphTexture : emptyTexture_);

  const Material* material = mesh.primitives[p.primitive].material >= 0 &&
                                     mesh.primitives[p.primitive].material < static_cast<int>(scene_->materials.size())
                                 ? &scene_->materials[mesh.primitives[p.primitive].material]
                                 : nullptr;
  const glm::vec4 base = material ? material->baseColor : glm::vec4(0.8f, 0.8f, 0.8f, 1.0f);
  glUniform4fv(shading_->uniform("uBaseColor"), 1, glm::value_ptr(base));
  const int image = material ? material->baseColorImage : -1;
  const bool textured = image >= 0 && image < static_cast<int>(textures_.size()) &&
                        !mesh.primitives[p.primitive].texcoords.empty();
  glUniform1i(shading_->uniform("uHasTexture"), textured);
  glActiveTexture(GL_TEXTURE2);
  glBindTexture(GL_TEXTURE_2D, textured ? textures_[image] : 0);
  glActiveTexture(GL_TEXTURE0);
}

bool MeshRenderer::cpuEligible() const { return cpuDeformation_ && allNormals_; }

bool MeshRenderer::appendCpuPose(const MeshFrame& frame, CpuPose& pose) {
  SceneDeformationJob job;
  job.scene = scene_;
  job.world = frame.world;
  job.morphWeights = frame.morphWeights;
  job.out = &cpuDeformed_;
  if (!frame.posed && (!job.validate().empty() || !job.run())) return false;
  pose.assign(scene_->meshInstances.size(), {});
  for (const DeformedPrimitive& d : frame.posed ? *frame.posed : cpuDeformed_) {
    if (d.instance < 0 || d.instance >= static_cast<int>(pose.size()) || d.normals.size() != d.positions.size())
      return false;
    std::vector<long long>& offsets = pose[d.instance];
    if (d.primitive >= static_cast<int>(offsets.size())) offsets.resize(d.primitive + 1, -1);
    offsets[d.primitive] = static_cast<long long>(cpuScratch_.size());
    const size_t at = cpuScratch_.size();
    cpuScratch_.resize(at + d.positions.size() * 6);
    float* out = &cpuScratch_[at];
    for (size_t v = 0; v < d.positions.size(); ++v, out += 6) {
      out[0] = d.positions[v].x;
      out[1] = d.positions[v].y;
      out[2] = d.positions[v].z;
      out[3] = d.normals[v].x;
      out[4] = d.normals[v].y;
      out[5] = d.normals[v].z;
    }
  }
  return true;
}

void MeshRenderer::uploadCpuScratch() {
  if (cpuScratch_.empty()) cpuScratch_.assign(6, 0.0f);
  glBindBuffer(GL_ARRAY_BUFFER, cpuBuffer_);
  glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(cpuScratch_.size() * sizeof(float)), cpuScratch_.data(),
               GL_STREAM_DRAW);
}

void MeshRenderer::drawInstancesCpu(const MeshFrame& frame, const CpuPose& pose, const ScreenRegion* region,
                                    bool frontFacesOnly) {
  const glm::mat4 identity(1.0f);
  const glm::mat3 identity3(1.0f);
  for (size_t i = 0; i < scene_->meshInstances.size() && i < pose.size(); ++i) {
    const MeshInstance& inst = scene_->meshInstances[i];
    if (!uploadedMesh(inst.mesh)) continue;
    for (int index : primitivesOfMesh_[inst.mesh]) {
      const GpuPrimitive& p = primitives_[index];
      if (p.indexCount == 0 || p.primitive >= static_cast<int>(scene_->meshes[inst.mesh].primitives.size())) continue;
      if (p.primitive >= static_cast<int>(pose[i].size()) || pose[i][p.primitive] < 0) continue;
      if (static_cast<long long>(scene_->meshes[inst.mesh].primitives[p.primitive].positions.size()) != p.vertexCount)
        continue;
      bindInstance(frame, static_cast<int>(i), p, false);
      // Already in world space, morphed and skinned: the shader's unskinned path, identity model.
      glUniform1i(shading_->uniform("uSkinning"), 0);
      glUniformMatrix4fv(shading_->uniform("uModel"), 1, GL_FALSE, glm::value_ptr(identity));
      glUniformMatrix3fv(shading_->uniform("uModelNormal"), 1, GL_FALSE, glm::value_ptr(identity3));
      glUniform1i(shading_->uniform("uMorphCount"), 0);
      glUniform1i(shading_->uniform("uAxisCount"), 0);
      glBindVertexArray(p.cpuVao);
      glBindBuffer(GL_ARRAY_BUFFER, cpuBuffer_);
      const size_t bytes = static_cast<size_t>(pose[i][p.primitive]) * sizeof(float);
      glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, 6 * sizeof(float), reinterpret_cast<void*>(bytes));
      glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, 6 * sizeof(float), reinterpret_cast<void*>(bytes + 3 * sizeof(float)));
      const float* posed = &cpuScratch_[static_cast<size_t>(pose[i][p.primitive])];
      // A closed surface wholly in front of the near plane shows only its front faces.
      bool cull = frontFacesOnly && region && p.closed && p.vertexCount > 0;
      if (cull) {
        glm::vec3 lo(posed[0], posed[1], posed[2]), hi = lo;
        for (int v = 1; v < p.vertexCount; ++v) {
          const glm::vec3 q(posed[6 * v], posed[6 * v + 1], posed[6 * v + 2]);
          lo = glm::min(lo, q), hi = glm::max(hi, q);
        }
        cull = boxInFrontOfNearPlane(region->viewProjection, lo, hi);
      }
      if (cull) {
        glEnable(GL_CULL_FACE);
        glCullFace(GL_BACK);
      } else {
        glDisable(GL_CULL_FACE);
      }
      if (region && region->culls()) {
        // A partial redraw: the triangles that may reach the limit (screen_culling.h), from
        // their own element buffer; the VAO's own one is put back for the next frame.
        cullScratch_.clear();
        appendTrianglesInRegion(*region, posed, 6,
                                static_cast<size_t>(p.vertexCount), scene_->meshes[inst.mesh].primitives[p.primitive].indices,
                                cullScratch_, cullWork_);
        if (!cullScratch_.empty()) {
          glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, cullIndices_);
          glBufferData(GL_ELEMENT_ARRAY_BUFFER, static_cast<GLsizeiptr>(cullScratch_.size() * sizeof(uint32_t)),
                       cullScratch_.data(), GL_STREAM_DRAW);
          glDrawElements(GL_TRIANGLES, static_cast<GLsizei>(cullScratch_.size()), GL_UNSIGNED_INT, nullptr);
        }
        glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, p.indices);
      } else {
        glDrawElements(GL_TRIANGLES, p.indexCount, GL_UNSIGNED_INT, nullptr);
      }
    }
  }
}

void MeshRenderer::draw(const MeshFrame& frame, const glm::mat4& viewProjection, const glm::mat4& view,
                        const ScreenRegion* region, bool frontFacesOnly) {
  if (!scene_ || !frame.world || primitives_.empty()) return;
  // Frames with an active deformer stack take the shader path with those primitives streamed
  // (bindCpuDeformed): the whole-scene CPU path below knows only morphs and skinning.
  if (cpuEligible() && frame.weightJoint < 0 && !anyDeformed(frame.deformed)) {
    cpuScratch_.clear();
    if (appendCpuPose(frame, cpuPose_)) {
      uploadCpuScratch();
      useProgram(posedProgram_);
      glUniformMatrix4fv(shading_->uniform("uViewProjection"), 1, GL_FALSE, glm::value_ptr(viewProjection));
      glUniformMatrix4fv(shading_->uniform("uView"), 1, GL_FALSE, glm::value_ptr(view));
      glUniform1i(shading_->uniform("uGhost"), 0);
      glEnable(GL_DEPTH_TEST);
      glDisable(GL_CULL_FACE);
      drawInstancesCpu(frame, cpuPose_, region, frontFacesOnly);
      glDisable(GL_CULL_FACE);
      unbindMeshDrawState();
      return;
    }
  }
  uploadJointMatrices(frame);
  useProgram(program_);
  glUniformMatrix4fv(shading_->uniform("uViewProjection"), 1, GL_FALSE, glm::value_ptr(viewProjection));
  glUniformMatrix4fv(shading_->uniform("uView"), 1, GL_FALSE, glm::value_ptr(view));
  glActiveTexture(GL_TEXTURE0);
  glBindTexture(GL_TEXTURE_BUFFER, jointTexture_);
  glUniform1i(shading_->uniform("uGhost"), 0);
  glEnable(GL_DEPTH_TEST);
  glDisable(GL_CULL_FACE);  // double-sided: the fragment shader lights back faces too
  drawInstances(frame, true);
  unbindMeshDrawState();
}

const DeformedPrimitive* MeshRenderer::cpuDeformed(const MeshFrame& frame, int instance, const GpuPrimitive& p) {
  if (!frame.deformed) return nullptr;
  for (const DeformedPrimitive& d : *frame.deformed)
    if (d.instance == instance && d.primitive == p.primitive)
      return static_cast<int>(d.positions.size()) == p.vertexCount ? &d : nullptr;
  return nullptr;
}

void MeshRenderer::bindCpuDeformed(GpuPrimitive& p, const DeformedPrimitive& d) {
  const MeshPrimitive& src = scene_->meshes[p.mesh].primitives[p.primitive];
  std::vector<glm::vec3> shading;
  if (d.normals.size() != d.positions.size()) computeVertexNormals(d.positions, src.indices, shading);
  const std::vector<glm::vec3>& normals = d.normals.size() == d.positions.size() ? d.normals : shading;
  const std::vector<PackedVertex> vertices = packVertices(d.positions, normals, src);
  if (!p.deformedVao) {
    glGenVertexArrays(1, &p.deformedVao);
    glBindVertexArray(p.deformedVao);
    glGenBuffers(1, &p.deformedVertices);
    glBindBuffer(GL_ARRAY_BUFFER, p.deformedVertices);
    glEnableVertexAttribArray(0);
    glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, sizeof(PackedVertex), reinterpret_cast<void*>(offsetof(PackedVertex, position)));
    glEnableVertexAttribArray(1);
    glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, sizeof(PackedVertex), reinterpret_cast<void*>(offsetof(PackedVertex, normal)));
    glEnableVertexAttribArray(2);
    glVertexAttribPointer(2, 2, GL_FLOAT, GL_FALSE, sizeof(PackedVertex), reinterpret_cast<void*>(offsetof(PackedVertex, texcoord)));
    if (p.influences) {  // kept for the weights view (the shader's rigid path reads them for heat only)
      const GLsizei s = static_cast<GLsizei>(kMaxInfluences * (sizeof(uint16_t) + sizeof(float)));
      const size_t w = kMaxInfluences * sizeof(uint16_t);
      glBindBuffer(GL_ARRAY_BUFFER, p.influences);
      glEnableVertexAttribArray(3);
      glVertexAttribIPointer(3, 4, GL_UNSIGNED_SHORT, s, nullptr);
      glEnableVertexAttribArray(4);
      glVertexAttribIPointer(4, 4, GL_UNSIGNED_SHORT, s, reinterpret_cast<void*>(4 * sizeof(uint16_t)));
      glEnableVertexAttribArray(5);
      glVertexAttribPointer(5, 4, GL_FLOAT, GL_FALSE, s, reinterpret_cast<void*>(w));
      glEnableVertexAttribArray(6);
      glVertexAttribPointer(6, 4, GL_FLOAT, GL_FALSE, s, reinterpret_cast<void*>(w + 4 * sizeof(float)));
    }
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, p.indices);
  }
  glBindVertexArray(p.deformedVao);
  glBindBuffer(GL_ARRAY_BUFFER, p.deformedVertices);
  glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(vertices.size() * sizeof(PackedVertex)), vertices.data(),
               GL_STREAM_DRAW);
  if (!p.influences) {  // an unskinned primitive: the shader reads constant zero influences
    glVertexAttribI4ui(3, 0, 0, 0, 0);
    glVertexAttribI4ui(4, 0, 0, 0, 0);
    glVertexAttrib4f(5, 0, 0, 0, 0);
    glVertexAttrib4f(6, 0, 0, 0, 0);
  }
  // Already world space, already morphed: no skinning, identity model, no morph targets.
  const glm::mat4 identity(1.0f);
  const glm::mat3 identity3(1.0f);
  glUniform1i(shading_->uniform("uSkinning"), 0);
  glUniformMatrix4fv(shading_->uniform("uModel"), 1, GL_FALSE, glm::value_ptr(identity));
  glUniformMatrix3fv(shading_->uniform("uModelNormal"), 1, GL_FALSE, glm::value_ptr(identity3));
  glUniform1i(shading_->uniform("uMorphCount"), 0);
  glUniform1i(shading_->uniform("uAxisCount"), 0);
}

void MeshRenderer::drawInstances(const MeshFrame& frame, bool weightsView) {
  for (size_t i = 0; i < scene_->meshInstances.size(); ++i) {
    const MeshInstance& inst = scene_->meshInstances[i];
    if (!uploadedMesh(inst.mesh)) continue;
    for (int index : primitivesOfMesh_[inst.mesh]) {
      GpuPrimitive& p = primitives_[index];
      if (p.indexCount == 0 || p.primitive >= static_cast<int>(scene_->meshes[inst.mesh].primitives.size())) continue;
      bindInstance(frame, static_cast<int>(i), p, weightsView);
      if (const DeformedPrimitive* d = cpuDeformed(frame, static_cast<int>(i), p)) {
        bindCpuDeformed(p, *d);
      } else {
        glBindVertexArray(p.vao);
      }
      glDrawElements(GL_TRIANGLES, p.indexCount, GL_UNSIGNED_INT, nullptr);
    }
  }
}

void MeshRenderer::drawGhosts(const std::vector<MeshGhost>& ghosts, const glm::mat4& viewProjection, const glm::mat4& view) {
  if (!scene_ || primitives_.empty() || ghosts.empty()) return;
  // CPU deformation: every ghost's vertices in one upload, then the same two passes.
  bool cpu = cpuEligible();
  for (const MeshGhost& ghost : ghosts) cpu = cpu && !anyDeformed(ghost.deformed);
  if (cpu) {
    cpuScratch_.clear();
    cpuGhostPoses_.resize(ghosts.size());
    for (size_t g = 0; g < ghosts.size() && cpu; ++g) {
      MeshFrame frame;
      frame.world = ghosts[g].world;
      frame.morphWeights = ghosts[g].morphWeights;
      if (!frame.world)
        cpuGhostPoses_[g].clear();
      else
        cpu = appendCpuPose(frame, cpuGhostPoses_[g]);
    }
    if (cpu) uploadCpuScratch();
  }
  // Every ghost's joints in one buffer of its own, pose after pose, uploaded once: as many
  // ghosts as the driver's texture buffers hold (the rest are left out).
  GLint maxTexels = 0;
  glGetIntegerv(GL_MAX_TEXTURE_BUFFER_SIZE, &maxTexels);
  const long long perPose = std::max(1LL, static_cast<long long>(jointSlots_) * kJointTexels);
  const size_t count = std::min(ghosts.size(), static_cast<size_t>(std::max(1LL, maxTexels / perPose)));
  jointScratch_.clear();
  for (size_t g = 0; g < count; ++g) {
    const size_t at = jointScratch_.size();
    if (ghosts[g].world) appendJointTexels(*ghosts[g].world);
    jointScratch_.resize(at + static_cast<size_t>(jointSlots_) * kJointTexels * 4, 0.0f);
  }
  if (jointScratch_.empty()) jointScratch_.assign(4, 0.0f);
  glBindBuffer(GL_TEXTURE_BUFFER, ghostBuffer_);
  glBufferData(GL_TEXTURE_BUFFER, static_cast<GLsizeiptr>(jointScratch_.size() * sizeof(float)), jointScratch_.data(),
               GL_STREAM_DRAW);
  glBindBuffer(GL_TEXTURE_BUFFER, 0);
  useProgram(cpu ? posedProgram_ : program_);
  glUniformMatrix4fv(shading_->uniform("uViewProjection"), 1, GL_FALSE, glm::value_ptr(viewProjection));
  glUniformMatrix4fv(shading_->uniform("uView"), 1, GL_FALSE, glm::value_ptr(view));
  glActiveTexture(GL_TEXTURE0);
  glBindTexture(GL_TEXTURE_BUFFER, ghostTexture_);
  glEnable(GL_DEPTH_TEST);
  glDisable(GL_CULL_FACE);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  // Ghosts a little behind their true depth: where a ghost coincides with the body (the parts
  // the clip does not move) the body wins, so only what moved is tinted.
  glEnable(GL_POLYGON_OFFSET_FILL);
  glPolygonOffset(1.0f, 4.0f);
  for (size_t g = 0; g < count; ++g) {
    if (!ghosts[g].world) continue;
    MeshFrame frame;
    frame.world = ghosts[g].world;
    frame.morphWeights = ghosts[g].morphWeights;
    frame.deformed = ghosts[g].deformed;
    jointSlotBase_ = static_cast<int>(g) * jointSlots_;
    // Depth only: the ghost's nearest surface where nothing opaque is in front of it...
    glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    glDepthMask(GL_TRUE);
    glDepthFunc(GL_LESS);
    glDisable(GL_BLEND);
    glUniform1i(shading_->uniform("uGhost"), 0);
    if (cpu)
      drawInstancesCpu(frame, cpuGhostPoses_[g]);
    else
      drawInstances(frame, false);
    // ...then that surface alone in the tint, blended once per pixel.
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glDepthMask(GL_FALSE);
    glDepthFunc(GL_LEQUAL);
    glEnable(GL_BLEND);
    glUniform1i(shading_->uniform("uGhost"), 1);
    glUniform4fv(shading_->uniform("uGhostColor"), 1, glm::value_ptr(ghosts[g].color));
    if (cpu)
      drawInstancesCpu(frame, cpuGhostPoses_[g]);
    else
      drawInstances(frame, false);
  }
  jointSlotBase_ = 0;
  glUniform1i(shading_->uniform("uGhost"), 0);
  glDisable(GL_POLYGON_OFFSET_FILL);
  glDisable(GL_BLEND);
  glDepthMask(GL_TRUE);
  glDepthFunc(GL_LESS);
  unbindMeshDrawState();
}

std::string MeshRenderer::deform(const MeshFrame& frame, bool skinnedOnly, std::vector<DeformedPrimitive>& out) {
  out.clear();
  if (!scene_ || !frame.world) return "the mesh renderer has no scene or no pose";
  uploadJointMatrices(frame);
  GLint previousFbo = 0;
  glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &previousFbo);
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, feedbackFbo_);
  useProgram(program_);
  glActiveTexture(GL_TEXTURE0);
  glBindTexture(GL_TEXTURE_BUFFER, jointTexture_);
  glEnable(GL_RASTERIZER_DISCARD);
  for (size_t i = 0; i < scene_->meshInstances.size(); ++i) {
    const MeshInstance& inst = scene_->meshInstances[i];
    if (!uploadedMesh(inst.mesh)) continue;
    if (skinnedOnly && inst.skin < 0) continue;
    for (int index : primitivesOfMesh_[inst.mesh]) {
      const GpuPrimitive& p = primitives_[index];
      if (p.primitive >= static_cast<int>(scene_->meshes[inst.mesh].primitives.size())) continue;
      if (const DeformedPrimitive* d = cpuDeformed(frame, static_cast<int>(i), p)) {
        DeformedPrimitive copy = *d;  // deformed on the CPU already: the GPU has nothing to add
        if (!p.hasNormals) copy.normals.clear();
        out.push_back(std::move(copy));
        continue;
      }
      DeformedPrimitive result;
      result.instance = static_cast<int>(i);
      result.primitive = p.primitive;
      if (p.vertexCount > 0) {
        bindInstance(frame, static_cast<int>(i), p, false);
        // One point per vertex, so gl_VertexID is the vertex index the morph deltas use.
        const GLsizeiptr bytes = static_cast<GLsizeiptr>(p.vertexCount) * 6 * sizeof(float);
        glBindBuffer(GL_TRANSFORM_FEEDBACK_BUFFER, feedbackBuffer_);
        glBufferData(GL_TRANSFORM_FEEDBACK_BUFFER, bytes, nullptr, GL_STREAM_READ);
        glBindBufferBase(GL_TRANSFORM_FEEDBACK_BUFFER, 0, feedbackBuffer_);
        glBindVertexArray(p.vao);
        glBeginTransformFeedback(GL_POINTS);
        glDrawArrays(GL_POINTS, 0, p.vertexCount);
        glEndTransformFeedback();
        std::vector<float> data(static_cast<size_t>(p.vertexCount) * 6);
        glGetBufferSubData(GL_TRANSFORM_FEEDBACK_BUFFER, 0, bytes, data.data());
        result.positions.resize(p.vertexCount);
        if (p.hasNormals) result.normals.resize(p.vertexCount);
        for (int v = 0; v < p.vertexCount; ++v) {
          const float* d = &data[static_cast<size_t>(v) * 6];
          result.positions[v] = glm::vec3(d[0], d[1], d[2]);
          if (p.hasNormals) result.normals[v] = glm::vec3(d[3], d[4], d[5]);
        }
      }
      out.push_back(std::move(result));
    }
  }
  glBindVertexArray(0);
  glDisable(GL_RASTERIZER_DISCARD);
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, static_cast<GLuint>(previousFbo));
  glBindBufferBase(GL_TRANSFORM_FEEDBACK_BUFFER, 0, 0);
  glBindTexture(GL_TEXTURE_BUFFER, 0);
  glUseProgram(0);
  const GLenum status = glGetError();
  if (status != GL_NO_ERROR) return "OpenGL error " + std::to_string(status) + " while reading skinned vertices back";
  return {};
}

Bounds MeshRenderer::deformedBounds(const MeshFrame& frame) {
  Bounds bounds;
  std::vector<DeformedPrimitive> deformed;
  if (!deform(frame, false, deformed).empty()) return bounds;
  for (const DeformedPrimitive& d : deformed)
    for (const glm::vec3& p : d.positions)
      if (isFinite(p)) bounds.add(p);
  return bounds;
}

}  // namespace kinema
