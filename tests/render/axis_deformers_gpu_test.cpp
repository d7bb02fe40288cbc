// Bend, twist and taper in the mesh renderer's vertex shader (issue 22) against the CPU's
// SceneDeformationJob, the reference: the default character posed away from rest with a
// stack of a twist, a bend parented to a joint (so its frame moves) and a taper, read back
// by transform feedback (MeshRenderer::deform). Positions agree to 1e-4 m; the shader's
// normals (central differences of the same map) point as the CPU's area-weighted ones.
// llvmpipe on EGL, as every render test.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <memory>

#include "core/forward_kinematics.h"
#include "render/gl_context.h"
#include "render/mesh_renderer.h"
#include "scene/default_character_scene.h"
#include "evaluation/scene_deformation.h"

namespace kinema {
namespace KINEMA_UNITY_ID {

Deformer axisDeformer(const std::string& name, DeformerType type, AxisDeformerKind kind, DeformAxis axis,
                      glm::vec3 origin, float low, float high, float amount) {
  Deformer d;
  d.name = name;
  d.type = type;
  d.axis.kind = kind;
  d.axis.axis = axis;
  d.axis.origin = origin;
  d.axis.low = low;
  d.axis.high = high;
  d.axis.amount = amount;
  return d;
}

TEST(AxisDeformersGpu, BendTwistTaperMatchTheCpuOnThePosedCharacter) {
  setenv("LIBGL_ALWAYS_SOFTWARE", "1", 0);
  Result<std::unique_ptr<HeadlessContext>> context = createHeadlessContext(HeadlessBackend::Egl);
  ASSERT_TRUE(context.ok()) << (context ? "" : context.error());
  MeshRenderer renderer;
  ASSERT_EQ(renderer.init(), "");
  const Scene scene = makeDefaultCharacterScene();
  ASSERT_EQ(renderer.upload(scene), "");

  // Posed: the spine and an arm turned, so skinning and the parented bend's frame both move.
  Pose pose = Pose::rest(scene.skeleton);
  const int spine = scene.skeleton.find("Spine"), arm = scene.skeleton.find("UpperArm.L");
  ASSERT_GE(spine, 0);
  ASSERT_GE(arm, 0);
  pose.local[spine].rotation = glm::angleAxis(0.4f, glm::normalize(glm::vec3(0.3f, 0.2f, 1.0f))) * pose.local[spine].rotation;
  pose.local[arm].rotation = glm::angleAxis(-0.7f, glm::vec3(0.0f, 0.0f, 1.0f)) * pose.local[arm].rotation;
  const std::vector<glm::mat4> rest = computeWorld(scene.skeleton, Pose::rest(scene.skeleton));
  const std::vector<glm::mat4> world = computeWorld(scene.skeleton, pose);

  std::vector<DeformerStack> stacks(scene.meshInstances.size());
  stacks[0].deformers.push_back(
      axisDeformer("twist", DeformerType::Twist, AxisDeformerKind::Twist, DeformAxis::Y, glm::vec3(0.0f), 0.9f, 1.7f, 0.8f));
  Deformer bend =
      axisDeformer("bend", DeformerType::Bend, AxisDeformerKind::Bend, DeformAxis::Y, glm::vec3(0.0f, 1.0f, 0.0f), 0.0f, 0.7f, 0.9f);
  bend.parentJoint = spine;
  bend.parentRest = rest[spine];
  stacks[0].deformers.push_back(bend);
  stacks[0].deformers.push_back(
      axisDeformer("taper", DeformerType::Taper, AxisDeformerKind::Taper, DeformAxis::X, glm::vec3(0.0f), -0.9f, 0.9f, 1.6f));
  Deformer off = axisDeformer("off", DeformerType::Twist, AxisDeformerKind::Twist, DeformAxis::Z, glm::vec3(0.0f), 0, 1, 3);
  off.enabled = false;  // skipped by both
  stacks[0].deformers.push_back(off);
  ASSERT_TRUE(axisStackOnGpu(stacks[0]));
  ASSERT_EQ(stacks[0].validate(scene.meshes[scene.meshInstances[0].mesh], scene.skeleton.size()), "");

  MeshFrame frame;
  frame.world = &world;
  frame.gpuDeformers = &stacks;
  std::vector<DeformedPrimitive> gpu;
  ASSERT_EQ(renderer.deform(frame, false, gpu), "");

  std::vector<DeformedPrimitive> cpu, undeformed;
  SceneDeformationJob job;
  job.scene = &scene;
  job.world = &world;
  job.deformers = &stacks;
  job.out = &cpu;
  ASSERT_TRUE(job.run());
  job.deformers = nullptr;
  job.out = &undeformed;
  ASSERT_TRUE(job.run());

  ASSERT_EQ(gpu.size(), cpu.size());
  double worst = 0.0, moved = 0.0, dots = 0.0;
  int normals = 0;
  for (size_t k = 0; k < gpu.size(); ++k) {
    ASSERT_EQ(gpu[k].instance, cpu[k].instance);
    ASSERT_EQ(gpu[k].positions.size(), cpu[k].positions.size());
    for (size_t v = 0; v < gpu[k].positions.size(); ++v) {
      worst = std::max(worst, double(glm::length(gpu[k].positions[v] - cpu[k].positions[v])));
      moved = std::max(moved, double(glm::length(cpu[k].positions[v] - undeformed[k].positions[v])));
      if (gpu[k].instance == 0 && !gpu[k].normals.empty() && !cpu[k].normals.empty()) {
        dots += glm::dot(gpu[k].normals[v], cpu[k].normals[v]);
        ++normals;
      }
    }
  }
  std::printf("[ gpu ] largest GPU - CPU distance %.3g m (the stack moves vertices up to %.3f m), mean normal cosine %.4f\n",
              worst, moved, normals ? dots / normals : 0.0);
  EXPECT_GT(moved, 0.1) << "the stack moves the body visibly";
  EXPECT_LE(worst, 1e-4) << "largest GPU - CPU distance (m)";
  ASSERT_GT(normals, 0);
  EXPECT_GT(dots / normals, 0.97) << "mean cosine between the shader's and the CPU's normals";

  // A stack with a lattice is not the shader's: nothing is deformed there (uAxisCount 0).
  std::vector<DeformerStack> lattice = stacks;
  lattice[0].deformers.push_back(Deformer{});
  EXPECT_FALSE(axisStackOnGpu(lattice[0]));
}

}  // namespace
}  // namespace kinema
