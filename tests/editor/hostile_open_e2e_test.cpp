// Issue 19 in the editor: opening hostile files through File > Open (Ctrl+O and the file
// dialog's path field) in the real `kinema edit` under xvfb-run. Each one - a FIFO, a device,
// a /proc file, a glTF whose buffer leaves its folder or names a FIFO, a truncated glTF, a
// 1 MB token, an image header claiming 16384 x 16384 - puts its one-line message in the error
// popup (and the log), the open document stays as it was, and the window never stops
// answering: the whole run must end within its time limit.
#include <sys/stat.h>
#include <unistd.h>

#include "editor/e2e_harness.h"
#include "io/hostile_files.h"
#include "io/message_text.h"

namespace kinema::test {
namespace KINEMA_UNITY_ID {

using namespace e2e;
using namespace hostile;

class HostileOpenE2e : public TempDirSuite<HostileOpenE2e> {
 public:
  static constexpr const char* kShotFolder = "hostile_open_e2e";
};

TEST_F(HostileOpenE2e, EachHostileFileShowsItsErrorAndTheDocumentStays) {
  const std::string d = dir_;
  writeFile(d + "/leg.bvh", kLegBvh);
  ASSERT_EQ(::mkfifo((d + "/pipe.bvh").c_str(), 0600), 0);
  ASSERT_EQ(::symlink("/dev/zero", (d + "/zero.bvh").c_str()), 0);
  ASSERT_EQ(::symlink("/proc/self/status", (d + "/status.kinema").c_str()), 0);
  ::mkdir((d + "/sub").c_str(), 0755);
  writeFile(d + "/outside.bin", std::string(36, '\0'));
  writeFile(d + "/sub/outside.gltf", gltfWithBufferUri("%2e%2e/outside.bin"));
  ASSERT_EQ(::mkfifo((d + "/sub/pipe.bin").c_str(), 0600), 0);
  writeFile(d + "/sub/pipe.gltf", gltfWithBufferUri("pipe.bin"));
  const std::string gltf = gltfWithBufferUri("data:application/octet-stream;base64,AAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAA");
  writeFile(d + "/cut.gltf", gltf.substr(0, gltf.find("base64,") + 20));
  std::string token = kLegBvh;
  token.replace(token.find("ROOT hips"), 9, std::string(1 << 20, 't'));
  writeFile(d + "/token.bvh", token);
  writeFile(d + "/claim.kinema", kinemaWithImages({pngClaiming(4, 4, 16384, 16384)}));

  // Each file and what its message must say after the file's name.
  const std::vector<std::pair<std::string, std::string>> cases = {
      {d + "/pipe.bvh", ": is a FIFO (named pipe), not a regular file"},
      {d + "/zero.bvh", ": is a character device, not a regular file"},
      {d + "/status.kinema", ": is on /proc, not a regular file"},
      {d + "/sub/outside.gltf", ": buffer 0: uri '../outside.bin' is outside the glTF file's folder"},
      {d + "/sub/pipe.gltf", ": buffer 0: uri 'pipe.bin' is a FIFO (named pipe), not a regular file"},
      {d + "/cut.gltf", ": the glTF JSON is malformed at line 1, "},
      {d + "/token.bvh", ":2: expected ROOT, JOINT, End Site or '}', found 'tttt"},
      {d + "/claim.kinema", ": images[0].png: 16384 x 16384 pixels would take"},
  };
  Script s(Script::Start::AsOpened);
  s.wait(2);
  for (size_t i = 0; i < cases.size(); ++i) {
    s.chord("O", {"ctrl"}).wait(2).type(cases[i].first).key("ENTER").wait(4);
    if (i + 1 < cases.size()) s.key("ESCAPE").wait(3);  // the last error stays up for the screenshot
  }
  // runEditor's command, under a time limit: a hang fails the test instead of blocking it.
  const std::string scriptPath = d + "/hostile.jsonl", dump = d + "/hostile.json";
  std::ofstream(scriptPath) << s.text();
  std::string out, err;
  const int rc = runCommand("timeout 300 " + xvfb() + editorEnvironment(d) + KINEMA_BINARY + " edit '" + d +
                                "/leg.bvh' --size " + windowSize() + " --script " + scriptPath + " --dump-state " + dump +
                                " --screenshot " + shotDir() + "/hostile_open.png",
                            &out, &err);
  ASSERT_EQ(rc, 0) << "the editor did not finish (124: it hung) " << err;
  const json state = readJson(dump);
  ASSERT_TRUE(state.is_object());

  // Every error reached the log, in order, one line each of at most 300 characters.
  std::vector<std::string> errors;
  for (const json& e : state["log"])
    if (e["error"].get<bool>()) errors.push_back(e["text"]);
  ASSERT_EQ(errors.size(), cases.size()) << state["log"];
  for (size_t i = 0; i < cases.size(); ++i) {
    SCOPED_TRACE(cases[i].first);
    EXPECT_EQ(errors[i].rfind(cases[i].first + cases[i].second, 0), 0u) << errors[i].substr(0, 400);
    EXPECT_LE(errors[i].size(), kMaxMessageBytes);
    EXPECT_EQ(errors[i].find('\n'), std::string::npos);
  }
  // The last one waits in the popup; the leg is still the open, unchanged document.
  ASSERT_EQ(state["errors"].size(), 1u) << state["errors"];
  EXPECT_EQ(state["errors"][0], errors.back());
  EXPECT_EQ(state["path"], d + "/leg.bvh");
  EXPECT_EQ(state["dirty"], false);
  std::vector<std::string> names;
  for (const json& j : state["joints"]) names.push_back(j["name"]);
  EXPECT_EQ(names, (std::vector<std::string>{"hips", "knee", "knee_End"}));
}

}  // namespace
}  // namespace kinema::test
