// L-systems: grammar parsing, derivation (forced and stochastic), the turtle's skeleton and
// its tube geometry, and `kinema lsystem`.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <nlohmann/json.hpp>

#include "core/forward_kinematics.h"
#include "io/scene_files.h"
#include "sim/lsystem_derivation.h"
#include "io/lsystem_grammar_file.h"
#include "scene/lsystem_scene.h"
#include "sim/lsystem_skeleton.h"
#include "skin/linear_blend_skinning.h"
#include "test_support.h"

namespace kinema {
namespace KINEMA_UNITY_ID {

using Json = nlohmann::json;

const char* kSeedGrammar =
    "# the seed's figure 16.27\n"
    "S -> A\n"
    "A -> [+B]fA\n"
    "A -> B\n"
    "B -> fB\n"
    "B -> f@\n";

// The seed's own derivation (chapter 003, 16.6).
const std::vector<std::string> kSeedStrings = {"S", "A", "[+B]fA", "[+fB]f[+B]fA", "[+ff@]f[+fB]fB", "[+ff@]f[+ff@]ff@"};
// Derived by hand from the strings above: generation 2 rewrites A (rule 0); generation 3 B (0)
// and A (0); generation 4 B (1), B (0), A (1); generation 5 B (1), B (1). S has one rule only.
const std::vector<int> kSeedChoices = {0, 0, 0, 1, 0, 1, 1, 1};

LSystemGrammar seedGrammar() {
  Result<LSystemGrammar> g = parseLSystemGrammar(kSeedGrammar, "seed.lsys");
  EXPECT_TRUE(g.ok()) << g.error();
  return g.value();
}

TEST(LSystemGrammar, ParsesRulesAnglesAndProbabilities) {
  const LSystemGrammar g = seedGrammar();
  EXPECT_EQ(g.start, 'S');
  EXPECT_EQ(g.angleDegrees, 60.0);
  ASSERT_EQ(g.rules.size(), 5u);
  EXPECT_EQ(g.rules[1].replacement, "[+B]fA");
  EXPECT_EQ(g.rules[1].line, 3);
  EXPECT_DOUBLE_EQ(g.rules[1].probability, 0.5);  // two rules for A share 1 equally
  EXPECT_DOUBLE_EQ(g.rules[0].probability, 1.0);

  Result<LSystemGrammar> p = parseLSystemGrammar("angle 22.5\nstart X\nX -> (0.3) f X # grow\nX -> f@\nX -> [+X]\n", "p");
  ASSERT_TRUE(p.ok()) << p.error();
  EXPECT_EQ(p->start, 'X');
  EXPECT_EQ(p->angleDegrees, 22.5);
  EXPECT_EQ(p->rules[0].replacement, "fX");  // spaces and the comment dropped
  EXPECT_DOUBLE_EQ(p->rules[0].probability, 0.3);
  EXPECT_DOUBLE_EQ(p->rules[1].probability, 0.35);  // (1 - 0.3) / 2
  EXPECT_DOUBLE_EQ(p->rules[2].probability, 0.35);
}

TEST(LSystemGrammar, ErrorsNameFileAndLine) {
  struct Case {
    const char* text;
    const char* where;
  } cases[] = {
      {"S -> A\nAB -> f\n", "g.lsys:2:"},
      {"S -> A\n\nangle wide\n", "g.lsys:3:"},
      {"S -> (1.5) A\n", "g.lsys:1:"},
      {"S -> (0.6) A\nS -> (0.6) f\n", "g.lsys:2:"},
      {"S -> (0.5) A\nS -> (0.4) f\n", "g.lsys:2:"},  // no rule left to take the rest
      {"f -> ff\n", "g.lsys:1:"},                     // turtle commands are terminals
      {"grow S\n", "g.lsys:1:"},
      {"# nothing\n", "g.lsys: no rules"},
  };
  for (const Case& c : cases) {
    Result<LSystemGrammar> g = parseLSystemGrammar(c.text, "g.lsys");
    ASSERT_FALSE(g.ok()) << c.text;
    EXPECT_EQ(g.error().rfind(c.where, 0), 0u) << g.error();
    EXPECT_EQ(g.error().find('\n'), std::string::npos) << g.error();
  }
}

TEST(LSystemDerivation, ForcedChoicesReproduceTheSeedsDerivation) {
  const LSystemGrammar g = seedGrammar();
  LSystemDerivationJob job;
  job.grammar = &g;
  job.generations = 5;
  job.choices = kSeedChoices;
  std::string error;
  ASSERT_TRUE(job.run(error)) << error;
  EXPECT_EQ(job.strings, kSeedStrings);
  EXPECT_EQ(job.choicesMade, kSeedChoices);

  job.choices = {0, 0, 0, 1, 0, 1, 1, 2};  // B has rules 0 and 1 only
  EXPECT_FALSE(job.run(error));
  EXPECT_NE(error.find("choice 8 is 2"), std::string::npos) << error;
}

TEST(LSystemDerivation, SameSeedSameStringAndProbabilitiesAreHonoured) {
  Result<LSystemGrammar> g = parseLSystemGrammar("S -> (0.25) a\nS -> b\n", "p");
  ASSERT_TRUE(g.ok());
  // One rewrite per run: the fraction of 'a' over many seeds approaches 0.25.
  int as = 0;
  const int runs = 4000;
  for (int s = 0; s < runs; ++s) {
    LSystemDerivationJob job;
    job.grammar = &g.value();
    job.generations = 1;
    job.seed = static_cast<uint64_t>(s);
    std::string error;
    ASSERT_TRUE(job.run(error));
    as += job.strings[1] == "a";
  }
  // Binomial: sd = sqrt(0.25 * 0.75 / 4000) = 0.0068; 5 sd.
  EXPECT_NEAR(as / double(runs), 0.25, 0.035);

  const LSystemGrammar seed = seedGrammar();
  LSystemDerivationJob a, b;
  a.grammar = b.grammar = &seed;
  a.generations = b.generations = 8;
  a.seed = b.seed = 42;
  std::string error;
  ASSERT_TRUE(a.run(error) && b.run(error));
  EXPECT_EQ(a.strings, b.strings);
}

TEST(LSystemDerivation, RunawayGrowthIsRefused) {
  Result<LSystemGrammar> g = parseLSystemGrammar("S -> SS\n", "p");
  LSystemDerivationJob job;
  job.grammar = &g.value();
  job.generations = 40;
  job.maxSymbols = 1000;
  std::string error;
  EXPECT_FALSE(job.run(error));
  EXPECT_NE(error.find("generation 10"), std::string::npos) << error;  // 2^10 = 1024 > 1000
}

TEST(LSystemTurtle, OneJointPerSegmentPlusTheRootAtTheTurtlesPositions) {
  LSystemTurtleJob t;
  t.symbols = kSeedStrings.back();  // [+ff@]f[+ff@]ff@
  t.angleDegrees = 60.0;
  t.segmentLength = 2.0f;
  std::string error;
  ASSERT_TRUE(t.run(error)) << error;
  const long fs = std::count(t.symbols.begin(), t.symbols.end(), 'f');
  EXPECT_EQ(t.skeleton.size(), fs + 1);
  EXPECT_EQ(t.skeleton.validate(), "");
  ASSERT_EQ(t.leaves.size(), 3u);
  // By hand: +60 deg about Z turns the heading (0,1) to (-sin 60, cos 60).
  const glm::vec3 left(-std::sqrt(3.0f) / 2.0f, 0.5f, 0.0f), up(0, 1, 0);
  const std::vector<glm::vec3> expected = {
      {0, 0, 0},                        // root
      2.0f * left, 4.0f * left,         // [+ff@]  from the root
      2.0f * up,                        // f
      2.0f * up + 2.0f * left, 2.0f * up + 4.0f * left,  // [+ff@]
      4.0f * up, 6.0f * up};            // ff@
  const std::vector<int> parents = {-1, 0, 1, 0, 3, 4, 3, 6};
  EXPECT_EQ(t.skeleton.parents, parents);
  const std::vector<glm::mat4> world = computeWorld(t.skeleton, Pose::rest(t.skeleton));
  for (int j = 0; j < t.skeleton.size(); ++j) EXPECT_VEC3_NEAR(glm::vec3(world[j][3]), expected[j], 1e-5f);
  // Every bone keeps the segment length.
  for (int j = 1; j < t.skeleton.size(); ++j) EXPECT_NEAR(glm::length(t.skeleton.rest[j].translation), 2.0f, 1e-5f);
  EXPECT_EQ(t.leaves[0].joint, 2);
  EXPECT_EQ(t.leaves[2].joint, 7);

  t.symbols = "f]f";
  EXPECT_FALSE(t.run(error));
  EXPECT_NE(error.find("closes no '['"), std::string::npos);
}

TEST(LSystemTurtle, RotatingAJointSwingsTheSegmentsThatGrowFromIt) {
  LSystemTurtleJob t;
  t.symbols = "f[+f]f";
  t.angleDegrees = 90.0;
  std::string error;
  ASSERT_TRUE(t.run(error));
  Pose pose = Pose::rest(t.skeleton);
  // Turn seg_1 (joint 1) by 90 degrees about Z: both of its children swing about (0,1,0).
  pose.local[1].rotation = pose.local[1].rotation * glm::angleAxis(glm::radians(90.0f), glm::vec3(0, 0, 1));
  const std::vector<glm::mat4> world = computeWorld(t.skeleton, pose);
  EXPECT_VEC3_NEAR(glm::vec3(world[1][3]), glm::vec3(0, 1, 0), 1e-5f);
  EXPECT_VEC3_NEAR(glm::vec3(world[2][3]), glm::vec3(0, 0, 0), 1e-5f);   // branch was (-1,1): now (0,0)
  EXPECT_VEC3_NEAR(glm::vec3(world[3][3]), glm::vec3(-1, 1, 0), 1e-5f);  // trunk was (0,2)
}

TEST(LSystemTube, SkinnedTubesFollowTheSkeleton) {
  Result<Scene> plant = makeLSystemScene("f[+f@]f", 90.0, 1.0f, 0.1f);
  ASSERT_TRUE(plant.ok()) << plant.error();
  const Scene& s = plant.value();
  ASSERT_EQ(s.meshes.size(), 1u);
  const MeshPrimitive& p = s.meshes[0].primitives[0];
  // 3 segments x 8 sides x 2 rings, plus one leaf of 4 corners on each side.
  EXPECT_EQ(p.vertexCount(), 3 * 16 + 8);
  EXPECT_EQ(p.indices.size(), size_t(3 * 8 * 6 + 12));
  // Every tube vertex lies at the radius from its segment's axis (rest pose).
  const std::vector<glm::mat4> world = computeWorld(s.skeleton, Pose::rest(s.skeleton));
  for (int v = 0; v < 3 * 16; ++v) {
    const int segmentChild = 1 + v / 16;
    const glm::vec3 a(world[s.skeleton.parents[segmentChild]][3]), b(world[segmentChild][3]);
    const glm::vec3 d = glm::normalize(b - a), q = p.positions[v] - a;
    EXPECT_NEAR(glm::length(q - glm::dot(q, d) * d), 0.1f, 1e-5f) << v;
    EXPECT_EQ(p.influenceJoints[v * kMaxInfluences], s.skeleton.parents[segmentChild]);
  }
  // Turning the root by 90 degrees about Z turns every skinned vertex with it.
  Pose pose = Pose::rest(s.skeleton);
  const glm::quat turn = glm::angleAxis(glm::radians(90.0f), glm::vec3(0, 0, 1));
  pose.local[0].rotation = turn;
  const std::vector<glm::mat4> posed = computeWorld(s.skeleton, pose);
  for (int v = 0; v < p.vertexCount(); ++v) {
    const int j = s.skins[0].joints[p.influenceJoints[v * kMaxInfluences]];
    const glm::vec3 skinned = glm::vec3(posed[j] * s.skins[0].inverseBind[j] * glm::vec4(p.positions[v], 1.0f));
    EXPECT_VEC3_NEAR(skinned, turn * p.positions[v], 1e-5f);
  }
}

int kinema(const std::string& args, std::string* out = nullptr, std::string* err = nullptr) {
  return test::runCommand(std::string(KINEMA_BINARY) + " " + args, out, err);
}

TEST(LSystemCommand, SeedGrammarWithForcedChoicesGivesTheSeedsStringsAndJoints) {
  const std::string dir = test::makeTempDir();
  test::writeFile(dir + "/seed.lsys", kSeedGrammar);
  std::string out, err;
  ASSERT_EQ(kinema("lsystem " + dir + "/seed.lsys --generations 5 --choices 0,0,0,1,0,1,1,1 --out " + dir +
                       "/plant.kinema --json",
                   &out, &err),
            0)
      << err;
  const Json j = Json::parse(out);
  ASSERT_EQ(j["generations"].size(), kSeedStrings.size());
  for (size_t g = 0; g < kSeedStrings.size(); ++g) {
    EXPECT_EQ(j["generations"][g]["generation"], g);
    EXPECT_EQ(j["generations"][g]["string"], kSeedStrings[g]);
  }
  EXPECT_EQ(j["joints"], 8);  // 7 f + the root
  Result<Scene> back = loadScene(dir + "/plant.kinema");
  ASSERT_TRUE(back.ok()) << back.error();
  EXPECT_EQ(back->skeleton.size(), 8);
  EXPECT_EQ(back->meshes.size(), 1u);
  // glTF too, and the documented example file gives the same plant.
  ASSERT_EQ(kinema("lsystem " + std::string(KINEMA_SOURCE_DIR) +
                       "/docs/examples/lsystems/seed_plant.lsys --generations 5 --choices 0,0,0,1,0,1,1,1 --out " + dir +
                       "/plant.gltf --json",
                   &out, &err),
            0)
      << err;
  EXPECT_EQ(Json::parse(out)["generations"][5]["string"], kSeedStrings[5]);
  Result<Scene> gltf = loadScene(dir + "/plant.gltf");
  ASSERT_TRUE(gltf.ok()) << gltf.error();
  EXPECT_EQ(gltf->skeleton.size(), 8);
}

TEST(LSystemCommand, BadInputAndUsage) {
  const std::string dir = test::makeTempDir();
  test::writeFile(dir + "/bad.lsys", "S -> A\nA => f\n");
  test::writeFile(dir + "/seed.lsys", kSeedGrammar);
  std::string out, err;
  EXPECT_EQ(kinema("lsystem " + dir + "/bad.lsys --generations 2 --out " + dir + "/p.kinema", &out, &err), 1);
  EXPECT_NE(err.find("bad.lsys:2:"), std::string::npos) << err;
  EXPECT_EQ(std::count(err.begin(), err.end(), '\n'), 1) << err;
  EXPECT_EQ(kinema("lsystem " + dir + "/missing.lsys --generations 2 --out " + dir + "/p.kinema", &out, &err), 1);
  EXPECT_EQ(kinema("lsystem " + dir + "/seed.lsys --generations -1 --out " + dir + "/p.kinema", &out, &err), 1);
  EXPECT_EQ(kinema("lsystem " + dir + "/seed.lsys --generations 3 --choices 0,5 --out " + dir + "/p.kinema", &out, &err), 1);
  EXPECT_FALSE(std::filesystem::exists(dir + "/p.kinema"));
  EXPECT_EQ(kinema("lsystem " + dir + "/seed.lsys --generations 3 --choices 0,x --out " + dir + "/p.kinema", &out, &err), 2);
  EXPECT_EQ(kinema("lsystem " + dir + "/seed.lsys --generations 3 --out " + dir + "/p.png", &out, &err), 2);
  EXPECT_EQ(kinema("lsystem " + dir + "/seed.lsys --out " + dir + "/p.kinema", &out, &err), 2);  // no --generations
  EXPECT_EQ(kinema("lsystem " + dir + "/seed.lsys --generations 3 --out " + dir + "/p.kinema --bogus", &out, &err), 2);
}

}  // namespace
}  // namespace kinema
