// .kinema files keep their particle systems (issue 24, "simulation.particles"): an exact
// round trip of every setting, defaults for members left out, and bad values refused with
// one line naming the JSON path.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "io/kinema_file.h"
#include "io/kinema_refusals.h"

namespace kinema {
namespace KINEMA_UNITY_ID {

Scene armed() {
  Scene scene;
  Skeleton& s = scene.skeleton;
  s.addJoint("Hips", -1, Transform::fromTranslation({0, 1, 0}));
  s.addJoint("Arm", 0, Transform::fromTranslation({0.3f, 0.4f, 0}));
  s.addJoint("Hand", 1, Transform::fromTranslation({0.3f, 0, 0}));
  return scene;
}

// Every kind of emitter and every setting, with values that have no short decimal form.
Scene withParticles() {
  Scene scene = armed();
  ParticleSystemSettings sparks;
  sparks.name = "sparks";
  sparks.seed = 18446744073709551557ull;  // above 2^63: the largest 64-bit prime
  sparks.maxParticles = 1234;
  sparks.style = ParticleDrawStyle::Points;
  sparks.size = 3.5f;
  sparks.colour = {0.1f, 1.0f / 3.0f, 0.9f, 0.75f};
  ParticleEmitter joint;
  joint.shape = EmitterShape::Joint;
  joint.joint = 2;
  joint.position = {0.01f, 0.0f, 1.0f / 7.0f};
  joint.direction = {0.0f, 1.0f, 0.2f};
  joint.coneDegrees = 33.3f;
  joint.speed = {2.7f, 0.31f, RandomDistribution::Normal};
  joint.rate = {120.5f, 10.0f, RandomDistribution::Uniform};
  joint.lifetime = {1.25f, 0.4f, RandomDistribution::Normal};
  ParticleEmitter sphere;
  sphere.shape = EmitterShape::Sphere;
  sphere.position = {1.0f, 2.0f, 3.0f};
  sphere.radius = 0.123f;
  ParticleEmitter surface;
  surface.shape = EmitterShape::MeshSurface;
  surface.surfacePositions = {{0, 0, 0}, {1, 0, 0}, {0, 0, 1.0f / 3.0f}, {1, 0, 1}};
  surface.surfaceIndices = {0, 2, 1, 1, 2, 3};
  surface.alongNormal = false;
  ParticleEmitter point;  // the defaults
  sparks.emitters = {joint, sphere, surface, point};
  sparks.forces.gravity = {0.0f, -9.81f, 0.0f};
  sparks.forces.wind = {1.5f, 0.0f, -0.1f};
  sparks.forces.drag = 0.7f;
  sparks.forces.ground = false;
  sparks.forces.groundHeight = -0.05f;
  sparks.forces.restitution = 0.45f;
  sparks.forces.friction = 0.15f;
  sparks.forces.spheres = {{{0.0f, 1.0f, 0.0f}, 0.25f}, {{2.0f, 0.5f, 0.0f}, 0.5f}};
  ParticleSystemSettings plain;  // all defaults, no emitters
  plain.name = "";
  scene.simulation.particles = {sparks, plain};
  return scene;
}

TEST(KinemaParticles, SystemsRoundTripExactly) {
  const Scene scene = withParticles();
  ASSERT_EQ(scene.simulation.validate(scene.skeleton), "");
  const std::string text = toKinemaJson(scene);
  Result<Scene> back = parseKinemaJson(text, "rt.kinema");
  ASSERT_TRUE(back) << back.error();
  ASSERT_EQ(back->simulation.particles.size(), 2u);
  EXPECT_TRUE(back->simulation.particles[0] == scene.simulation.particles[0]);
  EXPECT_TRUE(back->simulation.particles[1] == scene.simulation.particles[1]);
  EXPECT_EQ(toKinemaJson(back.value()), text) << "a second save writes the same bytes";
  // The written form docs/kinema-format.md shows: the joint by name, kinds as words.
  const nlohmann::json j = nlohmann::json::parse(text);
  const nlohmann::json& e = j["simulation"]["particles"][0]["emitters"];
  EXPECT_EQ(e[0]["kind"], "joint");
  EXPECT_EQ(e[0]["joint"], "Hand");
  EXPECT_EQ(e[0]["speed"]["distribution"], "normal");
  EXPECT_EQ(e[2]["kind"], "mesh_surface");
  EXPECT_EQ(e[2]["surface"]["indices"], nlohmann::json::array({0, 2, 1, 1, 2, 3}));
  EXPECT_EQ(j["simulation"]["particles"][0]["draw"]["style"], "points");
  EXPECT_EQ(j["simulation"]["particles"][0]["seed"].get<uint64_t>(), 18446744073709551557ull);
}

TEST(KinemaParticles, OnlyParticlesStillWritesTheSimulationKey) {
  Scene scene = armed();
  scene.simulation.particles.push_back(defaultParticleSystem(2, 1.8f));
  Result<Scene> back = parseKinemaJson(toKinemaJson(scene), "p.kinema");
  ASSERT_TRUE(back) << back.error();
  ASSERT_EQ(back->simulation.particles.size(), 1u);
  EXPECT_TRUE(back->simulation.particles[0] == scene.simulation.particles[0]);
  EXPECT_EQ(back->simulation.particles[0].emitters[0].joint, 2);
}

TEST(KinemaParticles, MembersLeftOutTakeTheDefaults) {
  nlohmann::ordered_json j = nlohmann::ordered_json::parse(toKinemaJson(armed()));
  j["simulation"] = {{"particles", {{{"emitters", {{{"kind", "point"}}}}}}}};
  Result<Scene> back = parseKinemaJson(j.dump(), "d.kinema");
  ASSERT_TRUE(back) << back.error();
  ParticleSystemSettings expected;
  expected.emitters.push_back(ParticleEmitter{});
  EXPECT_TRUE(back->simulation.particles.at(0) == expected);
}

TEST(KinemaParticles, BadValuesAreOneLineNamingTheJsonPath) {
  const nlohmann::ordered_json base = nlohmann::ordered_json::parse(toKinemaJson(armed()));
  using J = nlohmann::ordered_json;
  auto emitter = [](const char* key, const J& v) {
    J e = {{"kind", "point"}};
    e[key] = v;
    return J{{"particles", {{{"emitters", {e}}}}}};
  };
  auto system = [](const char* key, const J& v) {
    J s = {{"emitters", J::array()}};
    s[key] = v;
    return J{{"particles", {s}}};
  };
  auto forces = [&](const char* key, const J& v) { return system("forces", J{{key, v}}); };
  auto draw = [&](const char* key, const J& v) { return system("draw", J{{key, v}}); };
  const std::vector<std::pair<J, std::string>> cases = {
      {{{"particles", 3}}, "simulation.particles: expected an array"},
      {{{"particles", {{{"name", "x"}}}}}, "simulation.particles[0].emitters: missing"},
      {emitter("kind", "cube"), "simulation.particles[0].emitters[0].kind: 'cube' is not one of point, sphere, mesh_surface, joint"},
      {J{{"particles", {{{"emitters", {{{"kind", "joint"}}}}}}}}, "simulation.particles[0].emitters[0].joint: missing"},
      {emitter("joint", "Tail"), "simulation.particles[0].emitters[0].joint: no joint named 'Tail'"},
      {J{{"particles", {{{"emitters", {{{"kind", "mesh_surface"}}}}}}}}, "simulation.particles[0].emitters[0].surface: missing"},
      {emitter("surface", J{{"positions", {0, 0, 0, 1, 0, 0, 0, 1, 0}}, {"indices", {0, 1, 3}}}),
       "simulation.particles[0].emitters[0].surface.indices[2]: expected a vertex index 0 to 2"},
      {emitter("cone_deg", 200), "simulation.particles[0].emitters[0].cone_deg: must be 0 to 180 (degrees)"},
      {emitter("direction", {0, 0, 0}), "simulation.particles[0].emitters[0].direction: must not be zero"},
      {emitter("position", {0, 1}), "simulation.particles[0].emitters[0].position: expected an array of 3 numbers"},
      {emitter("radius", 0), "simulation.particles[0].emitters[0].radius: must be above 0"},
      {emitter("rate", J{{"mean", -1}}), "simulation.particles[0].emitters[0].rate.mean: must be >= 0"},
      {emitter("lifetime", J{{"spread", -1}}), "simulation.particles[0].emitters[0].lifetime.spread: must be >= 0"},
      {emitter("speed", J{{"distribution", "poisson"}}),
       "simulation.particles[0].emitters[0].speed.distribution: 'poisson' is not uniform or normal"},
      {forces("restitution", 1.5), "simulation.particles[0].forces.restitution: must be 0 to 1"},
      {forces("drag", -1), "simulation.particles[0].forces.drag: must be >= 0"},
      {forces("ground", 1), "simulation.particles[0].forces.ground: expected true or false"},
      {forces("spheres", J{{{"centre", {0, 0, 0}}}}), "simulation.particles[0].forces.spheres[0].radius: missing"},
      {draw("style", "lines"), "simulation.particles[0].draw.style: 'lines' is not points or quads"},
      {draw("size", 0), "simulation.particles[0].draw.size: must be above 0"},
      {draw("colour", {1, 0, 0, 2}), "simulation.particles[0].draw.colour[3]: must be 0 to 1"},
      {system("seed", -3), "simulation.particles[0].seed: expected a whole number"},
      {system("max_particles", 0), "simulation.particles[0].max_particles: expected a whole number 1 to 4194304"},
  };
  for (const auto& [simulation, expected] : cases) test::expectSimulationRefused(base, simulation, expected);
}

}  // namespace
}  // namespace kinema
