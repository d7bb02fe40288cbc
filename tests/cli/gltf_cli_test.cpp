// `kinema pose` on glTF files: the contract's node-order listing, and malformed files
// → exit 1 with one line on stderr.
#include <algorithm>
#include <nlohmann/json.hpp>
#include <string>

#include "io/gltf_test_files.h"
#include "test_support.h"

namespace kinema {
namespace KINEMA_UNITY_ID {

using nlohmann::json;
using test::GltfTestFile;

struct PoseRun {
  int status;
  std::string out, err;
};

PoseRun pose(const std::string& path, const std::string& args = "--time 0.5 --json") {
  PoseRun r;
  r.status = test::runCommand(std::string(KINEMA_BINARY) + " pose '" + path + "' " + args, &r.out, &r.err);
  return r;
}

TEST(GltfCli, PoseListsNodesInNodeOrderWithFileNames) {
  const std::string dir = test::makeTempDir();
  GltfTestFile f = test::smallAnimatedFile();
  // Node 2 is the parent of node 0 (a parent after its child), node 3 is unnamed.
  f.doc["nodes"][0]["name"] = "tip_parent_is_2";
  f.addNode({{"name", "top"}, {"children", {0}}, {"translation", {10, 0, 0}}});
  f.addNode(json::object());
  test::writeFile(dir + "/f.gltf", f.gltf());
  const PoseRun r = pose(dir + "/f.gltf");
  ASSERT_EQ(r.status, 0) << r.err;
  const json d = json::parse(r.out);
  ASSERT_EQ(d["joints"].size(), 4u);
  for (int i = 0; i < 4; ++i) EXPECT_EQ(d["joints"][i]["node"], i);
  EXPECT_EQ(d["joints"][0]["name"], "tip_parent_is_2");
  EXPECT_EQ(d["joints"][0]["parent"], 2);
  EXPECT_EQ(d["joints"][1]["parent"], 0);
  EXPECT_EQ(d["joints"][2]["parent"], -1);
  EXPECT_EQ(d["joints"][3]["parent"], -1);
  EXPECT_TRUE(d["joints"][3]["name"].is_string());
  // At t = 0.5 node 0's STEP translation holds its first key (0,0,0) (replacing the rest
  // translation) and its rotation is 90 deg about z; under node 2 at (10,0,0) it sits at
  // (10,0,0), and node 1, (0,2,0) below it, turns to (-2,0,0): world (8,0,0).
  EXPECT_NEAR(d["joints"][1]["world"][12].get<double>(), 8.0, 1e-5);
  EXPECT_NEAR(d["joints"][1]["world"][13].get<double>(), 0.0, 1e-5);
}

TEST(GltfCli, MalformedFilesExitOneWithOneLine) {
  const std::string dir = test::makeTempDir();
  GltfTestFile cycle;
  cycle.addNode({{"children", {1}}});
  cycle.addNode({{"children", {0}}});
  GltfTestFile past = test::smallAnimatedFile();
  past.doc["accessors"][1]["byteOffset"] = 400;
  GltfTestFile count = test::smallAnimatedFile();
  count.doc["accessors"][1]["count"] = 1;
  const std::string glb = test::smallAnimatedFile().glb();
  const std::pair<std::string, std::string> files[] = {
      {"cycle.gltf", cycle.gltf()},
      {"past.gltf", past.gltf()},
      {"count.glb", count.glb()},
      {"truncated.glb", glb.substr(0, glb.size() - 8)},
      {"empty.gltf", ""},
  };
  for (const auto& [name, bytes] : files) {
    test::writeFile(dir + "/" + name, bytes);
    const PoseRun r = pose(dir + "/" + name);
    EXPECT_EQ(r.status, 1) << name << ": " << r.err;
    EXPECT_TRUE(r.out.empty()) << name;
    ASSERT_FALSE(r.err.empty()) << name;
    EXPECT_EQ(r.err.find('\n'), r.err.size() - 1) << name << ": " << r.err;
    EXPECT_NE(r.err.find(name), std::string::npos) << r.err;
  }
}

// `kinema ik` on glTF lists joints like `kinema pose` (node order, "node"), and its trace
// names node indices.
TEST(GltfCli, IkUsesNodeOrder) {
  const std::string dir = test::makeTempDir();
  GltfTestFile f;
  f.addNode({{"name", "tip"}, {"translation", {0, 1, 0}}});              // 0: child of 1
  f.addNode({{"name", "elbow"}, {"children", {0}}, {"translation", {0, 1, 0}}});  // 1: child of 2
  f.addNode({{"name", "shoulder"}, {"children", {1}}});                  // 2: root
  test::writeFile(dir + "/arm.gltf", f.gltf());
  PoseRun r;
  r.status = test::runCommand(std::string(KINEMA_BINARY) + " ik '" + dir +
                                  "/arm.gltf' --effector tip --target 1,1,0 --solver ccd --trace --json",
                              &r.out, &r.err);
  ASSERT_EQ(r.status, 0) << r.err;
  const json d = json::parse(r.out);
  ASSERT_EQ(d["joints"].size(), 3u);
  for (int i = 0; i < 3; ++i) EXPECT_EQ(d["joints"][i]["node"], i);
  EXPECT_EQ(d["joints"][0]["name"], "tip");
  EXPECT_EQ(d["joints"][0]["parent"], 1);
  EXPECT_TRUE(d["converged"].get<bool>());
  // The tip reaches (1,1,0): |(1,1,0)| = sqrt(2) <= 2, the arm's length.
  EXPECT_NEAR(d["joints"][0]["world"][12].get<double>(), 1.0, 1e-2);
  EXPECT_NEAR(d["joints"][0]["world"][13].get<double>(), 1.0, 1e-2);
  std::vector<int> traced = d["trace_joints"].get<std::vector<int>>();
  std::sort(traced.begin(), traced.end());
  EXPECT_EQ(traced, (std::vector<int>{0, 1, 2}));  // node indices of the chain
}

}  // namespace
}  // namespace kinema
