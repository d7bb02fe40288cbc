// The command-line contract (docs/cli.md), driven through the built binary.
#include <nlohmann/json.hpp>

#include <fstream>
#include <sstream>

#include "io/image.h"
#include "test_support.h"

namespace kinema::test {
namespace {

// Root at (1,2,3); frame 1 turns the root 90 degrees about Z. Arm is 2 up, its End Site 1 up.
const char* kTwoFrames =
    "HIERARCHY\n"
    "ROOT Root\n{\n  OFFSET 0 0 0\n"
    "  CHANNELS 6 Xposition Yposition Zposition Zrotation Xrotation Yrotation\n"
    "  JOINT Arm\n  {\n    OFFSET 0 2 0\n    CHANNELS 3 Zrotation Xrotation Yrotation\n"
    "    End Site\n    {\n      OFFSET 0 1 0\n    }\n  }\n}\n"
    "MOTION\nFrames: 2\nFrame Time: 0.5\n"
    "1 2 3 0 0 0 0 0 0\n"
    "1 2 3 90 0 0 0 0 0\n";

class Cli : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = makeTempDir();
    ASSERT_FALSE(dir_.empty());
    bvh_ = dir_ + "/two.bvh";
    writeFile(bvh_, kTwoFrames);
  }
  void TearDown() override { std::system(("rm -rf '" + dir_ + "'").c_str()); }

  int kinema(const std::string& args) { return runCommand(std::string(KINEMA_BINARY) + " " + args, &out_, &err_); }
  nlohmann::json json() { return nlohmann::json::parse(out_); }
  static int lines(const std::string& s) {
    int n = 0;
    for (char c : s) n += c == '\n';
    return n;
  }

  std::string dir_, bvh_, out_, err_;
};

glm::vec3 position(const nlohmann::json& joint) {
  const auto& w = joint["world"];
  return {w[12].get<float>(), w[13].get<float>(), w[14].get<float>()};
}

TEST_F(Cli, HelpListsSubcommandsAndExitsZero) {
  EXPECT_EQ(kinema("--help"), 0);
  EXPECT_NE(out_.find("pose"), std::string::npos) << out_;
}

TEST_F(Cli, EditListCommandsPrintsTheControlsTableWithTheKeymapApplied) {
  // No window is needed: the table is the registry and the keymap (docs/cli.md). The config
  // folder is the test's own, first without a keymap file (the defaults), then with one.
  const std::string listCommands = "XDG_CONFIG_HOME='" + dir_ + "' " + KINEMA_BINARY + " edit --list-commands";
  ASSERT_EQ(runCommand(listCommands, &out_, &err_), 0) << err_;
  EXPECT_NE(out_.find("| Ctrl+S | Save: "), std::string::npos) << out_.substr(0, 400);
  EXPECT_NE(out_.find("`pose.pin_ik_target`"), std::string::npos);
  EXPECT_EQ(err_, "");
  runCommand("mkdir -p '" + dir_ + "/kinema'");
  writeFile(dir_ + "/kinema/keymap.txt", "file.save = F2\nfile.frobnicate = F3\n");
  ASSERT_EQ(runCommand(listCommands, &out_, &err_), 0) << err_;
  EXPECT_NE(out_.find("| F2 | Save: "), std::string::npos);
  EXPECT_NE(err_.find(dir_ + "/kinema/keymap.txt:2: unknown command 'file.frobnicate'"), std::string::npos) << err_;
}

TEST_F(Cli, DocsControlsIsTheRegistrysTableAsGenerated) {
  // docs/controls.md is `kinema edit --list-commands` with no keymap file; a command added,
  // renamed or rebound without regenerating it (docs/controls.md says how) fails here.
  ASSERT_EQ(runCommand("XDG_CONFIG_HOME='" + dir_ + "' " + KINEMA_BINARY + " edit --list-commands", &out_, &err_), 0)
      << err_;
  std::ifstream in(std::string(KINEMA_SOURCE_DIR) + "/docs/controls.md");
  std::stringstream doc;
  doc << in.rdbuf();
  const std::string text = doc.str(), marker = "<!-- generated: kinema edit --list-commands -->\n";
  const size_t at = text.find(marker);
  ASSERT_NE(at, std::string::npos) << "docs/controls.md lacks the generated marker";
  EXPECT_EQ(text.substr(at + marker.size()), out_) << "regenerate docs/controls.md (see its first lines)";
}

TEST_F(Cli, EditRefusesAScriptCommandThatIsNoCommand) {
  writeFile(dir_ + "/s.jsonl", "{\"frame\":1,\"type\":\"command\",\"id\":\"view.grid\"}\n"
                               "{\"frame\":2,\"type\":\"command\",\"id\":\"pose.pin\"}\n");
  EXPECT_EQ(kinema("edit --script '" + dir_ + "/s.jsonl'"), 1);
  EXPECT_NE(err_.find("s.jsonl: line 2: 'id' \"pose.pin\" is not a command"), std::string::npos) << err_;
}

TEST_F(Cli, PoseFrameGivesHandDerivedWorldTransforms) {
  ASSERT_EQ(kinema("pose '" + bvh_ + "' --frame 1 --json"), 0) << err_;
  const nlohmann::json j = json();
  EXPECT_DOUBLE_EQ(j["time"].get<double>(), 0.5);
  ASSERT_EQ(j["joints"].size(), 3u);
  EXPECT_EQ(j["joints"][0]["name"], "Root");
  EXPECT_EQ(j["joints"][0]["parent"], -1);
  EXPECT_EQ(j["joints"][1]["name"], "Arm");
  EXPECT_EQ(j["joints"][1]["parent"], 0);
  EXPECT_EQ(j["joints"][2]["name"], "Arm_End");
  EXPECT_EQ(j["joints"][2]["parent"], 1);
  // Root: Rz(90) then moved to (1,2,3); column-major.
  const float expected[16] = {0, 1, 0, 0, -1, 0, 0, 0, 0, 0, 1, 0, 1, 2, 3, 1};
  for (int k = 0; k < 16; ++k) EXPECT_NEAR(j["joints"][0]["world"][k].get<float>(), expected[k], 1e-6f) << k;
  // Rz(90) takes the arm's (0,2,0) to (-2,0,0) and the End Site's (0,1,0) to (-1,0,0).
  EXPECT_VEC3_NEAR(position(j["joints"][1]), glm::vec3(-1, 2, 3), 1e-6f);
  EXPECT_VEC3_NEAR(position(j["joints"][2]), glm::vec3(-2, 2, 3), 1e-6f);
}

TEST_F(Cli, PoseTimeInterpolatesAndClamps) {
  // Half-way: 45 degrees about Z takes (0,2,0) to (-sqrt2, sqrt2, 0).
  ASSERT_EQ(kinema("pose '" + bvh_ + "' --time 0.25 --json"), 0) << err_;
  const float r = std::sqrt(2.0f);
  EXPECT_VEC3_NEAR(position(json()["joints"][1]), glm::vec3(1 - r, 2 + r, 3), 1e-5f);
  // After the end: holds the last frame; before the start: holds the first.
  ASSERT_EQ(kinema("pose '" + bvh_ + "' --time 100 --json"), 0);
  EXPECT_DOUBLE_EQ(json()["time"].get<double>(), 100.0);
  EXPECT_VEC3_NEAR(position(json()["joints"][1]), glm::vec3(-1, 2, 3), 1e-6f);
  ASSERT_EQ(kinema("pose '" + bvh_ + "' --time -3 --json"), 0);
  EXPECT_VEC3_NEAR(position(json()["joints"][1]), glm::vec3(1, 4, 3), 1e-6f);
  ASSERT_EQ(kinema("pose '" + bvh_ + "' --frame 7 --json"), 0);
  EXPECT_DOUBLE_EQ(json()["time"].get<double>(), 3.5);
  EXPECT_VEC3_NEAR(position(json()["joints"][2]), glm::vec3(-2, 2, 3), 1e-6f);
}

TEST_F(Cli, PoseWithoutJsonPrintsATable) {
  ASSERT_EQ(kinema("pose '" + bvh_ + "' --frame 0"), 0);
  EXPECT_NE(out_.find("Arm_End"), std::string::npos);
  EXPECT_THROW(nlohmann::json::parse(out_), nlohmann::json::parse_error);
}

TEST_F(Cli, UsageErrorsExitTwoWithOneLine) {
  for (const std::string& args : std::vector<std::string>{"pose --no-such-flag", "no-such-command", "pose '" + bvh_ + "' --json",
                                 "pose '" + bvh_ + "' --time abc --json",
                                 "pose '" + bvh_ + "' --time 1 --frame 2 --json", "pose"}) {
    EXPECT_EQ(kinema(args), 2) << args;
    EXPECT_EQ(lines(err_), 1) << args << ": " << err_;
    EXPECT_NE(err_.find("--help"), std::string::npos) << args << ": " << err_;
    EXPECT_TRUE(out_.empty()) << args;
  }
}

TEST_F(Cli, BadInputExitsOneWithOneLine) {
  const std::string notBvh = dir_ + "/garbage.bvh";
  writeFile(notBvh, "HIERARCHY\nROOT A\n{\n  OFFSET 0 zero 0\n");
  const std::string unknownType = dir_ + "/thing.xyz";
  writeFile(unknownType, "x");
  const struct {
    std::string args, mentions;
  } cases[] = {
      {"pose '" + dir_ + "/missing.bvh' --frame 0 --json", "missing.bvh"},
      {"pose '" + notBvh + "' --frame 0 --json", "garbage.bvh:4"},
      {"pose '" + unknownType + "' --frame 0 --json", "thing.xyz"},
      {"pose '" + dir_ + "' --frame 0 --json", dir_},
      {"pose '" + bvh_ + "' --time nan --json", "finite"},
      {"pose '" + bvh_ + "' --time inf --json", "finite"},
      {"pose '" + bvh_ + "' --clip 3 --frame 0 --json", "clip"},
      {"pose '" + bvh_ + "' --clip -1 --frame 0 --json", "clip"},
  };
  for (const auto& c : cases) {
    EXPECT_EQ(kinema(c.args), 1) << c.args;
    EXPECT_EQ(lines(err_), 1) << c.args << ": " << err_;
    EXPECT_NE(err_.find(c.mentions), std::string::npos) << c.args << ": " << err_;
    EXPECT_TRUE(out_.empty()) << c.args;
  }
}

// Plain `kinema` opens the editor; without a display it renders the default character to
// ./kinema-default.png and prints that path.
TEST_F(Cli, NoSubcommandWithoutDisplayRendersTheDefaultCharacterToAPng) {
  ASSERT_EQ(runCommand("cd '" + dir_ + "' && env -u DISPLAY -u WAYLAND_DISPLAY LIBGL_ALWAYS_SOFTWARE=1 "
                           "ASAN_OPTIONS=${ASAN_OPTIONS:+$ASAN_OPTIONS:}detect_leaks=0 " +  // Mesa's own leftovers

                           std::string(KINEMA_BINARY), &out_, &err_), 0) << err_;
  const std::string path = dir_ + "/kinema-default.png";
  EXPECT_NE(out_.find(path), std::string::npos) << out_;
  Result<Image> image = loadPng(path);
  ASSERT_TRUE(image.ok()) << image.error();
  // Not blank: the background grey is not the only colour, and bones (light grey) are drawn.
  int bright = 0, background = 0;
  for (size_t i = 0; i < image->rgba.size(); i += 4) {
    bright += image->rgba[i] > 140 && image->rgba[i + 1] > 140 && image->rgba[i + 2] > 140;
    background += image->rgba[i] == image->rgba[0] && image->rgba[i + 1] == image->rgba[1];
  }
  EXPECT_GT(bright, 500);
  EXPECT_LT(background, static_cast<int>(image->rgba.size() / 4) * 95 / 100);
}

TEST_F(Cli, KinemaFileEvaluatesLikeTheBvhItCameFrom) {
  // The same motion saved as .kinema (written by hand here, not by Kinema) poses the same.
  const std::string path = dir_ + "/two.kinema";
  writeFile(path, R"({"format":"kinema","version":1,
    "skeleton":{"joints":[
      {"name":"Root","parent":-1,"translation":[0,0,0]},
      {"name":"Arm","parent":0,"translation":[0,2,0]}]},
    "clips":[{"name":"turn","channels":[
      {"joint":"Root","target":"translation","times":[0],"values":[[1,2,3]]},
      {"joint":"Root","target":"rotation","times":[0,0.5],
       "values":[[0,0,0,1],[0,0,0.70710678,0.70710678]]}]}]})");
  ASSERT_EQ(kinema("pose '" + path + "' --time 0.5 --json"), 0) << err_;
  EXPECT_VEC3_NEAR(position(json()["joints"][1]), glm::vec3(-1, 2, 3), 1e-6f);
  // No frame grid in this clip: --frame counts at 30 frames per second.
  ASSERT_EQ(kinema("pose '" + path + "' --frame 15 --json"), 0) << err_;
  EXPECT_NEAR(json()["time"].get<double>(), 0.5, 1e-12);
}

}  // namespace
}  // namespace kinema::test
