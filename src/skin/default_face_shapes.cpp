#include "skin/default_face_shapes.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/default_character.h"
#include "core/forward_kinematics.h"
#include "deform/deformer_stack.h"

namespace kinema {

const std::vector<std::string> kDefaultFaceShapeNames = {"jaw_open", "smile", "brow_raise", "blink"};

float DefaultFaceLandmarks::frontZ(float x, float y) const {
  const float u = x / radius[0], v = (y - centerY) / radius[1];
  return centerZ + radius[2] * std::sqrt(std::max(0.0f, 1.0f - u * u - v * v));
}

DefaultFaceLandmarks defaultFaceLandmarks() {
  // The head ellipsoid of skin/default_body_mesh.cpp, from the same joints.
  const Skeleton s = makeDefaultCharacter();
  const std::vector<glm::mat4> world = computeWorld(s, Pose::rest(s));
  const glm::vec3 head(world[s.find("Head")][3]), top(world[s.find("HeadTop")][3]);
  DefaultFaceLandmarks f;
  const float height = 0.5f * (top.y - head.y) + 0.005f;
  f.centerY = top.y - height;
  f.centerZ = head.z + 0.015f;
  f.radius[0] = 0.082f;
  f.radius[1] = height;
  f.radius[2] = 0.097f;
  // Proportions of a stylised face on a head 2 * height tall.
  f.chinY = f.centerY - 0.68f * height;
  f.mouthY = f.centerY - 0.42f * height;
  f.eyeY = f.centerY + 0.08f * height;
  f.browY = f.centerY + 0.32f * height;
  f.mouthX = 0.030f;
  f.eyeX = 0.032f;
  f.browX = 0.034f;
  return f;
}

namespace {

// The vertex nearest to p: a soft pull is centred on a picked vertex, as in the editor.
glm::vec3 nearestVertex(const std::vector<glm::vec3>& positions, const glm::vec3& p) {
  glm::vec3 best = p;
  float bestDistance = std::numeric_limits<float>::max();
  for (const glm::vec3& q : positions) {
    const float d = glm::dot(q - p, q - p);
    if (d < bestDistance) {
      bestDistance = d;
      best = q;
    }
  }
  return best;
}

Deformer pull(const std::string& name, const glm::vec3& center, const glm::vec3& offset, float radius) {
  Deformer d;
  d.name = name;
  d.type = DeformerType::SoftPull;
  d.pull.center = center;
  d.pull.offset = offset;
  d.pull.radius = radius;
  d.pull.falloff = Falloff::Smooth;
  return d;
}

MorphTarget bake(const MeshPrimitive& body, const DeformerStack& stack) {
  std::vector<glm::vec3> after(body.positions.size());
  DeformerStackJob job;
  job.stack = &stack;
  job.positions = body.positions.data();
  job.count = static_cast<int>(body.positions.size());
  job.outPositions = after.data();
  job.run();  // the stacks below are valid by construction
  return shapeFromDeformation(body.positions, after, body.indices);
}

}  // namespace

void addDefaultFaceShapes(MeshPrimitive& body) {
  const DefaultFaceLandmarks f = defaultFaceLandmarks();
  const std::vector<glm::vec3>& v = body.positions;
  auto front = [&](float x, float y) { return nearestVertex(v, glm::vec3(x, y, f.frontZ(x, y))); };

  // jaw_open: the chin drops and comes back, only below the mouth (a weight map ramping from
  // 0 a little above the mouth line to 1 a little below it).
  DeformerStack jaw;
  Deformer chin = pull("chin", front(0.0f, f.chinY), glm::vec3(0.0f, -0.035f, -0.012f), 0.08f);
  std::vector<float> lower(v.size());
  for (size_t i = 0; i < v.size(); ++i)
    lower[i] = std::clamp((f.mouthY + 0.01f - v[i].y) / 0.025f, 0.0f, 1.0f);
  chin.weights = {lower};
  jaw.deformers.push_back(chin);

  DeformerStack smile, brows, blink;
  for (float side : {1.0f, -1.0f}) {
    const char* tag = side > 0 ? ".L" : ".R";
    smile.deformers.push_back(pull(std::string("corner") + tag, front(side * f.mouthX, f.mouthY),
                                   glm::vec3(side * 0.012f, 0.016f, -0.006f), 0.04f));
    brows.deformers.push_back(pull(std::string("brow") + tag, front(side * f.browX, f.browY),
                                   glm::vec3(0.0f, 0.016f, 0.003f), 0.045f));
    blink.deformers.push_back(pull(std::string("lid") + tag, front(side * f.eyeX, f.eyeY),
                                   glm::vec3(0.0f, -0.01f, -0.01f), 0.03f));
  }
  for (const DeformerStack* stack : {&jaw, &smile, &brows, &blink}) body.targets.push_back(bake(body, *stack));
}

}  // namespace kinema
