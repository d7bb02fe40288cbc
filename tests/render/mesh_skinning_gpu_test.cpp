// GPU skinning (shaders/mesh.vert through MeshRenderer::deform, transform feedback) against
// CPU references: a hand-derived two-joint case, the CPU SceneDeformationJob, a plain
// double-precision LBS / DQS written here, three.js's skinned vertices
// (../shared/data/reference), and a synthetic 300-joint skin. On EGL, and on OSMesa when the build has it. Rendering stays on llvmpipe so a GPU host
// runs the same path as CI.
#include <cstdlib>
#include <fstream>
#include <functional>
#include <map>
#include <memory>
#include <random>

#include <glm/gtc/matrix_transform.hpp>
#include <nlohmann/json.hpp>

#include "anim/clip.h"
#include "core/forward_kinematics.h"
#include "render/camera.h"
#include "render/gl_context.h"
#include "render/mesh_renderer.h"
#include "evaluation/scene_deformation.h"
#include "test_support.h"
#include "io/scene_files.h"

namespace kinema {
namespace KINEMA_UNITY_ID {

using test::sharedDataDir;

// ---- A plain CPU reference, in double precision (independent of the shader's packing). ----

// The rotation of the polar decomposition (Higham's iteration); a reflection is negated.
glm::dmat3 polarRotation(const glm::dmat3& a) {
  glm::dmat3 r = a;
  for (int i = 0; i < 50; ++i) r = 0.5 * (r + glm::transpose(glm::inverse(r)));
  return glm::determinant(a) < 0.0 ? -r : r;
}

struct Deformed {
  glm::dvec3 position, normal;
};

// glTF skinning of one vertex; dual quaternions per Kavan 2007 with the scale/shear rest
// blended linearly first (normals by that blend's inverse transpose, then the rotation).
Deformed skinVertex(const glm::dvec3& p, const glm::dvec3& n, const uint16_t* joints, const float* weights,
                    const std::vector<glm::dmat4>& m, bool dualQuaternion) {
  Deformed out{glm::dvec3(0.0), glm::dvec3(0.0)};
  if (!dualQuaternion) {
    for (int i = 0; i < kMaxInfluences; ++i) {
      if (weights[i] == 0.0f) continue;
      const glm::dmat4& s = m[joints[i]];
      out.position += double(weights[i]) * glm::dvec3(s * glm::dvec4(p, 1.0));
      out.normal += double(weights[i]) * (glm::transpose(glm::inverse(glm::dmat3(s))) * n);
    }
  } else {
    glm::dquat real(0, 0, 0, 0), dual(0, 0, 0, 0), pivot(1, 0, 0, 0);
    glm::dmat3 rest(0.0);
    for (int i = 0; i < kMaxInfluences; ++i) {
      if (weights[i] == 0.0f) continue;
      const glm::dmat4& s = m[joints[i]];
      const glm::dmat3 r = polarRotation(glm::dmat3(s));
      const glm::dquat qr = glm::quat_cast(r);
      const glm::dvec3 t(s[3]);
      const glm::dquat qd = 0.5 * (glm::dquat(0.0, t.x, t.y, t.z) * qr);
      if (real == glm::dquat(0, 0, 0, 0)) pivot = qr;
      const double w = glm::dot(qr, pivot) < 0.0 ? -weights[i] : weights[i];
      real = real + w * qr;
      dual = dual + w * qd;
      const glm::dmat3 restI = glm::transpose(r) * glm::dmat3(s);
      rest += double(weights[i]) * restI;
    }
    const double len = glm::length(real);
    real = real / len;
    dual = dual / len;
    const glm::dquat t = 2.0 * dual * glm::conjugate(real);
    out.position = real * (rest * p) + glm::dvec3(t.x, t.y, t.z);
    out.normal = real * (glm::transpose(glm::inverse(rest)) * n);
  }
  if (glm::length(out.normal) > 0.0) out.normal = glm::normalize(out.normal);
  return out;
}

std::vector<glm::dmat4> skinningMatrices(const Skin& skin, const std::vector<glm::mat4>& world) {
  std::vector<glm::dmat4> m;
  for (size_t i = 0; i < skin.joints.size(); ++i) m.push_back(glm::dmat4(world[skin.joints[i]]) * glm::dmat4(skin.inverseBind[i]));
  return m;
}

// ---- GL set-up ----

struct Gpu {
  std::unique_ptr<HeadlessContext> context;
  std::unique_ptr<MeshRenderer> renderer;
};

std::vector<HeadlessBackend> backends() {
  std::vector<HeadlessBackend> b{HeadlessBackend::Egl};
  if (osMesaAvailable()) b.push_back(HeadlessBackend::OsMesa);
  return b;
}
const char* nameOf(HeadlessBackend b) { return b == HeadlessBackend::Egl ? "egl" : "osmesa"; }

// Opens a context (llvmpipe, as every render test) and an initialised renderer, or fails the test.
bool openGpu(HeadlessBackend backend, Gpu& gpu) {
  setenv("LIBGL_ALWAYS_SOFTWARE", "1", 0);
  Result<std::unique_ptr<HeadlessContext>> context = createHeadlessContext(backend);
  EXPECT_TRUE(context.ok()) << nameOf(backend) << ": " << (context ? "" : context.error());
  if (!context) return false;
  gpu.context = std::move(context.value());
  gpu.renderer = std::make_unique<MeshRenderer>();
  const std::string error = gpu.renderer->init();
  EXPECT_EQ(error, "") << nameOf(backend);
  return error.empty();
}

std::vector<DeformedPrimitive> gpuDeform(MeshRenderer& renderer, const Scene& scene, const std::vector<glm::mat4>& world,
                                         bool skinnedOnly, const std::vector<std::vector<float>>* morphWeights = nullptr) {
  std::vector<DeformedPrimitive> out;
  std::string error = renderer.upload(scene);
  EXPECT_EQ(error, "");
  MeshFrame frame;
  frame.world = &world;
  frame.morphWeights = morphWeights;
  error = renderer.deform(frame, skinnedOnly, out);
  EXPECT_EQ(error, "");
  return out;
}

// Largest distance between the GPU's skinned vertices and the double-precision reference.
struct Gap {
  double position = 0.0, normal = 0.0, size = 0.0;
};
Gap compareWithReference(const Scene& scene, const std::vector<glm::mat4>& world, const std::vector<DeformedPrimitive>& gpu) {
  Gap gap;
  Bounds box;
  for (const DeformedPrimitive& d : gpu) {
    const MeshInstance& inst = scene.meshInstances[d.instance];
    const MeshPrimitive& p = scene.meshes[inst.mesh].primitives[d.primitive];
    EXPECT_EQ(d.positions.size(), p.positions.size());
    if (d.positions.size() != p.positions.size()) continue;
    const std::vector<glm::dmat4> m = skinningMatrices(scene.skins[inst.skin], world);
    for (int v = 0; v < p.vertexCount(); ++v) {
      const glm::dvec3 n = p.normals.empty() ? glm::dvec3(0.0) : glm::dvec3(p.normals[v]);
      const Deformed ref = skinVertex(glm::dvec3(p.positions[v]), n, &p.influenceJoints[size_t(v) * kMaxInfluences],
                                      &p.influenceWeights[size_t(v) * kMaxInfluences], m,
                                      inst.skinning == SkinningMethod::DualQuaternion);
      box.add(glm::vec3(ref.position));
      gap.position = std::max(gap.position, glm::length(ref.position - glm::dvec3(d.positions[v])));
      if (!p.normals.empty()) gap.normal = std::max(gap.normal, glm::length(ref.normal - glm::dvec3(d.normals[v])));
    }
  }
  gap.size = 2.0 * box.radius();
  return gap;
}

// Largest gap between the GPU and the CPU's SceneDeformationJob (same order, same layout).
Gap compareWithCpuJob(const Scene& scene, const std::vector<glm::mat4>& world, const std::vector<DeformedPrimitive>& gpu,
                      bool skinnedOnly, const std::vector<std::vector<float>>* morphWeights = nullptr) {
  std::vector<DeformedPrimitive> cpu;
  SceneDeformationJob job;
  job.scene = &scene;
  job.world = &world;
  job.morphWeights = morphWeights;
  job.skinnedOnly = skinnedOnly;
  job.out = &cpu;
  EXPECT_EQ(job.validate(), "");
  EXPECT_TRUE(job.run());
  Gap gap;
  Bounds box;
  EXPECT_EQ(cpu.size(), gpu.size());
  for (size_t k = 0; k < std::min(cpu.size(), gpu.size()); ++k) {
    EXPECT_EQ(cpu[k].instance, gpu[k].instance);
    EXPECT_EQ(cpu[k].primitive, gpu[k].primitive);
    EXPECT_EQ(cpu[k].positions.size(), gpu[k].positions.size());
    EXPECT_EQ(cpu[k].normals.size(), gpu[k].normals.size());
    for (size_t v = 0; v < std::min(cpu[k].positions.size(), gpu[k].positions.size()); ++v) {
      box.add(cpu[k].positions[v]);
      gap.position = std::max(gap.position, double(glm::length(cpu[k].positions[v] - gpu[k].positions[v])));
    }
    for (size_t v = 0; v < std::min(cpu[k].normals.size(), gpu[k].normals.size()); ++v)
      gap.normal = std::max(gap.normal, double(glm::length(cpu[k].normals[v] - gpu[k].normals[v])));
  }
  gap.size = 2.0 * box.radius();
  return gap;
}

// ---- Hand-derived ----

// Two joints at the origin, the second turned a quarter about Z; a vertex at (1,0,0) with
// weights 1/2 and 1/2. LBS averages (1,0,0) and (0,1,0): (1/2, 1/2, 0), pulled inside the
// circle. DQS turns it by the average angle, 45 degrees: (sqrt(1/2), sqrt(1/2), 0).
Scene quarterTurnScene(SkinningMethod method) {
  Scene scene;
  scene.skeleton.addJoint("a", -1, Transform{});
  scene.skeleton.addJoint("b", -1, Transform{});
  MeshPrimitive p;
  p.positions = {glm::vec3(1, 0, 0), glm::vec3(0, 0, 1), glm::vec3(1, 0, 1)};
  p.normals = {glm::vec3(1, 0, 0), glm::vec3(1, 0, 0), glm::vec3(1, 0, 0)};
  p.indices = {0, 1, 2};
  p.influenceJoints.assign(3 * kMaxInfluences, 0);
  p.influenceWeights.assign(3 * kMaxInfluences, 0.0f);
  for (int v = 0; v < 3; ++v) {
    p.influenceJoints[v * kMaxInfluences + 1] = 1;
    p.influenceWeights[v * kMaxInfluences] = 0.5f;
    p.influenceWeights[v * kMaxInfluences + 1] = 0.5f;
  }
  scene.meshes.push_back(Mesh{"quarter", {p}, {}, {}});
  scene.skins.push_back(Skin{"skin", {0, 1}, {glm::mat4(1.0f), glm::mat4(1.0f)}, -1});
  MeshInstance inst;
  inst.joint = 0;
  inst.mesh = 0;
  inst.skin = 0;
  inst.skinning = method;
  scene.meshInstances.push_back(inst);
  return scene;
}

TEST(MeshSkinningGpu, QuarterTurnHalfWeightsMatchHandDerivedLbsAndDqs) {
  const float h = std::sqrt(0.5f);
  const std::vector<glm::mat4> world = {glm::mat4(1.0f),
                                        glm::mat4_cast(glm::angleAxis(glm::half_pi<float>(), glm::vec3(0, 0, 1)))};
  for (HeadlessBackend backend : backends()) {
    SCOPED_TRACE(nameOf(backend));
    Gpu gpu;
    if (!openGpu(backend, gpu)) continue;
    const Scene lbs = quarterTurnScene(SkinningMethod::LinearBlend);
    std::vector<DeformedPrimitive> out = gpuDeform(*gpu.renderer, lbs, world, true);
    ASSERT_EQ(out.size(), 1u);
    EXPECT_VEC3_NEAR(out[0].positions[0], glm::vec3(0.5f, 0.5f, 0.0f), 1e-6f);
    EXPECT_VEC3_NEAR(out[0].positions[1], glm::vec3(0.0f, 0.0f, 1.0f), 1e-6f);  // on the axis: unmoved
    EXPECT_VEC3_NEAR(out[0].normals[0], glm::vec3(h, h, 0.0f), 1e-6f);
    const Scene dqs = quarterTurnScene(SkinningMethod::DualQuaternion);
    out = gpuDeform(*gpu.renderer, dqs, world, true);
    ASSERT_EQ(out.size(), 1u);
    EXPECT_VEC3_NEAR(out[0].positions[0], glm::vec3(h, h, 0.0f), 1e-6f);
    EXPECT_VEC3_NEAR(out[0].positions[2], glm::vec3(h, h, 1.0f), 1e-6f);
    EXPECT_VEC3_NEAR(out[0].normals[0], glm::vec3(h, h, 0.0f), 1e-6f);
  }
}

// The GPU on the singular joint of skinning_decomposition_test.cpp (issue 17): joint 0 a
// quarter turn about Z flattened along Y (Q diag(1, 0, 1)), joint 1 the quarter turn Q,
// half and half. One decomposition for both paths: both rotations are Q and the stretch
// diag(1, 1/2, 1), so (1, 0, 0) -> (0, 1, 0) and (1, 0, 1) -> (0, 1, 1), as the CPU job
// gives. The GPU's old copy took the identity for joint 0 and bent them 45 degrees off.
TEST(MeshSkinningGpu, AFlattenedJointDeformsAsOnTheCpu) {
  const glm::mat4 quarter = glm::mat4_cast(glm::angleAxis(glm::half_pi<float>(), glm::vec3(0, 0, 1)));
  const glm::mat4 flat = quarter * glm::scale(glm::mat4(1.0f), glm::vec3(1, 0, 1));
  const std::vector<glm::mat4> world = {flat, quarter};
  const Scene dqs = quarterTurnScene(SkinningMethod::DualQuaternion);
  for (HeadlessBackend backend : backends()) {
    SCOPED_TRACE(nameOf(backend));
    Gpu gpu;
    if (!openGpu(backend, gpu)) continue;
    const std::vector<DeformedPrimitive> out = gpuDeform(*gpu.renderer, dqs, world, true);
    ASSERT_EQ(out.size(), 1u);
    EXPECT_VEC3_NEAR(out[0].positions[0], glm::vec3(0.0f, 1.0f, 0.0f), 1e-5f);
    EXPECT_VEC3_NEAR(out[0].positions[2], glm::vec3(0.0f, 1.0f, 1.0f), 1e-5f);
    const Gap cpu = compareWithCpuJob(dqs, world, out, true);
    EXPECT_LT(cpu.position, 1e-5) << "GPU and CPU differ on a singular skinning matrix";
  }
}

// ---- The Khronos samples ----

struct ReferenceCase {
  std::string file, reference;
  int clip;
  double time;
};
std::vector<ReferenceCase> referenceCases() {
  return {{"gltf/CesiumMan.glb", "CesiumMan.clip0.t1.skin.json", 0, 1.0},
          {"gltf/Fox.glb", "Fox.clip0.t1.7083.skin.json", 0, 1.7083},
          {"gltf/Fox.glb", "Fox.clip1.t0.3542.skin.json", 1, 0.3542},
          {"gltf/Fox.glb", "Fox.clip2.t0.5792.skin.json", 2, 0.5792},
          {"gltf/RiggedSimple.glb", "RiggedSimple.clip0.t3.3333.skin.json", 0, 3.3333},
          {"gltf/SimpleSkin.gltf", "SimpleSkin.clip0.t2.75.skin.json", 0, 2.75}};
}

std::vector<glm::mat4> posedWorld(const Scene& scene, int clip, double time) {
  Pose pose = Pose::rest(scene.skeleton);
  if (clip < static_cast<int>(scene.clips.size())) sampleClip(scene.clips[clip], static_cast<float>(time), pose);
  return computeWorld(scene.skeleton, pose);
}

const Scene& loaded(const std::string& relative) {
  static std::map<std::string, Scene> cache;
  auto it = cache.find(relative);
  if (it == cache.end()) {
    Result<Scene> scene = loadScene(sharedDataDir() + "/" + relative);
    EXPECT_TRUE(scene.ok()) << (scene ? "" : scene.error());
    it = cache.emplace(relative, scene ? scene.value() : Scene{}).first;
  }
  return it->second;
}

TEST(MeshSkinningGpu, KhronosSamplesMatchCpuLbsAndDqsAndThreeJs) {
  KINEMA_REQUIRE_SHARED_DATA();
  for (HeadlessBackend backend : backends()) {
    Gpu gpu;
    if (!openGpu(backend, gpu)) continue;
    for (const ReferenceCase& c : referenceCases()) {
      SCOPED_TRACE(std::string(nameOf(backend)) + " " + c.reference);
      Scene scene = loaded(c.file);
      ASSERT_FALSE(scene.skins.empty());
      const std::vector<glm::mat4> world = posedWorld(scene, c.clip, c.time);
      for (SkinningMethod method : {SkinningMethod::LinearBlend, SkinningMethod::DualQuaternion}) {
        for (MeshInstance& inst : scene.meshInstances) inst.skinning = method;
        const std::vector<DeformedPrimitive> out = gpuDeform(*gpu.renderer, scene, world, true);
        ASSERT_FALSE(out.empty());
        const Gap gap = compareWithReference(scene, world, out);
        const double tolerance = 1e-4 * std::max(1.0, gap.size);
        EXPECT_LT(gap.position, tolerance) << (method == SkinningMethod::LinearBlend ? "LBS" : "DQS") << ", model size " << gap.size;
        EXPECT_LT(gap.normal, 1e-4) << (method == SkinningMethod::LinearBlend ? "LBS" : "DQS");
        const Gap job = compareWithCpuJob(scene, world, out, true);
        EXPECT_LT(job.position, tolerance) << "vs SceneDeformationJob, " << (method == SkinningMethod::LinearBlend ? "LBS" : "DQS");
        EXPECT_LT(job.normal, 1e-4) << "vs SceneDeformationJob, " << (method == SkinningMethod::LinearBlend ? "LBS" : "DQS");
        if (method != SkinningMethod::LinearBlend) continue;
        // Outside opinion: three.js's SkinnedMesh at the same time (LBS, glTF semantics).
        std::ifstream in(sharedDataDir() + "/reference/" + c.reference);
        const nlohmann::json ref = nlohmann::json::parse(in);
        ASSERT_EQ(ref["meshes"].size(), out.size());
        for (size_t k = 0; k < out.size(); ++k) {
          const nlohmann::json& r = ref["meshes"][k];
          const MeshInstance& inst = scene.meshInstances[out[k].instance];
          EXPECT_EQ(r["node"].get<int>(), scene.fileIndexOf(inst.joint));
          EXPECT_EQ(r["mesh"].get<int>(), inst.mesh);
          EXPECT_EQ(r["primitive"].get<int>(), out[k].primitive);
          ASSERT_EQ(r["positions"].size(), out[k].positions.size());
          double worst = 0.0;
          for (size_t v = 0; v < out[k].positions.size(); ++v) {
            const glm::dvec3 p(r["positions"][v][0].get<double>(), r["positions"][v][1].get<double>(),
                               r["positions"][v][2].get<double>());
            worst = std::max(worst, glm::length(p - glm::dvec3(out[k].positions[v])));
          }
          EXPECT_LT(worst, tolerance) << "vs three.js, model size " << gap.size;
        }
      }
    }
  }
}

// ---- Hundreds of joints ----

// A 300-joint chain that curls (each joint turns a little about a varying axis) and a strip
// of vertices along it, each weighted to four joints spread over the whole chain, so the last
// joints' matrices must reach the shader intact.
TEST(MeshSkinningGpu, ThreeHundredJointSkinMatchesCpu) {
  constexpr int kJoints = 300, kVertices = 1200;
  Scene scene;
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> unit(-1.0f, 1.0f);
  for (int j = 0; j < kJoints; ++j) {
    Transform t;
    t.translation = glm::vec3(0.0f, j == 0 ? 0.0f : 0.01f, 0.0f);
    scene.skeleton.addJoint("j" + std::to_string(j), j - 1, t);
  }
  const std::vector<glm::mat4> bind = computeWorld(scene.skeleton, Pose::rest(scene.skeleton));
  Skin skin;
  skin.name = "long";
  for (int j = 0; j < kJoints; ++j) {
    skin.joints.push_back(j);
    skin.inverseBind.push_back(glm::inverse(bind[j]));
  }
  scene.skins.push_back(skin);
  MeshPrimitive p;
  for (int v = 0; v < kVertices; ++v) {
    const float along = 2.99f * static_cast<float>(v) / kVertices;
    p.positions.push_back(glm::vec3(0.05f * unit(rng), along, 0.05f * unit(rng)));
    p.normals.push_back(glm::normalize(glm::vec3(unit(rng), unit(rng), unit(rng)) + glm::vec3(0, 0, 2)));
    const int near = std::min(kJoints - 1, static_cast<int>(along / 0.01f));
    const int joints[4] = {near, (near + 150) % kJoints, kJoints - 1 - v % 7, (near * 13 + 5) % kJoints};
    const float weights[4] = {0.4f, 0.3f, 0.2f, 0.1f};
    for (int i = 0; i < kMaxInfluences; ++i) {
      p.influenceJoints.push_back(i < 4 ? static_cast<uint16_t>(joints[i]) : 0);
      p.influenceWeights.push_back(i < 4 ? weights[i] : 0.0f);
    }
  }
  for (int v = 0; v + 2 < kVertices; ++v) p.indices.insert(p.indices.end(), {uint32_t(v), uint32_t(v + 1), uint32_t(v + 2)});
  scene.meshes.push_back(Mesh{"strip", {p}, {}, {}});
  MeshInstance inst;
  inst.joint = 0;
  inst.mesh = 0;
  inst.skin = 0;
  scene.meshInstances.push_back(inst);

  Pose pose = Pose::rest(scene.skeleton);
  for (int j = 0; j < kJoints; ++j)
    pose.local[j].rotation = glm::angleAxis(0.02f + 0.01f * unit(rng), glm::normalize(glm::vec3(unit(rng), 0.3f, unit(rng))));
  const std::vector<glm::mat4> world = computeWorld(scene.skeleton, pose);
  for (HeadlessBackend backend : backends()) {
    SCOPED_TRACE(nameOf(backend));
    Gpu gpu;
    if (!openGpu(backend, gpu)) continue;
    for (SkinningMethod method : {SkinningMethod::LinearBlend, SkinningMethod::DualQuaternion}) {
      scene.meshInstances[0].skinning = method;
      const std::vector<DeformedPrimitive> out = gpuDeform(*gpu.renderer, scene, world, true);
      ASSERT_EQ(out.size(), 1u);
      const Gap gap = compareWithReference(scene, world, out);
      EXPECT_GT(gap.size, 0.5);  // the chain curled, it did not collapse to a point
      EXPECT_LT(gap.position, 1e-4 * std::max(1.0, gap.size)) << int(method);
      EXPECT_LT(gap.normal, 1e-4) << int(method);
      const Gap job = compareWithCpuJob(scene, world, out, true);
      EXPECT_LT(job.position, 1e-4 * std::max(1.0, gap.size)) << "vs SceneDeformationJob " << int(method);
      EXPECT_LT(job.normal, 1e-4) << "vs SceneDeformationJob " << int(method);
      // The chain's tip really moved: a vertex weighted to the last joints is not at rest.
      EXPECT_GT(glm::length(out[0].positions[kVertices - 1] - p.positions[kVertices - 1]), 0.1f);
    }
  }
}

// Skinning matrices with non-uniform scale, shear and a mirror (files whose inverse bind
// matrices scale): DQS splits each into rotation and stretch (two-phase) like the CPU.
TEST(MeshSkinningGpu, ScaledShearedAndMirroredMatricesMatchCpu) {
  Scene scene;
  for (int j = 0; j < 3; ++j) scene.skeleton.addJoint("j" + std::to_string(j), -1, Transform{});
  glm::mat4 shear(1.0f);
  shear[1][0] = 0.4f;  // x += 0.4 y
  const glm::mat4 mirror = glm::scale(glm::mat4(1.0f), glm::vec3(-1.0f, 1.0f, 1.0f));
  scene.skins.push_back(Skin{"s", {0, 1, 2},
                             {glm::scale(glm::mat4(1.0f), glm::vec3(1.0f, 2.0f, 0.5f)), shear, mirror}, -1});
  MeshPrimitive p;
  std::mt19937 rng(3);
  std::uniform_real_distribution<float> unit(-1.0f, 1.0f);
  for (int v = 0; v < 64; ++v) {
    p.positions.push_back(glm::vec3(unit(rng), unit(rng), unit(rng)));
    p.normals.push_back(glm::normalize(glm::vec3(unit(rng), unit(rng), 2.0f)));
    const float w0 = 0.5f + 0.4f * std::abs(unit(rng));
    const float w[3] = {w0, (1.0f - w0) * 0.7f, (1.0f - w0) * 0.3f};
    for (int i = 0; i < kMaxInfluences; ++i) {
      p.influenceJoints.push_back(static_cast<uint16_t>(i < 3 ? (v + i) % 3 : 0));
      p.influenceWeights.push_back(i < 3 ? w[i] : 0.0f);
    }
    p.indices.push_back(static_cast<uint32_t>(v));
  }
  p.indices.resize(63);
  scene.meshes.push_back(Mesh{"m", {p}, {}, {}});
  MeshInstance inst;
  inst.joint = 0;
  inst.mesh = 0;
  inst.skin = 0;
  scene.meshInstances.push_back(inst);
  std::vector<glm::mat4> world;
  for (int j = 0; j < 3; ++j)
    world.push_back(glm::translate(glm::mat4(1.0f), glm::vec3(0.3f * j, -0.2f, 0.1f)) *
                    glm::mat4_cast(glm::angleAxis(0.5f + 0.7f * j, glm::normalize(glm::vec3(1.0f, j, 2.0f)))));
  for (HeadlessBackend backend : backends()) {
    SCOPED_TRACE(nameOf(backend));
    Gpu gpu;
    if (!openGpu(backend, gpu)) continue;
    for (SkinningMethod method : {SkinningMethod::LinearBlend, SkinningMethod::DualQuaternion}) {
      scene.meshInstances[0].skinning = method;
      const std::vector<DeformedPrimitive> out = gpuDeform(*gpu.renderer, scene, world, true);
      ASSERT_EQ(out.size(), 1u);
      const Gap gap = compareWithReference(scene, world, out);
      EXPECT_LT(gap.position, 1e-5) << int(method);
      EXPECT_LT(gap.normal, 1e-5) << int(method);
      const Gap job = compareWithCpuJob(scene, world, out, true);
      EXPECT_LT(job.position, 1e-5) << "vs SceneDeformationJob " << int(method);
      EXPECT_LT(job.normal, 1e-5) << "vs SceneDeformationJob " << int(method);
    }
  }
}

// ---- Morph targets and unskinned instances ----

// Unskinned morphing meshes: p = joint world * (bind + sum_k w_k delta_k), with the mesh's
// default weights and with weights given for the frame.
TEST(MeshSkinningGpu, MorphTargetsBlendOnTheGpuForUnskinnedInstances) {
  KINEMA_REQUIRE_SHARED_DATA();
  for (HeadlessBackend backend : backends()) {
    Gpu gpu;
    if (!openGpu(backend, gpu)) continue;
    for (const std::string file : {"gltf/SimpleMorph/SimpleMorph.gltf", "gltf/AnimatedMorphCube/AnimatedMorphCube.gltf"}) {
      SCOPED_TRACE(std::string(nameOf(backend)) + " " + file);
      const Scene& scene = loaded(file);
      ASSERT_FALSE(scene.clips.empty());
      ASSERT_FALSE(scene.meshInstances.empty());
      const std::vector<glm::mat4> world = posedWorld(scene, 0, 0.0);
      std::vector<std::vector<float>> given(scene.meshInstances.size());
      for (size_t i = 0; i < given.size(); ++i) {
        const Mesh& mesh = scene.meshes[scene.meshInstances[i].mesh];
        for (size_t k = 0; k < mesh.primitives[0].targets.size(); ++k) given[i].push_back(0.3f + 0.4f * float(k));
      }
      using Weights = std::vector<std::vector<float>>;
      const Weights* none = nullptr;
      // The clip's own weights half way through (sampleMorphWeights), next to none and given ones.
      const Weights sampled = sampleMorphWeights(scene, 0, 0.5 * (scene.clips.empty() ? 0.0 : scene.clips[0].duration()));
      for (const Weights* weights : {none, static_cast<const Weights*>(&given), &sampled}) {
        const std::vector<DeformedPrimitive> out = gpuDeform(*gpu.renderer, scene, world, false, weights);
        ASSERT_FALSE(out.empty());
        const Gap job = compareWithCpuJob(scene, world, out, false, weights);
        EXPECT_LT(job.position, 1e-5) << "vs SceneDeformationJob";
        EXPECT_LT(job.normal, 1e-4) << "vs SceneDeformationJob";
        for (const DeformedPrimitive& d : out) {
          const MeshInstance& inst = scene.meshInstances[d.instance];
          const Mesh& mesh = scene.meshes[inst.mesh];
          const MeshPrimitive& p = mesh.primitives[d.primitive];
          ASSERT_FALSE(p.targets.empty());
          const std::vector<float>& w = weights ? (*weights)[d.instance]
                                        : !inst.morphWeights.empty() ? inst.morphWeights : mesh.morphWeights;
          const glm::dmat4 model(world[inst.joint]);
          double worst = 0.0, moved = 0.0;
          for (int v = 0; v < p.vertexCount(); ++v) {
            glm::dvec3 q(p.positions[v]);
            for (size_t k = 0; k < p.targets.size() && k < w.size(); ++k) q += double(w[k]) * glm::dvec3(p.targets[k].positionDeltas[v]);
            const glm::dvec3 expected(model * glm::dvec4(q, 1.0));
            worst = std::max(worst, glm::length(expected - glm::dvec3(d.positions[v])));
            moved = std::max(moved, glm::length(q - glm::dvec3(p.positions[v])));
          }
          EXPECT_LT(worst, 1e-5);
          if (weights) {
            EXPECT_GT(moved, 0.01) << "the given weights change the shape";
          }
        }
      }
    }
  }
}

}  // namespace
}  // namespace kinema
