// `kinema skin`: the contract's JSON shape and values (a hand-derived skinned triangle and
// the three.js reference for SimpleSkin), exit codes, a file without skins, --method,
// load warnings on stderr (also from `kinema convert`).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "io/gltf_test_files.h"
#include "skin/skinned_test_file.h"
#include "test_support.h"

namespace kinema {
namespace KINEMA_UNITY_ID {

using nlohmann::json;

struct CliRun {
  int status;
  std::string out, err;
};

CliRun kinema(const std::string& args) {
  CliRun r;
  r.status = test::runCommand(std::string(KINEMA_BINARY) + " " + args, &r.out, &r.err);
  return r;
}

std::string triangleFile(const std::string& dir, const std::vector<float>& weights) {
  const std::string path = dir + "/tri.gltf";
  test::writeFile(path, test::skinnedTriangleFile(weights).gltf());
  return path;
}

// At rest every skinning matrix is world x IBM = I, so the vertices stay where they are,
// and the body node's own (100, 0, 0) is ignored: (0,1,0), (1,1,0), (0,2,0). With one
// weight on each joint the third vertex (on the knee) proves the knee's IBM is used.
TEST(SkinCli, RestPoseJsonShape) {
  const std::string dir = test::makeTempDir();
  const CliRun r = kinema("skin '" + triangleFile(dir, {1, 0, 0, 0, 0.5f, 0.5f, 0, 0, 1, 0, 0, 0}) + "' --json");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.err, "");
  const json d = json::parse(r.out);
  ASSERT_EQ(d.size(), 1u);  // only "meshes"
  ASSERT_EQ(d["meshes"].size(), 1u);
  const json& m = d["meshes"][0];
  EXPECT_EQ(m["node"], 2);
  EXPECT_EQ(m["mesh"], 0);
  EXPECT_EQ(m["primitive"], 0);
  const std::vector<std::vector<double>> expected = {{0, 1, 0}, {1, 1, 0}, {0, 2, 0}};
  ASSERT_EQ(m["positions"].size(), 3u);
  for (int v = 0; v < 3; ++v)
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(m["positions"][v][c].get<double>(), expected[v][c], 1e-6) << v;
}

// The three.js reference for SimpleSkin at t = 2.75 through the CLI.
TEST(SkinCli, SimpleSkinMatchesThreeJs) {
  KINEMA_REQUIRE_SHARED_DATA();
  const std::string data = test::sharedDataDir();
  const CliRun r = kinema("skin '" + data + "/gltf/SimpleSkin.gltf' --time 2.75 --json");
  ASSERT_EQ(r.status, 0) << r.err;
  const json got = json::parse(r.out);
  std::ifstream in(data + "/reference/SimpleSkin.clip0.t2.75.skin.json");
  const json ref = json::parse(in);
  ASSERT_EQ(got["meshes"].size(), ref["meshes"].size());
  for (size_t i = 0; i < ref["meshes"].size(); ++i) {
    EXPECT_EQ(got["meshes"][i]["node"], ref["meshes"][i]["node"]);
    ASSERT_EQ(got["meshes"][i]["positions"].size(), ref["meshes"][i]["positions"].size());
    for (size_t v = 0; v < ref["meshes"][i]["positions"].size(); ++v)
      for (int c = 0; c < 3; ++c)
        EXPECT_NEAR(got["meshes"][i]["positions"][v][c].get<double>(), ref["meshes"][i]["positions"][v][c].get<double>(),
                    1e-4);
  }
}

TEST(SkinCli, FileWithoutSkinsPrintsNoMeshes) {
  const std::string dir = test::makeTempDir();
  test::writeFile(dir + "/bones.gltf", test::smallAnimatedFile().gltf());
  const CliRun r = kinema("skin '" + dir + "/bones.gltf' --time 0.5 --json");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(json::parse(r.out), json::parse(R"({"meshes":[]})"));
}

TEST(SkinCli, ExitCodes) {
  const std::string dir = test::makeTempDir();
  const std::string f = "'" + triangleFile(dir, {1, 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0}) + "'";
  struct Case {
    std::string args;
    int status;
    const char* message;
  };
  const Case cases[] = {
      {"skin " + f + " --clip 3 --json", 1, "--clip 3 does not exist"},
      {"skin '" + dir + "/missing.gltf' --json", 1, "missing.gltf"},
      {"skin " + f + " --time nan --json", 1, "--time must be a finite number"},
      {"skin " + f + " --time abc --json", 2, "see --help"},
      {"skin " + f + " --time 1 --frame 2 --json", 2, "see --help"},
      {"skin " + f + " --method cubic --json", 2, "see --help"},
      {"skin " + f + " --no-such-flag", 2, "see --help"},
      {"skin --json", 2, "see --help"},
  };
  for (const Case& c : cases) {
    const CliRun r = kinema(c.args);
    EXPECT_EQ(r.status, c.status) << c.args << "\n" << r.err;
    EXPECT_NE(r.err.find(c.message), std::string::npos) << c.args << "\n" << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << c.args << "\n" << r.err;
    EXPECT_EQ(r.out, "") << c.args;
  }
}

// A glTF whose weights do not sum to 1: one warning line on stderr from `skin` and from
// `convert`, naming the file, the primitive and the count; the output is still produced.
TEST(SkinCli, RenormalisedWeightsWarnOnStderr) {
  const std::string dir = test::makeTempDir();
  const std::string f = triangleFile(dir, {0.5f, 0.25f, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0});
  for (const std::string& args : {"skin '" + f + "' --json", "convert '" + f + "' '" + dir + "/out.kinema'"}) {
    const CliRun r = kinema(args);
    ASSERT_EQ(r.status, 0) << args << "\n" << r.err;
    EXPECT_NE(r.err.find("warning: " + f + ": mesh 0 primitive 0: 1 of 3 vertices had skin weights not summing to 1"),
              std::string::npos)
        << args << "\n" << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  }
}

// Bent knee (the skeleton's own animation is absent, so pose the file by editing the
// knee's rest rotation: a quarter turn about Z). Vertex 1, half on hip and half on knee:
// hip keeps (1, 1, 0); the knee maps it through its IBM to (1, -1, 0) relative to itself,
// turns that to (1, 1, 0) and adds its (0, 2, 0): (1, 3, 0). Linear blend: (1, 2, 0).
// Dual quaternions blend to the eighth turn about the knee's Z axis through (0, 2, 0):
// (0,2,0) + Rz(45) (1, -1, 0) = (sqrt2, 2, 0).
TEST(SkinCli, MethodOverridesEachInstance) {
  const std::string dir = test::makeTempDir();
  test::GltfTestFile file = test::skinnedTriangleFile({1, 0, 0, 0, 0.5f, 0.5f, 0, 0, 1, 0, 0, 0});
  file.doc["nodes"][1]["rotation"] = {0, 0, std::sqrt(0.5), std::sqrt(0.5)};
  const std::string f = dir + "/bent.gltf";
  test::writeFile(f, file.gltf());
  const CliRun linear = kinema("skin '" + f + "' --json");
  const CliRun dq = kinema("skin '" + f + "' --method dq --json");
  ASSERT_EQ(linear.status, 0) << linear.err;
  ASSERT_EQ(dq.status, 0) << dq.err;
  const json l = json::parse(linear.out)["meshes"][0]["positions"][1];
  const json q = json::parse(dq.out)["meshes"][0]["positions"][1];
  EXPECT_NEAR(l[0].get<double>(), 1.0, 1e-6);
  EXPECT_NEAR(l[1].get<double>(), 2.0, 1e-6);
  EXPECT_NEAR(q[0].get<double>(), std::sqrt(2.0), 1e-6);
  EXPECT_NEAR(q[1].get<double>(), 2.0, 1e-6);
  // Without --json: a summary naming the method.
  const CliRun table = kinema("skin '" + f + "' --method dq");
  ASSERT_EQ(table.status, 0);
  EXPECT_NE(table.out.find("node 2 mesh 0 primitive 0 (dual quaternion): 3 vertices"), std::string::npos) << table.out;
}

}  // namespace
}  // namespace kinema
