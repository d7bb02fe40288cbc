#pragma once
#include <string>
#include <vector>

#include <glad/gl.h>

#include "core/math.h"
#include "scene/scene.h"
#include "render/camera.h"
#include "render/screen_culling.h"
#include "render/shader_program.h"
#include "evaluation/scene_deformation.h"

namespace kinema {

// What the mesh pass of one frame shows: the posed scene's joints (one world matrix per
// skeleton joint) and optional per-instance morph weights (sampleMorphWeights; null or an
// empty entry: the instance's or the mesh's default weights).
struct MeshFrame {
  const std::vector<glm::mat4>* world = nullptr;
  const std::vector<std::vector<float>>* morphWeights = nullptr;
  // Optional: primitives deformed on the CPU (SceneDeformationJob with withDeformersOnly: the
  // instances whose deformer stack is active), world space. Those are drawn from these
  // positions and normals, streamed each frame, instead of being morphed and skinned here.
  const std::vector<DeformedPrimitive>* deformed = nullptr;
  // Optional, for the CPU path (drawsPosed()): every instance already morphed, skinned and
  // deformed by the caller (SceneDeformationJob with `world`, `morphWeights` and the
  // frame's deformer stacks), world space; draw() uploads these instead of running the job
  // itself, so a caller that needs the vertices too (SceneDamageJob) deforms once, and
  // deformed bodies take the CPU path too. Ignored elsewhere.
  const std::vector<DeformedPrimitive>* posed = nullptr;
  // Optional, per instance (sampleDeformerStacks): stacks the vertex shader runs after
  // skinning, those for which axisStackOnGpu holds (others are ignored here: deform them on
  // the CPU, `deformed`). The CPU's SceneDeformationJob is the reference (1e-4 m).
  const std::vector<DeformerStack>* gpuDeformers = nullptr;
  // Skeleton joint whose skin weights are shown as heat colours (blue 0 -> red 1) instead of
  // the shaded material; -1 shows the materials.
  int weightJoint = -1;
};

// One onion-skin ghost of the meshes: the scene posed by `world` (one matrix per skeleton
// joint, as MeshFrame::world) with its morph weights (as MeshFrame::morphWeights; may be
// null), drawn in a translucent tint: rgb, alpha = opacity (brighter at the silhouette).
struct MeshGhost {
  const std::vector<glm::mat4>* world = nullptr;
  const std::vector<std::vector<float>>* morphWeights = nullptr;
  glm::vec4 color{1.0f};
  const std::vector<DeformedPrimitive>* deformed = nullptr;  // as MeshFrame::deformed
};

// Whether the vertex shader can run `stack` (issue 22): one to four enabled deformers, every
// enabled one a bend, twist or taper without vertex-group weights. Lattices and soft pulls
// stay on the CPU.
constexpr int kMaxGpuAxisDeformers = 4;  // shaders/mesh.vert kMaxAxisDeformers
bool axisStackOnGpu(const DeformerStack& stack);

// Draws a Scene's meshes with OpenGL 3.3 core, skinned in the vertex shader
// (shaders/mesh.vert): the scene's vertex data and textures are uploaded once by upload(),
// each frame sends only the skinning matrices (computeSkinningMatrices) as a texture
// buffer, so skins with hundreds of joints work, and the morph weights. Morph targets are
// blended on the GPU from deltas uploaded once (a texture buffer), so a frame never
// re-uploads vertices. Linear blend or dual quaternion per instance (MeshInstance::skinning);
// unskinned instances follow their joint's world matrix. Create, use and destroy it with
// one context current.
class MeshRenderer {
 public:
  MeshRenderer() = default;
  ~MeshRenderer();
  MeshRenderer(const MeshRenderer&) = delete;
  MeshRenderer& operator=(const MeshRenderer&) = delete;

  // Compiles the shaders. Empty string on success.
  std::string init();
  // Uploads the scene's meshes, skins and textures (replacing any earlier scene). The scene
  // must outlive the renderer's use of it (draw() reads its skins and instances); upload
  // again when its meshes or skins change (draws skip what no longer matches, never crash).
  std::string upload(const Scene& scene);
  bool empty() const { return primitives_.empty(); }
  // True when `scene` is not the scene last uploaded (another object, or the same object
  // given other meshes, skins or images since: a file opened into it).
  bool needsUpload(const Scene& scene) const;

  // Draws every mesh instance into the bound framebuffer (depth test on, both faces lit).
  // `region` (optional; its viewProjection the same as here): a partial redraw, where the
  // CPU-posed path leaves out triangles that cannot reach region->limit (screen_culling.h).
  // `frontFacesOnly` (FrameDescription's, needs `region`): on the CPU-posed path, primitives
  // that bound a solid (isClosedOutwardSurface) and lie wholly in front of the near plane are
  // drawn without their back faces.
  void draw(const MeshFrame& frame, const glm::mat4& viewProjection, const glm::mat4& view,
            const ScreenRegion* region = nullptr, bool frontFacesOnly = false);

  // Onion-skin ghosts over what the framebuffer holds: each ghost is depth-tested against
  // the scene and blended once per pixel (its nearest surface: a depth-only pass, then a
  // colour pass at equal depth), so a ghost reads as one translucent body and is hidden
  // where something opaque is in front of it or coincides with it (the body's parts that did
  // not move). Leaves the ghosts' depth in the depth buffer.
  void drawGhosts(const std::vector<MeshGhost>& ghosts, const glm::mat4& viewProjection, const glm::mat4& view);

  // The same vertex shader run through transform feedback: world-space positions and
  // normals of every instance x primitive, in SceneDeformationJob's order and layout (normals
  // empty where the primitive has none), so tests compare the GPU with the CPU.
  // skinnedOnly as in SceneDeformationJob. Empty string on success.
  std::string deform(const MeshFrame& frame, bool skinnedOnly, std::vector<DeformedPrimitive>& out);

  // The box around every deformed vertex of the frame (deform() then a loop); empty bounds
  // when there is nothing to draw.
  Bounds deformedBounds(const MeshFrame& frame);

  // Where the vertices are deformed for draw() and drawGhosts(): true, on the CPU by
  // SceneDeformationJob, uploaded each frame, drawn with the shader's unskinned path;
  // false, in the vertex shader. init() picks the CPU for software rasterisers (llvmpipe,
  // softpipe): they run vertex shaders on the CPU anyway, one thread, and the shader's
  // eight masked influence loops with texel fetches cost about 0.5 us a triangle there
  // (4 ms a frame for the default character) against microseconds for the SIMD job. The
  // weight heat view and primitives without normals always take the shader's path.
  void setCpuDeformation(bool on) { cpuDeformation_ = on; }
  bool cpuDeformation() const { return cpuDeformation_; }
  // Whether draw() draws from MeshFrame::posed when given one (and no weight view): the CPU
  // path with every uploaded primitive carrying normals. Meaningful after upload().
  bool drawsPosed() const { return cpuEligible(); }

  // Most morph targets a primitive blends (more are ignored, with a warning from upload()).
  static constexpr int kMaxMorphTargets = 32;
  // Warnings upload() found (too many morph targets...), one line each.
  const std::vector<std::string>& warnings() const { return warnings_; }

 private:
  struct GpuPrimitive {
    int mesh = -1, primitive = -1;
    GLuint vao = 0, vertices = 0, influences = 0, indices = 0;
    GLuint cpuVao = 0;  // CPU-deformed drawing: positions and normals from cpuBuffer_, texcoords and indices shared
    GLuint morphBuffer = 0, morphTexture = 0;
    GLuint deformedVao = 0, deformedVertices = 0;  // MeshFrame::deformed vertices, made when first needed
    int vertexCount = 0, indexCount = 0, morphCount = 0;
    bool hasNormals = false, morphNormals = false, skinned = false;
    bool closed = false;  // bounds a solid, faces wound outward (isClosedOutwardSurface, at upload)
  };
  void bindInstance(const MeshFrame& frame, int instance, const GpuPrimitive& p, bool weightsView);
  // The instance's stack of frame.gpuDeformers as the shader's uAxis* uniforms (uAxisCount 0
  // when it has none the shader runs).
  void bindAxisDeformers(const MeshFrame& frame, int instance);
  void uploadJointMatrices(const MeshFrame& frame);
  void appendJointTexels(const std::vector<glm::mat4>& world);  // one pose's texels onto jointScratch_
  void drawInstances(const MeshFrame& frame, bool weightsView);
  // CPU deformation: one pose's deformed vertices appended to cpuScratch_ (position, normal
  // interleaved), with the float offset of each instance's primitive (-1: none). False when
  // the job's output does not match the uploaded primitives (then the shader path draws).
  using CpuPose = std::vector<std::vector<long long>>;  // [instance][primitive]
  bool appendCpuPose(const MeshFrame& frame, CpuPose& pose);
  void uploadCpuScratch();
  void drawInstancesCpu(const MeshFrame& frame, const CpuPose& pose, const ScreenRegion* region = nullptr,
                        bool frontFacesOnly = false);
  bool cpuEligible() const;
  // The frame's CPU-deformed primitive for (instance, primitive of the mesh), or null.
  static const DeformedPrimitive* cpuDeformed(const MeshFrame& frame, int instance, const GpuPrimitive& p);
  // Streams a CPU-deformed primitive into p's own buffer and binds it as world-space, unskinned,
  // unmorphed geometry (after bindInstance).
  void bindCpuDeformed(GpuPrimitive& p, const DeformedPrimitive& d);
  static bool anyDeformed(const std::vector<DeformedPrimitive>* deformed) { return deformed && !deformed->empty(); }
  bool uploadedMesh(int mesh) const;
  void release();

  ShaderProgram program_;
  // Meshes posed on the CPU: mesh_posed.vert (world-space vertices in, no skinning code).
  ShaderProgram posedProgram_;
  ShaderProgram* shading_ = &program_;  // the program in use: uniforms are set on it
  void useProgram(ShaderProgram& p) {
    shading_ = &p;
    glUseProgram(p.id());
  }
  const Scene* scene_ = nullptr;
  std::vector<GpuPrimitive> primitives_;
  std::vector<std::vector<int>> primitivesOfMesh_;  // indices into primitives_
  std::vector<GLuint> textures_;                     // one per scene image
  GLuint feedbackFbo_ = 0, feedbackColor_ = 0;
  GLuint jointBuffer_ = 0, jointTexture_ = 0, feedbackBuffer_ = 0, emptyBuffer_ = 0, emptyTexture_ = 0;
  std::vector<int> skinOffset_;  // first joint slot of each skin in the joint buffer
  int jointSlots_ = 0;           // joint slots of one pose (every skin's joints)
  int jointSlotBase_ = 0;        // the pose drawn starts at this slot (ghosts: one pose after another)
  GLuint ghostBuffer_ = 0, ghostTexture_ = 0;  // every ghost's joints (the frame's buffer is not re-filled mid-frame)
  std::vector<float> jointScratch_;
  std::vector<glm::mat4> skinScratch_;
  std::vector<std::string> warnings_;
  bool cpuDeformation_ = false;
  bool allNormals_ = true;  // every uploaded primitive has its own normals
  GLuint cpuBuffer_ = 0;
  GLuint cullIndices_ = 0;  // a partial redraw's triangles (drawInstancesCpu)
  std::vector<uint32_t> cullScratch_;
  ScreenCullScratch cullWork_;
  std::vector<float> cpuScratch_;
  std::vector<DeformedPrimitive> cpuDeformed_;
  CpuPose cpuPose_;
  std::vector<CpuPose> cpuGhostPoses_;
  // What upload() saw: the scene's address and its mesh, skin, instance and image arrays.
  std::vector<const void*> uploadKey_;
  static std::vector<const void*> keyOf(const Scene& scene);
};

// A FrameDescription's mesh pass: the renderer holding the uploaded scene and this frame's pose.
struct MeshDraw {
  MeshRenderer* renderer = nullptr;
  MeshFrame frame;
};

// The per-joint texels mesh.vert reads for a skinning matrix M: M's 4 columns, the 3x3
// inverse transpose (3 texels), the rigid part as a unit dual quaternion (real xyzw, dual
// xyzw) and the scale/shear rest S = rigid^-1 * M (3), as DualQuaternionSkinningJob splits it.
constexpr int kJointTexels = 12;
void packJointTexels(const glm::mat4& m, float* out);  // writes kJointTexels * 4 floats

}  // namespace kinema
