// .kinema mesh instances keep their deformer stacks (issue 22): an exact round trip of every
// deformer type, files without deformers written and read as before, and bad values refused
// with one line naming the JSON path.
#include <gtest/gtest.h>

#include <cstring>
#include <nlohmann/json.hpp>

#include "anim/scalar_property.h"
#include "io/kinema_file.h"
#include "scene/default_character_scene.h"

namespace kinema {
namespace KINEMA_UNITY_ID {

Scene twoJointsAndAQuad() {
  Scene scene;
  scene.skeleton.addJoint("Root", -1, Transform::fromTranslation({0, 1, 0}));
  scene.skeleton.addJoint("Head", 0, Transform::fromTranslation({0, 0.5f, 0}));
  Mesh mesh;
  mesh.name = "quad";
  MeshPrimitive prim;
  prim.positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  prim.indices = {0, 1, 2, 0, 2, 3};
  mesh.primitives.push_back(prim);
  scene.meshes.push_back(mesh);
  MeshInstance a, b;
  a.joint = 0;
  a.mesh = 0;
  b.joint = 1;
  b.mesh = 0;
  scene.meshInstances = {a, b};
  return scene;
}

// Values chosen so that none is a round decimal: a float that survives the file bit for
// bit survives because it is written exactly, not because it is short.
Scene everyDeformer() {
  Scene scene = twoJointsAndAQuad();
  DeformerStack& stack = scene.editDeformerStack(1);
  Deformer lattice;
  lattice.name = "cage";
  lattice.type = DeformerType::Lattice;
  const int counts[3] = {3, 2, 4};
  lattice.lattice = fitLattice(scene.meshes[0].primitives[0].positions, {}, counts, 0.1f);
  lattice.lattice.points[5] += glm::vec3(0.1f, -0.3f / 7.0f, 1.0f / 3.0f);
  lattice.parentJoint = 1;
  lattice.parentRest = glm::mat4(1.0f);
  lattice.parentRest[3] = glm::vec4(0.1f, 1.5f, -0.2f / 3.0f, 1.0f);
  lattice.weights = {{0.0f, 0.25f, 1.0f / 3.0f, 1.0f}};
  stack.deformers.push_back(lattice);
  for (DeformerType t : {DeformerType::Bend, DeformerType::Twist, DeformerType::Taper}) {
    Deformer d;
    d.name = toString(t);
    d.type = t;
    d.axis.kind = t == DeformerType::Bend ? AxisDeformerKind::Bend
                  : t == DeformerType::Twist ? AxisDeformerKind::Twist
                                             : AxisDeformerKind::Taper;
    d.axis.axis = t == DeformerType::Twist ? DeformAxis::Z : DeformAxis::X;
    d.axis.origin = glm::vec3(0.1f, 0.2f, 0.3f);
    d.axis.low = -0.7f;
    d.axis.high = 1.0f / 3.0f;
    d.axis.amount = 0.9f / 7.0f;
    d.enabled = t != DeformerType::Twist;
    stack.deformers.push_back(d);
  }
  Deformer pull;
  pull.name = "pull";
  pull.type = DeformerType::SoftPull;
  pull.pull.center = glm::vec3(1, 1.0f / 3.0f, 0);
  pull.pull.offset = glm::vec3(0.01f, -0.02f, 0.3f / 7.0f);
  pull.pull.radius = 0.45f;
  pull.pull.falloff = Falloff::Sharp;
  stack.deformers.push_back(pull);
  Clip clip;
  clip.name = "wobble";
  Channel ch(1, ChannelTarget::Scalar, Interpolation::Linear, {0.0f, 0.5f}, {glm::vec4(0.1f), glm::vec4(0.7f)});
  ch.property = deformerParameterProperty("cage", "point.5.y");
  clip.channels.push_back(ch);
  scene.clips.push_back(clip);
  return scene;
}

void expectSameBits(const float* a, const float* b, size_t n, const std::string& what) {
  EXPECT_EQ(std::memcmp(a, b, n * sizeof(float)), 0) << what;
}

TEST(KinemaDeformers, EveryDeformerRoundTripsExactly) {
  const Scene scene = everyDeformer();
  const std::string text = toKinemaJson(scene);
  Result<Scene> loaded = parseKinemaJson(text, "stack.kinema");
  ASSERT_TRUE(loaded) << loaded.error();
  ASSERT_EQ(loaded->deformers.size(), 2u);  // one per instance, the first one empty
  EXPECT_TRUE(loaded->deformers[0].empty());
  const DeformerStack& a = scene.deformers[1];
  const DeformerStack& b = loaded->deformers[1];
  ASSERT_EQ(a.deformers.size(), b.deformers.size());
  for (size_t i = 0; i < a.deformers.size(); ++i) {
    const Deformer &x = a.deformers[i], &y = b.deformers[i];
    SCOPED_TRACE(x.name);
    EXPECT_EQ(x.name, y.name);
    EXPECT_EQ(x.type, y.type);
    EXPECT_EQ(x.enabled, y.enabled);
    EXPECT_EQ(x.parentJoint, y.parentJoint);
    expectSameBits(glm::value_ptr(x.parentRest), glm::value_ptr(y.parentRest), 16, "parent rest");
    ASSERT_EQ(x.weights.size(), y.weights.size());
    for (size_t p = 0; p < x.weights.size(); ++p)
      expectSameBits(x.weights[p].data(), y.weights[p].data(), x.weights[p].size(), "weights");
    if (x.type == DeformerType::Lattice) {
      for (int k = 0; k < 3; ++k) EXPECT_EQ(x.lattice.counts[k], y.lattice.counts[k]);
      expectSameBits(&x.lattice.origin.x, &y.lattice.origin.x, 3, "origin");
      expectSameBits(&x.lattice.axes[0].x, &y.lattice.axes[0].x, 9, "axes");
      ASSERT_EQ(x.lattice.points.size(), y.lattice.points.size());
      expectSameBits(&x.lattice.points[0].x, &y.lattice.points[0].x, 3 * x.lattice.points.size(), "points");
    } else if (x.type == DeformerType::SoftPull) {
      expectSameBits(&x.pull.center.x, &y.pull.center.x, 3, "center");
      expectSameBits(&x.pull.offset.x, &y.pull.offset.x, 3, "offset");
      expectSameBits(&x.pull.radius, &y.pull.radius, 1, "radius");
      EXPECT_EQ(x.pull.falloff, y.pull.falloff);
    } else {
      EXPECT_EQ(x.axis.kind, y.axis.kind);
      EXPECT_EQ(x.axis.axis, y.axis.axis);
      expectSameBits(&x.axis.origin.x, &y.axis.origin.x, 3, "origin");
      expectSameBits(&x.axis.low, &y.axis.low, 1, "low");
      expectSameBits(&x.axis.high, &y.axis.high, 1, "high");
      expectSameBits(&x.axis.amount, &y.axis.amount, 1, "amount");
    }
  }
  EXPECT_EQ(loaded->clips[0].channels[0].property, "deformers/cage/point.5.y");
  // Written again, the loaded scene gives the same text.
  EXPECT_EQ(toKinemaJson(loaded.value()), text);
}

TEST(KinemaDeformers, FilesWithoutDeformersAreWrittenAsBefore) {
  const Scene scene = makeDefaultCharacterScene();
  const std::string text = toKinemaJson(scene);
  EXPECT_EQ(text.find("deformers"), std::string::npos) << "nothing written for instances without deformers";
  Result<Scene> loaded = parseKinemaJson(text, "plain.kinema");
  ASSERT_TRUE(loaded) << loaded.error();
  EXPECT_TRUE(loaded->deformers.empty());
  EXPECT_EQ(toKinemaJson(loaded.value()), text);
  // A stack emptied in the editor writes nothing either.
  Scene emptied = scene;
  emptied.editDeformerStack(0);
  EXPECT_EQ(toKinemaJson(emptied), text);
}

std::string withDeformer(const nlohmann::json& deformer) {
  nlohmann::ordered_json j = nlohmann::ordered_json::parse(toKinemaJson(twoJointsAndAQuad()));
  j["mesh_instances"][1]["deformers"] = nlohmann::json::array({deformer});
  return j.dump();
}

TEST(KinemaDeformers, BadValuesAreOneLineNamingThePlace) {
  using J = nlohmann::json;
  const J twist = {{"name", "t"}, {"type", "twist"}, {"axis", {{"axis", "y"}, {"low", 0}, {"high", 1}, {"amount", 1}}}};
  const J box = {{"counts", {2, 2, 2}},
                 {"origin", {0, 0, 0}},
                 {"axes", {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}},
                 {"points", {0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0, 0, 0, 1, 1, 0, 1, 0, 1, 1, 1, 1, 1}}};
  auto with = [](J d, const char* key, const J& value) {
    d[key] = value;
    return d;
  };
  auto lattice = [&](const char* key, const J& value) {
    J b = box;
    b[key] = value;
    return J{{"name", "cage"}, {"type", "lattice"}, {"lattice", b}};
  };
  const std::string at = "bad.kinema: mesh_instances[1].deformers[0]";
  struct Case {
    std::string text;
    std::string message;
  };
  const Case cases[] = {
      {withDeformer(with(twist, "type", "squash")),
       at + ".type: 'squash' is not one of lattice, bend, twist, taper, soft_pull"},
      {withDeformer(with(twist, "name", "a/b")), at + ".name: a deformer's name must be non-empty and without '/'"},
      {withDeformer(with(twist, "parent", "Neck")), at + ".parent: no joint named 'Neck'"},
      {withDeformer(with(twist, "enabled", 1)), at + ".enabled: expected true or false, found number"},
      {withDeformer(with(twist, "axis", {{"axis", "w"}})), at + ".axis.axis: 'w' is not one of x, y, z"},
      {withDeformer(with(twist, "axis", {{"low", 2}, {"high", 1}})),
       at + ".axis: twist deformer's range is empty (low must be below high)"},
      {withDeformer(with(twist, "weights", {{0, 1, 0.5}})),
       at + ".weights[0]: expected 4 weights (one per vertex) or none, found 3"},
      {withDeformer(with(twist, "weights", {{0, 1, 1.5, 0}})), at + ".weights[0][2]: a weight must be in [0, 1]"},
      {withDeformer(with(twist, "weights", {J::array(), J::array()})),
       at + ".weights: weights for 2 primitives, the mesh has 1"},
      {withDeformer(J{{"name", "t"}, {"type", "twist"}}), at + ".axis: missing"},
      {withDeformer(lattice("counts", {2, 9, 2})), at + ".lattice.counts[1]: 9 is out of range (2..8)"},
      {withDeformer(lattice("points", {0, 0, 0})), at + ".lattice.points: expected 8 points (3 numbers each), found 1"},
      {withDeformer(lattice("axes", {{1, 0, 0}, {0, 1, 0}, {"z"}})),
       at + ".lattice.axes[2]: expected an array of 3 numbers"},
      {withDeformer(J{{"name", "p"}, {"type", "soft_pull"}, {"pull", {{"center", {0, 0, 0}}, {"radius", 0}}}}),
       at + ".pull: soft pull's radius must be above 0"},
      {withDeformer(J{{"name", "p"}, {"type", "soft_pull"}, {"pull", {{"center", {0, 0, 0}}, {"falloff", "cubic"}}}}),
       at + ".pull.falloff: 'cubic' is not one of smooth, sphere, root, sharp, linear, constant"},
  };
  for (const Case& c : cases) {
    Result<Scene> r = parseKinemaJson(c.text, "bad.kinema");
    ASSERT_FALSE(r) << c.message;
    EXPECT_EQ(r.error(), c.message);
    EXPECT_EQ(r.error().find('\n'), std::string::npos);
  }
  // Two deformers of one name.
  nlohmann::ordered_json j = nlohmann::ordered_json::parse(toKinemaJson(twoJointsAndAQuad()));
  j["mesh_instances"][0]["deformers"] = J::array({twist, twist});
  Result<Scene> r = parseKinemaJson(j.dump(), "bad.kinema");
  ASSERT_FALSE(r);
  EXPECT_EQ(r.error(),
            "bad.kinema: mesh_instances[0].deformers[1].name: 't' is the name of deformer 0 too (names must be unique "
            "in a stack)");
}

TEST(KinemaDeformers, SavingRefusesWhatReadingRefuses) {
  Scene scene = everyDeformer();
  scene.deformers[1].deformers[4].name = "bend";
  const std::string error = saveKinemaFile("/nonexistent-folder/x.kinema", scene);
  EXPECT_NE(error.find("mesh instance 1: deformer 4 ('bend'): the name is used by deformer 1 too"), std::string::npos)
      << error;
}

}  // namespace
}  // namespace kinema
