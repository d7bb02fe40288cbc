// Issue 19, the readers: hostile files built by the test (FIFOs, devices, /proc, glTF uris
// leaving their folder, huge images, a JSON tree of zeros, 50 MB tokens, truncated glTF)
// are refused by a child `kinema` process with exit 1 and one readable line naming the file
// and the place, without hanging and within 4 x the input's size + 256 MB of memory.
// KINEMA_HOSTILE_MB scales the large cases (default 50, 8 when CI is set).
#include <fcntl.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <string>
#include <thread>
#include <vector>

#include "io/bvh.h"
#include "io/image.h"
#include "io/json_document.h"
#include "io/kinema_file.h"
#include "io/message_text.h"
#include "io/scene_files.h"
#include "io/text_file.h"
#include "io/hostile_files.h"
#include "test_support.h"

namespace kinema {
namespace KINEMA_UNITY_ID {

using test::makeTempDir;
using test::writeFile;
using namespace test::hostile;

size_t hostileMegabytes(size_t localDefault) {
  if (const char* v = std::getenv("KINEMA_HOSTILE_MB")) return std::max<size_t>(1, std::strtoull(v, nullptr, 10));
#ifdef KINEMA_UNDER_SANITIZER
  (void)localDefault;  // ASan's shadow memory: small cases only
  return 4;
#else
  return std::getenv("CI") ? 8 : localDefault;
#endif
}

struct ChildRun {
  int exitCode = -1;
  bool timedOut = false;
  std::string out, err;
  long long maxRssBytes = 0;
};

// Runs the kinema binary with `args` (stdin closed), killing it after `timeoutSeconds`;
// the peak resident memory is the child's own (wait4's rusage, as RUSAGE_CHILDREN counts it).
ChildRun runKinema(const std::vector<std::string>& args, int timeoutSeconds = 30) {
  const std::string dir = makeTempDir();
  const std::string outPath = dir + "/out", errPath = dir + "/err";
  std::vector<std::string> argv = {KINEMA_BINARY};
  argv.insert(argv.end(), args.begin(), args.end());
  const pid_t pid = ::fork();
  if (pid == 0) {
    const int in = ::open("/dev/null", O_RDONLY);
    const int out = ::open(outPath.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    const int err = ::open(errPath.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    ::dup2(in, 0);
    ::dup2(out, 1);
    ::dup2(err, 2);
    std::vector<char*> c;
    for (std::string& a : argv) c.push_back(a.data());
    c.push_back(nullptr);
    ::execv(c[0], c.data());
    ::_exit(127);
  }
  ChildRun run;
  int status = 0;
  struct rusage usage {};
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(timeoutSeconds);
  while (true) {
    const pid_t done = ::wait4(pid, &status, WNOHANG, &usage);
    if (done == pid) break;
    if (std::chrono::steady_clock::now() > deadline) {
      run.timedOut = true;
      ::kill(pid, SIGKILL);
      ::wait4(pid, &status, 0, &usage);
      break;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  run.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  run.maxRssBytes = static_cast<long long>(usage.ru_maxrss) * 1024;
  run.out = test::readFile(outPath);
  run.err = test::readFile(errPath);
  std::system(("rm -rf '" + dir + "'").c_str());
  return run;
}

// Exit 1 and one line "kinema: MESSAGE" of at most 300 characters that contains each of `parts`.
void expectRefused(const ChildRun& run, const std::vector<std::string>& parts) {
  EXPECT_FALSE(run.timedOut) << "kinema did not finish (a hang)";
  EXPECT_EQ(run.exitCode, 1) << run.err.substr(0, 400);
  ASSERT_FALSE(run.err.empty());
  EXPECT_EQ(run.err.find('\n'), run.err.size() - 1) << "not one line: " << run.err.substr(0, 400);
  const std::string prefix = "kinema: ";
  ASSERT_EQ(run.err.rfind(prefix, 0), 0u) << run.err.substr(0, 400);
  const std::string message = run.err.substr(prefix.size(), run.err.size() - prefix.size() - 1);
  EXPECT_LE(message.size(), kMaxMessageBytes) << message.substr(0, 400);
  for (const std::string& p : parts) EXPECT_NE(message.find(p), std::string::npos) << "no '" << p << "' in: " << message;
}

// Peak memory within 4 x the input's size + 256 MB (ASan's shadow memory would not be).
void expectBoundedMemory(const ChildRun& run, long long inputBytes) {
#ifdef KINEMA_UNDER_SANITIZER
  (void)run, (void)inputBytes;
#else
  const long long bound = 4 * inputBytes + (256LL << 20);
  EXPECT_LE(run.maxRssBytes, bound) << "peak " << (run.maxRssBytes >> 20) << " MB for an input of "
                                    << (inputBytes >> 20) << " MB";
#endif
}

class HostileRead : public ::testing::Test {
 protected:
  void SetUp() override { dir = makeTempDir(); }
  void TearDown() override { std::system(("rm -rf '" + dir + "'").c_str()); }
  std::string dir;
};

TEST_F(HostileRead, FifosAreRefusedBeforeOpeningWithoutHanging) {
  for (const std::string name : {"pipe.bvh", "pipe.kinema", "pipe.gltf", "pipe.glb"}) {
    const std::string path = dir + "/" + name;
    ASSERT_EQ(::mkfifo(path.c_str(), 0600), 0);
    for (const char* command : {"pose", "convert", "skin"}) {
      std::vector<std::string> args = {command, path};
      if (std::string(command) == "pose") args.push_back("--frame=0");
      if (std::string(command) == "convert") args.push_back(dir + "/out.kinema");
      SCOPED_TRACE(std::string(command) + " " + name);
      const ChildRun run = runKinema(args, 20);
      expectRefused(run, {path + ": is a FIFO (named pipe), not a regular file"});
    }
  }
  // A glTF buffer naming a FIFO beside it: refused too (tinygltf's own check would block).
  ASSERT_EQ(::mkfifo((dir + "/buffer.bin").c_str(), 0600), 0);
  writeFile(dir + "/fifo_buffer.gltf", gltfWithBufferUri("buffer.bin"));
  expectRefused(runKinema({"pose", dir + "/fifo_buffer.gltf", "--frame=0"}, 20),
                {"fifo_buffer.gltf: buffer 0: uri 'buffer.bin' is a FIFO (named pipe), not a regular file"});
}

TEST_F(HostileRead, DevicesAndProcAreRefusedBeforeReadingAByte) {
  ASSERT_EQ(::symlink("/dev/zero", (dir + "/zero.bvh").c_str()), 0);
  ASSERT_EQ(::symlink("/dev/urandom", (dir + "/random.kinema").c_str()), 0);
  ASSERT_EQ(::symlink("/proc/self/status", (dir + "/status.bvh").c_str()), 0);
  for (const auto& [file, why] : std::vector<std::pair<std::string, std::string>>{
           {"zero.bvh", "is a character device, not a regular file"},
           {"random.kinema", "is a character device, not a regular file"},
           {"status.bvh", "is on /proc, not a regular file"}}) {
    SCOPED_TRACE(file);
    const ChildRun run = runKinema({"pose", dir + "/" + file, "--frame=0"});
    expectRefused(run, {dir + "/" + file + ": " + why});
    expectBoundedMemory(run, 0);  // nothing is read: the bound is the 256 MB floor
  }
  // The same check as a library call, for the editor and the other readers.
  std::string text;
  EXPECT_EQ(readTextFile("/dev/zero", text), "/dev/zero: is a character device, not a regular file");
  EXPECT_EQ(notARegularFile("/proc/self/status"), "is on /proc, not a regular file");
  EXPECT_EQ(notARegularFile(dir), "is a directory, not a file");
}

TEST_F(HostileRead, ReadingStopsAtTheLimitWhateverTheFileClaims) {
  writeFile(dir + "/a.bvh", std::string(1000, 'x'));
  std::string text;
  EXPECT_EQ(readTextFile(dir + "/a.bvh", text, 1000), "");
  EXPECT_EQ(text.size(), 1000u);
  EXPECT_EQ(readTextFile(dir + "/a.bvh", text, 999),
            dir + "/a.bvh: the file is 1000 bytes, more than the limit of 999 (InputLimits::maxFileBytes)");
  EXPECT_TRUE(text.empty());
}

TEST_F(HostileRead, GltfUrisLeavingTheFolderAreRefusedPlainOrPercentEncoded) {
  // root/outside.bin holds a valid triangle; root/sub/*.gltf name it in three ways.
  ::mkdir((dir + "/sub").c_str(), 0755);
  writeFile(dir + "/outside.bin", triangleBytes());
  writeFile(dir + "/sub/inside.bin", triangleBytes());
  ASSERT_EQ(::symlink((dir + "/outside.bin").c_str(), (dir + "/sub/link.bin").c_str()), 0);
  writeFile(dir + "/sub/plain.gltf", gltfWithBufferUri("../outside.bin"));
  writeFile(dir + "/sub/encoded.gltf", gltfWithBufferUri("%2e%2e%2Foutside.bin"));
  writeFile(dir + "/sub/link.gltf", gltfWithBufferUri("link.bin"));
  writeFile(dir + "/sub/inside.gltf", gltfWithBufferUri("inside.bin"));
  ASSERT_EQ(runKinema({"pose", dir + "/sub/inside.gltf", "--frame=0"}).exitCode, 0) << "the file itself is valid";
  for (const std::string name : {"plain", "encoded", "link"}) {
    SCOPED_TRACE(name);
    const std::string file = dir + "/sub/" + name + ".gltf";
    const std::string uri = name == "link" ? "link.bin" : "../outside.bin";
    for (const char* command : {"pose", "convert"}) {
      std::vector<std::string> args = {command, file};
      args.push_back(std::string(command) == "pose" ? "--frame=0" : dir + "/out.glb");
      expectRefused(runKinema(args), {file + ": buffer 0: uri '" + uri + "' is outside the glTF file's folder"});
      // The user may allow it; the bytes are then the triangle.
      args.push_back("--allow-outside-paths");
      EXPECT_EQ(runKinema(args).exitCode, 0) << command;
    }
  }
  // A real system file: refused, and its size is not told (a second try could match it).
  writeFile(dir + "/sub/passwd.gltf", gltfWithBufferUri("../../../../../../../../etc/passwd"));
  expectRefused(runKinema({"convert", dir + "/sub/passwd.gltf", dir + "/out.glb"}),
                {"buffer 0: uri '../../../../../../../../etc/passwd' is outside the glTF file's folder"});
  std::string passwd;
  ASSERT_EQ(readTextFile("/etc/passwd", passwd), "");
  const ChildRun allowed = runKinema({"pose", dir + "/sub/passwd.gltf", "--frame=0", "--allow-outside-paths"});
  expectRefused(allowed, {"buffer 0: uri '../../../../../../../../etc/passwd' does not hold the buffer's byteLength of 36"});
  EXPECT_EQ(allowed.err.find(std::to_string(passwd.size())), std::string::npos) << allowed.err;
  // Devices stay refused with --allow-outside-paths.
  writeFile(dir + "/sub/zero.gltf", gltfWithBufferUri("/dev/zero"));
  ASSERT_EQ(::symlink("/dev/zero", (dir + "/sub/zero.bin").c_str()), 0);
  writeFile(dir + "/sub/zero_link.gltf", gltfWithBufferUri("zero.bin"));
  expectRefused(runKinema({"pose", dir + "/sub/zero_link.gltf", "--frame=0", "--allow-outside-paths"}),
                {"buffer 0: uri 'zero.bin' is a character device, not a regular file"});
  // An absolute path is named as one, with or without the option (it was "is not there").
  for (const bool allow : {false, true}) {
    std::vector<std::string> args = {"pose", dir + "/sub/zero.gltf", "--frame=0"};
    if (allow) args.push_back("--allow-outside-paths");
    expectRefused(runKinema(args), {"buffer 0: uri '/dev/zero' is an absolute path; Kinema reads uris relative to the glTF file"});
  }
  // Climbing out is judged on the uri's text, before looking: a missing file outside the
  // folder gets the same answer as a present one, so a refusal tells nothing about outside.
  writeFile(dir + "/sub/missing.gltf", gltfWithBufferUri("../no-such-file.bin"));
  expectRefused(runKinema({"pose", dir + "/sub/missing.gltf", "--frame=0"}),
                {"buffer 0: uri '../no-such-file.bin' is outside the glTF file's folder"});
  // Going down and back up stays inside.
  writeFile(dir + "/sub/around.gltf", gltfWithBufferUri("x/../inside.bin"));
  ::mkdir((dir + "/sub/x").c_str(), 0755);
  EXPECT_EQ(runKinema({"pose", dir + "/sub/around.gltf", "--frame=0"}).exitCode, 0);
}

TEST_F(HostileRead, TinygltfMessagesGetTheirObjectIndex) {
  std::string count = gltfWithBufferUri("inside.bin");
  writeFile(dir + "/inside.bin", triangleBytes());
  count.replace(count.find("\"count\": 3"), 10, "\"count\": -3");
  writeFile(dir + "/count.gltf", count);
  expectRefused(runKinema({"pose", dir + "/count.gltf", "--frame=0"}),
                {dir + "/count.gltf: accessor 0: 'count' property is not a positive integer"});
  std::string stride = gltfWithBufferUri("inside.bin");
  const std::string view = R"("bufferViews": [{"buffer": 0, "byteLength": 36})";
  stride.replace(stride.find(view), view.size(), R"("bufferViews": [{"buffer": 0, "byteLength": 36, "byteStride": 13})");
  writeFile(dir + "/stride.gltf", stride);
  expectRefused(runKinema({"pose", dir + "/stride.gltf", "--frame=0"}), {"stride.gltf: bufferView 0: ", "byteStride"});
  std::string missing = gltfWithBufferUri("missing.bin");
  writeFile(dir + "/missing.gltf", missing);
  expectRefused(runKinema({"pose", dir + "/missing.gltf", "--frame=0"}),
                {"missing.gltf: buffer 0: uri 'missing.bin' is not there"});
  writeFile(dir + "/data.gltf", gltfWithBufferUri("data:application/zip;base64,AAAA"));
  expectRefused(runKinema({"pose", dir + "/data.gltf", "--frame=0"}),
                {"data.gltf: buffer 0: uri 'data:application/zip;base64,AAAA' is not a base64 data URI"});
  // A number past double's range: the line it is on.
  writeFile(dir + "/overflow.gltf", "{\"asset\": {\"version\": \"2.0\"},\n\"nodes\": [{\"translation\": [1e400, 0, 0]}]}");
  expectRefused(runKinema({"pose", dir + "/overflow.gltf", "--frame=0"}),
                {"overflow.gltf: the glTF JSON is malformed at line 2, ", "number overflow parsing '1e400'"});
}

TEST_F(HostileRead, TruncatedGltfIsOneShortLineWithoutItsBase64) {
  // A self-contained .gltf (buffers as base64) of a BVH's skeleton and motion, cut in half.
  writeFile(dir + "/walk.bvh", kLegBvh);
  ASSERT_EQ(runKinema({"convert", dir + "/walk.bvh", dir + "/walk.gltf"}).exitCode, 0);
  const std::string whole = test::readFile(dir + "/walk.gltf");
  const size_t data = whole.find("base64,");
  ASSERT_NE(data, std::string::npos);
  writeFile(dir + "/cut.gltf", whole.substr(0, data + 40));
  const ChildRun run = runKinema({"pose", dir + "/cut.gltf", "--frame=0"});
  expectRefused(run, {dir + "/cut.gltf: the glTF JSON is malformed at line "});
  EXPECT_EQ(run.err.find(whole.substr(data + 7, 30)), std::string::npos) << "base64 echoed: " << run.err;
}

TEST_F(HostileRead, LongTokensAndJointNamesAreCutInMessages) {
  const size_t megabytes = hostileMegabytes(50);
  const std::string huge(megabytes << 20, 'n');
  // A joint name used twice, a token where ROOT belongs and a .kinema joint reference.
  std::string twice = kLegBvh;
  twice.replace(twice.find("knee"), 4, huge);
  twice.replace(twice.find("ROOT hips"), 9, "ROOT " + huge);
  writeFile(dir + "/twice.bvh", twice);
  std::string token = kLegBvh;
  token.replace(token.find("ROOT hips"), 9, huge);
  writeFile(dir + "/token.bvh", token);
  const std::string kinema = R"({"format": "kinema", "version": 1, "skeleton": {"joints": [{"name": "a", "parent": -1}]},)"
                             R"( "clips": [{"name": "c", "channels": [{"joint": ")" + huge +
                             R"(", "target": "translation", "times": [0], "values": [[0, 0, 0]]}]}]})";
  writeFile(dir + "/name.kinema", kinema);
  const std::string cut = std::string(40, 'n');
  for (const auto& [file, parts] : std::vector<std::pair<std::string, std::vector<std::string>>>{
           {"twice.bvh", {"twice.bvh:6: joint name '" + cut, "\xe2\x80\xa6' is used twice"}},
           {"token.bvh", {"token.bvh:2: expected ROOT, JOINT, End Site or '}', found '" + cut, "\xe2\x80\xa6'"}},
           {"name.kinema", {"name.kinema: clips[0].channels[0].joint: no joint named '" + cut, "\xe2\x80\xa6'"}}}) {
    SCOPED_TRACE(file);
    const ChildRun run = runKinema({"pose", dir + "/" + file, "--frame=0"}, 120);
    expectRefused(run, parts);
    expectBoundedMemory(run, static_cast<long long>(test::readFile(dir + "/" + file).size()));
  }
}

TEST_F(HostileRead, BvhWithAByteOrderMarkLoads) {
  const Result<BvhData> plain = parseBvh(kLegBvh, "plain.bvh");
  const Result<BvhData> marked = parseBvh("\xEF\xBB\xBF" + std::string(kLegBvh), "bom.bvh");
  ASSERT_TRUE(plain) << plain.error();
  ASSERT_TRUE(marked) << marked.error();
  ASSERT_EQ(marked->joints.size(), plain->joints.size());
  for (size_t j = 0; j < plain->joints.size(); ++j) EXPECT_EQ(marked->joints[j].name, plain->joints[j].name);
  EXPECT_EQ(marked->motion, plain->motion);
  // Lines still count from the first: an error on line 2 is reported there.
  const Result<BvhData> bad = parseBvh("\xEF\xBB\xBFHIERARCHY\nRUT hips\n", "bad.bvh");
  ASSERT_FALSE(bad);
  EXPECT_EQ(bad.error().rfind("bad.bvh:2: ", 0), 0u) << bad.error();
}

TEST_F(HostileRead, ImagesAreCountedAgainstTheFilesBudgetBeforeDecoding) {
  // A header claiming 16384 x 16384 (1 GiB decoded) in a file of a few hundred bytes.
  writeFile(dir + "/claim.kinema", kinemaWithImages({pngClaiming(4, 4, 16384, 16384)}));
  const ChildRun claim = runKinema({"pose", dir + "/claim.kinema", "--frame=0"});
  expectRefused(claim, {"claim.kinema: images[0].png: 16384 x 16384 pixels would take",
                        "(InputLimits::imageBytesOverFileSize)"});
  expectBoundedMemory(claim, 0);
  // Forty real images of 2048 x 2048 (16 MiB each decoded; they compress to almost nothing):
  // those within the file's size + 64 MiB decode, the next one is refused.
  const int side = 2048;
  const std::string png = pngClaiming(side, side, side, side);
  const std::string text = kinemaWithImages(std::vector<std::string>(40, png));
  writeFile(dir + "/forty.kinema", text);
  const size_t each = size_t(side) * side * 4;
  const size_t fits = (text.size() + (size_t(64) << 20)) / each;
  const ChildRun forty = runKinema({"pose", dir + "/forty.kinema", "--frame=0"});
  expectRefused(forty, {"forty.kinema: images[" + std::to_string(fits) + "].png: 2048 x 2048 pixels would take"});
  expectBoundedMemory(forty, static_cast<long long>(text.size()));
  // The same budget in the library: the images before it are decoded, the file refused.
  InputLimits limits;
  limits.imageBytesOverFileSize = 3 * each;  // with the file's own size: three images, not four
  const Result<Scene> r = parseKinemaJson(kinemaWithImages(std::vector<std::string>(4, png)), "four.kinema", limits);
  ASSERT_FALSE(r);
  EXPECT_EQ(r.error().rfind("four.kinema: images[3].png: ", 0), 0u) << r.error();
}

TEST_F(HostileRead, AGltfImageOverTheBudgetIsDroppedWithAWarningNotDecoded) {
  // A base-colour image whose header claims 8192 x 8192 (256 MiB decoded) in a tiny .gltf:
  // the file loads, the image is not decoded and a warning names the limit.
  const std::string gltf = R"({"asset": {"version": "2.0"}, "nodes": [{"name": "n"}], "images": [{"uri": )"
                           R"("data:image/png;base64,)" + base64(pngClaiming(4, 4, 8192, 8192)) +
                           R"("}], "textures": [{"source": 0}], "materials": [{"pbrMetallicRoughness": )"
                           R"({"baseColorTexture": {"index": 0}}}]})";
  writeFile(dir + "/claim.gltf", gltf);
  const Result<Scene> scene = loadScene(dir + "/claim.gltf");
  ASSERT_TRUE(scene) << scene.error();
  ASSERT_EQ(scene->images.size(), 1u);
  EXPECT_TRUE(scene->images[0].rgba.empty());
  bool warned = false;
  for (const std::string& w : scene->warnings)
    warned = warned || (w.rfind("image 0: 8192x8192 pixels would take", 0) == 0 &&
                        w.find("(InputLimits::imageBytesOverFileSize): shown without its texture") != std::string::npos);
  EXPECT_TRUE(warned) << ::testing::PrintToString(scene->warnings);
  const ChildRun run = runKinema({"pose", dir + "/claim.gltf", "--frame=0"});
  EXPECT_EQ(run.exitCode, 0) << run.err;
  expectBoundedMemory(run, static_cast<long long>(gltf.size()));
}

TEST_F(HostileRead, AKinemaFileOfZerosIsRefusedBeforeItsTreeIsBuilt) {
  // A large array of zeros: 2 bytes of text, 16 bytes as a JSON value.
  const size_t megabytes = hostileMegabytes(200);
  std::string text = R"({"format": "kinema", "version": 1, "skeleton": {"joints": [{"name": "a", "parent": -1}]}, "z": [0)";
  text.reserve((megabytes << 20) + 16);
  while (text.size() < (megabytes << 20)) text += ",0";
  text += "]}";
  writeFile(dir + "/zeros.kinema", text);
  const ChildRun run = runKinema({"pose", dir + "/zeros.kinema", "--frame=0"}, 120);
  expectRefused(run, {"zeros.kinema: the JSON would take ", "(2 x the file's size + InputLimits::jsonTreeBytesOverFileSize)"});
  expectBoundedMemory(run, static_cast<long long>(text.size()));
  // The count: at least one 16-byte value per number; 0 for text that is not JSON.
  std::string zeros = "[0";
  for (int i = 0; i < 100000; ++i) zeros += ",0";
  zeros += "]";
  EXPECT_GE(jsonTreeBytes(zeros.data(), zeros.size()), 100001u * 16);
  const std::string broken = "[0,,0]";
  EXPECT_EQ(jsonTreeBytes(broken.data(), broken.size()), 0u);
}

TEST_F(HostileRead, NumberOverflowInAKinemaFileNamesItsLine) {
  const std::string text = "{\"format\": \"kinema\", \"version\": 1,\n\"skeleton\": {\"joints\": [\n"
                           "{\"name\": \"a\", \"parent\": -1, \"translation\": [1e400, 0, 0]}]}}";
  const Result<Scene> r = parseKinemaJson(text, "big.kinema");
  ASSERT_FALSE(r);
  EXPECT_EQ(r.error().rfind("big.kinema: not valid JSON: line 3, column ", 0), 0u) << r.error();
  EXPECT_NE(r.error().find(": number overflow parsing '1e400'"), std::string::npos) << r.error();
}

TEST(MessageText, CutsLongTextAtACharacterBoundaryAndKeepsOneLine) {
  EXPECT_EQ(cutForMessage("short"), "short");
  EXPECT_EQ(cutForMessage(std::string(100, 'a'), 10), "aaaaaaa\xe2\x80\xa6");
  // "é" is two bytes: a cut never splits it.
  const std::string cut = cutForMessage(std::string(6, 'a') + "\xc3\xa9\xc3\xa9\xc3\xa9", 10);
  EXPECT_EQ(cut, "aaaaaa\xe2\x80\xa6");
  EXPECT_EQ(cutForMessage("a\nb"), "a\\x0ab");
  const std::string line = oneLineMessage("file: " + std::string(1000, 'x') + "\nmore");
  EXPECT_LE(line.size(), kMaxMessageBytes);
  EXPECT_EQ(line.find('\n'), std::string::npos);
  EXPECT_EQ(line.substr(line.size() - 3), "\xe2\x80\xa6");
}

}  // namespace
}  // namespace kinema
