// Renders the default character with a viewport overlay (rotate gizmo on UpperArm.L in local
// axes, an IK target handle pulling Hand.R, a swing/twist limit cone on UpperArm.R and a
// box-select rectangle) headless into a PNG. Used by the overlay golden test, which runs it
// as a subprocess on llvmpipe like the `kinema render` goldens.
// Usage: kinema_overlay_sample OUT.png [egl|osmesa]; prints "pivot X Y" (the gizmo's pixel).
#include <cstdio>
#include <string>

#include "core/default_character.h"
#include "core/forward_kinematics.h"
#include "editor/viewport/overlay_builder.h"
#include "io/image.h"
#include "render/headless_renderer.h"
#include "render/skeleton_view.h"

int main(int argc, char** argv) {
  using namespace kinema;
  if (argc < 2) {
    std::fprintf(stderr, "usage: kinema_overlay_sample OUT.png [egl|osmesa]\n");
    return 2;
  }
  const int width = 320, height = 240;
  const Skeleton skeleton = makeDefaultCharacter();
  const std::vector<glm::mat4> world = computeWorld(skeleton, Pose::rest(skeleton));
  const OrbitCamera camera = defaultCamera(jointBounds(world), static_cast<float>(width) / height);
  const ViewportView view = ViewportView::of(camera, {width, height});
  auto position = [&](const char* name) { return glm::vec3(world[skeleton.find(name)][3]); };

  SkeletonDrawList skeletonList;
  SkeletonDrawJob job;
  job.parents = &skeleton.parents;
  job.world = &world;
  job.selectedJoint = skeleton.find("UpperArm.L");
  job.run(skeletonList);

  OverlayDrawList overlay;
  LimitShapeJob limit;
  limit.limit = JointLimit::cone({-1, 0, 0}, glm::radians(45.0f), glm::radians(-30.0f), glm::radians(30.0f));
  limit.jointPosition = position("UpperArm.R");
  limit.restBoneDirection = {-1, 0, 0};
  limit.size = glm::length(position("LowerArm.R") - position("UpperArm.R"));
  LimitShape shape;
  limit.run(shape);
  addLimitShape(overlay, shape);
  addIkTargetHandle(overlay, position("Hand.R") + glm::vec3(0.05f, -0.3f, 0.2f), position("Hand.R"), true);
  RotateGizmo gizmo;
  gizmo.pivot = position("UpperArm.L");
  gizmo.axesRotation = RotateGizmo::axesFor(GizmoOrientation::Local, glm::quat_cast(glm::mat3(world[skeleton.find("UpperArm.L")])));
  gizmo.ringRadiusPixels = 26;
  gizmo.viewRingRadiusPixels = 32;
  addRotateGizmo(overlay, gizmo, view, GizmoPart::AxisZ);
  addBoxSelectRectangle(overlay, {200, 225}, {300, 175});

  const HeadlessBackend backend = argc > 2 && std::string(argv[2]) == "osmesa" ? HeadlessBackend::OsMesa : HeadlessBackend::Egl;
  Result<std::unique_ptr<HeadlessRenderer>> renderer = HeadlessRenderer::open(backend, width, height);
  if (!renderer) {
    std::fprintf(stderr, "cannot render: %s\n", renderer.error().c_str());
    return 1;
  }
  FrameDescription frame;
  frame.skeleton = &skeletonList;
  frame.camera = camera;
  frame.sceneRadius = jointBounds(world).radius();
  frame.overlay = &overlay;
  const std::string error = savePng(argv[1], renderer.value()->render(frame));
  if (!error.empty()) {
    std::fprintf(stderr, "%s\n", error.c_str());
    return 1;
  }
  glm::vec2 pivot;
  view.project(gizmo.pivot, pivot);
  std::printf("pivot %.3f %.3f\n", pivot.x, pivot.y);
  return 0;
}
