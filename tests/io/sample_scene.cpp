#include "io/sample_scene.h"

#include "core/forward_kinematics.h"
#include "core/rotation.h"

namespace kinema::test {

namespace {

Channel channel(int joint, ChannelTarget target, Interpolation mode, std::vector<float> times,
                std::vector<glm::vec4> values) {
  return Channel(joint, target, mode, std::move(times), std::move(values));
}

glm::vec4 quatValue(const glm::vec3& axis, float angle) {
  const glm::quat q = axisAngle(axis, angle);
  return {q.x, q.y, q.z, q.w};
}

}  // namespace

Scene makeSampleScene() {
  Scene scene;
  Skeleton& s = scene.skeleton;
  Transform root = Transform::fromTranslation({0, 1, 0});
  root.rotation = axisAngle({0, 1, 0}, 0.5f);
  s.addJoint("Root", -1, root);
  for (int i = 1; i <= 7; ++i) {
    Transform t = Transform::fromTranslation({0, 0.25f, 0});
    if (i == 3) t.rotation = axisAngle({1, 0, 0}, 0.2f);
    s.addJoint("B" + std::to_string(i), i - 1, t);
  }
  s.addJoint("Body", -1, Transform::identity());
  scene.nodeOfJoint = {2, 3, 4, 5, 6, 7, 8, 0, 1};  // B7 and Body come first in the file

  // Skin: the eight chain joints, inverse bind = inverse rest world matrix.
  Skin skin;
  skin.name = "chain";
  const std::vector<glm::mat4> world = computeWorld(s, Pose::rest(s));
  for (int j = kRoot; j <= kB7; ++j) {
    skin.joints.push_back(j);
    skin.inverseBind.push_back(glm::inverse(world[j]));
  }
  skin.skeletonRoot = kRoot;
  scene.skins.push_back(skin);

  // A strip of 8 vertices in two columns; vertex v is pulled by all 8 joints (v even) or
  // by two (v odd).
  Mesh mesh;
  mesh.name = "strip";
  MeshPrimitive p;
  for (int v = 0; v < 8; ++v) {
    p.positions.push_back({v % 2 ? 0.1f : -0.1f, 1.0f + 0.25f * (v / 2), 0.0f});
    p.normals.push_back({0, 0, 1});
    p.texcoords.push_back({float(v % 2), float(v / 2) / 3.0f});
    float weights[kMaxInfluences] = {};
    uint16_t joints[kMaxInfluences] = {};
    if (v % 2 == 0) {
      float sum = 0.0f;
      for (int i = 0; i < kMaxInfluences; ++i) sum += float(kMaxInfluences - i);
      for (int i = 0; i < kMaxInfluences; ++i) {
        joints[i] = static_cast<uint16_t>((v / 2 + i) % 8);
        weights[i] = float(kMaxInfluences - i) / sum;
      }
    } else {
      joints[0] = static_cast<uint16_t>(v / 2 + 1);
      joints[1] = static_cast<uint16_t>(v / 2);
      weights[0] = 0.75f;
      weights[1] = 0.25f;
    }
    p.influenceJoints.insert(p.influenceJoints.end(), joints, joints + kMaxInfluences);
    p.influenceWeights.insert(p.influenceWeights.end(), weights, weights + kMaxInfluences);
  }
  p.indices = {0, 1, 2, 2, 1, 3, 2, 3, 4, 4, 3, 5, 4, 5, 6, 6, 5, 7};
  MorphTarget smile, blink;
  for (int v = 0; v < 8; ++v) {
    smile.positionDeltas.push_back({0.0f, 0.0f, 0.05f * v});
    smile.normalDeltas.push_back({0.0f, 0.0f, 0.0f});
    blink.positionDeltas.push_back({v % 2 ? 0.02f : -0.02f, 0.0f, 0.0f});
  }
  blink.normalDeltas.assign(8, glm::vec3(0.0f));
  p.targets = {smile, blink};
  p.material = 0;
  mesh.primitives.push_back(p);
  mesh.morphWeights = {0.25f, 0.0f};
  mesh.targetNames = {"smile", "blink"};
  scene.meshes.push_back(mesh);
  scene.meshInstances.push_back({kBody, 0, 0, {}});

  Material material;
  material.name = "clay";
  material.baseColor = {0.8f, 0.5f, 0.2f, 1.0f};
  material.baseColorImage = 0;
  material.doubleSided = true;
  scene.materials.push_back(material);
  TextureImage checker;
  checker.name = "checker";
  checker.width = checker.height = 4;
  for (int y = 0; y < 4; ++y)
    for (int x = 0; x < 4; ++x) {
      const uint8_t c = (x + y) % 2 ? 255 : 40;
      checker.rgba.insert(checker.rgba.end(), {c, uint8_t(255 - c), 128, 255});
    }
  scene.images.push_back(checker);

  // Clips.
  Clip dance;
  dance.name = "dance";
  // Catmull-Rom on uneven key times: exact CUBICSPLINE.
  dance.channels.push_back(channel(kB1, ChannelTarget::Translation, Interpolation::CatmullRom,
                                   {0.0f, 0.3f, 0.5f, 1.0f, 1.2f},
                                   {{0, 0.25f, 0, 0}, {0.1f, 0.3f, 0, 0}, {0.05f, 0.2f, 0.1f, 0}, {-0.1f, 0.25f, 0, 0},
                                    {0, 0.25f, 0, 0}}));
  // Squad rotation: glTF cannot hold it, resampled.
  dance.channels.push_back(channel(kB2, ChannelTarget::Rotation, Interpolation::Squad, {0.0f, 0.4f, 0.8f, 1.2f},
                                   {quatValue({1, 0, 0}, 0.0f), quatValue({1, 0, 0}, 0.8f),
                                    quatValue({0, 0, 1}, 0.6f), quatValue({0, 1, 0}, -0.4f)}));
  // Linear rotation through more than 180 degrees of quaternion sign: exact LINEAR.
  dance.channels.push_back(channel(kB3, ChannelTarget::Rotation, Interpolation::Linear, {0.0f, 0.6f, 1.2f},
                                   {quatValue({1, 0, 0}, 0.2f), quatValue({0, 1, 0}, 2.5f),
                                    -quatValue({0, 0, 1}, 1.0f)}));
  dance.channels.push_back(channel(kB4, ChannelTarget::Scale, Interpolation::Step, {0.0f, 0.5f, 1.0f},
                                   {{1, 1, 1, 0}, {1.5f, 1, 1, 0}, {1, 2, 1, 0}}));
  Channel euler = channel(kB5, ChannelTarget::Euler, Interpolation::Linear, {0.0f, 0.6f, 1.2f},
                          {{0, 0, 0, 0}, {0.5f, 1.0f, -0.3f, 0}, {1.2f, -0.4f, 0.2f, 0}});
  euler.eulerOrder = EulerOrder::ZXY;
  dance.channels.push_back(euler);
  // Bezier with automatic handles (a third of each interval): exact CUBICSPLINE.
  dance.channels.push_back(channel(kB6, ChannelTarget::Translation, Interpolation::Bezier, {0.0f, 0.25f, 0.9f, 1.2f},
                                   {{0, 0.25f, 0, 0}, {0.2f, 0.25f, 0, 0}, {0.0f, 0.35f, 0.1f, 0}, {0, 0.25f, 0, 0}}));
  // Hermite rotation with explicit tangents: glTF's own CUBICSPLINE rotation.
  Channel hermite = channel(kB7, ChannelTarget::Rotation, Interpolation::Hermite, {0.0f, 0.5f, 1.2f},
                            {quatValue({0, 0, 1}, 0.0f), quatValue({0, 0, 1}, 0.7f), quatValue({1, 0, 0}, 0.5f)});
  hermite.keys.resize(3);
  for (KeySettings& k : hermite.keys) k.interpolation = Interpolation::Hermite;
  hermite.keys[0].outTangent = {0, 0, 0.5f, 0};
  hermite.keys[1].inTangent = {0, 0, 0.3f, -0.1f};
  hermite.keys[1].outTangent = {0.2f, 0, 0.1f, -0.1f};
  hermite.keys[2].inTangent = {0.3f, 0, -0.2f, 0};
  dance.channels.push_back(hermite);
  // TCB translation on the root.
  Channel tcb = channel(kRoot, ChannelTarget::Translation, Interpolation::TCB, {0.0f, 0.2f, 0.7f, 1.2f},
                        {{0, 1, 0, 0}, {0.2f, 1.1f, 0, 0}, {0.3f, 0.9f, 0.2f, 0}, {0, 1, 0, 0}});
  tcb.keys.resize(4);
  for (KeySettings& k : tcb.keys) k.interpolation = Interpolation::TCB;
  tcb.keys[1].tension = 0.5f;
  tcb.keys[2].continuity = -0.3f;
  tcb.keys[2].bias = 0.4f;
  dance.channels.push_back(tcb);
  // Morph weights: two channels sharing key times, LINEAR.
  Channel w0 = channel(kBody, ChannelTarget::Scalar, Interpolation::Linear, {0.0f, 0.6f, 1.2f},
                       {{0.25f, 0, 0, 0}, {1, 0, 0, 0}, {0, 0, 0, 0}});
  w0.property = "weights/0";
  Channel w1 = channel(kBody, ChannelTarget::Scalar, Interpolation::Linear, {0.0f, 0.6f, 1.2f},
                       {{0, 0, 0, 0}, {0.5f, 0, 0, 0}, {1, 0, 0, 0}});
  w1.property = "weights/1";
  dance.channels.push_back(w0);
  dance.channels.push_back(w1);
  // A property glTF has no place for.
  Channel other = channel(kRoot, ChannelTarget::Scalar, Interpolation::Linear, {0.0f, 1.0f},
                          {{1, 0, 0, 0}, {2, 0, 0, 0}});
  other.property = "temperature";
  dance.channels.push_back(other);
  scene.clips.push_back(dance);

  Clip idle;
  idle.name = "idle";
  idle.frameTime = 1.0 / 24.0;
  idle.channels.push_back(channel(kB1, ChannelTarget::Translation, Interpolation::Linear, {0.0f, 1.0f},
                                  {{0, 0.25f, 0, 0}, {0, 0.3f, 0, 0}}));
  scene.clips.push_back(idle);
  return scene;
}

}  // namespace kinema::test
