// .kinema files keep their crowds (simulation.crowds; issue 24): an exact round trip of every
// setting, defaults for members left out, and bad values refused with one line naming the
// JSON path.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "io/kinema_file.h"
#include "test_support.h"
#include "io/kinema_refusals.h"

namespace kinema {
namespace KINEMA_UNITY_ID {

Scene character() {
  Scene scene;
  scene.skeleton.addJoint("Hips", -1, Transform::fromTranslation({0, 1, 0}));
  return scene;
}

CrowdSettings oddCrowd() {
  CrowdSettings c;  // values with no short decimal form, to catch a writer that rounds
  c.name = "walkers";
  c.character = "../shared/data/gltf/CesiumMan.glb";
  c.clip = 2;
  c.members = 321;
  c.seed = 18446744073709551557ull;  // above 2^63: a double would round it
  c.spawnCentre = {1.0f / 3.0f, 0.0f, -7.25f};
  c.strideSpeed = 1.0f / 7.0f;
  c.forwardDegrees = 90.5f;
  c.debugMember = 17;
  BoidsSettings& b = c.boids;
  b.separationDistance = 0.7f;
  b.neighbourRadius = 3.3f;
  b.fieldOfViewDegrees = 200.0f;
  b.separationWeight = 1.1f;
  b.alignmentWeight = 0.3f;
  b.cohesionWeight = 0.05f;
  b.avoidanceWeight = 2.5f;
  b.avoidanceDistance = 1.25f;
  b.goalWeight = 0.9f;
  b.maxSpeed = 3.1f;
  b.cruiseSpeed = 1.4f;
  b.maxAcceleration = 12.5f;
  b.hasGoal = true;
  b.goal = {10.0f, 0.0f, 1e-3f};
  b.allocation = AccelerationAllocation::Average;
  b.spheres = {{{0.0f, 0.0f, 0.1f}, 2.0f}, {{5.0f, 0.0f, 5.0f}, 0.3f}};
  b.boxes = {{{-1.0f, -1.0f, -1.0f}, {1.0f, 1.0f, 3.0f}}};
  return c;
}

TEST(KinemaCrowds, EverySettingRoundTripsExactly) {
  Scene scene = character();
  CrowdSettings plain;  // the defaults: no goal, no obstacles
  scene.simulation.crowds = {oddCrowd(), plain};
  const std::string text = toKinemaJson(scene);
  Result<Scene> back = parseKinemaJson(text, "rt.kinema");
  ASSERT_TRUE(back) << back.error();
  ASSERT_EQ(back->simulation.crowds.size(), 2u);
  EXPECT_TRUE(back->simulation.crowds[0] == scene.simulation.crowds[0]);
  EXPECT_TRUE(back->simulation.crowds[1] == plain);
  EXPECT_FALSE(back->simulation.crowds[1].boids.hasGoal);
  EXPECT_EQ(toKinemaJson(back.value()), text) << "a second save writes the same bytes";
  const nlohmann::json j = nlohmann::json::parse(text);
  EXPECT_EQ(j["simulation"]["crowds"][0]["allocation"], "average");
  EXPECT_EQ(j["simulation"]["crowds"][0]["obstacles"]["boxes"][0]["max"], nlohmann::json::array({1, 1, 3}));
  EXPECT_FALSE(j["simulation"]["crowds"][1].contains("goal"));
  // A crowd alone is something to simulate; files without crowds never gain the key.
  EXPECT_FALSE(back->simulation.empty());
  scene.simulation.crowds.clear();
  scene.simulation.springChains.push_back(SpringBoneChain{});
  scene.simulation.springChains[0].joints = {0};
  EXPECT_EQ(toKinemaJson(scene).find("crowds"), std::string::npos);
}

TEST(KinemaCrowds, MembersLeftOutTakeTheDefaults) {
  nlohmann::ordered_json j = nlohmann::ordered_json::parse(toKinemaJson(character()));
  j["simulation"] = {{"crowds", {nlohmann::ordered_json::object()}}};
  Result<Scene> back = parseKinemaJson(j.dump(), "d.kinema");
  ASSERT_TRUE(back) << back.error();
  EXPECT_TRUE(back->simulation.crowds.at(0) == CrowdSettings{});
}

TEST(KinemaCrowds, BadValuesAreOneLineNamingTheJsonPath) {
  const nlohmann::ordered_json base = nlohmann::ordered_json::parse(toKinemaJson(character()));
  auto with = [](const char* key, const nlohmann::ordered_json& v) {
    nlohmann::ordered_json c = nlohmann::ordered_json::object();
    c[key] = v;
    return nlohmann::ordered_json{{"crowds", {c}}};
  };
  const std::vector<std::pair<nlohmann::ordered_json, std::string>> cases = {
      {{{"crowds", 3}}, "simulation.crowds: expected an array"},
      {{{"crowds", {7}}}, "simulation.crowds[0]: expected an object"},
      {with("members", 0), "simulation.crowds[0].members: must be 1 to 100000"},
      {with("members", 2.5), "simulation.crowds[0].members: expected a whole number"},
      {with("seed", -1), "simulation.crowds[0].seed: expected a whole number >= 0"},
      {with("character", 5), "simulation.crowds[0].character: expected a string"},
      {with("separation_distance", 0), "simulation.crowds[0].separation_distance: must be above 0"},
      {with("field_of_view_degrees", 400), "simulation.crowds[0].field_of_view_degrees: must be above 0 and at most 360"},
      {with("weights", {{"cohesion", -1}}), "simulation.crowds[0].weights.cohesion: must be >= 0"},
      {with("goal", {1, 2}), "simulation.crowds[0].goal: expected an array of 3 numbers"},
      {with("allocation", "mean"), "simulation.crowds[0].allocation: expected \"priority\" or \"average\""},
      {with("obstacles", {{"spheres", {{{"centre", {0, 0, 0}}, {"radius", -2}}}}}),
       "simulation.crowds[0].obstacles.spheres[0].radius: must be above 0"},
      {with("obstacles", {{"boxes", {{{"min", {0, 0, 0}}, {"max", {1, -1, 1}}}}}}),
       "simulation.crowds[0].obstacles.boxes[0]: min must not pass max on any axis"},
      {with("debug_member", 50), "simulation.crowds[0].debug_member: must be 0 to 49"},
      {with("cruise_speed", 9), "simulation.crowds[0]: crowd 'crowd': the cruise speed must not pass the max speed"},
  };
  for (const auto& [simulation, expected] : cases) test::expectSimulationRefused(base, simulation, expected);
}

}  // namespace
}  // namespace kinema
